# The two commands a newcomer runs: `make demo` and `make test` (see README.md).
BUILD_DIR ?= build
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=
DEMO_SECONDS ?= 2

.PHONY: all deps configure build demo test bench clean

all: build

deps:
	@scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS) >/dev/null

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

# The default scene (the seed's free-fall demo) through `tide run`, frames in out/demo.
demo: build
	@$(BUILD_DIR)/bin/tide run scenes/free_fall.json --out out/demo --force --end-time $(DEMO_SECONDS)

test: build
	@cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

# Kernels (Google Benchmark), then whole simulations (BENCH_SECONDS simulated each; the
# SPlisHSPlasH comparison in docs/performance.md uses 1).
BENCH_SECONDS ?= 0.1
bench: build
	@$(BUILD_DIR)/bin/tide_bench --benchmark_counters_tabular=true
	@$(BUILD_DIR)/bin/tide_scenarios --seconds $(BENCH_SECONDS)

clean:
	@rm -rf $(BUILD_DIR)
