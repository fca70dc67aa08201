#!/usr/bin/env bash
# scripts/report.sh - regenerates what accuracy costs: docs/cost-report.{csv,json,svg} and the
# table in docs/cost.md, from one `cdref report` run (every implementation of every query timed
# side by side, and the error campaign). Builds cdref first, as scripts/cdref.sh does. It takes
# some minutes and both cores: run it on an otherwise idle machine, and put the machine, the
# build and the date beside the table in docs/cost.md.
# Arguments are passed to `cdref report` (e.g. --query ray-sphere-cast for one query's rows).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
cmake --preset release >/dev/null
cmake --build --preset release --target cdref_tools
./build/release/cdref report --reps 7 --error-n 1000 \
    --csv docs/cost-report.csv --json docs/cost-report.json --svg docs/cost-report.svg "$@"
python3 scripts/cost_table.py docs/cost-report.csv docs/cost.md
echo "docs/cost-report.{csv,json,svg} and the table in docs/cost.md regenerated" >&2
