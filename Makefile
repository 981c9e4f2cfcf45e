# The two commands a newcomer runs: `make demo` and `make test` (see README.md).
BUILD_DIR ?= build
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=
DEMO_SECONDS ?= 4
# The long-flume wave benchmark's particle spacing (0.005 m: 8 particles per wave height, hours on 2 cores).
WAVE_BENCH_SPACING ?= 0.005

.PHONY: all deps configure build demo test check-sanitizers bench soak validate clean

all: build

deps:
	@scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS) >/dev/null

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

# The default scene (a directional sea around a pile, open on all four sides; docs/ocean.md)
# through `tide run`: frames, gauges.csv and stats.json in out/demo; then drawn by `tide render`
# (the sea to the horizon around the near field) as PNG frames in out/demo_render.
# DEMO_SCENE picks another.
DEMO_SCENE ?= scenes/ocean_pile.json
demo: build
	@$(BUILD_DIR)/bin/tide run $(DEMO_SCENE) --out out/demo --force --end-time $(DEMO_SECONDS)
	@$(BUILD_DIR)/bin/tide render $(DEMO_SCENE) --out out/demo_render --force --end-time $(DEMO_SECONDS) --width 960 --height 540

test: build
	@cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

# ASan+UBSan unit tests, TSan threaded tests, FUZZ_SECONDS of each fuzz target (clang builds in
# build-asan/ and build-tsan/; docs/robustness.md). CI runs it after `make test`.
FUZZ_SECONDS ?= 30
check-sanitizers: deps
	@JOBS=$(JOBS) FUZZ_SECONDS=$(FUZZ_SECONDS) scripts/check-sanitizers.sh

# Kernels (Google Benchmark), then whole simulations (BENCH_SECONDS simulated each; the
# SPlisHSPlasH comparison in docs/performance.md uses 1).
BENCH_SECONDS ?= 0.1
bench: build
	@$(BUILD_DIR)/bin/tide_bench --benchmark_counters_tabular=true
	@$(BUILD_DIR)/bin/tide_scenarios --seconds $(BENCH_SECONDS)
	@OMP_WAIT_POLICY=PASSIVE $(BUILD_DIR)/bin/tide_live_bench --seconds 8 --threads 2
	@$(BUILD_DIR)/bin/tide_wave_bench --spacing $(WAVE_BENCH_SPACING)

# Soak (not CI): the beach scene for SOAK_SECONDS of wall time (default 600); memory and energy.
soak: build
	@bench/soak.sh $(BUILD_DIR)

# The validation report (not part of `make test`): every case of validation/run.py at its stated
# resolution, then docs/validation.md and docs/images/validation-*.png (< 1 h on 2 idle cores).
# VALIDATE_QUICK=1: coarser, for development; VALIDATE_CASES=surge,hydrostatic: some cases only.
VALIDATE_QUICK ?=
VALIDATE_CASES ?=
validate: build
	@/usr/bin/python3 validation/run.py --build $(BUILD_DIR) $(if $(VALIDATE_QUICK),--quick) $(if $(VALIDATE_CASES),--cases $(VALIDATE_CASES))

clean:
	@rm -rf $(BUILD_DIR) build-asan build-tsan
