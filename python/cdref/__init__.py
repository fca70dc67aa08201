"""cdref: the exact answer for the primitive queries of Chapter 3 of van den Bergen's
*Collision Detection in Interactive 3D Environments*, with every value correctly rounded.

Every query is a function named after it (``ray-sphere-cast`` is ``cdref.ray_sphere_cast``),
its arguments in the order of the query's case-file columns, each group of ``_x _y _z`` columns
one 3-vector argument::

    >>> import cdref
    >>> r = cdref.ray_sphere_cast(source=(0, 0, -5), direction=(0, 0, 1), center=(0.5, 0, 0), radius=1)
    >>> r.hit, r.lambda_enter        # lambda_enter: the double nearest 5 - sqrt(0.75)
    (True, 4.133974596215562)

Give arrays with a leading dimension N instead and the call answers N cases at once, in C++,
without the GIL, on ``threads`` threads; it returns a dict of arrays, one per answer column,
with ``status`` (0 answered, 1 refused) and ``errors`` (row -> message) so that one bad row
never loses the others.

``cdref.cases`` generates a campaign's cases as such arrays, ``cdref.score`` grades answers
against the exact ones, and ``cdref.validate`` runs your own function over a query's families
and reports where it goes wrong (in ulps, absolutely and relative to the inputs' scale).
"""

import inspect as _inspect
import numbers as _numbers

import numpy as _np

from . import _cdref

__version__ = _cdref.__version__
#: Raised for input outside a query's domain (a NaN, a negative radius, a zero direction, ...).
InvalidInput = _cdref.InvalidInput

_QUERIES = {q["name"]: q for q in _cdref.queries()}

_CONVENTIONS = {
    "cast": "A cast is on closed solids; lambda is in units of |direction| for a ray (lambda >= 0) "
    "and of target - source for a segment (0 <= lambda <= 1). A source inside gives lambda_enter = 0, "
    "point = source and normal = 0. Values exist on a hit; on a miss they are 0.",
    "proximity": "Solids are closed; distance and depth are >= 0 and at most one is nonzero; witness_a "
    "lies on the first argument of the query's book function, witness_b on the second.",
    "separation": "Solids are closed (touching intersects); axis is the index of the first separating "
    "axis in the query's documented order when apart, -1 when they intersect.",
    "triangles": "Triangles are closed and two-sided; a zero-area triangle is the segment or point it spans.",
}


def queries():
    """The names of every query, in cdref's order."""
    return list(_QUERIES)


def _arguments(columns):
    """The query's arguments from its columns: (name, kind, column indices), kind one of
    'vector', 'scalar', 'vertices' (a polygon: its n column and up to 8 vertices) and 'ring'
    (a fan's ring: its n column and up to 8 ring vertices)."""
    index = {c: k for k, c in enumerate(columns)}
    args, used = [], set()
    for k, c in enumerate(columns):
        if k in used:
            continue
        prefix = c[:-1] if c.endswith("n") and (c == "n" or c.endswith("_n")) else None
        if prefix is not None and (prefix + "p0_x") in index:
            cols = [k] + [index["%sp%d_%s" % (prefix, v, a)] for v in range(8) for a in "xyz"]
            args.append((prefix + "vertices", "vertices", cols))
            used.update(cols)
        elif prefix is not None and (prefix + "r0_x") in index:
            cols = [k] + [index["%sr%d_%s" % (prefix, v, a)] for v in range(8) for a in "xyz"]
            args.append((prefix + "ring", "ring", cols))
            used.update(cols)
        elif c.endswith("_x") and columns[k + 1 : k + 3] == [c[:-2] + "_y", c[:-2] + "_z"]:
            args.append((c[:-2], "vector", [k, k + 1, k + 2]))
            used.update((k, k + 1, k + 2))
        else:
            args.append((c, "scalar", [k]))
            used.add(k)
    # a fan's n column comes first in its columns; its ring is the argument after its centre
    for i, (name, kind, cols) in enumerate(args):
        if kind == "ring":
            centre = [j for j, a in enumerate(args) if a[0] == name[:-4] + "center"]
            if centre:
                args.insert(centre[0], args.pop(i))
            break
    return args


_ARGS = {name: _arguments(q["inputs"]) for name, q in _QUERIES.items()}


def _rows(query, kwargs):
    """The (N, columns) float64 matrix of a call's arguments, and whether it was one case."""
    q = _QUERIES[query]
    args = _ARGS[query]
    if len(kwargs) != len(args) or any(a not in kwargs for a, _, _ in args):
        _name_arguments(query, args, kwargs)
    values, batch = {}, None
    for name, kind, _ in args:
        try:
            v = _np.asarray(kwargs[name], dtype=_np.float64)
        except (TypeError, ValueError) as e:
            raise TypeError("%s: argument %s is not a number array (%s)" % (query, name, e)) from None
        base = {"scalar": 0, "vector": 1, "vertices": 2, "ring": 2}[kind]
        if kind == "vector" and (v.ndim < 1 or v.shape[-1] != 3):
            raise ValueError("%s: argument %s must be a 3-vector or an (N, 3) array, not shape %s"
                             % (query, name, v.shape))
        if kind in ("vertices", "ring") and (v.ndim < 2 or v.shape[-1] != 3 or not 1 <= v.shape[-2] <= 8):
            raise ValueError("%s: argument %s must be a list of up to 8 points (k, 3), or an (N, k, 3) array, "
                             "not shape %s" % (query, name, v.shape))
        if v.ndim > base + 1:
            raise ValueError("%s: argument %s has shape %s: one case or a batch (N, ...) only" % (query, name, v.shape))
        if v.ndim == base + 1:
            if batch is not None and v.shape[0] != batch:
                raise ValueError("%s: argument %s has %d rows where another has %d" % (query, name, v.shape[0], batch))
            batch = v.shape[0]
        values[name] = v
    single = batch is None
    n = 1 if single else batch
    out = _np.zeros((n, len(q["inputs"])), dtype=_np.float64)
    for name, kind, cols in args:
        v = values[name]
        if kind == "scalar":
            out[:, cols[0]] = v
        elif kind == "vector":
            out[:, cols] = v if single else _np.broadcast_to(v, (n, 3))
        else:
            pts = v[None] if single else _np.broadcast_to(v, (n,) + v.shape[-2:])
            k = pts.shape[1]
            # a row's points end at its first NaN point (arrays of several sizes padded with NaN)
            finite_rows = ~_np.isnan(pts).all(axis=2)
            count = _np.where(finite_rows.all(axis=1), k, _np.argmin(finite_rows, axis=1))
            out[:, cols[0]] = count
            flat = _np.where(_np.arange(k)[None, :, None] < count[:, None, None], pts, 0.0).reshape(n, 3 * k)
            out[:, cols[1 : 1 + 3 * k]] = flat
    return out, single


def _name_arguments(query, args, kwargs):
    """Raises the TypeError that names the missing or unexpected arguments of a call."""
    missing = [a for a, _, _ in args if a not in kwargs]
    if missing:
        raise TypeError("%s() missing argument(s): %s" % (_fname(query), ", ".join(missing)))
    extra = [a for a in kwargs if a not in {n for n, _, _ in args}]
    raise TypeError("%s() got unexpected argument(s): %s (its arguments: %s)"
                    % (_fname(query), ", ".join(extra), ", ".join(n for n, _, _ in args)))


def _fname(query):
    return query.replace("-", "_")


class Result:
    """One case's exact answer: its classification (``hit`` or ``intersect``) and every output
    group of the query as an attribute (3-vectors as numpy arrays of shape (3,))."""

    def __init__(self, query, fields):
        self._query = query
        self._fields = list(fields)
        for k, v in fields.items():
            setattr(self, k, v)

    def _asdict(self):
        """The fields as a dict, in the answer columns' order."""
        return {k: getattr(self, k) for k in self._fields}

    def __repr__(self):
        parts = []
        for k in self._fields:
            v = getattr(self, k)
            parts.append("%s=%s" % (k, list(map(float, v)) if isinstance(v, _np.ndarray) else repr(v)))
        return "%s(%s)" % (_fname(self._query), ", ".join(parts))


def answer(query, inputs, precision=53, threads=1, path="oracle"):
    """Exact answers for a query on an (N, columns) array of its case-file input columns: a dict
    of arrays (the classification, each output group, ``status``, ``errors``). The functions
    named after the queries call this."""
    if query not in _QUERIES:
        raise ValueError("unknown query %r (queries: %s)" % (query, ", ".join(_QUERIES)))
    if path not in ("oracle", "exact"):
        raise ValueError("path must be 'oracle' or 'exact', not %r" % (path,))
    return _cdref.answer(query, inputs, precision, threads, path == "exact")


def _precision(dtype):
    d = _np.dtype(dtype)
    if d == _np.float64:
        return 53
    if d == _np.float32:
        return 24
    raise ValueError("dtype must be float64 or float32, not %s" % d)


def _make_function(query):
    q = _QUERIES[query]
    args = _ARGS[query]
    names = [n for n, _, _ in args]

    def f(*positional, dtype=_np.float64, threads=1, path="oracle", **named):
        if len(positional) > len(names):
            raise TypeError("%s() takes %d arguments (%s), %d given" % (_fname(query), len(names), ", ".join(names), len(positional)))
        for n, v in zip(names, positional):
            if n in named:
                raise TypeError("%s() got argument %s twice" % (_fname(query), n))
            named[n] = v
        rows, single = _rows(query, named)
        out = answer(query, rows, _precision(dtype), threads, path)
        if not single:
            return out
        if out["status"][0]:
            raise InvalidInput("%s: %s" % (query, out["errors"][0]))
        fields = {}
        for k, v in out.items():
            if k in ("status", "errors"):
                continue
            x = v[0]
            if isinstance(x, _np.ndarray):
                fields[k] = x.copy()
            elif isinstance(x, _np.bool_):
                fields[k] = bool(x)
            elif isinstance(x, _np.integer):
                fields[k] = int(x)
            else:
                fields[k] = float(x) if dtype == _np.float64 else _np.float32(x)
        return Result(query, fields)

    kind = ("cast" if query.endswith("-cast") else
            "proximity" if any(o["name"] == "distance" for o in q["outputs"]) else
            "separation" if any(o["name"] == "axis" for o in q["outputs"]) else None)
    arglines = []
    for n, k, cols in args:
        what = {"vector": "3-vector", "scalar": "number", "vertices": "3 to 8 points (a polygon, fan around the first)",
                "ring": "2 to 8 points (the fan's ring)"}[k]
        arglines.append("    %-18s %s (columns: %s)" % (n, what, ", ".join(q["inputs"][c] for c in cols[:4]) +
                                                        (", ..." if len(cols) > 4 else "")))
    f.__name__ = _fname(query)
    f.__qualname__ = f.__name__
    P = _inspect.Parameter
    f.__signature__ = _inspect.Signature(
        [P(n, P.POSITIONAL_OR_KEYWORD) for n in names] +
        [P("dtype", P.KEYWORD_ONLY, default=_np.float64), P("threads", P.KEYWORD_ONLY, default=1),
         P("path", P.KEYWORD_ONLY, default="oracle")])
    f.__doc__ = "\n".join([
        q["describe"], "",
        "%s(%s, *, dtype=numpy.float64, threads=1, path='oracle')" % (_fname(query), ", ".join(names)), "",
        "Arguments (one case; or arrays with a leading dimension N for N cases):",
        *arglines, "",
        "Returns a Result with %s and these answer columns (correctly rounded to dtype):" % q["classification"],
        q["answer_help"].rstrip(),
        "",
        *([_CONVENTIONS[kind]] if kind else []),
        *([_CONVENTIONS["triangles"]] if ("triangle" in query or "fan" in query or "polygon" in query) else []),
        "For arrays: a dict of numpy arrays, one per answer column, with 'status' (0 answered, 1 refused)",
        "and 'errors' (row -> message). dtype=numpy.float32 answers at float's rounding of the inputs.",
        "path='exact' evaluates the book at exact rationals on every case (slower, the same answer).",
        "Raises cdref.InvalidInput (a ValueError) naming what is wrong for one case outside the domain.",
    ])
    return f


for _q in _QUERIES:
    globals()[_fname(_q)] = _make_function(_q)
del _q


def arguments(query):
    """The argument names of a query's function, in order."""
    return [n for n, _, _ in _arguments(_QUERIES[_check_query(query)]["inputs"])]


def families(query):
    """A query's case families: {name: {'describe': ..., 'scales': [...]}}."""
    return {f["name"]: {"describe": f["describe"], "scales": list(f["scales"])}
            for f in _QUERIES[_check_query(query)]["families"]}


def _check_query(query):
    if query not in _QUERIES:
        raise ValueError("unknown query %r (queries: %s)" % (query, ", ".join(_QUERIES)))
    return query


def _split(query, rows):
    """A (N, columns) matrix as the query function's arguments (arrays with a leading N)."""
    out = {}
    for name, kind, cols in _arguments(_QUERIES[query]["inputs"]):
        if kind == "scalar":
            out[name] = rows[:, cols[0]].copy()
        elif kind == "vector":
            out[name] = rows[:, cols].copy()
        else:
            count = rows[:, cols[0]].astype(int)
            pts = rows[:, cols[1:]].reshape(len(rows), 8, 3).copy()
            pts[_np.arange(8)[None, :] >= count[:, None]] = _np.nan
            out[name] = pts
    return out


def cases(query, family, scale, n, seed=1, first=0, columns=False):
    """Cases first .. first + n - 1 of one (query, family, scale) cell under `seed`: the same
    cases `cdref cases` writes. Returns the query function's arguments as arrays with a leading
    dimension n (so ``cdref.ray_sphere_cast(**cdref.cases(...))`` answers them; polygons and fans
    padded with NaN points), or with columns=True the (n, columns) matrix of the case-file
    columns."""
    _check_query(query)
    if not isinstance(n, _numbers.Integral) or isinstance(n, bool) or n < 0:
        raise ValueError("n must be a whole number >= 0, not %r" % (n,))
    if not isinstance(first, _numbers.Integral) or isinstance(first, bool) or first < 0 or first >= 2 ** 64:
        raise ValueError("first must be a whole number from 0 to 2^64 - 1, not %r" % (first,))
    if not isinstance(scale, _numbers.Integral) or isinstance(scale, bool):
        raise ValueError("scale must be a whole number, not %r" % (scale,))
    if not isinstance(seed, _numbers.Integral) or isinstance(seed, bool) or seed < 0 or seed >= 2 ** 64:
        raise ValueError("seed must be a whole number from 0 to 2^64 - 1, not %r" % (seed,))
    fams = families(query)
    if family not in fams:
        raise ValueError("%s has no family %r (its families: %s)" % (query, family, ", ".join(fams)))
    rows = _cdref.cases(query, family, int(scale), int(n), int(seed), int(first))
    return rows if columns else _split(query, rows)


# ---- grading ----
def _ulps(a, b, precision):
    """Representable values between a and b (arrays), in float (24) or double (53)."""
    if precision == 24:
        a = _np.asarray(a, dtype=_np.float32).astype(_np.float32)
        b = _np.asarray(b, dtype=_np.float32).astype(_np.float32)
        ia, ib = a.view(_np.int32).astype(_np.int64), b.view(_np.int32).astype(_np.int64)
        lo = -(2 ** 31)
    else:
        a = _np.asarray(a, dtype=_np.float64)
        b = _np.asarray(b, dtype=_np.float64)
        ia, ib = a.view(_np.int64), b.view(_np.int64)
        lo = _np.iinfo(_np.int64).min
    with _np.errstate(over="ignore"):
        la = _np.where(ia < 0, lo - ia, ia).astype(_np.int64)
        lb = _np.where(ib < 0, lo - ib, ib).astype(_np.int64)
        d = _np.where(la >= lb, la.view(_np.uint64) - lb.view(_np.uint64), lb.view(_np.uint64) - la.view(_np.uint64))
    d = _np.where(a == b, _np.uint64(0), d)
    bad = ~(_np.isfinite(a) & _np.isfinite(b)) & (a != b)
    return _np.where(bad, _np.uint64(2 ** 64 - 1), d)


class Report:
    """How an implementation's answers compare with the exact ones.

    cases, refused, set_apart, graded: counts; false_positives, false_negatives, misclassified:
    of the classification; fields: {column group: FieldReport}; examples: the worst case of each
    kind with its inputs by argument name, the given answer and the exact one."""

    def __init__(self, query, precision):
        self.query = query
        self.precision = precision
        self.cases = self.refused = self.set_apart = self.graded = 0
        self.false_positives = self.false_negatives = 0
        self.fields = {}
        self.examples = []

    @property
    def misclassified(self):
        """False positives plus false negatives."""
        return self.false_positives + self.false_negatives

    def max_ulps(self, field):
        """The largest error of an output group, in ulps of the precision."""
        return self.fields[field].max_ulps if field in self.fields else 0

    def table(self):
        """The report as text."""
        t = ["cdref: %s, %d cases, %d graded, %d refused, %d set apart by convention; errors against the correctly "
             "rounded exact answer (%s)" % (self.query, self.cases, self.graded, self.refused, self.set_apart,
                                            "float" if self.precision == 24 else "double"),
             "classification: %d false positives, %d false negatives" % (self.false_positives, self.false_negatives),
             "%-14s %8s %8s %12s %12s %12s" % ("field", "graded", "wrong", "max ulps", "max abs", "max rel")]
        for name, f in self.fields.items():
            t.append("%-14s %8d %8s %12d %12.3g %12.3g" % (name, f.graded, f.wrong if f.label else "-", f.max_ulps,
                                                          f.max_abs, f.max_rel))
        for e in self.examples:
            t.append("worst %s%s: row %d%s, given %s, exact %s%s, inputs %s" % (
                e["what"], "" if "cell" not in e else " (" + e["cell"] + ")", e["row"], "", e["given"], e["exact"],
                "" if "ulps" not in e else " (%d ulps)" % e["ulps"], e["inputs"]))
        return "\n".join(t)

    def __repr__(self):
        return self.table()

    def _merge(self, other):
        self.cases += other.cases
        self.refused += other.refused
        self.set_apart += other.set_apart
        self.graded += other.graded
        self.false_positives += other.false_positives
        self.false_negatives += other.false_negatives
        for k, f in other.fields.items():
            if k not in self.fields:
                self.fields[k] = f
            else:
                self.fields[k]._merge(f)
        # the worst example of each kind across cells (the classification's: the first)
        for e in other.examples:
            same = [i for i, x in enumerate(self.examples) if x["what"] == e["what"]]
            if not same:
                self.examples.append(e)
            elif e.get("ulps", 0) > self.examples[same[0]].get("ulps", 0):
                self.examples[same[0]] = e


class FieldReport:
    """One output group's errors: graded values, the largest in ulps, absolute and relative to
    the inputs' scale (for a label, wrong counts the cases where it differs)."""

    def __init__(self, label):
        self.label = label
        self.graded = self.wrong = self.max_ulps = 0
        self.max_abs = self.max_rel = 0.0

    def _merge(self, o):
        self.graded += o.graded
        self.wrong += o.wrong
        self.max_ulps = max(self.max_ulps, o.max_ulps)
        self.max_abs = max(self.max_abs, o.max_abs)
        self.max_rel = max(self.max_rel, o.max_rel)

    def __repr__(self):
        return "FieldReport(graded=%d, wrong=%d, max_ulps=%d, max_abs=%g, max_rel=%g)" % (
            self.graded, self.wrong, self.max_ulps, self.max_abs, self.max_rel)


def score(query, cases, answers, precision=53, threads=1, set_apart=None):
    """Grades `answers` (a dict: the classification column and any output groups, arrays of N)
    for `cases` (the query function's arguments as arrays of N, as cdref.cases gives them, or the
    (N, columns) matrix) against the exact answers. `set_apart` (a boolean array of N) marks
    cases your convention gives another meaning; they are counted, not graded. Returns a Report."""
    _check_query(query)
    q = _QUERIES[query]
    rows = cases if isinstance(cases, _np.ndarray) else _rows(query, dict(cases))[0]
    n = len(rows)
    truth = answer(query, rows, precision, threads)
    rep = Report(query, precision)
    rep.cases = n
    ok = truth["status"] == 0
    rep.refused = int((~ok).sum())
    if set_apart is not None:
        apart = _np.asarray(set_apart, dtype=bool).reshape(n)
        rep.set_apart = int((apart & ok).sum())
        ok = ok & ~apart
    known = {q["classification"]} | {o["name"] for o in q["outputs"]}
    unknown = [k for k in answers if k not in known]
    if unknown:
        raise ValueError("%s: unknown answer column(s) %s (its columns: %s)" % (query, ", ".join(unknown), ", ".join(sorted(known))))
    rep.graded = int(ok.sum())
    exact_cls = truth[q["classification"]]
    given_cls = None
    if q["classification"] in answers:
        given_cls = _np.asarray(answers[q["classification"]], dtype=bool).reshape(n)
        fp = ok & given_cls & ~exact_cls
        fn = ok & ~given_cls & exact_cls
        rep.false_positives, rep.false_negatives = int(fp.sum()), int(fn.sum())
        wrong = _np.flatnonzero(fp | fn)
        if len(wrong):
            r = int(wrong[0])
            rep.examples.append({"what": "classification", "row": r, "given": bool(given_cls[r]),
                                 "exact": bool(exact_cls[r]), "inputs": _row_args(query, rows[r])})
    # the scales values are measured against
    args = _arguments(q["inputs"])
    coord = [c for _, kind, cols in args for c in (cols[1:] if kind in ("vertices", "ring") else cols)
             if q["inputs"][c] not in ("closed",)]
    scene = _np.maximum(_np.abs(rows[:, coord]).max(axis=1), _np.finfo(_np.float64).tiny)
    lam = _np.ones(n)
    if "direction_x" in q["inputs"]:
        k = q["inputs"].index("direction_x")
        lam = scene / _np.maximum(_np.abs(rows[:, k : k + 3]).max(axis=1), _np.finfo(_np.float64).tiny)
    for o in q["outputs"]:
        name = o["name"]
        if name not in answers:
            continue
        given = _np.asarray(answers[name], dtype=_np.float64)
        exact = _np.asarray(truth[name], dtype=_np.float64)
        given = given.reshape(exact.shape)
        gate = ok.copy()
        if o["when"] == "on_hit":
            gate &= exact_cls & (given_cls if given_cls is not None else True)
        elif o["when"] == "on_miss":
            gate &= ~exact_cls & (~given_cls if given_cls is not None else True)
        f = FieldReport(o["label"])
        f.graded = int(gate.sum())
        if f.graded:
            g, e = given[gate], exact[gate]
            if o["label"]:
                bad = g != e
                f.wrong = int(bad.sum())
                f.max_ulps = int(bad.any())
                f.max_abs = f.max_rel = float(bad.any())
            else:
                scale = {"lambda_enter": lam, "lambda_exit": lam}.get(name, scene)
                if name in ("normal", "u", "v"):
                    scale = _np.ones(n)
                s = scale[gate]
                if g.ndim == 2:
                    s = s[:, None]
                ulps = _ulps(g, e, precision)
                with _np.errstate(invalid="ignore", over="ignore"):
                    ab = _np.abs(g - e)
                ab = _np.where(_np.isnan(ab), _np.inf, ab)
                rel = ab / s
                f.max_ulps = int(ulps.max())
                f.max_abs = float(ab.max())
                f.max_rel = float(rel.max())
                worst = ulps.max(axis=1) if ulps.ndim == 2 else ulps
                i = int(_np.argmax(worst))
                r = int(_np.flatnonzero(gate)[i])
                if worst[i] > 0:
                    rep.examples.append({"what": name, "row": r, "given": _plain(given[r]), "exact": _plain(exact[r]),
                                         "ulps": int(worst[i]), "inputs": _row_args(query, rows[r])})
        rep.fields[name] = f
    return rep


def _plain(x):
    return list(map(float, x)) if isinstance(x, _np.ndarray) and x.ndim else float(x)


def _row_args(query, row):
    """One row of columns as the query function's arguments (plain Python numbers)."""
    one = _split(query, row[None, :])
    out = {}
    for k, v in one.items():
        v = v[0]
        if isinstance(v, _np.ndarray) and v.ndim == 2:
            v = v[~_np.isnan(v).all(axis=1)]
        out[k] = v.tolist() if isinstance(v, _np.ndarray) else float(v)
    return out


def validate(implementation, query, families=None, n=1000, seed=1, precision=53, scales=None, batched=False,
             convention=None, threads=1):
    """Runs your implementation of `query` on n cases of each (family, scale) and grades it
    against the exact answers. `implementation` takes the query function's arguments by name and
    returns its classification (a bool) or a dict of answer columns (the classification and any
    output groups); with batched=True it is called once per cell with arrays of n and returns a
    dict of arrays. `convention(args, exact)` (optional; per case, the exact answer a Result) says
    where your documented convention gives another meaning: those cases are set apart, not graded.
    Returns a Report with `cells`, the per-(family, scale) reports."""
    _check_query(query)
    q = _QUERIES[query]
    fams = families if families is not None else list(globals()["families"](query))
    total = Report(query, precision)
    total.cells = {}
    dtype = _np.float32 if precision == 24 else _np.float64
    for fam in fams:
        for scale in (scales if scales is not None else globals()["families"](query)[fam]["scales"]):
            rows = cases(query, fam, scale, n, seed, columns=True)
            if precision == 24:
                rows = rows.astype(_np.float32).astype(_np.float64)
            args = _split(query, rows)
            if batched:
                got = implementation(**args)
                if not isinstance(got, dict):
                    got = {q["classification"]: got}
            else:
                got = _per_case(implementation, query, args, n, dtype)
            apart = None
            if convention is not None:
                fn = globals()[_fname(query)]
                apart = _np.zeros(n, dtype=bool)
                for i in range(n):
                    one = {k: v[i] for k, v in args.items()}
                    try:
                        exact = fn(**one, dtype=dtype)
                    except InvalidInput:
                        continue
                    apart[i] = bool(convention(one, exact))
            rep = score(query, rows, got, precision, threads, set_apart=apart)
            for e in rep.examples:
                e["cell"] = "%s/%d" % (fam, scale)
            total.cells[(fam, scale)] = rep
            total._merge(rep)
    return total


def _per_case(implementation, query, args, n, dtype):
    cls = _QUERIES[query]["classification"]
    out = {}
    for i in range(n):
        one = {}
        for k, v in args.items():
            x = v[i]
            if isinstance(x, _np.ndarray) and x.ndim == 2:
                x = x[~_np.isnan(x).all(axis=1)]
            one[k] = x.astype(dtype) if isinstance(x, _np.ndarray) else dtype(x)
        got = implementation(**one)
        if not isinstance(got, dict):
            got = {cls: got}
        for k, v in got.items():
            if k not in out:
                shape = _np.shape(v)
                out[k] = _np.zeros((n,) + shape, dtype=bool if k == cls else _np.float64)
            out[k][i] = v
    return out
