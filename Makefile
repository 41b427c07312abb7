# The two commands of the README. Everything else is CMake in build/.
.PHONY: demo test bench build configure bootstrap clean format

JOBS ?= $(shell nproc)

bootstrap:
	scripts/bootstrap --no-build

# Ninja (bootstrap installs it) compiles a library's sources while the libraries below it are
# still building, so both cores stay busy; a build/ made before keeps its generator.
GENERATOR := $(if $(wildcard build/CMakeCache.txt),,-G Ninja)

configure: bootstrap
	cmake -S . -B build $(GENERATOR) -DCMAKE_BUILD_TYPE=Release >/dev/null

# Everything: the library, the program, the tests, the benchmarks and the fuzz replays.
build: configure
	cmake --build build -j $(JOBS)

# The default study: generate meshes, report on them and draw the gallery (out/demo). Builds
# only the program and its libraries, not the tests and benchmarks it does not run.
demo: configure
	cmake --build build -j $(JOBS) --target vorodg
	scripts/demo

test: build
	cd build && ctest --output-on-failure -j $(JOBS)

# The Google Benchmark programs (build/bin/bench_*), built and listed; run one with its own flags.
bench: configure
	cmake --build build -j $(JOBS) --target benchmarks
	ls build/bin/bench_*

format:
	clang-format-14 -i $$(git ls-files '*.cpp' '*.hpp')

clean:
	rm -rf build
