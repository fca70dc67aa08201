#!/usr/bin/env python3
"""examples/validate.py - validate your own float function against cdref's exact answers.

Run from a build tree:  PYTHONPATH=build/release/python python3 examples/validate.py
(after `cmake --install`, the installed module is found without PYTHONPATH).

The function under test is Moller and Trumbore's ray-triangle cast in NumPy doubles, as a ray
tracer writes it. cdref.validate calls it on every case of the families asked for, with the
query's arguments by name (cdref.arguments("ray-triangle-cast")), and grades what it returns
against the exact answer, every value correctly rounded to double: the classification, and
each output group it returns (here lambda_enter, and u and v). The script exits non-zero when
the function fails the checks a test suite would hold it to.
"""
import sys

import numpy as np

import cdref


def moller_trumbore(source, direction, v0, v1, v2):
    """The first hit of the ray source + lambda direction (lambda >= 0) on the triangle."""
    e1, e2 = v1 - v0, v2 - v0
    p = np.cross(direction, e2)
    det = e1 @ p
    if det == 0.0:                   # the ray is parallel to the triangle's plane: a miss
        return {"hit": False}
    t = source - v0
    u = (t @ p) / det
    q = np.cross(t, e1)
    v = (direction @ q) / det
    lam = (e2 @ q) / det
    if u < 0.0 or v < 0.0 or u + v > 1.0 or lam < 0.0:
        return {"hit": False}
    return {"hit": True, "lambda_enter": lam, "u": u, "v": v}


def in_plane(args, exact):
    """cdref's convention differs from this function's on a ray in the triangle's plane (cdref:
    the closed triangle is met; this function: a miss): those cases are set apart, not graded."""
    n = np.cross(args["v1"] - args["v0"], args["v2"] - args["v0"])
    return exact.hit and n @ args["direction"] == 0.0


print(cdref.arguments("ray-triangle-cast"))        # ['source', 'direction', 'v0', 'v1', 'v2']

# Uniform cases: a double implementation should classify every one exactly.
uniform = cdref.validate(moller_trumbore, "ray-triangle-cast", families=["uniform"], n=2000,
                         convention=in_plane)
print(uniform.table())

# Near an edge (2^-k of the triangle's size from it): where double rounding decides.
near_edge = cdref.validate(moller_trumbore, "ray-triangle-cast", families=["near-edge"], n=200,
                           scales=[8, 24, 52], convention=in_plane)
print(near_edge.table())
for (family, scale), cell in near_edge.cells.items():
    print("%s 2^-%d: %d of %d misclassified" % (family, scale, cell.misclassified, cell.cases))

failures = []
if uniform.misclassified != 0:
    failures.append("%d uniform cases misclassified" % uniform.misclassified)
if uniform.max_ulps("lambda_enter") > 1 << 20:
    failures.append("lambda_enter %d ulps off on uniform cases" % uniform.max_ulps("lambda_enter"))
if near_edge.cells[("near-edge", 8)].misclassified != 0:
    failures.append("a shot 2^-8 from an edge misclassified")
if failures:
    sys.exit("FAIL: " + "; ".join(failures))
print("validate.py: all checks passed")
