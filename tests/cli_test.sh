#!/usr/bin/env bash
# tests/cli_test.sh CDREF - the command line end to end: case files (cases, oracle, score,
# partial answer files, malformed lines), shards and merge, errors by name.
set -euo pipefail
cdref="$1"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
fail() { echo "FAIL: $*" >&2; exit 1; }

# every query (from its descriptor): cases -> oracle -> score grades the oracle as exact
queries=$("$cdref" describe | awk -F: '/^[a-z]/ {print $1}')
[ "$(echo "$queries" | wc -l)" -ge 8 ] || fail "describe lists $(echo "$queries" | wc -l) queries"
for q in $queries; do
  "$cdref" cases --query "$q" --family degenerate --n 60 --seed 3 --out c.csv
  [ "$(wc -l < c.csv)" = 61 ] || fail "$q: cases wrote $(wc -l < c.csv) lines"
  "$cdref" oracle --query "$q" --cases c.csv --out a.csv
  # every graded column exact: no misclassification and every value within 0 ulps (exit 0)
  "$cdref" score --query "$q" --cases c.csv --answers a.csv --max-ulps 0 > s.txt ||
    fail "$q: the oracle does not score as exact: $(cat s.txt)"
  grep -q "60 answered and graded, 0 unanswered, 0 malformed" s.txt || fail "$q: score: $(head -1 s.txt)"
  awk '$1 == "hit" || $1 == "intersect" || $1 == "predicate" { if ($3 != "0/0") bad=1 } END { exit bad }' s.txt ||
    fail "$q: misclassified: $(cat s.txt)"
  # decimal cases read back to the same answers
  "$cdref" cases --query "$q" --family degenerate --n 60 --seed 3 --decimal --out cd.csv
  "$cdref" oracle --query "$q" --cases cd.csv --out ad.csv
  cmp -s a.csv ad.csv || fail "$q: decimal case file gives other answers"
  "$cdref" cases --describe "$q" | grep -q "answer file columns: case," || fail "$q: --describe"
done

# a partial answer file with a wrong value, a malformed line and a missing answer
q=segment-sphere-cast
"$cdref" cases --query $q --family near-tangent --scale 52 --n 50 --seed 5 --out c.csv
"$cdref" oracle --query $q --cases c.csv --out a.csv
awk -F, 'BEGIN{OFS=","} NR==1 {print "case","hit","lambda_enter"; next}
         NR==3 {print $1, 1-$2, $4; next}      # case 1: classification flipped
         NR==5 {print $1, $2; next}            # case 3: a malformed line (one field short)
         NR==7 {next}                          # case 5: no answer
         {print $1, $2, $4}' a.csv > partial.csv
set +e
"$cdref" score --query $q --cases c.csv --answers partial.csv > s.txt 2> err.txt
status=$?
set -e
[ $status = 1 ] || fail "score with a malformed line exited $status"
grep -q "partial.csv:5: expected 3 fields, found 2" err.txt || fail "malformed line not named: $(cat err.txt)"
grep -q "50 cases, 48 answered and graded, 2 unanswered, 1 malformed" s.txt || fail "partial: $(head -1 s.txt)"
grep -Eq "^hit +48 +[01]/[01]" s.txt || fail "partial: hit row: $(cat s.txt)"
! grep -q "^point_x" s.txt || fail "partial: an ungraded column was graded"
grep -q "^lambda_enter" s.txt || fail "partial: lambda_enter not graded"

# a malformed case line is reported and skipped; the rest still answered
awk 'NR==4 {print "3,x,0,1,2"; next} {print}' c.csv > badc.csv
set +e
"$cdref" oracle --query $q --cases badc.csv --out a2.csv 2> err.txt
status=$?
set -e
[ $status = 1 ] || fail "oracle with a malformed case exited $status"
grep -q "badc.csv:4: expected 13 fields, found 5" err.txt || fail "malformed case not named: $(cat err.txt)"
[ "$(wc -l < a2.csv)" = 50 ] || fail "oracle lost the other cases"

# non-finite inputs and literals beyond double's range are refused by name, per case, for
# every query; every finite case is still answered, and nothing dies of a signal
for q in $queries; do
  "$cdref" cases --query "$q" --n 6 --seed 9 --out c.csv
  awk -F, 'BEGIN{OFS=","} NR==3 {$4="nan"} NR==4 {$NF="-inf"} NR==5 {$5="1e400"} NR==6 {$4="0x1p+2000"} {print}' c.csv > nf.csv
  for p in 53 24; do
    set +e
    "$cdref" oracle --query "$q" --cases nf.csv --precision $p --out a.csv 2> err.txt
    status=$?
    set -e
    [ $status = 1 ] || fail "$q: oracle with non-finite cases exited $status: $(cat err.txt)"
    [ "$(wc -l < a.csv)" = 3 ] || fail "$q: oracle answered $(($(wc -l < a.csv) - 1)) of the 2 finite cases"
    grep -q "^case 1: .* is not finite (nan); no answer" err.txt || fail "$q: nan not named: $(cat err.txt)"
    grep -q "^case 2: .* is not finite (-inf); no answer" err.txt || fail "$q: -inf not named: $(cat err.txt)"
    grep -q "^case 3: .* '1e400' is beyond the range of double; no answer" err.txt || fail "$q: 1e400: $(cat err.txt)"
    grep -q "^case 4: .* '0x1p+2000' is beyond the range of double; no answer" err.txt || fail "$q: 0x1p+2000"
  done
  set +e
  "$cdref" oracle --query "$q" --cases nf.csv --out a.csv 2> /dev/null
  "$cdref" score --query "$q" --cases nf.csv --answers a.csv > s.txt 2> err.txt
  status=$?
  set -e
  grep -q "6 cases, 2 answered and graded, 0 unanswered, 4 malformed or refused" s.txt && [ $status = 1 ] ||
    fail "$q: score with non-finite cases: $status $(cat s.txt err.txt)"
  grep -q "^case 1: .* is not finite (nan); not graded" err.txt || fail "$q: score: nan not named: $(cat err.txt)"
done

# shards merge into exactly the unsharded result
args=(campaign --query sphere-box --query ray-box-cast --family near-touching --family grazing --n 300 --seed 4 --quiet)
"$cdref" "${args[@]}" --out whole.txt --json whole.json
"$cdref" "${args[@]}" --shard 0/2 --out s0.txt
"$cdref" "${args[@]}" --shard 1/2 --out s1.txt --threads 1
"$cdref" merge --out merged.txt --json merged.json s1.txt s0.txt > /dev/null
cmp -s whole.txt merged.txt || fail "merged shards differ from the unsharded run"
cmp -s whole.json merged.json || fail "merged JSON differs"
set +e
"$cdref" merge s0.txt > /dev/null 2> err.txt
status=$?
set -e
[ $status = 2 ] && grep -q "shard 1/2 is missing" err.txt || fail "merge of one shard: $status $(cat err.txt)"

# errors by name
set +e
"$cdref" campaign --query sphere-cube 2> err.txt; s1=$?
"$cdref" campaign --n -5 2>> err.txt; s2=$?
"$cdref" campaign --query box-box --family grazing 2>> err.txt; s3=$?
"$cdref" campaign --query box-box --family uniform --family grazng 2>> err.txt; s4=$?
"$cdref" campaign --query box-box --checkpoint-every -1 2>> err.txt; s5=$?
"$cdref" campaign --query box-box --mpi 2>> err.txt; s6=$?
"$cdref" campaign --query box-box --outputs certian 2>> err.txt; s7=$?
set -e
[ $s1 = 2 ] && [ $s2 = 2 ] && [ $s3 = 2 ] && [ $s4 = 2 ] && [ $s5 = 2 ] && [ $s6 = 2 ] && [ $s7 = 2 ] ||
  fail "bad options did not fail: $s1 $s2 $s3 $s4 $s5 $s6 $s7"
grep -q "\-\-outputs: is one of all, cls, certain, not 'certian'" err.txt ||
  fail "bad --outputs message: $(cat err.txt)"
grep -q "no family 'grazng' for query box-box" err.txt || fail "a misspelt family beside a known one: $(cat err.txt)"
grep -q "\-\-checkpoint-every: wants a number from 0 to 1e+06, not '-1'" err.txt || fail "bad --checkpoint-every message"
grep -q "\-\-mpi: campaigns across MPI ranks run as .mpirun" err.txt || fail "--mpi message: $(cat err.txt)"
grep -q "\-\-query: is one of sphere-sphere, .*, not 'sphere-cube'" err.txt || fail "unknown query message"
grep -q "\-\-n: wants a whole number from 1 to [0-9]*, not '-5'" err.txt || fail "bad --n message"
grep -q "no family 'grazing' for query box-box" err.txt || fail "unknown family message"

# JSON and CSV are produced and well-formed enough to parse
python3 -c "import json,sys; d=json.load(open('whole.json')); assert len(d['cells'])>0" || fail "JSON does not parse"
"$cdref" "${args[@]}" --csv out.csv
head -1 out.csv | grep -q "^query,impl,family,scale,cases" || fail "CSV header"
# the cost report: every row of every query measured in one run, as a table, CSV, JSON and
# SVG (every query has its bare, book, stable, robust, oracle and exact rows)
"$cdref" report --n 40 --reps 1 --error-n 10 --csv report.csv --json report.json --svg report.svg > report.txt
# segment-sphere-cast: bare, 6 book rows, 4 stable, 4 robust, 6 oracle (classification, every output, lambda_enter: uniform and near-boundary), 4 staged (classification and every output: uniform and near-boundary), 2 truth API (uniform and near-boundary), 3 exact, 2 CGAL
[ "$(grep -c '^segment-sphere-cast,' report.csv)" = 32 ] || fail "report rows: $(cat report.txt)"
[ "$(grep -c '^box-box,' report.csv)" = 24 ] || fail "report rows: $(cat report.txt)"
grep -q "^  bare (book at double, unchecked)  *[0-9.]*  *1.00 " report.txt || fail "report: no bare baseline row"
grep -q "^  book double  *[0-9.]*  *[0-9.]*  *1.00 " report.txt || fail "report: no book double baseline row"
grep -q "^  stable double  " report.txt || fail "report: no stable row"
python3 -c "
import csv, json
rows = list(csv.reader(open('report.csv')))
assert all(len(r) == len(rows[0]) for r in rows), 'a CSV row with the wrong number of fields'
d = json.load(open('report.json'))
assert len(d['queries']) == len(set(l.split(',')[0] for l in open('report.csv').readlines()[1:]))
assert sum(len(q['rows']) for q in d['queries']) == len(open('report.csv').readlines()) - 1
for q in d['queries']:
    assert all(r['ns_per_query'] > 0 for r in q['rows']), q['query']
" || fail "report JSON"
grep -q "<svg" report.svg || fail "report SVG"
"$cdref" report --query box-box --n 10 --reps 1 --error-n 5 > one.txt
grep -q "^box-box" one.txt && ! grep -q "^sphere-box" one.txt || fail "report --query"
# a malformed count is refused by name with exit status 2 (not read as its prefix, not wrapped)
for bad in "--n abc" "--n 1e400" "--n -5" "--n 99999999999" "--n 65537" "--threads 0" "--reps x"; do
  set +e; "$cdref" report $bad --query box-box > /dev/null 2> err.txt; status=$?; set -e
  [ $status = 2 ] && grep -q "cdref: .*\(--n\|--threads\|--reps\)" err.txt || fail "report $bad: status $status, $(cat err.txt)"
done
# scenes: the default runs and compares; --json and --svg write; a malformed scene is refused
# with its place and exit status 2, before anything runs; a run its type cannot carry is
# named and the others still print (exit status 1)
"$cdref" scene --json scene.json --svg scene.svg > scene.txt
grep -q "^float against exact: " scene.txt && grep -q "^double against exact: " scene.txt || fail "scene: $(head -3 scene.txt)"
grep -q "trigger 'door-opens' begin door-area/avatar" scene.txt || fail "scene log"
python3 -c "
import json
d = json.load(open('scene.json'))
assert [r['precision'] for r in d['runs']] == ['float', 'double', 'exact'], d['runs']
assert len(d['comparisons']) == 2
assert all(r['counts']['intersect'] > 0 for r in d['runs'])
" || fail "scene JSON"
grep -q "<svg" scene.svg || fail "scene SVG"
"$cdref" scene --precision double | grep -q "^scene built-in default (scenes/default.json) at double" || fail "scene --precision"
printf '{"time_step": 0.1, "frames": 3,\n "bodies": [{"name": "a", "shape": "sphere", "radius": -1}], "effects": []}' > bad.json
set +e
"$cdref" scene bad.json > out.txt 2> err.txt; st=$?
set -e
[ "$st" = 2 ] && grep -q "bad.json: at /bodies/0/radius: negative radius (-1)" err.txt && [ ! -s out.txt ] \
  || fail "malformed scene: status $st, $(cat err.txt)"
printf '{"time_step": 0.5, "frames": 3, "bodies": [{"name": "o", "shape": "sphere", "radius": 1e39},
  {"name": "p", "shape": "sphere", "radius": 1, "position": [3, 0, 0]}], "effects": [{"type": "trigger", "a": "o", "b": "p"}]}' > big.json
set +e
"$cdref" scene big.json > out.txt 2> err.txt; st=$?
set -e
[ "$st" = 1 ] && grep -q "body 'o' radius (9.9999999999999994e+38) is beyond float's range" err.txt \
  && grep -q "^double against exact: 1 events at the same frame" out.txt || fail "scene beyond float: status $st, $(cat err.txt)"
# peers: every adapter runs on its query's families; the JSON has a row per family
"$cdref" peers --n 40 --json peers.json --svg peers.svg > peers.txt 2> peers_err.txt
grep -q "<svg" peers.svg || fail "peers SVG"
python3 -c "
import json
d = json.load(open('peers.json'))
names = [p['function'] for p in d]
assert any(n.startswith('AlignedBox3f::intersects') for n in names), names
for p in d:
    assert p['families'], p['function']
    for f in p['families']:
        assert f['cases'] >= f['convention'] + f['false_positives'] + f['false_negatives'], (p['function'], f)
        # a misclassified family names a case of it, its inputs by column, the answer and the truth
        if f['false_positives'] + f['false_negatives']:
            e = f['misclassified_example']
            assert e['inputs'] and e['got'] != e['want'], e
ex = [f for p in d for f in p['families'] if 'misclassified_example' in f]
assert ex, 'no misclassified example'
# where each function first goes wrong, and its counts at each family's largest scale
for p in d:
    for f in p['families']:
        assert ('first_misclassified_scale' in f) == (f['false_positives'] + f['false_negatives'] > 0), (p['function'], f['family'])
assert all('largest_scale' in f for p in d for f in p['families'])
" || fail "peers JSON"
grep -q "^Eigen 3.4: AlignedBox3f::exteriorDistance" peers.txt || fail "peers table"
# --library: one library's rows alone; a library cdref does not know is refused by name
"$cdref" peers --n 20 --library Eigen --json peers1.json > peers1.txt || fail "peers --library"
python3 -c "
import json
d = json.load(open('peers1.json'))
assert d and all(p['library'].startswith('Eigen ') for p in d), [p['library'] for p in d]
" || fail "peers --library rows"
st=0; "$cdref" peers --n 20 --library Nope > /dev/null 2> err.txt || st=$?
[ "$st" = 2 ] && grep -q "library" err.txt || fail "peers --library Nope: status $st, $(cat err.txt)"
# ODE's rows where it was built with it (scripts/deps.sh installs libode-dev), each at double
if ! grep -q "ODE not found at build time" peers.txt; then
  python3 -c "
import json
d = json.load(open('peers.json'))
ode = [p for p in d if p['library'].startswith('ODE ')]
assert len(ode) == 5 and all(p['precision'] == 53 for p in ode), [p['function'] for p in ode]
assert sum(f['convention'] for p in ode for f in p['families']) > 0
" || fail "peers ODE rows"
fi
# Embree's rows where it was built with it (libembree-dev), each at float, its fan rows at mesh level
if ! grep -q "Embree not found at build time" peers.txt; then
  python3 -c "
import json
d = json.load(open('peers.json'))
em = [p for p in d if p['library'].startswith('Embree ')]
assert len(em) == 4 and all(p['precision'] == 24 for p in em), [p['function'] for p in em]
assert sorted(p['query'] for p in em) == ['ray-fan-cast'] * 2 + ['ray-triangle-cast'] * 2
assert all(any(f['family'] == 'watertight' for f in p['families']) for p in em if p['query'] == 'ray-fan-cast')
" || fail "peers Embree rows"
fi
# FCL's rows where it was built with it (libfcl-dev), each at double; its messages kept from the
# terminal and counted with the row
if ! grep -q "FCL not found at build time" peers.txt; then
  python3 -c "
import json
d = json.load(open('peers.json'))
fc = [p for p in d if p['library'].startswith('FCL ')]
assert len(fc) == 7 and all(p['precision'] == 53 for p in fc), [p['function'] for p in fc]
assert sorted(set(p['query'] for p in fc)) == ['obb-obb', 'sphere-box', 'sphere-sphere', 'sphere-triangle', 'triangle-box', 'triangle-triangle']
obb = [p for p in fc if p['query'] == 'obb-obb'][0]
assert sum(f['convention'] for f in obb['families']) > 0, 'the 1e-6 margin sets no case apart'
" || fail "peers FCL rows"
  grep -q "too many iterations in Jacobi" peers.txt && ! grep -q "Jacobi" peers_err.txt || fail "peers FCL messages"
fi
# Open3D's rows where it was built with it (libopen3d-dev), each at float; the cases its float
# routine would abort on refused, the process going on
if ! grep -q "Open3D not found at build time" peers.txt; then
  python3 -c "
import json
d = json.load(open('peers.json'))
o3 = [p for p in d if p['library'].startswith('Open3D ')]
assert len(o3) == 3 and all(p['precision'] == 24 for p in o3), [p['function'] for p in o3]
assert sorted(p['query'] for p in o3) == ['point-triangle', 'ray-fan-cast', 'ray-triangle-cast']
" || fail "peers Open3D rows"
fi
# Rapier's rows where its package was installed (scripts/deps.sh, npm), each at f32 through node
if ! grep -q "Rapier not found at build time" peers.txt; then
  python3 -c "
import json
d = json.load(open('peers.json'))
ra = [p for p in d if p['library'].startswith('Rapier ')]
assert len(ra) == 9 and all(p['precision'] == 24 for p in ra), [p['function'] for p in ra]
assert all(f['cases'] > f['refused'] for p in ra for f in p['families']), 'Rapier refused every case'
" || fail "peers Rapier rows"
fi
echo "cli: all checks passed"
