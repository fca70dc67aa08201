#!/usr/bin/env bash
# tests/slurm_test.sh SRC CDREF [CDREF_MPI MPIRUN] - the Slurm scripts of scripts/slurm run as
# plain processes, with Slurm's environment variables set by hand:
#  - the array: three shard tasks (one killed mid-run and run again, as a requeue does), then
#    the merge job: exactly the single process's text form, JSON and CSV;
#  - an array not numbered 0..N-1 refused by name;
#  - the MPI job script (when cdref-mpi is built) on 2 ranks: the same result.
set -euo pipefail
src="$1"
cdref="$2"
cdref_mpi="${3:-}"
mpirun="${4:-}"
dir=$(mktemp -d)
trap 'kill -9 $(jobs -p) 2>/dev/null || true; rm -rf "$dir"' EXIT
cd "$dir"
fail() { echo "FAIL: $*" >&2; exit 1; }

args=(--query segment-sphere-cast --query box-box --query ray-triangle-cast
      --family long-range --family degenerate --impl book-float --impl book-double --impl robust-double
      --n 1500 --seed 11)
"$cdref" campaign "${args[@]}" --threads 2 --out ref.txt --json ref.json --csv ref.csv --quiet

unset SLURM_ARRAY_TASK_MIN SLURM_ARRAY_TASK_MAX  # (should the tests themselves run in an array)
export CDREF="$cdref" CDREF_DIR="$dir/shards" SLURM_ARRAY_TASK_COUNT=3 SLURM_CPUS_PER_TASK=1
mkdir shards
task() { SLURM_ARRAY_TASK_ID=$1 bash "$src/scripts/slurm/campaign-array.sbatch" "${args[@]}"; }
task 0
# task 1 (a checkpoint after every round of work) killed once its checkpoint exists, then run
# again: it resumes
SLURM_ARRAY_TASK_ID=1 bash -c 'exec bash "$0/scripts/slurm/campaign-array.sbatch" "${@}"' "$src" "${args[@]}" \
  --checkpoint-every 0 &
job=$!
for _ in $(seq 3000); do
  [ -e shards/shard-1.ckpt ] && break
  sleep 0.01
done
[ -e shards/shard-1.ckpt ] || fail "task 1 wrote no checkpoint"
kill -9 $(pgrep -P $job) $job 2>/dev/null || true
if wait $job; then fail "task 1 finished before it was killed (make its shard longer)"; fi
[ ! -e shards/shard-1.txt ] || fail "a killed task left a shard file"
task 1
task 2
bash "$src/scripts/slurm/merge.sbatch" > merge.log
for f in txt json csv; do
  cmp -s ref.$f shards/merged.$f || fail "the merged array differs from one process ($f): $(diff ref.$f shards/merged.$f | head -5)"
done

# an array numbered otherwise is refused
set +e
SLURM_ARRAY_TASK_ID=1 SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_MAX=3 bash "$src/scripts/slurm/campaign-array.sbatch" \
  "${args[@]}" 2> err.txt
status=$?
set -e
[ $status = 2 ] || fail "a 1-3 array exited $status"
grep -q "the array must be 0-2 (a task per shard), not 1-3" err.txt || fail "1-3 array: $(cat err.txt)"

if [ -n "$cdref_mpi" ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  mkdir mpi
  CDREF_MPI="$cdref_mpi" CDREF_DIR="$dir/mpi" MPIRUN="$mpirun" MPIRUN_ARGS="--oversubscribe -np 2" \
    bash "$src/scripts/slurm/campaign-mpi.sbatch" "${args[@]}" --out mpi/out.txt --json mpi/out.json \
    --csv mpi/out.csv --quiet
  for f in txt json csv; do
    cmp -s ref.$f mpi/out.$f || fail "the MPI job script's result differs from one process ($f)"
  done
  [ -e mpi/campaign.ckpt ] || fail "the MPI job script wrote no checkpoint"
fi
echo "slurm: the array's shards (one killed and requeued) merge into the single-process result"
