"""bench/bench_python.py - the Python module's cost against the C++ loop, in one run.

For each query: the C++ loop is cdref_bench's "oracle, every output rounded" row on the uniform
family (ns a case, one thread, fresh sets of cases); the Python module answers N uniform cases
in one batched call (threads=1, the same oracle, plus the arrays in and out) and then a scalar
call at a time. Printed: ns a case each way and the ratio batched / C++ (the issue's target:
at most 2, i.e. at least half the C++ loop's throughput).

  PYTHONPATH=build/release/python python3 bench/bench_python.py build/release/cdref_bench [N]
"""
import re
import subprocess
import sys
import time

import cdref

QUERIES = ["ray-sphere-cast", "sphere-box", "ray-box-cast", "triangle-box", "ray-triangle-cast", "sphere-triangle",
           "obb-obb", "polygon-sphere"]


def cxx_ns(bench, query):
    out = subprocess.run([bench, "--benchmark_filter=^%s/uniform-0/oracle-every-output-rounded/" % query],
                         capture_output=True, text=True, check=True).stdout
    for line in out.splitlines():
        line = re.sub(r"\x1b\[[0-9;]*m", "", line)
        m = re.match(r"\S+\s+([\d.]+) ns\s+[\d.]+ ns\s+\d+\s+([\d.]+)k", line)
        if m:
            return float(m.group(1)) / (float(m.group(2)) * 1000)
    raise RuntimeError("no row for " + query)


def main():
    bench = sys.argv[1]
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 100_000
    print("%-20s %12s %14s %8s %14s" % ("query", "C++ ns/case", "batched ns", "ratio", "scalar us/call"))
    for q in QUERIES:
        scale = cdref.families(q)["uniform"]["scales"][0]
        args = cdref.cases(q, "uniform", scale, n, seed=11)
        f = getattr(cdref, q.replace("-", "_"))
        f(**{k: v[:1000] for k, v in args.items()})  # warm
        t0 = time.perf_counter()
        f(**args, threads=1)
        batched = (time.perf_counter() - t0) / n * 1e9
        m = 2000
        ones = [{k: (v[i][~(v[i] != v[i]).all(axis=1)] if v.ndim == 3 else v[i]) for k, v in args.items()} for i in range(m)]
        t0 = time.perf_counter()
        for one in ones:
            try:
                f(**one)
            except cdref.InvalidInput:
                pass
        scalar = (time.perf_counter() - t0) / m * 1e6
        c = cxx_ns(bench, q)
        print("%-20s %12.1f %14.1f %8.2f %14.1f" % (q, c, batched, batched / c, scalar))


if __name__ == "__main__":
    main()
