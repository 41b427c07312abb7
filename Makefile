# The two commands of the README. Everything else is CMake in build/.
.PHONY: demo test build bootstrap clean format

JOBS ?= $(shell nproc)

bootstrap:
	scripts/bootstrap --no-build

build: bootstrap
	cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
	cmake --build build -j $(JOBS)

# The default study: generate meshes, report on them and draw the gallery (out/demo).
demo: build
	scripts/demo

test: build
	cd build && ctest --output-on-failure -j $(JOBS)

format:
	clang-format-14 -i $$(git ls-files '*.cpp' '*.hpp')

clean:
	rm -rf build
