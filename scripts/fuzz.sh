#!/usr/bin/env bash
# Builds the libFuzzer targets with clang 14 (AddressSanitizer and UndefinedBehaviorSanitizer)
# and runs each query's target, the case-file reader's, the scene reader's and the results
# readers' (campaign text form, cdref-mpi checkpoints), for a fixed time, starting from
# the seed corpus in fuzz/corpus.
#   bash scripts/fuzz.sh [SECONDS-PER-TARGET]   (default 10)
# New inputs found go to build/fuzz/corpus/<target> (the repository's corpus is not changed);
# a crash or a violated check leaves its input in build/fuzz/ and fails the script.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-10}"
# A fixed seed by default, so that a run explores the same inputs first wherever it runs
# (CDREF_FUZZ_SEED=0 asks libFuzzer for a random one).
seed="${CDREF_FUZZ_SEED:-1}"
bash scripts/deps.sh
bash scripts/deps.sh clang-14 libclang-rt-14-dev
cmake -S . -B build/fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 \
  -DCDREF_FUZZ=ON -DBUILD_TESTING=OFF >/dev/null
cmake --build build/fuzz --target fuzz_query fuzz_casefile fuzz_scene fuzz_results cdref_fuzz_replay
mapfile -t targets < <(build/fuzz/cdref_fuzz_replay --list)
failed=()
for t in "${targets[@]}"; do
  mkdir -p "build/fuzz/corpus/$t"
  echo "cdref: fuzzing $t for ${seconds}s"
  case "$t" in casefile) bin=./fuzz_casefile ;; scene) bin=./fuzz_scene ;; results) bin=./fuzz_results ;; *) bin=./fuzz_query ;; esac
  # libFuzzer exits nonzero on a crash or a violated check (and leaves crash-* in build/fuzz)
  set +e
  (cd build/fuzz && CDREF_FUZZ_QUERY="$t" "$bin" -max_total_time="$seconds" -seed="$seed" -print_final_stats=1 \
     -artifact_prefix="$t-" "corpus/$t" "../../fuzz/corpus/$t" > "fuzz-$t.log" 2>&1)
  status=$?
  set -e
  grep -aE "^(stat::number_of_executed_units|stat::peak_rss_mb|==|SUMMARY|cdref fuzz|  inputs)" "build/fuzz/fuzz-$t.log" || true
  if [ "$status" != 0 ]; then failed+=("$t"); fi
done
if [ "${#failed[@]}" != 0 ]; then
  echo "cdref: fuzz targets failed: ${failed[*]}; inputs left in build/fuzz/<target>-crash-*, logs in build/fuzz/fuzz-*.log" >&2
  exit 1
fi
echo "cdref: fuzz targets ran ${seconds}s each with no failure"
