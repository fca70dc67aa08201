#!/usr/bin/env bash
# Builds the libFuzzer targets with clang 14 (AddressSanitizer and UndefinedBehaviorSanitizer)
# and runs each for a fixed time, starting from the seed corpus in fuzz/corpus.
#   bash scripts/fuzz.sh [SECONDS-PER-TARGET]   (default 10)
# New inputs found go to build/fuzz/corpus/<target> (the repository's corpus is not changed);
# a crash or a violated check leaves its input in build/fuzz/ and fails the script.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-10}"
bash scripts/deps.sh
bash scripts/deps.sh clang-14 libclang-rt-14-dev
cmake -S . -B build/fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 \
  -DCDREF_FUZZ=ON -DBUILD_TESTING=OFF >/dev/null
targets=(sphere-sphere segment-sphere-cast ray-sphere-cast segment-sphere box-box segment-box-cast ray-box-cast
         sphere-box casefile)
cmake --build build/fuzz --target "${targets[@]/#/fuzz_}"
for t in "${targets[@]}"; do
  mkdir -p "build/fuzz/corpus/$t"
  echo "cdref: fuzzing $t for ${seconds}s"
  (cd build/fuzz && "./fuzz_$t" -max_total_time="$seconds" -print_final_stats=1 "corpus/$t" "../../fuzz/corpus/$t" \
     2>&1 | grep -aE "^(stat::number_of_executed_units|stat::peak_rss_mb|==|SUMMARY|cdref fuzz)" || true)
done
# the runs above stop at the first failure and leave crash-* files
if ls build/fuzz/crash-* build/fuzz/leak-* build/fuzz/timeout-* >/dev/null 2>&1; then
  echo "cdref: a fuzz target failed; inputs left in build/fuzz/" >&2
  exit 1
fi
echo "cdref: fuzz targets ran ${seconds}s each with no failure"
