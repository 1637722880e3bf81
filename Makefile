# feel — the two commands of the README, and a few more.
#   make demo   install what is missing, build, render a sample sensation, plot it
#   make test   install what is missing, build, run every test (and a short fuzz run)
BUILD      ?= build
BUILD_TYPE ?= RelWithDebInfo
# CI (which sets CI=true) turns warnings into errors.
WERROR     := $(if $(filter true 1 yes,$(CI)),ON,OFF)
FEEL       := $(BUILD)/apps/feel/feel
FUZZ_SECONDS ?= 30

.PHONY: all deps build demo plots test unit-tests fuzz bench clean

all: build

deps:
	@bash scripts/install-deps.sh

build: deps
	cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) -DFEEL_WERROR=$(WERROR)
	cmake --build $(BUILD)

demo: build
	@mkdir -p out
	$(FEEL) check examples/primer.feel.json
	$(FEEL) render examples/primer.feel.json --sensation cross_wind_with_gun_blasts \
	    --device joystick --hand firm -o out/cross_wind_with_gun_blasts.csv \
	    --plot out/cross_wind_with_gun_blasts.svg
	$(FEEL) render examples/primer.feel.json --sensation railing_impact \
	    --device joystick --hand firm -o out/railing_impact.csv --plot out/railing_impact.png
	$(FEEL) render examples/walls.feel.json --sensation horizontal_wall \
	    --device joystick --hand firm --motion circle:6000:0.5 -o out/horizontal_wall.csv \
	    --plot out/horizontal_wall.png

# The fuzz run goes first so that the test summary is the last thing printed.
test: build fuzz unit-tests

unit-tests:
	ctest --test-dir $(BUILD) --output-on-failure

# The sensation-file parser under libFuzzer (clang), for a bounded time. New inputs go to
# the build tree; the committed seeds in fuzz/corpus are only read.
fuzz: deps
	CC=clang CXX=clang++ cmake -S . -B $(BUILD)-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	    -DFEEL_WERROR=$(WERROR) -DFEEL_BUILD_FUZZ=ON -DFEEL_BUILD_TESTS=OFF -DFEEL_BUILD_BENCH=OFF
	cmake --build $(BUILD)-fuzz --target fuzz_sensation_file
	@mkdir -p $(BUILD)-fuzz/corpus
	$(BUILD)-fuzz/fuzz/fuzz_sensation_file -max_total_time=$(FUZZ_SECONDS) -print_final_stats=1 \
	    -dict=fuzz/sensation_file.dict $(BUILD)-fuzz/corpus fuzz/corpus/sensation_file

# Every sensation of every example file, rendered and plotted under out/examples/.
plots: build
	bash scripts/render-examples.sh $(FEEL)

bench: build
	$(BUILD)/bench/feel_bench_tick

clean:
	rm -rf $(BUILD) $(BUILD)-fuzz out
