# bemcontact: the two commands of the README, and their parts.
BUILD_DIR ?= build
JOBS ?= 2
DEMO ?= examples/contact_hertz_sphere.toml

.PHONY: deps configure build demo test bench clean

deps:
	@bash scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release > $(BUILD_DIR).configure.log 2>&1 || (cat $(BUILD_DIR).configure.log; exit 1)

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

demo: build
	@$(BUILD_DIR)/bemcontact run $(DEMO) -o $(BUILD_DIR)/demo

test: build
	@cd $(BUILD_DIR) && OMP_NUM_THREADS=$(JOBS) ctest --output-on-failure -j $(JOBS)

bench: build
	@for b in $(BUILD_DIR)/bench/*; do $$b --benchmark_min_time=0.2; done

clean:
	rm -rf $(BUILD_DIR) $(BUILD_DIR).configure.log
