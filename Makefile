# semslam: the two commands of the quick start are `make demo` and `make test`.
#
#   make deps     install the Debian packages the build needs (only those missing)
#   make build    configure and build (Release) into build/
#   make test     build, then run every test through ctest
#   make demo     build, then run paper B's mm-nh and known association on the built-in ambiguous log, plot both
#   make bench    build and run the benchmarks (installs libceres-dev for the Ceres comparison), then the
#                 incremental replay benchmark, the candidate pre-selection benchmark and what calling from Python
#                 costs (bench/python_overhead.py)
#   make fuzz     build the libFuzzer harnesses of fuzz/ with clang-14 (installs clang-14 and libclang-rt-14-dev),
#                 run each FUZZ_SECONDS seconds (default 60; FUZZ_RUNS=N: stop a harness at N executions;
#                 FUZZ_ONLY=a,b: only those; FUZZ_PARALLEL harnesses side by side, default one per core) and
#                 print executions, exec/s, corpus size and findings
#   make sanitize build the library, the tool and every C++ test with -fsanitize=address,undefined
#                 -fno-sanitize-recover=all -D_GLIBCXX_ASSERTIONS into build-sanitize/ (MPI and the Python tests
#                 off) and run them through ctest; any sanitizer report fails its test
#   make results  regenerate the measured results in docs/results.md
#   make install  build, then install under PREFIX (default /usr/local; sudo only when PREFIX is not writable):
#                 bin/semslam, include/semslam, lib/libsemslam.a, lib/cmake/semslam (find_package(semslam)),
#                 lib/pkgconfig/semslam.pc, share/semslam/python (the plotting scripts), share/doc/semslam

BUILD_DIR ?= build
PREFIX ?= /usr/local
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
# Debian's interpreter, where python3-matplotlib is installed.
PYTHON ?= /usr/bin/python3
SUDO := $(shell [ "$$(id -u)" -eq 0 ] || echo sudo)

DEB_PACKAGES := build-essential cmake pkg-config libeigen3-dev libsuitesparse-dev libgtest-dev libgmock-dev \
                libcli11-dev nlohmann-json3-dev libboost-dev python3 python3-matplotlib python3-numpy \
                python3-scipy libopenmpi-dev openmpi-bin python3-dev pybind11-dev python3-pybind11 python3-pytest
BENCH_PACKAGES := libbenchmark-dev libceres-dev
FUZZ_PACKAGES := clang-14 libclang-rt-14-dev
FUZZ_SECONDS ?= 60
# 0: no limit on executions (FUZZ_SECONDS alone bounds a harness).
FUZZ_RUNS ?= 0
FUZZ_PARALLEL ?= $(JOBS)
# Empty: every harness; else a comma-separated list of them (FUZZ_ONLY=log,metrics).
FUZZ_ONLY ?=
FUZZ_HARNESSES := $(notdir $(wildcard fuzz/corpus/*))

# Installs each named package that dpkg does not report as installed; `apt-get update` first, since a fresh
# machine has no package lists.
define install_missing
	@missing=""; for p in $(1); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "install ok installed" || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  echo "installing:$$missing"; \
	  $(SUDO) apt-get update && DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y --no-install-recommends $$missing; \
	fi
endef

.PHONY: deps deps-bench deps-fuzz configure build test demo bench fuzz sanitize results install clean

deps:
	$(call install_missing,$(DEB_PACKAGES))

deps-bench: deps
	$(call install_missing,$(BENCH_PACKAGES))

configure: deps
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release -DSEMSLAM_BUILD_BENCH=OFF -DPYTHON_EXECUTABLE=$(PYTHON)

build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

test: build
	ctest --test-dir $(BUILD_DIR) --output-on-failure -j $(JOBS)

demo: build
	$(BUILD_DIR)/bin/semslam demo --overwrite --out $(BUILD_DIR)/demo
	$(PYTHON) python/plot_run.py $(BUILD_DIR)/demo --compare $(BUILD_DIR)/demo/known \
	  --title "semslam demo: paper B's mm-nh and known association among look-alike landmarks"

bench: deps-bench
	cmake -S . -B $(BUILD_DIR)-bench -DCMAKE_BUILD_TYPE=Release -DSEMSLAM_BUILD_TESTS=OFF -DSEMSLAM_BUILD_BENCH=ON -DPYTHON_EXECUTABLE=$(PYTHON) \
	  -DSEMSLAM_BUILD_EXAMPLES=OFF
	cmake --build $(BUILD_DIR)-bench -j $(JOBS)
	$(BUILD_DIR)-bench/bin/semslam_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
	$(BUILD_DIR)-bench/bin/semslam_incremental_bench
	$(BUILD_DIR)-bench/bin/semslam_preselection_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
	PYTHONPATH=$(BUILD_DIR)-bench/python $(PYTHON) bench/python_overhead.py \
	  --baseline $(BUILD_DIR)-bench/bin/semslam_build_solve_baseline

deps-fuzz: deps
	$(call install_missing,$(FUZZ_PACKAGES))

# The library and the harnesses with -fsanitize=fuzzer,address,undefined in their own build folder.
fuzz: deps-fuzz
	CC=clang-14 CXX=clang++-14 cmake -S . -B $(BUILD_DIR)-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DSEMSLAM_BUILD_TESTS=OFF -DSEMSLAM_BUILD_EXAMPLES=OFF -DSEMSLAM_BUILD_BENCH=OFF -DSEMSLAM_BUILD_FUZZ=ON \
	  -DSEMSLAM_BUILD_PYTHON=OFF \
	  "-DCMAKE_CXX_FLAGS=-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all"
	cmake --build $(BUILD_DIR)-fuzz -j $(JOBS) --target $(addprefix fuzz_,$(FUZZ_HARNESSES))
	$(PYTHON) fuzz/run_fuzzers.py --bin $(BUILD_DIR)-fuzz/bin --seconds $(FUZZ_SECONDS) --runs $(FUZZ_RUNS) \
	  --parallel $(FUZZ_PARALLEL) --work $(BUILD_DIR)-fuzz/work $(if $(FUZZ_ONLY),--only $(FUZZ_ONLY))

# The library, the tool and the C++ tests with AddressSanitizer and UndefinedBehaviorSanitizer (every report is fatal)
# and libstdc++'s assertions, in their own build folder. MPI off (OpenMPI's runtime is not built for ASan), the
# Python tests off (SEMSLAM_PYTHON_TESTS: they test scripts and the Python module, not C++) and the Python module
# off (an extension loaded into an uninstrumented interpreter cannot carry ASan's runtime); the packaging tests are left out, since a
# downstream program cannot link the sanitized library without the sanitizers' runtime.
# -O1, as the sanitizers' documentation advises; -g1 for line numbers in their reports.
SANITIZE_FLAGS := -O1 -g1 -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=all \
                  -D_GLIBCXX_ASSERTIONS
sanitize: deps
	cmake -S . -B $(BUILD_DIR)-sanitize -DCMAKE_BUILD_TYPE=None -DSEMSLAM_BUILD_BENCH=OFF -DSEMSLAM_WITH_MPI=OFF \
	  -DSEMSLAM_PYTHON_TESTS=OFF -DSEMSLAM_BUILD_PYTHON=OFF "-DCMAKE_CXX_FLAGS=$(SANITIZE_FLAGS)" \
	  "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined"
	cmake --build $(BUILD_DIR)-sanitize -j $(JOBS)
	ASAN_OPTIONS=detect_leaks=1:abort_on_error=0:halt_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	  ctest --test-dir $(BUILD_DIR)-sanitize --output-on-failure -j $(JOBS) -E '^packaging\.'

results: build
	$(PYTHON) python/make_results.py --build $(BUILD_DIR)

# Installs what `make build` built (nothing is rebuilt as root). sudo is used only when the nearest existing folder
# of PREFIX is not writable, so `make install PREFIX=$HOME/.local` needs no root.
install: build
	@dir="$(PREFIX)"; while [ ! -e "$$dir" ]; do dir=$$(dirname "$$dir"); done; \
	if [ -w "$$dir" ]; then sudo=""; else sudo="$(SUDO)"; fi; \
	echo "$$sudo cmake --install $(BUILD_DIR) --prefix $(PREFIX)"; \
	$$sudo cmake --install $(BUILD_DIR) --prefix "$(PREFIX)"

clean:
	rm -rf $(BUILD_DIR) $(BUILD_DIR)-bench $(BUILD_DIR)-fuzz $(BUILD_DIR)-sanitize
