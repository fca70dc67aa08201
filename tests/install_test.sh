#!/usr/bin/env bash
# tests/install_test.sh BUILD SOURCE - cdref as an installed CMake package: installs the build
# into a temporary prefix, then configures, builds and runs the README's validation example
# (examples/validate) against it with find_package(cdref), as a user's project would.
set -euo pipefail
build="$1"
src="$2"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cmake --install "$build" --prefix "$dir/prefix" > "$dir/install.log"
[ -f "$dir/prefix/lib/cmake/cdref/cdrefConfig.cmake" ] || { echo "FAIL: no cdrefConfig.cmake" >&2; exit 1; }
[ -f "$dir/prefix/include/cdref/validate.hpp" ] || { echo "FAIL: no cdref/validate.hpp" >&2; exit 1; }
# (no build type: the example's own code is compiled without optimisation, which is quicker;
# cdref's libraries are the optimised ones installed)
cmake -S "$src/examples/validate" -B "$dir/example" -G Ninja \
  -DCMAKE_PREFIX_PATH="$dir/prefix" > "$dir/configure.log" || { cat "$dir/configure.log" >&2; exit 1; }
cmake --build "$dir/example" > "$dir/build.log" || { cat "$dir/build.log" >&2; exit 1; }
ctest --test-dir "$dir/example" --output-on-failure
echo "install: the example built and passed against the installed package"
