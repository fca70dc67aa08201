#!/usr/bin/env python3
"""A ray-sphere cast in plain Python (double precision), graded by cdref through case files.

    cdref cases --query ray-sphere-cast --family near-tangent --n 1000 --out cases.csv
    python3 examples/ray_sphere_cast.py cases.csv answers.csv
    cdref score --query ray-sphere-cast --cases cases.csv --answers answers.csv

The cast is the textbook quadratic: |s + t d - c|^2 = r^2, t = (-b - sqrt(b^2 - a k)) / a with
a = d.d, b = d.(s - c), k = |s - c|^2 - r^2. It follows cdref's convention for the ray (a
source inside the sphere hits at lambda 0; a sphere wholly behind the source is missed) and
answers the columns it computes: hit, lambda_enter, point. Case files carry every number as a
C99 hex float, which float.fromhex reads exactly; float.hex writes the answers exactly.
"""
import csv
import math
import sys


def cast(s, d, c, r):
    m = [s[i] - c[i] for i in range(3)]
    a = sum(x * x for x in d)
    b = sum(d[i] * m[i] for i in range(3))
    k = sum(x * x for x in m) - r * r
    if k <= 0:  # the source is inside (or on) the sphere
        return True, 0.0
    if b >= 0:  # outside and moving away
        return False, 0.0
    disc = b * b - a * k
    if disc < 0:
        return False, 0.0
    return True, (-b - math.sqrt(disc)) / a


def main():
    cases, answers = sys.argv[1], sys.argv[2]
    with open(cases, newline="") as f, open(answers, "w", newline="") as g:
        out = csv.writer(g)
        out.writerow(["case", "hit", "lambda_enter", "point_x", "point_y", "point_z"])
        for row in csv.DictReader(f):
            v = {k: float.fromhex(x) for k, x in row.items() if k not in ("case", "family", "scale")}
            s = [v["source_x"], v["source_y"], v["source_z"]]
            d = [v["direction_x"], v["direction_y"], v["direction_z"]]
            c = [v["center_x"], v["center_y"], v["center_z"]]
            hit, t = cast(s, d, c, v["radius"])
            p = [s[i] + t * d[i] for i in range(3)] if hit else [0.0, 0.0, 0.0]
            out.writerow([row["case"], int(hit), t.hex()] + [x.hex() for x in p])


if __name__ == "__main__":
    main()
