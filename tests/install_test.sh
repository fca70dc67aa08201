#!/usr/bin/env bash
# tests/install_test.sh BUILD SOURCE [PYTHON] - cdref as an installed CMake package: installs the
# build into a temporary prefix, then configures, builds and runs the README's examples against it
# with find_package(cdref), as a user's project would: the validation example (examples/validate)
# and the truth API's Catch2, GoogleTest and exact-value examples (examples/truth); with PYTHON,
# also the installed Python module on examples/truth.py.
set -euo pipefail
build="$1"
src="$2"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cmake --install "$build" --prefix "$dir/prefix" > "$dir/install.log"
[ -f "$dir/prefix/lib/cmake/cdref/cdrefConfig.cmake" ] || { echo "FAIL: no cdrefConfig.cmake" >&2; exit 1; }
[ -f "$dir/prefix/include/cdref/validate.hpp" ] || { echo "FAIL: no cdref/validate.hpp" >&2; exit 1; }
[ -f "$dir/prefix/include/cdref/truth.hpp" ] || { echo "FAIL: no cdref/truth.hpp" >&2; exit 1; }
# the exported targets put no numeric flags on a user's own code; cdref::strict_fp is the opt-in
bad=$(awk '/^set_target_properties\(cdref::/ {t=$1; sub(/.*\(/, "", t)} /fp-contract|slp-vectorize|-Wall/ {print t}' \
      "$dir/prefix/lib/cmake/cdref/cdrefTargets.cmake" | grep -v "^cdref::strict_fp$" || true)
[ -z "$bad" ] || { echo "FAIL: $bad exports cdref's own compile flags to the user's code" >&2; exit 1; }
grep -q "cdref::strict_fp" "$dir/prefix/lib/cmake/cdref/cdrefTargets.cmake" || { echo "FAIL: no cdref::strict_fp" >&2; exit 1; }
# the command line runs from the prefix: a case file written and answered
"$dir/prefix/bin/cdref" cases --query ray-sphere-cast --n 3 --out "$dir/cases.csv" ||
  { echo "FAIL: the installed cdref did not run" >&2; exit 1; }
"$dir/prefix/bin/cdref" oracle --query ray-sphere-cast --cases "$dir/cases.csv" | grep -q "^case,hit," ||
  { echo "FAIL: the installed cdref oracle gave no answers" >&2; exit 1; }
# (no build type: the example's own code is compiled without optimisation, which is quicker;
# cdref's libraries are the optimised ones installed)
cmake -S "$src/examples/validate" -B "$dir/example" -G Ninja \
  -DCMAKE_PREFIX_PATH="$dir/prefix" > "$dir/configure.log" || { cat "$dir/configure.log" >&2; exit 1; }
cmake --build "$dir/example" > "$dir/build.log" || { cat "$dir/build.log" >&2; exit 1; }
ctest --test-dir "$dir/example" --output-on-failure
cmake -S "$src/examples/truth" -B "$dir/truth" -G Ninja \
  -DCMAKE_PREFIX_PATH="$dir/prefix" > "$dir/configure-truth.log" || { cat "$dir/configure-truth.log" >&2; exit 1; }
cmake --build "$dir/truth" > "$dir/build-truth.log" || { cat "$dir/build-truth.log" >&2; exit 1; }
ctest --test-dir "$dir/truth" --output-on-failure
if [ $# -ge 3 ] && [ -n "$3" ]; then
  site=$(find "$dir/prefix" -path '*dist-packages/cdref/__init__.py' -printf '%h\n' | head -1)
  [ -n "$site" ] || { echo "FAIL: the Python package was not installed" >&2; exit 1; }
  (cd "$dir" && PYTHONPATH="$(dirname "$site")" "$3" "$src/examples/truth.py" > "$dir/python.log") \
    || { cat "$dir/python.log" >&2; exit 1; }
  echo "install: the installed Python module ran examples/truth.py"
fi
echo "install: the examples built and passed against the installed package"
