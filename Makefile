# The two commands a newcomer runs: `make demo` and `make test` (see README.md).
BUILD_DIR ?= build
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=
DEMO_SECONDS ?= 1

.PHONY: all deps configure build demo test bench clean

all: build

deps:
	@scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS) >/dev/null

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

# The default scene: the seed's free-fall demo through the Fluid API, headless.
demo: build
	@$(BUILD_DIR)/bin/free_fall --seconds $(DEMO_SECONDS) --every 0.1

test: build
	@cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

bench: build
	@$(BUILD_DIR)/bin/tide_bench --benchmark_counters_tabular=true

clean:
	@rm -rf $(BUILD_DIR)
