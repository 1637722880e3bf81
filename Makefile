# feel — the two commands of the README, and a few more.
#   make demo   install what is missing, build, render sample sensations and plot them, play
#               one on the simulated device through the host API, stream forces to it
#   make test   install what is missing, build, run every test (and a short fuzz run)
BUILD      ?= build
BUILD_TYPE ?= RelWithDebInfo
# CI (which sets CI=true) turns warnings into errors.
WERROR     := $(if $(filter true 1 yes,$(CI)),ON,OFF)
FEEL       := $(BUILD)/apps/feel/feel
FUZZ_SECONDS ?= 15

.PHONY: all deps build demo plots test unit-tests fuzz bench clean firmware

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
	$(FEEL) play examples/primer.feel.json --sensation railing_impact --seconds 1
	$(FEEL) stream --rate 60 --seconds 1

# The fuzz run goes first so that the test summary is the last thing printed.
test: build firmware fuzz unit-tests

unit-tests:
	ctest --test-dir $(BUILD) --output-on-failure

# Every parser and decoder under libFuzzer (clang), each for a bounded time: the
# sensation-file reader, the protocol's report decoder and the device's protocol session.
# New inputs go to the build tree; the committed seeds in fuzz/corpus/<target> are only read.
FUZZ_TARGETS := sensation_file protocol_decode descriptor_parser device_session
fuzz: deps
	CC=clang CXX=clang++ cmake -S . -B $(BUILD)-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	    -DFEEL_WERROR=$(WERROR) -DFEEL_BUILD_FUZZ=ON -DFEEL_BUILD_TESTS=OFF -DFEEL_BUILD_BENCH=OFF
	cmake --build $(BUILD)-fuzz --target $(addprefix fuzz_,$(FUZZ_TARGETS))
	@set -e; for t in $(FUZZ_TARGETS); do \
	    mkdir -p $(BUILD)-fuzz/corpus/$$t; \
	    dict=; [ -f fuzz/$$t.dict ] && dict=-dict=fuzz/$$t.dict; \
	    echo "fuzz_$$t: $(FUZZ_SECONDS) s"; \
	    $(BUILD)-fuzz/fuzz/fuzz_$$t -max_total_time=$(FUZZ_SECONDS) -print_final_stats=1 $$dict \
	        $(BUILD)-fuzz/corpus/$$t fuzz/corpus/$$t; \
	done

# The engine for a Cortex-M4F (arm-none-eabi-gcc, firmware/), then its size report; the
# test program runs on qemu's mps2-an386 board in make test (tests/firmware/).
firmware: deps
	cmake -S firmware -B $(BUILD)-firmware -G Ninja -DCMAKE_TOOLCHAIN_FILE=$(CURDIR)/firmware/arm-none-eabi.cmake
	cmake --build $(BUILD)-firmware
	bash firmware/size-report.sh $(BUILD)-firmware

# Every sensation of every example file, rendered and plotted under out/examples/.
plots: build
	bash scripts/render-examples.sh $(FEEL)

bench: build
	$(BUILD)/bench/feel_bench_tick
	$(BUILD)/bench/feel_bench_motion_estimator
	$(BUILD)/bench/feel_bench_runtime
	$(BUILD)/bench/feel_bench_host_latency
	$(BUILD)/bench/feel_bench_streaming

clean:
	rm -rf $(BUILD) $(BUILD)-fuzz $(BUILD)-firmware out
