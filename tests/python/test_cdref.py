"""The Python module: exact answers for hand cases, agreement with `cdref oracle` on every query's
families, scalar and batched calls alike, bad rows refused one by one, cases/score/validate."""

import math
import os
import subprocess
import tempfile
from fractions import Fraction

import numpy as np
import pytest

import cdref

CDREF = os.environ.get("CDREF_EXE", "")


def correctly_rounded_sqrt_offset(x, offset, sign, square):
    """Whether the double x is the nearest double to offset + sign * sqrt(square), decided with
    exact fractions on the midpoints either side of x."""
    lo = (Fraction(x) + Fraction(math.nextafter(x, -math.inf))) / 2
    hi = (Fraction(x) + Fraction(math.nextafter(x, math.inf))) / 2
    a = lo - offset if sign > 0 else offset - hi
    b = hi - offset if sign > 0 else offset - lo
    return (a <= 0 or a * a <= square) and (b >= 0 and b * b >= square)


def test_every_query_is_a_function_with_help():
    listed = [line.split(":")[0] for line in subprocess.run([CDREF, "describe"], check=True, capture_output=True,
                                                             text=True).stdout.splitlines()
              if line and not line.startswith(" ")]
    assert cdref.queries() == listed and len(listed) >= 29
    for q in cdref.queries():
        f = getattr(cdref, q.replace("-", "_"))
        assert f.__doc__ and "Arguments" in f.__doc__, q
    doc = cdref.ray_triangle_cast.__doc__
    assert "two-sided" in doc and "units of |direction|" in doc
    assert cdref.arguments("ray-sphere-cast") == ["source", "direction", "center", "radius"]
    assert cdref.arguments("polygon-polygon") == ["a_vertices", "b_vertices"]
    assert cdref.arguments("point-triangle") == ["p", "v0", "v1", "v2"]
    assert cdref.arguments("polygon-obb") == ["vertices", "center", "extent", "axis0", "axis1", "axis2"]
    assert cdref.arguments("ray-fan-cast") == ["source", "direction", "closed", "ring", "center"] or \
        cdref.arguments("ray-fan-cast") == ["source", "direction", "closed", "center", "ring"]


def test_ray_sphere_cast_hand_case_correctly_rounded():
    r = cdref.ray_sphere_cast((0, 0, -5), (0, 0, 1), (0.5, 0, 0), 1)
    assert r.hit is True
    assert correctly_rounded_sqrt_offset(r.lambda_enter, 5, -1, Fraction(3, 4))
    assert correctly_rounded_sqrt_offset(r.lambda_exit, 5, 1, Fraction(3, 4))
    assert list(r.point[:2]) == [0, 0]
    assert r.normal[0] == -0.5
    # named arguments in any order
    s = cdref.ray_sphere_cast(radius=1, center=(0.5, 0, 0), direction=(0, 0, 1), source=(0, 0, -5))
    assert s.lambda_enter == r.lambda_enter
    # the exact path answers alike
    assert cdref.ray_sphere_cast((0, 0, -5), (0, 0, 1), (0.5, 0, 0), 1, path="exact").lambda_enter == r.lambda_enter
    # at float: the float nearest the exact value
    f = cdref.ray_sphere_cast((0, 0, -5), (0, 0, 1), (0.5, 0, 0), 1, dtype=np.float32)
    assert isinstance(f.lambda_enter, np.float32)
    x = float(f.lambda_enter)
    below = float(np.nextafter(np.float32(x), np.float32(-np.inf)))
    above = float(np.nextafter(np.float32(x), np.float32(np.inf)))
    exact = 5 - math.sqrt(0.75)
    assert abs(x - exact) <= min(abs(below - exact), abs(above - exact))


def test_other_queries_hand_cases():
    p = cdref.sphere_box(center=(3, 0, 0), radius=1, box_center=(0, 0, 0), box_extent=(1, 1, 1))
    assert p.intersect is False and p.distance == 1 and p.depth == 0
    assert list(p.witness_a) == [2, 0, 0] and list(p.witness_b) == [1, 0, 0]
    t = cdref.segment_triangle_cast((0.25, 0.5, 1), (0.25, 0.5, -1), (0, 0, 0), (1, 0, 0), (0, 1, 0))
    assert t.hit and t.lambda_enter == 0.5 and t.u == 0.25 and t.v == 0.5
    assert list(t.normal) == [0, 0, 1]
    sq = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
    c = cdref.ray_polygon_cast((0.5, 0.5, 2), (0, 0, -1), sq)
    assert c.hit and c.lambda_enter == 2
    assert cdref.box_box((0, 0, 0), (1, 1, 1), (2, 0, 0), (1, 1, 1)).intersect  # touching: closed
    assert not cdref.box_box((0, 0, 0), (1, 1, 1), (math.nextafter(2, 3), 0, 0), (1, 1, 1)).intersect
    tb = cdref.triangle_box((-1, -1, 2), (1, -1, 2), (0, 1, 3), (0, 0, 0), (1, 1, 1))
    assert tb.intersect is False and tb.axis == 0
    tt = cdref.triangle_triangle((-1, -1, 0), (3, -1, 0), (-1, 3, 0), (0, 0, -1), (0, 0, 1), (1, 0, 0))
    assert tt.intersect and tt.coplanar == 0 and list(tt.p) == [0, 0, 0] and list(tt.q) == [1, 0, 0]
    pt = cdref.point_triangle(p=(0.25, 0.25, 1), v0=(0, 0, 0), v1=(1, 0, 0), v2=(0, 1, 0))
    assert pt.intersect is False and pt.distance == 1 and pt.depth == 0
    assert list(pt.witness_a) == [0.25, 0.25, 1] and list(pt.witness_b) == [0.25, 0.25, 0]
    assert cdref.point_triangle((0.5, 0, 0), (0, 0, 0), (1, 0, 0), (0, 1, 0)).intersect  # on an edge: closed
    assert not cdref.point_triangle((0.5, math.nextafter(0, -1), 0), (0, 0, 0), (1, 0, 0), (0, 1, 0)).intersect
    # a unit square at z = 1 against a box of half-extent 1 turned 45 degrees about z: touching its top face
    r = math.sqrt(0.5)
    sq1 = [(0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
    assert cdref.polygon_obb(sq1, (0, 0, 0), (1, 1, 1), (r, r, 0), (-r, r, 0), (0, 0, 1)).intersect
    sq2 = [(0, 0, 1.5), (1, 0, 1.5), (1, 1, 1.5), (0, 1, 1.5)]
    assert not cdref.polygon_obb(sq2, (0, 0, 0), (1, 1, 1), (r, r, 0), (-r, r, 0), (0, 0, 1)).intersect


def test_bad_input_is_named():
    with pytest.raises(cdref.InvalidInput, match="radius is negative"):
        cdref.ray_sphere_cast((0, 0, -5), (0, 0, 1), (0, 0, 0), -1)
    with pytest.raises(ValueError, match="direction is the zero vector"):
        cdref.ray_sphere_cast((0, 0, -5), (0, 0, 0), (0, 0, 0), 1)
    with pytest.raises(cdref.InvalidInput, match="not finite"):
        cdref.ray_sphere_cast((0, float("nan"), -5), (0, 0, 1), (0, 0, 0), 1)
    with pytest.raises(cdref.InvalidInput, match="beyond the range of float"):
        cdref.ray_sphere_cast((0, 0, -5), (0, 0, 1), (0, 0, 0), 1e300, dtype=np.float32)
    with pytest.raises(TypeError, match="missing argument"):
        cdref.ray_sphere_cast((0, 0, -5), (0, 0, 1), (0, 0, 0))
    with pytest.raises(TypeError, match="unexpected argument"):
        cdref.ray_sphere_cast((0, 0, -5), (0, 0, 1), (0, 0, 0), 1, radiuss=2)
    with pytest.raises(ValueError, match="3-vector"):
        cdref.ray_sphere_cast((0, 0), (0, 0, 1), (0, 0, 0), 1)
    with pytest.raises(ValueError, match="up to 8 points"):
        cdref.ray_polygon_cast((0, 0, 1), (0, 0, -1), [(0, 0, 0)] * 9)
    with pytest.raises(ValueError, match="3 to 8"):
        cdref.ray_polygon_cast((0, 0, 1), (0, 0, -1), [(0, 0, 0), (1, 0, 0)])
    with pytest.raises(ValueError, match="unknown query"):
        cdref.cases("ray-sphere", "uniform", 0, 3)
    with pytest.raises(ValueError, match="has no family"):
        cdref.cases("ray-sphere-cast", "nope", 0, 3)
    with pytest.raises(ValueError, match="has no scale"):
        cdref.cases("ray-sphere-cast", "uniform", 12345, 3)
    with pytest.raises(ValueError, match="n must be"):
        cdref.cases("ray-sphere-cast", "uniform", 0, -1)


def test_bad_options_are_named():
    one = ((0, 0, -5), (0, 0, 1), (0, 0, 0), 1)
    with pytest.raises(ValueError, match="threads must be 1 to 1024"):
        cdref.ray_sphere_cast(*one, threads=0)
    with pytest.raises(ValueError, match="dtype must be float64 or float32"):
        cdref.ray_sphere_cast(*one, dtype=np.int32)
    with pytest.raises(ValueError, match="path must be 'oracle' or 'exact'"):
        cdref.ray_sphere_cast(*one, path="fast")
    with pytest.raises(TypeError, match="argument radius is not a number"):
        cdref.ray_sphere_cast((0, 0, -5), (0, 0, 1), (0, 0, 0), "one")
    with pytest.raises(TypeError, match="takes 4 arguments"):
        cdref.ray_sphere_cast(*one, 5)
    with pytest.raises(ValueError, match="rows where another has"):
        cdref.ray_sphere_cast(np.zeros((3, 3)), np.ones((4, 3)), (0, 0, 0), 1)
    with pytest.raises(ValueError, match="at most 2\\^28"):
        cdref.cases("ray-sphere-cast", "uniform", 0, 2 ** 29)
    with pytest.raises(ValueError, match="seed must be"):
        cdref.cases("ray-sphere-cast", "uniform", 0, 3, seed=-1)
    # numpy integers are whole numbers too
    assert cdref.cases("ray-sphere-cast", "uniform", np.int64(0), np.int64(3))["radius"].shape == (3,)
    # an infinity or an overflowing value in a batch: that row refused by name, the others answered
    out = cdref.sphere_sphere(np.array([[0, 0, 0], [np.inf, 0, 0]]), 1, (3, 0, 0), 1)
    assert list(out["status"]) == [0, 1] and "not finite" in out["errors"][1] and out["distance"][0] == 1


def test_batched_rows_refused_one_by_one():
    src = np.array([[0, 0, -5], [0, 0, -5], [0, np.nan, -5], [0, 0, -5]], dtype=float)
    d = np.array([[0, 0, 1], [0, 0, 0], [0, 0, 1], [0, 0, 1]], dtype=float)
    out = cdref.ray_sphere_cast(src, d, (0.5, 0, 0), np.array([1, 1, 1, -1.0]))
    assert list(out["status"]) == [0, 1, 1, 1]
    assert "zero vector" in out["errors"][1]
    assert "not finite" in out["errors"][2]
    assert "negative" in out["errors"][3]
    assert out["hit"][0] and out["lambda_enter"][0] == cdref.ray_sphere_cast(src[0], d[0], (0.5, 0, 0), 1).lambda_enter
    assert out["point"].shape == (4, 3)


def test_batched_equals_scalar_on_every_query():
    for q in cdref.queries():
        fam = next(iter(cdref.families(q)))
        scale = cdref.families(q)[fam]["scales"][0]
        args = cdref.cases(q, fam, scale, 12, seed=3)
        f = getattr(cdref, q.replace("-", "_"))
        batch = f(**args, threads=2)
        for i in range(12):
            one = {k: (v[i][~np.isnan(v[i]).all(axis=1)] if v.ndim == 3 else v[i]) for k, v in args.items()}
            if batch["status"][i]:
                with pytest.raises(cdref.InvalidInput):
                    f(**one)
                continue
            r = f(**one)._asdict()
            for k, v in r.items():
                assert np.array_equal(np.asarray(v), np.asarray(batch[k][i])), (q, i, k)


def test_threads_do_not_change_answers():
    args = cdref.cases("sphere-triangle", "uniform", cdref.families("sphere-triangle")["uniform"]["scales"][0], 3000)
    a = cdref.sphere_triangle(**args, threads=1)
    b = cdref.sphere_triangle(**args, threads=4)
    for k in a:
        if k != "errors":
            assert np.array_equal(a[k], b[k]), k


@pytest.mark.skipif(not CDREF, reason="CDREF_EXE not set")
def test_agrees_with_cdref_oracle_on_every_family():
    with tempfile.TemporaryDirectory() as d:
        for q in cdref.queries():
            for fam, info in cdref.families(q).items():
                scale = info["scales"][-1]
                path = os.path.join(d, "c.csv")
                subprocess.run([CDREF, "cases", "--query", q, "--family", fam, "--scale", str(scale), "--n", "20",
                                "--seed", "5", "--out", path], check=True, capture_output=True)
                res = subprocess.run([CDREF, "oracle", "--query", q, "--cases", path], check=True,
                                     capture_output=True, text=True).stdout
                lines = [l for l in res.splitlines() if l and not l.startswith("#")]
                header = lines[0].split(",")
                rows = cdref.cases(q, fam, scale, 20, seed=5, columns=True)
                ours = cdref.answer(q, rows)
                for line in lines[1:]:
                    cells = dict(zip(header, line.split(",")))
                    i = int(cells["case"])
                    if ours["status"][i]:
                        continue
                    for col, text in cells.items():
                        if col in ("case", "predicate", "family", "scale"):
                            continue
                        base, comp = (col[:-2], "xyz".index(col[-1])) if col[-2:] in ("_x", "_y", "_z") and col[:-2] in ours else (col, None)
                        v = ours[base][i] if comp is None else ours[base][i][comp]
                        want = float.fromhex(text) if "0x" in text or "p" in text else float(text)
                        assert float(v) == want, (q, fam, i, col, float(v), want)


def test_cases_round_trip_with_cdref_cases():
    if not CDREF:
        pytest.skip("CDREF_EXE not set")
    out = subprocess.run([CDREF, "cases", "--query", "ray-triangle-cast", "--family", "uniform", "--scale",
                          str(cdref.families("ray-triangle-cast")["uniform"]["scales"][0]), "--n", "5", "--seed", "9"],
                         check=True, capture_output=True, text=True).stdout
    lines = [l for l in out.splitlines() if l and not l.startswith("#")]
    header = lines[0].split(",")
    rows = cdref.cases("ray-triangle-cast", "uniform", cdref.families("ray-triangle-cast")["uniform"]["scales"][0], 5,
                       seed=9, columns=True)
    for k, line in enumerate(lines[1:]):
        cells = dict(zip(header, line.split(",")))
        for j, c in enumerate(header[1:]):
            if c in ("family", "scale"):
                continue
            assert float.fromhex(cells[c]) == rows[k][[h for h in header if h not in ("case", "family", "scale")].index(c)]


def test_score_counts_what_is_wrong():
    q = "ray-sphere-cast"
    args = cdref.cases(q, "uniform", cdref.families(q)["uniform"]["scales"][0], 500, seed=2)
    exact = cdref.ray_sphere_cast(**args)
    perfect = cdref.score(q, args, {"hit": exact["hit"], "lambda_enter": exact["lambda_enter"]})
    assert perfect.misclassified == 0 and perfect.max_ulps("lambda_enter") == 0 and perfect.graded == 500
    wrong = dict(hit=exact["hit"].copy(), lambda_enter=exact["lambda_enter"].copy())
    hits = np.flatnonzero(exact["hit"])
    wrong["hit"][np.flatnonzero(~exact["hit"])[:3]] = True       # 3 false positives
    wrong["lambda_enter"][hits[0]] = np.nextafter(wrong["lambda_enter"][hits[0]], np.inf)
    rep = cdref.score(q, args, wrong)
    assert rep.false_positives == 3 and rep.false_negatives == 0
    assert rep.max_ulps("lambda_enter") == 1
    assert rep.fields["lambda_enter"].max_abs > 0 and rep.fields["lambda_enter"].max_rel > 0
    assert any(e["what"] == "classification" and "source" in e["inputs"] for e in rep.examples)
    with pytest.raises(ValueError, match="unknown answer column"):
        cdref.score(q, args, {"hits": exact["hit"]})


def test_validate_finds_a_float_implementations_drift():
    def naive_cast(source, direction, center, radius):
        # the textbook quadratic at the caller's precision
        s = source - center
        a = direction @ direction
        b = s @ direction
        c = s @ s - radius * radius
        disc = b * b - a * c
        if disc < 0:
            return {"hit": False}
        t0 = (-b - math.sqrt(disc)) / a
        t1 = (-b + math.sqrt(disc)) / a
        if t1 < 0:
            return {"hit": False}
        return {"hit": True, "lambda_enter": max(t0, 0.0)}

    rep = cdref.validate(naive_cast, "ray-sphere-cast", families=["uniform", "long-range"], n=150)
    assert rep.cases == 150 * sum(len(cdref.families("ray-sphere-cast")[f]["scales"]) for f in ["uniform", "long-range"])
    assert rep.max_ulps("lambda_enter") > 0  # far from the sphere, the quadratic cancels
    assert ("uniform", cdref.families("ray-sphere-cast")["uniform"]["scales"][0]) in rep.cells
    assert "lambda_enter" in rep.table()

    # the exact answer itself passes with nothing wrong
    def exact(**kw):
        r = cdref.ray_sphere_cast(**kw)
        return {"hit": r.hit, "lambda_enter": r.lambda_enter}

    ok = cdref.validate(exact, "ray-sphere-cast", families=["uniform"], n=100)
    assert ok.misclassified == 0 and ok.max_ulps("lambda_enter") == 0

    # batched, and a convention that sets apart the casts from inside
    def batched(source, direction, center, radius):
        return {"hit": cdref.ray_sphere_cast(source, direction, center, radius)["hit"]}

    b = cdref.validate(batched, "ray-sphere-cast", families=["uniform"], n=100, batched=True,
                       convention=lambda args, exact: exact.hit and exact.lambda_enter == 0)
    assert b.misclassified == 0 and b.set_apart + b.graded + b.refused == b.cases
