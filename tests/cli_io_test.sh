#!/usr/bin/env bash
# tests/cli_io_test.sh CDREF - the command line and its I/O as a hostile user meets them: bad
# command lines refused by name (exit 2), every subcommand's --help, writes that fail (never
# exit 0), user text that never reaches gnuplot's language, `cdref score` as a CI gate, case
# files and checkpoints that refuse what they cannot read exactly, bounded memory, scenes.
set -uo pipefail
cdref="$1"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
fail() { echo "FAIL: $*" >&2; exit 1; }
# run CMD...: status in $st, standard output in out.txt, standard error in err.txt
run() { "$@" > out.txt 2> err.txt; st=$?; }
# refused EXPECTED-MESSAGE-REGEX ARGS...: exit status 2 and the message names the problem
refused() {
  local want="$1"; shift
  run "$cdref" "$@"
  [ "$st" = 2 ] || fail "cdref $*: exit status $st (want 2): $(head -c 400 err.txt)"
  grep -Eq -- "$want" err.txt || fail "cdref $*: message '$(head -c 400 err.txt)' does not say /$want/"
}

# ---- one parser: help, --opt=value, refusals by name ----
for c in campaign merge describe demo cases oracle score plot report scene peers; do
  run "$cdref" $c --help
  [ "$st" = 0 ] && grep -q "Usage: .*$c" out.txt || fail "$c --help: $st $(head -3 out.txt err.txt)"
done
run "$cdref" help
[ "$st" = 0 ] && grep -q "^Usage: cdref \[OPTIONS\] \[SUBCOMMAND\]" out.txt && grep -q "^  score " out.txt || fail "help: $(head -3 out.txt)"
run "$cdref" help score
[ "$st" = 0 ] && grep -q "max-ulps" out.txt || fail "help score: $(head -3 out.txt)"
run "$cdref" --version
[ "$st" = 0 ] && grep -Eq "^cdref [0-9]+\.[0-9]+\.[0-9]+ \(commit [0-9a-f]+|unknown\)" out.txt || fail "--version: $(cat out.txt)"
run "$cdref" cases --query=ray-box --n=2
[ "$st" = 0 ] && [ "$(wc -l < out.txt)" = 3 ] || fail "--opt=value: $st $(cat err.txt)"
refused "^cdref: --n: wants a whole number from 1 to [0-9]+, not '-1'" cases --query ray-box --n -1
refused "^cdref: --n: wants a whole number .* not 'abc'" cases --query ray-box --n abc
refused "^cdref: --n: wants a whole number .* not '1e3'" cases --query ray-box --n 1e3
refused "^cdref: --n: wants a whole number .* not '0x10'" cases --query ray-box --n 0x10
refused "^cdref: --scale: wants a scale .* not 'abc'" cases --query ray-box --scale abc
refused "--scale 5000: family uniform of ray-box has the scales" cases --query ray-box --scale 5000
refused "^cdref: --n: wants a whole number" plot --query ray-box --family uniform --n -1
refused "^cdref: --threads: wants a whole number from 1 to 4096, not '999999999999'" peers --threads 999999999999
# the gallery is a program of its own beside cdref: without it, `cdref peers` fails naming it
# (a copy of cdref alone in a folder), and `cdref help peers` is the gallery's own help
mkdir alone && cp "$cdref" alone/cdref
run alone/cdref peers --n 1
[ "$st" = 2 ] && grep -q "^cdref: peers: cannot run the gallery's program .*/alone/cdref_peers: No such file" err.txt ||
  fail "peers without its program: status $st, $(head -c 300 err.txt)"
run "$cdref" help peers
[ "$st" = 0 ] && grep -q "^Usage: cdref peers \[OPTIONS\]" out.txt && grep -q -- "--library" out.txt ||
  fail "help peers: $st $(head -3 out.txt err.txt)"
refused "^cdref: --seed: wants a whole number from 0 to 18446744073709551615, not '-1'" campaign --seed -1
refused "--scale 5000: no chosen family has this scale" campaign --query ray-box --scale 5000
refused "not expected: extra" describe extra
refused "not expected: x" demo x
refused "not expected: bogus" bogus
refused "^cdref: --n is given 2 times; it takes one value" campaign --n 5 --n 6
refused "^cdref: --query: is one of .* not 'ray-bx'" cases --query ray-bx
refused "^cdref: --precision: is one of 24, 53, 64, not '32'" oracle --query ray-box --precision 32
refused "--family grazing is given twice" campaign --query ray-box --family grazing --family grazing
refused "--family all takes no other family" cases --query ray-box --family all --family uniform
refused "^cdref: --checkpoint-every: wants a number from 0 to .* not 'nan'" campaign --checkpoint-every nan
refused "^cdref: --max-abs: wants a number .* not 'inf'" score --query ray-box --cases x --answers y --max-abs inf
refused "FILE is required" merge
refused "--n excludes --describe" cases --describe ray-box --n 3
refused "File does not exist: nofile.txt" merge nofile.txt
refused "/etc/passwd:1: not a cdref results file" merge /etc/passwd
refused "--compare wants two precisions, e.g. float,exact, not 'float'" scene --compare float
# list options accumulate: two families, every family at every scale
run "$cdref" cases --query ray-box --family uniform --family grazing --n 2
[ "$st" = 0 ] && [ "$(cut -d, -f2 out.txt | sort -u | tr '\n' ' ')" = "family grazing uniform " ] || fail "two families: $(cat out.txt err.txt)"
cells=$("$cdref" describe | awk '/^ray-box:/ {on=1; next} /^[a-z]/ {on=0} on && /scales/ {sub(/.*\(scales /, ""); sub(/\).*/, ""); n += split($0, a, " ")} END {print n}')
run "$cdref" cases --query ray-box --family all --scale all --n 2
[ "$st" = 0 ] && [ "$(($(wc -l < out.txt) - 1))" = "$((2 * cells))" ] || fail "--family all --scale all: $(wc -l < out.txt) lines for $cells cells"
[ "$(cut -d, -f1 out.txt | sort | uniq -d | wc -l)" = 0 ] || fail "--family all: case ids repeat"

# negative scales (the magnitude families) are scales; a leading zero is decimal, not octal
run "$cdref" cases --query sphere-sphere --family magnitude --scale -320 --n 2
[ "$st" = 0 ] && [ "$(sed -n 2p out.txt | cut -d, -f3)" = -320 ] || fail "--scale -320: $st $(cat err.txt)"
run "$cdref" campaign --query sphere-sphere --family magnitude --scale=-50 --impl book-double --n 5 --quiet
[ "$st" = 0 ] || fail "campaign --scale=-50: $st $(cat err.txt)"
"$cdref" cases --query ray-box --n 3 --seed 010 > s010.csv
"$cdref" cases --query ray-box --n 3 --seed 10 > s10.csv
cmp -s s010.csv s10.csv || fail "--seed 010 is not --seed 10"

# ---- one output layer: no failed write exits 0; paths checked before the work ----
run "$cdref" cases --query ray-box --n 3 --out /dev/full
[ "$st" = 2 ] && grep -q "cannot write the case file /dev/full: No space left on device" err.txt || fail "cases to /dev/full: $st $(cat err.txt)"
"$cdref" cases --query ray-box --n 3 > /dev/full 2> err.txt; st=$?
[ "$st" = 2 ] && grep -q "standard output: No space left on device" err.txt || fail "cases > /dev/full: $st $(cat err.txt)"
"$cdref" cases --query ray-box --n 20 --out c.csv
"$cdref" oracle --query ray-box --cases c.csv > /dev/full 2> err.txt; st=$?
[ "$st" = 2 ] || fail "oracle > /dev/full: $st"
"$cdref" describe > /dev/full 2> err.txt; st=$?
[ "$st" = 2 ] || fail "describe > /dev/full: $st"
start=$(date +%s)
refused "cannot write --out /nonexistent/x.txt: No such file or directory" campaign --query ray-box --n 100000 --out /nonexistent/x.txt
[ $(($(date +%s) - start)) -lt 10 ] || fail "a bad --out was refused only after the work"
refused "cannot write --json $dir: it is a directory" campaign --query ray-box --n 10 --json "$dir"
refused "cannot write --checkpoint /dev/null: it is not a regular file" campaign --query ray-box --n 10 --checkpoint /dev/null
# one output fails, the others are still written, and the failure is named
run "$cdref" campaign --query ray-box --family uniform --n 50 --json /dev/full --csv ok.csv --quiet
[ "$st" = 2 ] && grep -q "cannot write --json /dev/full" err.txt && [ -s ok.csv ] || fail "--json /dev/full beside --csv: $st $(cat err.txt)"
ls -a | grep -q "tmp-" && fail "a temporary file was left: $(ls -a)"
# a symbolic link: the file it names is replaced, the link stays, the file keeps its permissions
mkdir -p real && echo old > real/target.csv && chmod 600 real/target.csv && ln -sf real/target.csv link.csv
"$cdref" cases --query ray-box --n 2 --out link.csv
[ -L link.csv ] && grep -q "^case," real/target.csv && [ "$(stat -c %a real/target.csv)" = 600 ] ||
  fail "--out through a symbolic link: $(ls -l link.csv real/target.csv)"
"$cdref" demo > /dev/full 2> err.txt; st=$?
[ "$st" = 2 ] || fail "demo > /dev/full: $st"
# a closed pipe ends the command quietly: no signal, no message
"$cdref" cases --query ray-box --n 200000 2> err.txt | head -1 > /dev/null
st=${PIPESTATUS[0]}
[ "$st" = 0 ] && [ ! -s err.txt ] || fail "cases | head: status $st, $(cat err.txt)"
"$cdref" describe 2> err.txt | head -c 10 > /dev/null
[ "${PIPESTATUS[0]}" = 0 ] || fail "describe | head: status ${PIPESTATUS[0]}"

# ---- no user text reaches gnuplot's language ----
rm -f pwned
evil="x'; system('touch pwned'); print '.svg"
run "$cdref" plot --query ray-triangle-cast --family grazing --n 30 --out "$evil"
[ "$st" = 0 ] && [ ! -e pwned ] && [ -s "$evil" ] || fail "plot --out with quotes: $st $(cat err.txt)"
python3 -c "import sys, xml.dom.minidom as m; m.parse(sys.argv[1])" "$evil" || fail "plot: the SVG does not parse"
rm -f pwned
run "$cdref" report --query obb-obb --n 20 --reps 1 --error-n 5 --svg "r\"'\`touch pwned\`.svg"
[ "$st" = 0 ] && [ ! -e pwned ] && grep -q "</svg>" "r\"'\`touch pwned\`.svg" || fail "report --svg with quotes: $st $(cat err.txt)"
# every (query, family) draws, the descriptions with apostrophes included; a campaign's JSON too
for q in triangle-box obb-obb polygon-polygon; do
  for f in $("$cdref" describe | awk -v q="$q:" '$1 == q {on=1; next} /^[a-z]/ {on=0} on && /^    [a-z]/ {print $1}'); do
    run "$cdref" plot --query $q --family $f --n 10 --out p.svg
    [ "$st" = 0 ] && python3 -c "import xml.dom.minidom as m; m.parse('p.svg')" || fail "plot $q $f: $st $(cat err.txt)"
  done
done
"$cdref" campaign --query segment-sphere-cast --family near-tangent --impl robust-float --impl stable-double --n 30 --json camp.json --quiet
run "$cdref" plot --query segment-sphere-cast --family near-tangent --from camp.json --out from.svg
[ "$st" = 0 ] && grep -q "robust-float" from.svg && grep -q "stable-double" from.svg || fail "plot --from: $st $(cat err.txt)"

# ---- cdref score gates a CI job ----
q=segment-sphere-cast
"$cdref" cases --query $q --family near-tangent --scale 28 --n 40 --out c.csv
"$cdref" oracle --query $q --cases c.csv --out a.csv
run "$cdref" score --query $q --cases c.csv --answers a.csv --json s.json --csv s.csv --max-ulps 0
[ "$st" = 0 ] && grep -q "^PASS: no graded value is misclassified, not finite or beyond --max-ulps 0" out.txt || fail "score of the truth: $st $(tail -3 out.txt)"
python3 -c "
import json, csv
d = json.load(open('s.json'))
assert d['pass'] and d['failures'] == 0 and d['graded'] == 40, d
assert any(c['column'] == 'lambda_enter' and c['max_ulps'] == 0 for c in d['columns'])
rows = list(csv.DictReader(open('s.csv')))
assert {r['column'] for r in rows} >= {'hit', 'lambda_enter'}
" || fail "score --json/--csv"
# every classification flipped: exit 1, examples with named inputs and the exact answer
awk -F, 'BEGIN{OFS=","} NR==1 {print "case","hit"; next} {print $1, 1-$2}' a.csv > wrong.csv
run "$cdref" score --query $q --cases c.csv --answers wrong.csv
[ "$st" = 1 ] && grep -q "^FAIL: 40 graded values are misclassified" out.txt && grep -q "hit, case 0: given [01], exact [01]" out.txt &&
  grep -q "source_x=" out.txt || fail "score of wrong answers: $st $(cat out.txt)"
# a value one ulp off: beyond --max-ulps 0, within --max-ulps 1 and within --max-abs 1e-12
python3 - <<'PY'
import csv, math
rows = list(csv.reader(open('a.csv')))
h = rows[0]; k = h.index('lambda_enter')
out = [['case', 'hit', 'lambda_enter']]
for r in rows[1:]:
    v = float.fromhex(r[k])
    if r[1] == '1': v = math.nextafter(v, math.inf)
    out.append([r[0], r[1], v.hex()])
csv.writer(open('ulp.csv', 'w', newline='')).writerows(out)
PY
run "$cdref" score --query $q --cases c.csv --answers ulp.csv --max-ulps 0
[ "$st" = 1 ] && grep -q "lambda_enter, case" out.txt || fail "score --max-ulps 0 of 1-ulp answers: $st"
run "$cdref" score --query $q --cases c.csv --answers ulp.csv --max-ulps 1
[ "$st" = 0 ] || fail "score --max-ulps 1 of 1-ulp answers: $st $(tail -5 out.txt)"
run "$cdref" score --query $q --cases c.csv --answers ulp.csv --max-abs 1e-12
[ "$st" = 0 ] || fail "score --max-abs of 1-ulp answers: $st"
# set apart by the answers' own convention: counted, not graded
awk -F, 'BEGIN{OFS=","} NR==1 {print "case","hit","set_apart"; next} {print $1, 1-$2, 1}' a.csv > apart.csv
run "$cdref" score --query $q --cases c.csv --answers apart.csv
[ "$st" = 0 ] && grep -q "40 set apart" out.txt || fail "set_apart: $st $(head -2 out.txt)"
# with --json -, standard output is the JSON alone (the table goes to standard error)
"$cdref" score --query $q --cases c.csv --answers a.csv --json - > sj.json 2> /dev/null
python3 -c "import json; assert json.load(open('sj.json'))['pass']" || fail "score --json -: $(head -c 300 sj.json)"
# an answer to a malformed case line: that case is not graded, the others are (exit 1)
awk -F, 'BEGIN{OFS=","} NR==4 {$4="abc"} {print}' c.csv > c2.csv
run "$cdref" score --query $q --cases c2.csv --answers a.csv
[ "$st" = 1 ] && grep -q "39 answered and graded" out.txt || fail "an answer to a malformed case: $st $(cat err.txt)"
# answers the grade cannot trust: refused by name, exit 2
awk -F, 'NR==2 {print; n=split($0, f, ","); f[2]=1-f[2]; s=f[1]; for (i=2;i<=n;i++) s=s","f[i]; print s; next} {print}' a.csv > dup.csv
refused "dup.csv:3: case 0 is answered twice \(also on line 2\)" score --query $q --cases c.csv --answers dup.csv
{ cat a.csv; sed -n 2p a.csv | sed 's/^0,/999,/'; } > extra.csv
refused "extra.csv:42: case 999 is not in the case file c.csv" score --query $q --cases c.csv --answers extra.csv
sed '1s/lambda_exit/lambda_enter/' a.csv > dupcol.csv
refused "the header names column 'lambda_enter' twice" score --query $q --cases c.csv --answers dupcol.csv
refused "cannot read the case file $dir: it is a directory" score --query $q --cases "$dir" --answers a.csv

# ---- case files refuse what they cannot read exactly ----
head -1 c.csv > h.csv
line=$(sed -n 2p c.csv)
{ cat h.csv; echo "$line" | awk -F, 'BEGIN{OFS=","} {$4="1 2"; print}'; } > sp.csv
run "$cdref" oracle --query $q --cases sp.csv
[ "$st" = 1 ] && grep -q "sp.csv:2: source_x '1 2' has a blank inside; line skipped" err.txt || fail "embedded blank: $(cat err.txt)"
{ cat h.csv; echo "$line" | awk -F, 'BEGIN{OFS=","} {$1="99999999999999999999999"; print}'; } > big.csv
run "$cdref" oracle --query $q --cases big.csv
[ "$st" = 1 ] && grep -q "case id '99999999999999999999999' is beyond 2^64 - 1" err.txt || fail "id past 2^64: $(cat err.txt)"
for lit in 1e-400 0x1p-1100; do
  { cat h.csv; echo "$line" | awk -F, -v v=$lit 'BEGIN{OFS=","} {$5=v; print}'; } > u.csv
  run "$cdref" oracle --query $q --cases u.csv
  [ "$st" = 1 ] && grep -q "source_y '$lit' underflows" err.txt || fail "underflow $lit: $(cat err.txt)"
done
{ cat h.csv; echo "$line"; echo "$line"; } > twice.csv
run "$cdref" oracle --query $q --cases twice.csv
[ "$st" = 1 ] && grep -q "twice.csv:3: case id 0 is already on line 2" err.txt || fail "duplicate case id: $(cat err.txt)"
{ sed '1s/source_z/source_x/' h.csv; echo "$line"; } > dh.csv
refused "dh.csv:1: the header names column 'source_x' twice" oracle --query $q --cases dh.csv
{ printf '\xef\xbb\xbf'; cat h.csv; echo "$line"; } > bom.csv
run "$cdref" oracle --query $q --cases bom.csv
[ "$st" = 0 ] && [ "$(wc -l < out.txt)" = 2 ] || fail "a BOM: $st $(cat err.txt)"
{ cat h.csv; printf '1,x\0y\n'; echo "$line"; } > nul.csv
run "$cdref" oracle --query $q --cases nul.csv
[ "$st" = 1 ] && grep -q "nul.csv:2: the line holds a NUL byte" err.txt || fail "a NUL: $(cat err.txt)"
"$cdref" cases --query polygon-polygon --n 3 --out pc.csv
awk -F, 'BEGIN{OFS=","} NR==1 {for (i=1;i<=NF;i++) if ($i=="b_n") k=i} NR==2 {$k=9} {print}' pc.csv > pbad.csv
run "$cdref" oracle --query polygon-polygon --cases pbad.csv
[ "$st" = 1 ] && grep -q "case 0: polygon b: b_n must be a whole number of vertices from 3 to 8 (9)" err.txt || fail "polygon b: $(cat err.txt)"

# ---- checkpoints and shards are checked before they are trusted ----
args=(campaign --query ray-box --family uniform --scale 0 --impl book-double --n 600 --seed 2 --quiet)
"$cdref" "${args[@]}" --checkpoint ck.txt --out whole.txt
items=$(awk '$1 == "items" {print $3}' ck.txt)
sed "s/^items .*/items $((items + 5)) $items/" ck.txt > over.txt
refused "says $((items + 5)) of $items items are done" "${args[@]}" --checkpoint over.txt --resume
sed "s/^items .*/items 0 $items/" ck.txt > zero.txt
refused "has statistics but none of its items is done" "${args[@]}" --checkpoint zero.txt --resume
awk '$1 == "cell" {$6 = $6 + 1} {print}' ck.txt > cnt.txt
refused "counts 601 cases; its done items hold 600" "${args[@]}" --checkpoint cnt.txt --resume
sed 's/$/\r/' ck.txt > crlf.txt
run "$cdref" "${args[@]}" --checkpoint crlf.txt --resume --out resumed.txt
[ "$st" = 0 ] && cmp -s whole.txt resumed.txt || fail "a CRLF checkpoint: $st $(cat err.txt)"
"$cdref" "${args[@]}" --shard 0/2 --out s0.txt
"$cdref" "${args[@]}" --shard 1/2 --out s1.txt
awk '$1 == "cell" {$6 = $6 + 7} {print}' s1.txt > s1bad.txt
refused "shard 1: cell ray-box book-double uniform 0 counts 307 cases" merge s0.txt s1bad.txt

# ---- memory bounded by what is held, not by what is asked ----
# a campaign of 10^12 cases starts at once (its work items are computed, not listed) and runs
# under a 1 GB address-space limit until it is stopped
( ulimit -v 1000000; timeout 4 "$cdref" campaign --query ray-box --family uniform --scale 0 --impl book-double \
    --n 1000000000000 --threads 1 --quiet > /dev/null 2> err.txt ); st=$?
[ "$st" = 124 ] || fail "campaign --n 10^12 under 1 GB: status $st $(head -c 300 err.txt)"

# ---- errors beside ulps: absolute and relative to the inputs' scale ----
# the book's u near an exact 0 is 10^18 ulps away and 1e-15 off: every report says both
"$cdref" campaign --query ray-triangle-cast --family long-range --scale 9 --impl book-double --n 300 \
  --json rt.json --csv rt.csv > rt.txt
python3 -c "
import json, csv
d = json.load(open('rt.json'))
u = d['cells'][0]['outputs']['u']
assert u['max'] > 10**15 and 0 < u['max_abs'] < 1e-12 and 0 < u['max_rel'] < 1e-12, u
assert d['cells'][0]['outputs']['u']['worst']['inputs']['source_x'].startswith(('0x', '-0x'))
rows = [r for r in csv.DictReader(open('rt.csv')) if r['output'] == 'u']
assert float(rows[0]['max_rel']) == u['max_rel'], rows
" || fail "max_abs/max_rel in the campaign's JSON and CSV"
grep -Eq "^ray-triangle-cast +book-double .* [0-9.]+e-1[4-6] +4\.[0-9]+e\+18 \(u in long-range/9\)" rt.txt || fail "max rel in the table: $(head -8 rt.txt)"
grep -q "source_x=" rt.txt || fail "examples without column names: $(tail -4 rt.txt)"

# ---- scenes ----
printf '{"time_step": 0.1, "time_step": 0.2, "frames": 3, "bodies": [], "effects": []}' > dupkey.json
refused "the key 'time_step' is given twice in one object" scene dupkey.json
python3 -c "print('{\"description\": ' + '[' * 100000 + ']' * 100000 + '}')" > deep.json
refused "nesting deeper than 32 levels" scene deep.json
printf '{"description": [], "time_step": 0.1, "frames": 3, "bodies": [], "effects": []}' > desc.json
refused "at /description: expected a string, found array" scene desc.json
printf '{"time_step": 0.1, "frames": 3, "bodies": [{"name": "a\\u0000b", "shape": "sphere", "radius": 1}], "effects": []}' > nul.json
refused "at /bodies/0/name: the string holds a control character \(0\)" scene nul.json
printf '{"time_step": 0.1, "frames": 3, "bodies": [{"name": "m", "shape": "mesh", "vertices": [[0,0,0],[1,0,0],[0,1,0]], "faces": [[0, 1, 18446744073709551615]]}], "effects": []}' > face.json
refused "face names vertex 18446744073709551615, but the mesh has 3 vertices" scene face.json
run "$cdref" scene --quiet --json -
[ "$st" = 0 ] && [ ! -e ./- ] && python3 -c "import json; json.load(open('out.txt'))" || fail "scene --json -: $st"

echo "cli io: all checks passed"
