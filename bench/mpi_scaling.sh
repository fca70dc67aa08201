#!/usr/bin/env bash
# bench/mpi_scaling.sh [BUILD] - what cdref-mpi gains on this machine, in one run:
#  1. cases per second of one campaign run by one process (1 and 2 threads) and by cdref-mpi
#     on 1, 2 and 4 ranks, as ratios to one process on one thread (every run prints the same
#     results: checked);
#  2. the reduction (rank 0's exact merge of the ranks' results, after a barrier) as the number
#     of cells grows, with the size of the merged result.
# Ranks run unbound (--bind-to none: mpirun would bind each of two ranks to one core, and the
# threads of a rank would take turns on it). Run it on an idle machine: every figure is one run.
set -euo pipefail
build="${1:-build/release}"
cdref="$build/cdref"
mpi="$build/cdref-mpi"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

campaign=(--query ray-triangle-cast --query box-box --query segment-sphere-cast --n 6000 --seed 5)
secs() { awk '/evaluations in/ {print $4}' "$1"; }
evals() { awk '/evaluations in/ {print $1}' "$1"; }

echo "1. one campaign (${campaign[*]}), every implementation of its queries"
"$cdref" campaign "${campaign[@]}" --threads 1 --out "$tmp/ref.txt" > "$tmp/p1.log"
base=$(secs "$tmp/p1.log")
n=$(evals "$tmp/p1.log")
printf "%-34s %10s %14s %8s\n" "run" "seconds" "evaluations/s" "ratio"
row() { printf "%-34s %10.2f %14.0f %8.2f\n" "$1" "$2" "$(echo "$n / $2" | bc -l)" "$(echo "$base / $2" | bc -l)"; }
row "cdref, 1 thread (baseline)" "$base"
"$cdref" campaign "${campaign[@]}" --threads 2 --out "$tmp/o.txt" > "$tmp/p.log"
cmp -s "$tmp/ref.txt" "$tmp/o.txt" || { echo "cdref on 2 threads gave other results" >&2; exit 1; }
row "cdref, 2 threads" "$(secs "$tmp/p.log")"
for cfg in "1 1" "2 1" "4 1" "1 2" "2 2"; do
  set -- $cfg
  mpirun --oversubscribe --bind-to none -np "$1" "$mpi" campaign "${campaign[@]}" --threads "$2" --out "$tmp/o.txt" > "$tmp/p.log"
  cmp -s "$tmp/ref.txt" "$tmp/o.txt" || { echo "cdref-mpi on $1 ranks gave other results" >&2; exit 1; }
  row "cdref-mpi, $1 ranks x $2 threads" "$(secs "$tmp/p.log")"
done

echo
echo "2. the reduction (one work item per cell: --n 256), 2 and 4 ranks of 1 thread"
printf "%-12s %7s %6s %12s %16s %18s\n" "queries" "cells" "ranks" "reduction" "bytes to rank 0" "merged text form"
mapfile -t all < <("$cdref" describe | awk -F: '/^[a-z]/ {print $1}')
for k in 1 8 ${#all[@]}; do
  qs=()
  for q in "${all[@]:0:$k}"; do qs+=(--query "$q"); done
  for np in 2 4; do
    mpirun --oversubscribe --bind-to none -np $np "$mpi" campaign "${qs[@]}" --n 256 --threads 1 --out "$tmp/r.txt" > "$tmp/r.log"
    line=$(grep "the reduction of" "$tmp/r.log")
    cells=$(echo "$line" | sed -E 's/.*reduction of ([0-9]+) cells.*/\1/')
    ms=$(echo "$line" | sed -E 's/.*cells took ([0-9.e+-]+) ms.*/\1/')
    bytes=$(echo "$line" | sed -E 's/.* ms, ([0-9]+) bytes.*/\1/')
    printf "%-12s %7s %6s %9.1f ms %16s %16s B\n" "$k" "$cells" "$np" "$ms" "$bytes" "$(wc -c < "$tmp/r.txt")"
  done
done
