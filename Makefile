# Thin wrapper over CMake. `make demo` builds and runs the main job; `make test` builds and runs
# every test twice: a debug build, then an AddressSanitizer + UBSan build. `make install PREFIX=...`
# installs the library, header, command, man page, pkg-config and CMake files (docs/install.md);
# `make api-docs` regenerates docs/api/ from the header's doc comments; `make deb-test` builds and
# checks the Debian packages.
PREFIX ?= /usr/local
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE ?= cmake

.PHONY: all build demo test test-debug test-asan test-release install api-docs deb-test fuzz fuzz-build msan valgrind clean

all: build

build:
	$(CMAKE) -S . -B build -DCMAKE_BUILD_TYPE=Release -DFL_TESTS=OFF >/dev/null
	$(CMAKE) --build build -j $(JOBS)

demo: build
	./build/flintstone demo

test: test-debug test-asan

test-debug:
	$(CMAKE) -S . -B build-debug -DCMAKE_BUILD_TYPE=Debug >/dev/null
	$(CMAKE) --build build-debug -j $(JOBS)
	cd build-debug && ctest --output-on-failure -j $(JOBS)

test-asan:
	$(CMAKE) -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DFL_SANITIZE=ON >/dev/null
	$(CMAKE) --build build-asan -j $(JOBS)
	cd build-asan && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
		ctest --output-on-failure -j $(JOBS)

# What a plain `cmake -S . -B DIR && cmake --build DIR` builds: Release with the tests (gcc -O2
# finds warnings the debug build cannot), then its ctest. Run by CI.
test-release:
	$(CMAKE) -S . -B build-release -DCMAKE_BUILD_TYPE=Release -DFL_TESTS=ON >/dev/null
	$(CMAKE) --build build-release -j $(JOBS)
	cd build-release && ctest --output-on-failure -j $(JOBS)

install: build
	DESTDIR=$(DESTDIR) $(CMAKE) --install build --prefix $(PREFIX)

api-docs:
	$(CMAKE) -S . -B build -DCMAKE_BUILD_TYPE=Release -DFL_TESTS=OFF >/dev/null
	$(CMAKE) --build build --target api-docs

# Builds the Debian packages (debian/) from a copy of the tree and checks them; needs debhelper.
deb-test:
	sh tests/install/test_deb.sh .

# libFuzzer targets (clang, ASan + UBSan) built into build-fuzz/; `make fuzz FUZZ_SECONDS=N`
# runs every target for N seconds (default 30) from its seed corpus (fuzz/README.md).
FUZZ_SECONDS ?= 30
fuzz-build:
	$(MAKE) -C fuzz all

fuzz:
	$(MAKE) -C fuzz run FUZZ_SECONDS=$(FUZZ_SECONDS)

# MemorySanitizer: the library and every fuzz target built with clang -fsanitize=memory into
# build-msan/, each replaying its committed corpus (fuzz/corpus/<target>) once.
msan:
	$(MAKE) -C fuzz msan

# valgrind memcheck on a fast subset of the debug-build tests: zero errors and leaks required.
valgrind:
	$(CMAKE) -S . -B build-debug -DCMAKE_BUILD_TYPE=Debug >/dev/null
	$(CMAKE) --build build-debug -j $(JOBS)
	scripts/valgrind.sh build-debug

clean:
	rm -rf build build-debug build-asan build-release build-fuzz build-msan
