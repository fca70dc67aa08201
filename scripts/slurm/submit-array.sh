#!/usr/bin/env bash
# scripts/slurm/submit-array.sh N [cdref campaign options]: submits the campaign as an array
# of N shard tasks and the merge as a job that runs when every task has succeeded.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
n=${1:?usage: submit-array.sh N [cdref campaign options]}
shift
case $n in '' | *[!0-9]*) echo "submit-array.sh: N wants a positive whole number, not '$n'" >&2; exit 2 ;; esac
n=$((10#$n))
[ "$n" -ge 1 ] || { echo "submit-array.sh: N wants a positive whole number, not 0" >&2; exit 2; }
job=$(sbatch --parsable --array=0-$((n - 1)) "$here/campaign-array.sbatch" "$@")
sbatch --dependency=afterok:"${job%%;*}" "$here/merge.sbatch"
echo "cdref: array job $job of $n shards; the merge runs after it"
