#!/usr/bin/env bash
# tests/python_roundtrip.sh CDREF EXAMPLE - the any-language round trip: cdref writes case files,
# a Python 3 program (examples/ray_sphere_cast.py) answers them with its own ray-sphere cast,
# cdref score grades it. The grading must see every answer, and must see a planted mistake.
set -euo pipefail
cdref="$1"
example="$2"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
fail() { echo "FAIL: $*" >&2; exit 1; }
for fam in uniform near-tangent long-range; do
  "$cdref" cases --query ray-sphere-cast --family "$fam" --n 500 --seed 7 --out c.csv
  python3 "$example" c.csv a.csv
  [ "$(wc -l < a.csv)" = 501 ] || fail "$fam: the example wrote $(wc -l < a.csv) lines"
  # exit status 1 exactly when a graded classification is wrong (no value bound is given)
  st=0; "$cdref" score --query ray-sphere-cast --cases c.csv --answers a.csv > s.txt || st=$?
  grep -q "500 answered and graded, 0 unanswered, 0 malformed" s.txt || fail "$fam: $(head -1 s.txt)"
  wrong=$(awk '$1 == "hit" || $1 == "predicate" {split($3, w, "/"); n += w[1] + w[2]} END {print n + 0}' s.txt)
  { [ "$wrong" = 0 ] && [ $st = 0 ]; } || { [ "$wrong" != 0 ] && [ $st = 1 ]; } || fail "$fam: exit status $st with $wrong wrong"
  grep -q "^lambda_enter " s.txt || fail "$fam: lambda_enter not graded: $(cat s.txt)"
  # a planted mistake: the first case's hit flipped is one more misclassification
  before=$(awk '$1 == "hit" {split($3, w, "/"); print w[1] + w[2]}' s.txt)
  awk -F, 'BEGIN {OFS = ","} NR == 2 {$2 = 1 - $2} {print}' a.csv > b.csv
  "$cdref" score --query ray-sphere-cast --cases c.csv --answers b.csv > t.txt || true
  after=$(awk '$1 == "hit" {split($3, w, "/"); print w[1] + w[2]}' t.txt)
  [ "$after" = $((before + 1)) ] || [ "$after" = $((before - 1)) ] || fail "$fam: a flipped hit not seen ($before -> $after)"
done
echo "python round trip: all checks passed"
