"""examples/truth.py - the exact answer for one input, and for a million, from Python.

Run from a build tree:  PYTHONPATH=build/release/python python3 examples/truth.py
"""
import numpy as np

import cdref

# one case: every field correctly rounded to double
r = cdref.ray_sphere_cast(source=(0, 0, -5), direction=(0, 0, 1), center=(0.5, 0, 0), radius=1)
print(r)                       # ray_sphere_cast(hit=True, lambda_enter=4.1339745962155616, ...)
assert r.hit  # r.lambda_enter: the double nearest 5 - sqrt(3/4), rounded once

# many: arrays with a leading dimension; refused rows are flagged, the others answered
n = 100_000
rng = np.random.default_rng(1)
out = cdref.ray_sphere_cast(source=rng.uniform(-10, 10, (n, 3)), direction=rng.normal(size=(n, 3)),
                            center=(0, 0, 0), radius=rng.uniform(0, 3, n), threads=2)
print("hits:", int(out["hit"].sum()), "of", n, "- refused:", int((out["status"] != 0).sum()))

# your own float code graded against the truth on cdref's hard families
def my_cast(source, direction, center, radius):
    m = source - center
    a, b, c = direction @ direction, m @ direction, m @ m - radius * radius
    disc = b * b - a * c
    if disc < 0 or (b > 0 and c > 0):
        return {"hit": False}
    return {"hit": True, "lambda_enter": max((-b - np.sqrt(disc)) / a, 0.0)}

report = cdref.validate(my_cast, "ray-sphere-cast", families=["uniform", "near-tangent"], n=300)
print(report.table())
assert report.cases == 300 * (len(cdref.families("ray-sphere-cast")["uniform"]["scales"]) +
                              len(cdref.families("ray-sphere-cast")["near-tangent"]["scales"]))
