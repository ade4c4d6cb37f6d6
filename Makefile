# bemcontact: the two commands of the README, and their parts.
BUILD_DIR ?= build
SANITIZE_DIR ?= build-asan
JOBS ?= 2
DEMO ?= examples/contact_hertz_sphere_adaptive.toml
DEMO_SET ?=
FUZZ_SECONDS ?= 300
# Ninja for a new build folder: it compiles a target's sources while the libraries they link
# are still being built (make waits for each target), so both cores stay busy: 5 min 49 s
# against 6 min 28 s for the Release build here, 5 min 49 s against 6 min 57 s for the
# sanitizer build. A folder configured before keeps its generator.
generator = $(if $(wildcard $(1)/CMakeCache.txt),,-G Ninja)

.PHONY: deps deps-core deps-mpi configure build demo test test-sanitize test-mpi fuzz bench clean

# Everything the tests need (Python module, figures, VTK read-back, Gmsh), or only what the
# library and the command need (the demo).
deps:
	@bash scripts/install-deps.sh

deps-core:
	@bash scripts/install-deps.sh --core

deps-mpi:
	@bash scripts/install-deps.sh --mpi

configure: deps
	@cmake $(call generator,$(BUILD_DIR)) -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release -DBEMCONTACT_BUILD_TESTS=ON -DBEMCONTACT_BUILD_BENCH=ON \
	  -DBEMCONTACT_REQUIRE_PYTHON=ON -DBEMCONTACT_WITH_MPI=OFF \
	  > $(BUILD_DIR).configure.log 2>&1 || (cat $(BUILD_DIR).configure.log; exit 1)

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

# The demo needs only the library and the command; the compiler's output goes to a log,
# shown only when the build fails.
demo: deps-core
	@cmake $(call generator,$(BUILD_DIR)) -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release -DBEMCONTACT_BUILD_TESTS=OFF -DBEMCONTACT_BUILD_BENCH=OFF \
	  -DBEMCONTACT_REQUIRE_PYTHON=OFF -DBEMCONTACT_WITH_MPI=OFF > $(BUILD_DIR).configure.log 2>&1 \
	  || (cat $(BUILD_DIR).configure.log; exit 1)
	@echo "bemcontact: building the library and the command (a few minutes the first time; log in $(BUILD_DIR).build.log)"
	@cmake --build $(BUILD_DIR) -j $(JOBS) --target bemcontact > $(BUILD_DIR).build.log 2>&1 \
	  || (tail -n 60 $(BUILD_DIR).build.log; exit 1)
	@$(BUILD_DIR)/bemcontact run $(DEMO) $(DEMO_SET) -o $(BUILD_DIR)/demo

# ctest runs JOBS tests at once, each on one OpenMP thread (CMakeLists.txt: two threads
# per test made OpenMP spin against the other test, 1.8 times the time).
test: build
	@cd $(BUILD_DIR) && OMP_NUM_THREADS=1 ctest --output-on-failure -j $(JOBS)

# The whole test suite again under AddressSanitizer + UndefinedBehaviorSanitizer, with
# libstdc++'s assertions and the library's own debug checks (no NDEBUG). A unity build
# (16 sources per compiler run: the headers are parsed once per batch) takes 6 min here
# against 10; the Release build above keeps the library's sources one file per run (and
# compiles every public header alone), so a missing #include still fails there. UBSan's
# alignment and null checks are off (CMakeLists.txt: they doubled the compile). PlasticSphere.* (the axisymmetric elastoplastic region converging on 264
# cells: 3 min under the sanitizers) is left out; PlasticSphereCoarse.* runs the same code
# on 14 cells. So is CompatiblePlasticStrain.ShearBands* (a 512-cell block, 30 s there):
# the re-meshing at the cells runs in the other elastoplastic tests. So is
# ContactHertzSphere.FineMeshStopsAtTheRoundOffWithAWarning (701 pairs on the formed route:
# 23 s there, 4 s in Release): the same Newton code runs there on the coarser balls.
test-sanitize: deps
	@cmake $(call generator,$(SANITIZE_DIR)) -S . -B $(SANITIZE_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
	  -DCMAKE_UNITY_BUILD=ON -DCMAKE_UNITY_BUILD_BATCH_SIZE=16 \
	  -DBEMCONTACT_SANITIZE=ON -DBEMCONTACT_BUILD_BENCH=OFF > $(SANITIZE_DIR).configure.log 2>&1 \
	  || (cat $(SANITIZE_DIR).configure.log; exit 1)
	@cmake --build $(SANITIZE_DIR) -j $(JOBS)
	@cd $(SANITIZE_DIR) && OMP_NUM_THREADS=1 ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 \
	  LSAN_OPTIONS=suppressions=$(CURDIR)/scripts/lsan.supp:print_suppressions=0 \
	  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ctest --output-on-failure -j $(JOBS) -E '^(PlasticSphere\.|CompatiblePlasticStrain\.ShearBands|ContactHertzSphere\.FineMeshStopsAtTheRoundOff)'

# Distributed runs (not needed by the two README commands): OpenMPI and PETSc, the command
# rebuilt in the same tree with BEMCONTACT_WITH_MPI (only the MPI layer and the command
# compile: the library is the one `make test` built), then 1- and 2-process runs compared
# (tests/mpi/run.sh). `make test` or `make demo` afterwards rebuild the serial command.
test-mpi: deps deps-mpi
	@cmake $(call generator,$(BUILD_DIR)) -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release -DBEMCONTACT_BUILD_TESTS=ON -DBEMCONTACT_BUILD_BENCH=ON \
	  -DBEMCONTACT_REQUIRE_PYTHON=ON -DBEMCONTACT_WITH_MPI=ON > $(BUILD_DIR).configure.log 2>&1 \
	  || (cat $(BUILD_DIR).configure.log; exit 1)
	@cmake --build $(BUILD_DIR) -j $(JOBS) --target bemcontact
	@bash tests/mpi/run.sh $(BUILD_DIR)/bemcontact

# A bounded libFuzzer run (clang); findings are copied into tests/fuzz_regressions/.
fuzz:
	@FUZZ_SECONDS=$(FUZZ_SECONDS) bash scripts/fuzz.sh

bench: build
	@for b in $(BUILD_DIR)/bench/*; do $$b --benchmark_min_time=0.2; done

clean:
	rm -rf $(BUILD_DIR) $(BUILD_DIR).configure.log $(BUILD_DIR).build.log $(SANITIZE_DIR) $(SANITIZE_DIR).configure.log build-fuzz build-fuzz.configure.log
