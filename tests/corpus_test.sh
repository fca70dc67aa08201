#!/usr/bin/env bash
# tests/corpus_test.sh CDREF SOURCE - the fuzz seed corpus is what scripts/make_corpus.py makes:
# two runs write the same bytes, and every file it writes equals the one in fuzz/corpus (so a
# change to a family's generator that moves its cases shows here, not in someone's later run).
set -euo pipefail
cdref="$1"
src="$2"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
python3 "$src/scripts/make_corpus.py" "$cdref" --out "$dir/a"
python3 "$src/scripts/make_corpus.py" "$cdref" --out "$dir/b"
diff -r "$dir/a" "$dir/b" > /dev/null || { echo "FAIL: two runs of make_corpus.py differ" >&2; exit 1; }
stale=0
while IFS= read -r f; do
  rel=${f#"$dir/a/"}
  if ! cmp -s "$f" "$src/fuzz/corpus/$rel"; then
    echo "stale or missing: fuzz/corpus/$rel (run scripts/make_corpus.py build/release/cdref)" >&2
    stale=1
  fi
done < <(find "$dir/a" -type f | sort)
[ $stale = 0 ] || exit 1
echo "corpus: $(find "$dir/a" -type f | wc -l) generated files, identical in two runs and to fuzz/corpus"
