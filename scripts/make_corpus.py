#!/usr/bin/env python3
"""Writes the seed corpus of the fuzz targets (fuzz/corpus/), reproducibly.

usage: scripts/make_corpus.py CDREF [--out DIR]   (default: fuzz/corpus of this checkout)

For each query (`cdref describe`): two cases of every family (from `cdref cases`), encoded as
the fuzz targets decode them (a mode byte 0xff then 8 raw bytes per input), plus small exact
cases in the dyadic encoding (a mode byte k < 192, then an int8: the value int8 / 2^(k%8)):
the hand-made ones below, or else the degenerate family's first cases rounded to halves.
For the case-file reader: small case files, good and malformed, and with the tokens a case file
must survive (non-finite values, literals beyond double's range, subnormals, empty fields).
"""
import os, struct, subprocess, sys

if len(sys.argv) not in (2, 4) or (len(sys.argv) == 4 and sys.argv[2] != "--out"):
    sys.exit("usage: scripts/make_corpus.py CDREF [--out DIR]")
cdref = sys.argv[1]
root = sys.argv[3] if len(sys.argv) == 4 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "fuzz", "corpus")

def run(*args):
    return subprocess.run([cdref, *args], check=True, capture_output=True, text=True).stdout

# (cdref is asked once for the queries and their families, and once per query for every
# family's cases, not once per family)
described = run("describe").splitlines()
queries = [line.split(":")[0] for line in described if line and not line.startswith(" ")]

def families(q):
    fams, inside = [], False
    for line in described:
        if line.startswith(q + ":"):
            inside = True
        elif not line.startswith(" ") and inside:
            break
        elif inside and line.startswith("    "):
            fams.append(line.split()[0])
    return fams

def dyadic(values):
    return b"".join(bytes([0, v & 0xff]) for v in values)

# small exact cases: inputs as integers (touching, tangent, through the centre, zero sizes)
exact = {
    "sphere-sphere": [[0, 0, 0, 1, 2, 0, 0, 1], [1, 2, 3, 1, 1, 2, 3, 2], [0, 0, 0, 0, 0, 0, 0, 0]],
    "segment-sphere-cast": [[-2, 1, 0, 2, 1, 0, 0, 0, 0, 1], [1, 0, 0, 2, 0, 0, 0, 0, 0, 1], [0, 0, 0, 0, 0, 0, 0, 0, 0, 0]],
    "ray-sphere-cast": [[-5, 0, 1, 1, 0, 0, 0, 0, 0, 1], [0, 0, 0, 0, 0, 1, 0, 0, 0, 1], [1, 1, 1, 0, 0, 0, 0, 0, 0, 1]],
    "segment-sphere": [[-1, 0, 0, 1, 0, 0, 0, 0, 0, 1], [0, 0, 0, 0, 0, 0, 0, 0, 0, 1], [-1, 2, 0, 1, 2, 0, 0, 0, 0, 2]],
    "box-box": [[0, 0, 0, 1, 1, 1, 2, 2, 0, 1, 1, 1], [0, 0, 0, 0, 0, 0, 1, 0, 0, 1, 1, 1]],
    "segment-box-cast": [[-2, -3, 0, 0, -1, 0, 0, 0, 0, 1, 2, 3], [-3, 0, 3, 3, 0, 3, 0, 0, 0, 1, 2, 3], [1, 0, 0, 2, 0, 0, 0, 0, 0, 1, 2, 3]],
    "ray-box-cast": [[-3, 2, 0, 1, 0, 0, 0, 0, 0, 1, 2, 3], [0, 0, 3, 0, 0, 1, 0, 0, 0, 1, 2, 3], [0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1]],
    "sphere-box": [[3, 5, 9, 7, 0, 0, 0, 1, 2, 3], [1, 0, 0, 1, 0, 0, 0, 1, 2, 3], [0, 0, 0, 1, 0, 0, 0, 0, 0, 0]],
}

def halves(q):
    """The degenerate (or uniform) family's first cases, rounded to multiples of 1/2 within int8."""
    fam = "degenerate" if "degenerate" in families(q) else "uniform"
    lines = run("cases", "--query", q, "--family", fam, "--n", "3", "--seed", "5").splitlines()[1:]
    return [[max(-128, min(127, round(2 * float.fromhex(c)))) for c in row.split(",")[3:]] for row in lines]

def halves_encoded(vals):
    return b"".join(bytes([1, v & 0xff]) for v in vals)

for q in queries:
    d = os.path.join(root, q)
    os.makedirs(d, exist_ok=True)
    # every family's cases in one call: each family's are those `--family F` alone gives, the
    # case column counting on across families (so a file is named by its place in its family)
    args = [a for fam in families(q) for a in ("--family", fam)]
    lines = run("cases", "--query", q, *args, "--n", "2", "--seed", "11").splitlines()
    seen = {}
    for row in lines[1:]:
        cells = row.split(",")
        fam = cells[1]
        k = seen.get(fam, 0)
        seen[fam] = k + 1
        data = b"".join(b"\xff" + struct.pack("<d", float.fromhex(c)) for c in cells[3:])
        with open(os.path.join(d, f"{fam}-{k}.bin"), "wb") as f:
            f.write(data)
    cases = [dyadic(v) for v in exact[q]] if q in exact else [halves_encoded(v) for v in halves(q)]
    for i, data in enumerate(cases):
        with open(os.path.join(d, f"exact-{i}.bin"), "wb") as f:
            f.write(data)
    # non-finite inputs, which must be refused
    with open(os.path.join(d, "nan.bin"), "wb") as f:
        f.write(b"\xff" + struct.pack("<d", float("nan")) + cases[0][2:])
    # the last input negative (a radius or an extent for the Section 3.1-3.2 queries), or
    # infinite, and an infinity in the middle: the filters that run before the input checks
    # must leave every one of them to the checks
    inputs = [cases[0][i:i + 2] for i in range(0, len(cases[0]), 2)]
    inf, ninf = b"\xff" + struct.pack("<d", float("inf")), b"\xff" + struct.pack("<d", float("-inf"))
    for name, at, enc in (("negative-last", -1, bytes([0, 0xff])), ("inf-last", -1, inf), ("inf-middle", len(inputs) // 2, ninf)):
        bad = list(inputs)
        bad[at] = enc
        with open(os.path.join(d, f"{name}.bin"), "wb") as f:
            f.write(b"".join(bad))

d = os.path.join(root, "casefile")
os.makedirs(d, exist_ok=True)
good = run("cases", "--query", "segment-sphere-cast", "--n", "3", "--seed", "2")
samples = {
    "good-hex": bytes([1]) + good.encode(),
    "good-decimal": bytes([1]) + run("cases", "--query", "segment-sphere-cast", "--n", "3", "--decimal").encode(),
    "short-line": bytes([1]) + (good + "7,uniform,0,1,2\n").encode(),
    "bad-number": bytes([1]) + (good + "8,uniform,0,x,1,2,3,4,5,6,7,8,9\n").encode(),
    "no-header": bytes([0]) + b"1,2,3\n",
    "empty": bytes([2]),
    # bytes 0xf0.. stand for tokens (fuzz/fuzzcheck.cpp): nan, -nan, inf, -inf, 1e400, -1e400,
    # 0x1p+2000, the smallest subnormal (decimal and hex), 1e-400, -0, an empty field, ...
    "nonfinite-tokens": bytes([1]) + good.encode() + b"".join(
        b"%d,uniform,0" % (10 + t) + (b"," + bytes([0xf0 + t])) + b",1" * 9 + b"\n" for t in range(16)),
    "nonfinite-literal": bytes([1]) + (good + "40,uniform,0,nan,1,2,3,inf,5,6,-inf,8,1e400\n"
                                       "41,uniform,0,0x1p+2000,1,2,3,4,5,6,7,8,4.9e-324\n").encode(),
}
for name, data in samples.items():
    with open(os.path.join(d, name + ".txt"), "wb") as f:
        f.write(data)
