# feel — the two commands of the README, and a few more.
#   make demo   install what is missing, build, render sample sensations and plot them, play
#               one on the simulated device through the host API, stream forces to it
#   make test   install what is missing, build, run every test (and a short fuzz run), and
#               again under ASan+UBSan, the threaded suites under TSan
#   make test-sanitizers   only the two sanitizer runs
BUILD      ?= build
BUILD_TYPE ?= RelWithDebInfo
# CI (which sets CI=true) turns warnings into errors.
WERROR     := $(if $(filter true 1 yes,$(CI)),ON,OFF)
FEEL       := $(BUILD)/apps/feel/feel
FUZZ_SECONDS ?= 15
space := $(subst ,, )

.PHONY: all deps build demo plots test unit-tests test-install test-studio test-linux fuzz bench clean \
        test-asan test-tsan test-sanitizers firmware

all: build

deps:
	@bash scripts/install-deps.sh

# The test files reuse one precompiled header (tests/CMakeLists.txt). CI, which never
# debugs its tree, keeps line tables only (-g1) instead of full debug information: a quarter
# less compile time for the libraries (docs/testing.md, "Time").
DEBUG_INFO := $(if $(filter ON,$(WERROR)),-g1,-g)
build: deps
	cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) -DFEEL_WERROR=$(WERROR) -DFEEL_TEST_PCH=ON \
	    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 $(DEBUG_INFO) -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 $(DEBUG_INFO) -DNDEBUG"
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
	    --plot out/horizontal_wall.png --plot-xy out/horizontal_wall_xy.png
	$(FEEL) play examples/primer.feel.json --sensation railing_impact --seconds 1
	$(FEEL) stream --rate 60 --seconds 1

# make test's stages, in this order, each a make target of its own; scripts/stages.sh times
# them, so that CI's log ends with the wall time of each (docs/testing.md, "Time"). The
# fuzz run goes early, and the ASan+UBSan run right after it completes the same tree. The
# sanitizer stages carry their expected wall time on CI's machine (STAGE~SECONDS, from the
# CPU time measured in docs/testing.md, "Time"): CI runs them all; only a machine so slow
# that one would take the whole run past STAGE_BUDGET_S (CI's 40 minutes less one for the
# clone and the runner) skips it, saying so, rather than losing every stage's result to
# CI's timeout. Projected: test-asan 592 s, test-tsan 252 s, all of make test 37 minutes.
ASAN_STAGE_S := 650
TSAN_STAGE_S := 260
STAGE_BUDGET_S ?= 2340
TEST_STAGES := build firmware fuzz test-asan~$(ASAN_STAGE_S) test-install test-linux test-studio unit-tests \
               test-tsan~$(TSAN_STAGE_S)
test:
	@MAKE="$(MAKE)" STAGE_BUDGET_S=$(STAGE_BUDGET_S) bash scripts/stages.sh $(TEST_STAGES)

test-sanitizers: test-asan test-tsan

unit-tests:
	ctest --test-dir $(BUILD) --output-on-failure -j2

# feel as an installed package: install into a temporary prefix, then a C++ consumer
# (find_package), a C one (pkg-config, libfeel.so) and Python's ctypes, against it only.
test-install: build
	bash scripts/test-install.sh $(BUILD)

# The Studio end to end: feel studio in Debian's Chromium, driven by playwright-core;
# screenshots to out/studio/, latency figures printed (docs/studio.md).
test-studio: build
	cd studio && FEEL=$(abspath $(FEEL)) node --test --test-concurrency=1 e2e/

# Sanitizer trees: built by clang at -O1 with line tables for the reports: of the choices
# measured (docs/testing.md, "Time") the one that compiles fastest under the sanitizers; the
# test files at -O0 with one precompiled header of GoogleTest and the standard headers
# (tests/CMakeLists.txt). No benchmarks. Warnings are the plain build's job, so no -Werror
# here. Every finding stops its test (halt_on_error); leak reports go through
# scripts/lsan.supp (third-party leaks only, each entry says why).
# The libraries and the test executables build in unity batches (CMAKE_UNITY_BUILD and
# FEEL_TEST_UNITY: files compiled 8 to a translation unit, their shared headers parsed and
# their templates instantiated once; docs/testing.md "Time").
# They link with lld (about 70 executables: 1.2 s of CPU each instead of ld.bfd's 2.6).
# --fresh: the options below always win over a tree configured before (another compiler or
# sanitizer); only objects whose command changed are rebuilt.
SANITIZER_TREE := -G Ninja -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_UNITY_BUILD=ON \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
    -DFEEL_WERROR=OFF -DFEEL_BUILD_BENCH=OFF -DFEEL_TEST_PCH=ON -DFEEL_TEST_UNITY=ON \
    -DCMAKE_EXE_LINKER_FLAGS=-fuse-ld=lld -DCMAKE_SHARED_LINKER_FLAGS=-fuse-ld=lld
# The ASan+UBSan tree also holds the libFuzzer targets (fuzz/CMakeLists.txt): its libraries
# carry libFuzzer's coverage instrumentation as well, so that they are compiled once for the
# fuzz run and the sanitizer run of the tests. The fuzzed libraries and the fuzz targets
# keep CI's -Werror (FEEL_FUZZ_WERROR): clang's warnings on them, as the separate fuzz tree
# had. The TSan tree has the tests only.
ASAN_TREE := $(SANITIZER_TREE) -DFEEL_SANITIZE=address -DFEEL_BUILD_FUZZ=ON -DFEEL_FUZZ_WERROR=$(WERROR)
TSAN_TREE := $(SANITIZER_TREE) -DFEEL_SANITIZE=thread -DFEEL_BUILD_FUZZ=OFF

# Every parser and decoder under libFuzzer (clang, ASan+UBSan), each for a bounded time, two
# at a time (scripts/run-fuzzers.sh): the sensation-file reader, the protocol's report
# decoder, the device's protocol session, the USB requests, the ff_effect translation and
# the importers. New inputs go to the build tree; the committed seeds in
# fuzz/corpus/<target> are only read.
FUZZ_TARGETS := sensation_file protocol_decode descriptor_parser device_session usb_requests ff_translation ffe_import ahap_import
fuzz: deps
	cmake --fresh -S . -B $(BUILD)-asan $(ASAN_TREE)
	cmake --build $(BUILD)-asan --target $(addprefix fuzz_,$(FUZZ_TARGETS))
	bash scripts/run-fuzzers.sh $(BUILD)-asan $(FUZZ_SECONDS) $(FUZZ_TARGETS)

# Two tests at a time: every test is its own process, with its own temporary files and
# socket paths and port 0 for TCP. The ASan run leaves out the firmware comparison (label
# firmware): its other half runs on qemu, and its x86 half is the engine every suite covers.
SANITIZER_CTEST := --output-on-failure -j2
# ThreadSanitizer runs the subsystems with threads (ctest labels = folders under tests/).
TSAN_SUITES := runtime transport peripheral host
test-asan: export ASAN_OPTIONS := halt_on_error=1:abort_on_error=1:detect_leaks=1:strict_string_checks=1
test-asan: export UBSAN_OPTIONS := halt_on_error=1:print_stacktrace=1
test-asan: export LSAN_OPTIONS := suppressions=$(CURDIR)/scripts/lsan.supp:print_suppressions=0
test-tsan: export TSAN_OPTIONS := halt_on_error=1:second_deadlock_stack=1

test-asan: deps
	cmake --fresh -S . -B $(BUILD)-asan $(ASAN_TREE)
	cmake --build $(BUILD)-asan
	ctest --test-dir $(BUILD)-asan $(SANITIZER_CTEST) -LE '^firmware$$'

test-tsan: deps
	cmake --fresh -S . -B $(BUILD)-tsan $(TSAN_TREE)
	cmake --build $(BUILD)-tsan --target $(addprefix feel_suite_,$(TSAN_SUITES))
	ctest --test-dir $(BUILD)-tsan $(SANITIZER_CTEST) -L '^($(subst $(space),|,$(TSAN_SUITES)))$$'

# The engine for a Cortex-M4F (arm-none-eabi-gcc, firmware/), then its size report; the
# test program runs on qemu's mps2-an386 board in make test (tests/firmware/).
firmware: deps
	cmake -S firmware -B $(BUILD)-firmware -G Ninja -DCMAKE_TOOLCHAIN_FILE=$(CURDIR)/firmware/arm-none-eabi.cmake
	cmake --build $(BUILD)-firmware
	bash firmware/size-report.sh $(BUILD)-firmware

# The Linux kernel as judge (docs/usb-device.md): Debian's kernel in a qemu VM (TCG, no KVM)
# binds usbhid + hid-pidff to `feel device --sim --usb`; fftest and SDL2's testhaptic play
# their effects; the device log is checked per effect. Leaves out/linux/console.log and
# out/linux/device.log. The .debs are cached in $(BUILD)/linux-cache.
test-linux: build
	bash tests/linux/run.sh $(FEEL) $(BUILD)/tests/linux/feel_check_device_log \
	    $(BUILD)/tests/linux/ff_spy.so $(BUILD)/tests/linux/ff_probe out/linux

# Every sensation of every example file, rendered and plotted under out/examples/.
plots: build
	bash scripts/render-examples.sh $(FEEL)

bench: build
	$(BUILD)/bench/feel_bench_tick
	$(BUILD)/bench/feel_bench_friction
	$(BUILD)/bench/feel_bench_motion_estimator
	$(BUILD)/bench/feel_bench_runtime
	$(BUILD)/bench/feel_bench_host_latency
	$(BUILD)/bench/feel_bench_streaming
	$(BUILD)/bench/feel_bench_queue_calls

clean:
	rm -rf $(BUILD) $(BUILD)-fuzz $(BUILD)-asan $(BUILD)-tsan $(BUILD)-firmware out
