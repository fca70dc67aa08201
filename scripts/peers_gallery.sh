#!/usr/bin/env bash
# Regenerates the gallery in the docs in one command: runs `cdref peers` at its default size,
# writes docs/peers.svg, and replaces the table in docs/peers.md (between its "gallery" markers)
# with this run's, headed by the machine, the compiler, the libraries' versions, the date and the
# run's time. Usage: bash scripts/peers_gallery.sh [path/to/cdref] (default build/release/cdref).
set -euo pipefail
cd "$(dirname "$0")/.."
cdref=${1:-build/release/cdref}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
start=$(date +%s)
"$cdref" peers --json "$tmp/peers.json" --svg "$tmp/peers.svg" > "$tmp/table.txt"
secs=$(( $(date +%s) - start ))
cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1)
cores=$(nproc)
gxx=$(g++ -dumpfullversion)
python3 - "$tmp/table.txt" "$tmp/peers.json" "$secs" "$cpu" "$cores" "$gxx" docs/peers.md <<'PY'
import datetime, json, sys
table, rows, secs, cpu, cores, gxx, doc = sys.argv[1:8]
libs = []
for r in json.load(open(rows)):
    name = r['library'].split(' (')[0]
    if name not in libs:
        libs.append(name)
head = (f"Measured on {cores} cores of an {cpu}, g++ {gxx}, Release build, "
        f"{datetime.date.today().isoformat()}; {', '.join(libs)} as Debian 12 ships them (Rapier from npm) "
        f"(`cdref peers`, {secs} s):")
block = (head + "\n\n![misclassified share against scale per library function](peers.svg)\n\n```\n"
         + open(table).read().rstrip("\n") + "\n```\n")
text = open(doc).read()
begin, end = "<!-- gallery: begin (scripts/peers_gallery.sh) -->\n", "<!-- gallery: end -->\n"
i, j = text.index(begin) + len(begin), text.index(end)
open(doc, "w").write(text[:i] + block + text[j:])
PY
cp "$tmp/peers.svg" docs/peers.svg
echo "cdref: docs/peers.md and docs/peers.svg regenerated ($secs s)"
