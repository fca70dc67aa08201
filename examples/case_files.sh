#!/usr/bin/env bash
# examples/case_files.sh CDREF [DIR] - a CI job that checks an implementation in any language
# against cdref's exact answers through case files.
#
#   1. cdref cases  writes the inputs (here: sphere-sphere, two families, decimal numbers);
#   2. your program answers them (here: a sphere-sphere test and distance in awk, doubles);
#   3. cdref oracle writes the exact answers, correctly rounded (for reading beside yours);
#   4. cdref score  grades your answers and exits 0 when nothing graded is wrong, 1 when a case is
#      misclassified or beyond the bound given, 2 when the files cannot be used.
#
# The job fails (non-zero exit) when the grade fails. DIR (default: a temporary directory)
# keeps the files for reading.
set -euo pipefail
cdref="${1:?usage: case_files.sh CDREF [DIR]}"
dir="${2:-$(mktemp -d)}"
[ -n "${2:-}" ] || trap 'rm -rf "$dir"' EXIT
mkdir -p "$dir"
cd "$dir"

# 1. the cases: 500 uniform placements and 500 at (r_a + r_b)(1 +- 1/2) apart (each family's
#    first scale; `cdref describe` lists the families and their scales)
"$cdref" cases --query sphere-sphere --family uniform --family near-touching --n 500 --seed 1 \
    --decimal --out cases.csv

# 2. the implementation under test: the sphere-sphere test of Section 3.1.1 and the distance
#    |c_a - c_b| - (r_a + r_b), in awk's doubles. It reads the columns by name from the header.
awk -F, '
  NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i
            print "case,intersect,distance"; next }
  { dx = $col["a_center_x"] - $col["b_center_x"]
    dy = $col["a_center_y"] - $col["b_center_y"]
    dz = $col["a_center_z"] - $col["b_center_z"]
    s = $col["a_radius"] + $col["b_radius"]
    d2 = dx * dx + dy * dy + dz * dz
    hit = (d2 <= s * s)
    dist = hit ? 0 : sqrt(d2) - s
    printf "%s,%d,%.17g\n", $col["case"], hit, dist }
' cases.csv > answers.csv

# 3. the exact answers, for reading beside the program's
"$cdref" oracle --query sphere-sphere --cases cases.csv --decimal --out truth.csv

# 4. the grade: no misclassification, every distance within 8 ulps or 1e-15 of the inputs' scale
"$cdref" score --query sphere-sphere --cases cases.csv --answers answers.csv \
    --max-ulps 8 --max-rel 1e-15 --json grade.json
