// cdref/robust/ray_triangle.hpp - the robust ray and segment casts on a triangle (Section 3.4)
// at float, double and long double: watertight, with a certificate.
//
// Two pieces: the classification (below, "Classification and certificate": exact where the
// double words decide, never a false miss where they do not), and the values where the double
// words cannot give them: the double words with lenient signs (words.hpp: a comparison too
// close to call takes the double word's own sign; the entry point is continuous there) where
// they complete with a hit, each value kept from Woop, Benthin and Wald's watertight test run
// in F where that lies within the double word's enclosure, and WBW's values otherwise: the
// stable tier's arithmetic (stable/ray_triangle.hpp derives it, and why no ray leaks between
// two triangles that share an edge), on scaled inputs.
//
// Every length is first scaled by a power of two (robust/words.hpp), so that the shear's products
// neither overflow nor underflow early. Two triangles of a mesh may get different scales; away
// from underflow a power of two commutes with every rounding, so their shared edge's function
// still has the same sign in both. Values: lambda = t/det, the
// barycentric weights b_k = e_k/det, point = b0 v0 + b1 v1 + b2 v2 (pbrt's), the normal
// (v1 - v0) x (v2 - v0) normalised and turned to face the source. At double, where the double
// words leave any of lambda_enter, u, v or a coordinate of the point loose (an enclosure wider
// than 2^-57 of its value: an exact 0 on an edge or at a vertex carries a residue of u^2 of the
// triangle's size, and a shot in the plane enters at an edge), and on a proven hit whose double
// words did not complete, those values and lambda_exit are computed on GMP rationals
// (exact_triangle_values) and rounded correctly: every value of a certain hit then lies within
// one ulp of the truth's (the test holds it on every family of both casts).
//
// Classification and certificate. At double the oracle's first stage runs first (the
// orientation form below in double against static error bounds, filters/triangle_filter.hpp, and
// the signs those leave on double words, filters/triangle_words.hpp): where it decides, the answer
// is exact and certain, and a miss returns at once. WBW's signs
// are exact only for the rounded sheared coordinates, not for the inputs: on a shot in the
// triangle's plane it reports a miss (the sheared triangle is not exactly flat), and near an
// edge it may differ from the exact answer. So the classification is taken from the inputs
// themselves: the book's cast (or its hit(), which decide() tries first) run on double words
// (robust/words.hpp: exact inputs, rigorous bounds) is exact when it completes (certain, values
// from the double words rounded to F, not claimed correctly rounded). Otherwise the signs of
// the orientation form (w_k = d . (B x C), ..., Ns, Nt of filters/triangle_filter.hpp) are
// taken on double words one by one, and a sign too close to call counts as met: two certain
// opposite signs (or lambda certainly out of range) prove a miss (certain), and anything else
// is reported as a hit, uncertain, with WBW's values in F. A false miss is therefore
// impossible: a ray that meets the union of a mesh's closed triangles hits one of them, on
// every mesh, whatever each triangle's scale (this is stronger than WBW's own argument, which
// holds only while every triangle is evaluated by WBW). A false hit is possible only where the
// answer is uncertain: that is what campaigns count.
#pragma once

#include <cdref/book/ray_triangle.hpp>
#include <cdref/filters/triangle_filter.hpp>
#include <cdref/filters/triangle_words.hpp>
#include <cdref/stable/ray_triangle.hpp>

#include "rational.hpp"
#include "words.hpp"

namespace cdref::robust {

namespace detail {

template <class F>
TriangleCast<F> triangle_cast_value(const TriangleCast<W>& c) {
  TriangleCast<F> r;
  static_cast<Cast<F>&>(r) = cast_value<F>(c);
  r.u = value<F>(c.u);
  r.v = value<F>(c.v);
  return r;
}

// At double, the oracle's first stage (filters/triangle_filter.hpp: the orientation form in
// double against static bounds), and where it cannot decide the same signs on double words
// (filters/triangle_words.hpp), before the book's test on double words: 1 (a hit), 0 (a miss)
// or 2 (undecided; always at float and long double). Where it decides, its answer is the book's
// at an exact type, so every entry point takes it (decide(), the predicate and the cast classify
// alike); a miss has no values, so the cast then returns at once.
template <class F>
int triangle_first_stage(const Segment<F>& s, const Triangle<F>& t) {
  if constexpr (std::is_same_v<F, double>) {
    const int f = filters::ray_triangle::filter(s.source, &s.target, s.target, t);
    return f != filters::ray_triangle::unknown ? f : filters::ray_triangle::orientation_on_words(s.source, &s.target, s.target, t);
  } else {
    return filters::ray_triangle::unknown;
  }
}
template <class F>
int triangle_first_stage(const Ray<F>& r, const Triangle<F>& t) {
  if constexpr (std::is_same_v<F, double>) {
    const int f = filters::ray_triangle::filter(r.source, nullptr, r.direction, t);
    return f != filters::ray_triangle::unknown ? f : filters::ray_triangle::orientation_on_words(r.source, nullptr, r.direction, t);
  } else {
    return filters::ray_triangle::unknown;
  }
}

// A sign on double words, or 2 when it is too close to call.
inline int sign_or_unknown(const W& x) {
  try {
    return x > W(0.0) ? 1 : (x < W(0.0) ? -1 : 0);
  } catch (const cdref::uncertain&) {
    return 2;
  }
}

// The orientation form on exact double words: 0 a proven miss, 1 a proven hit, 2 a sign too
// close to call (then no miss is proven).
template <class ShotW>
int orientation_hit(const ShotW& shot, const Triangle<W>& tri, bool bounded) {
  const Vec3<W> s = shot.source;
  const Vec3<W> d = [&] {
    if constexpr (std::is_same_v<ShotW, Ray<W>>)
      return shot.direction;
    else
      return Vec3<W>(shot.target - shot.source);
  }();
  const Vec3<W> A = tri.vertex[0] - s, B = tri.vertex[1] - s, C = tri.vertex[2] - s;
  const int w[3] = {sign_or_unknown(d.dot(Vec3<W>(B.cross(C)))), sign_or_unknown(d.dot(Vec3<W>(C.cross(A)))),
                    sign_or_unknown(d.dot(Vec3<W>(A.cross(B))))};
  bool pos = false, neg = false, unknown = false;
  for (int k : w) pos |= k == 1, neg |= k == -1, unknown |= k == 2;
  if (pos && neg) return 0;
  if (unknown || (!pos && !neg)) return 2;  // a sign too close to call, or the flat cases
  const int sD = pos ? 1 : -1;
  const Vec3<W> n = Vec3<W>(tri.vertex[1] - tri.vertex[0]).cross(Vec3<W>(tri.vertex[2] - tri.vertex[0]));
  const int ns = sign_or_unknown(A.dot(n));
  if (ns == -sD) return 0;  // lambda < 0
  int nt = -sD;
  if constexpr (!std::is_same_v<ShotW, Ray<W>>) {
    if (bounded) {
      nt = sign_or_unknown(Vec3<W>(tri.vertex[0] - shot.target).dot(n));
      if (nt == sD) return 0;  // lambda > 1
    }
  }
  return ns != 2 && nt != 2 ? 1 : 2;
}

// Where the book's cast on double words did not complete: its hit() on double words (0 or 1,
// exact), else the orientation form (0 a proven miss, 1 a proven hit, 2 unknown).
template <class Shot, class F>
int words_hit_or_orientation(const Shot& shot, const Triangle<F>& tri, bool bounded) {
  if (const auto h = on_words(shot, tri, [](const auto& a, const auto& b) { return book::hit(a, b); })) return int(*h);
  const auto w = on_words(shot, tri, [bounded](const auto& a, const auto& b) { return orientation_hit(a, b, bounded); });
  return w ? *w : 2;
}

// The book's cast on double words, its entry point the tighter of two enclosures coordinate by
// coordinate: the book's s + lambda_enter d and the barycentric v0 + u (v1 - v0) + v (v2 - v0)
// (the same point in exact arithmetic: book/ray_triangle.hpp, u and v the weights of v1 and v2
// there, also for a zero-area triangle's span). s + lambda d carries lambda's u^2 times |lambda d|,
// the whole distance from the source; the barycentric form u^2 of the triangle's size, and none
// at a vertex or on an edge, where the weights are exact (a ray through a polygon's vertex gave a
// coordinate of 1e-32 where the truth is 0). Both are rigorous enclosures (cdref::Bounded2),
// so the point keeps whichever bound is smaller.
template <class Shot, class Tri>
auto cast_on_words(const Shot& a, const Tri& b) {
  auto c = book::cast(a, b, want_all);
  if (c.hit) {
    using V = std::decay_t<decltype(b.vertex[0])>;
    const V q = V(b.vertex[0] + V(b.vertex[1] - b.vertex[0]) * c.u + V(b.vertex[2] - b.vertex[0]) * c.v);
    for (int i = 0; i < 3; ++i)
      if (q[i].bound() < c.point[i].bound()) c.point[i] = q[i];
  }
  return c;
}

// A hit's values exactly, correctly rounded: the book's cast (book/ray_triangle.hpp) on GMP
// rationals, for a triangle of nonzero area. det = e1 . (d x e2) != 0: lambda = e2 . q / det,
// u = (s - v0) . p / det, v = d . q / det (p = d x e2, q = (s - v0) x e1). det = 0 on a hit
// with n = e1 x e2 != 0: the shot lies in the plane, [lambda_enter, lambda_exit] is [0, 1] or
// [0, inf) clipped by the edges' half-planes (alpha + lambda beta >= 0, alpha = (ab x (s - a)) . n,
// beta = (ab x d) . n), and u, v are the weights at s + lambda_enter d: ((x - v0) x e2) . n / n.n
// and (e1 x (x - v0)) . n / n.n. Nothing for a zero-area triangle, or where a value falls outside
// the normal range. The normal n / |n| turned to face the source (0 where the source lies in
// the plane), each coordinate n_i / sqrt(n . n) in MPFR at 159 bits (three roundings) and
// rounded once: within an ulp of the truth. Called only where the double words leave a value's
// rounding loose (a weight or a coordinate whose enclosure holds 0, or is wide beside it: a shot
// through an edge or a vertex, in the plane) or do not complete (a proven hit whose words meet
// an exact 0), each a few microseconds.
struct ExactTriangleValues {
  double lambda_enter, lambda_exit, u, v;
  Vec3<double> point, normal;
};
inline std::optional<ExactTriangleValues> exact_triangle_values(const Vec3<double>& src, const Vec3<double>& dt,
                                                                bool d_is_target, bool bounded,
                                                                const Triangle<double>& tri) {
  RVec S, R, V0, V1, V2, e1, e2, sv, p;
  set_vec(S, src);
  set_vec(R, dt);
  if (d_is_target) sub_vec(R, R, S);
  set_vec(V0, tri.vertex[0]);
  set_vec(V1, tri.vertex[1]);
  set_vec(V2, tri.vertex[2]);
  sub_vec(e1, V1, V0);
  sub_vec(e2, V2, V0);
  sub_vec(sv, S, V0);
  cross_vec(p, R, e2);
  RVec n;  // the plane's normal, for the flat case and the normal
  Rational nn;
  cross_vec(n, e1, e2);
  dot_vec(nn, n, n);
  Rational det, lo, hi, u, v;
  dot_vec(det, e1, p);
  bool open = false;
  if (mpq_sgn(det.q) != 0) {
    RVec q;
    cross_vec(q, sv, e1);
    dot_vec(lo, e2, q);
    mpq_div(lo.q, lo.q, det.q);
    mpq_set(hi.q, lo.q);
    dot_vec(u, sv, p);
    mpq_div(u.q, u.q, det.q);
    dot_vec(v, R, q);
    mpq_div(v.q, v.q, det.q);
  } else {
    if (mpq_sgn(nn.q) == 0) return std::nullopt;  // a zero-area triangle
    const RVec* vert[3] = {&V0, &V1, &V2};
    mpq_set_ui(lo.q, 0, 1);
    mpq_set_ui(hi.q, 1, 1);
    open = !bounded;
    for (int k = 0; k < 3; ++k) {
      RVec ab, sa, c;
      Rational alpha, beta;
      sub_vec(ab, *vert[(k + 1) % 3], *vert[k]);
      sub_vec(sa, S, *vert[k]);
      cross_vec(c, ab, sa);
      dot_vec(alpha, c, n);
      cross_vec(c, ab, R);
      dot_vec(beta, c, n);
      if (mpq_sgn(beta.q) == 0) continue;
      mpq_div(alpha.q, alpha.q, beta.q);
      mpq_neg(alpha.q, alpha.q);  // the edge's lambda
      if (mpq_sgn(beta.q) > 0) {
        if (mpq_cmp(alpha.q, lo.q) > 0) mpq_set(lo.q, alpha.q);
      } else if (open || mpq_cmp(alpha.q, hi.q) < 0) {
        mpq_set(hi.q, alpha.q);
        open = false;
      }
    }
    RVec x, xv, c;
    Rational t;
    for (int i = 0; i < 3; ++i) {
      mpq_mul(t.q, R[i].q, lo.q);
      mpq_add(x[i].q, S[i].q, t.q);
    }
    sub_vec(xv, x, V0);
    cross_vec(c, xv, e2);
    dot_vec(u, c, n);
    mpq_div(u.q, u.q, nn.q);
    cross_vec(c, e1, xv);
    dot_vec(v, c, n);
    mpq_div(v.q, v.q, nn.q);
  }
  ExactTriangleValues out;
  {
    Rational side;
    dot_vec(side, sv, n);
    out.normal = Vec3<double>(0, 0, 0);
    if (const int turn = mpq_sgn(side.q); turn != 0) {
      mpfr_t len, c;
      mpfr_inits2(159, len, c, (mpfr_ptr)0);
      mpfr_set_q(len, nn.q, MPFR_RNDN);
      mpfr_sqrt(len, len, MPFR_RNDN);
      for (int i = 0; i < 3; ++i) {
        mpfr_set_q(c, n[i].q, MPFR_RNDN);
        mpfr_div(c, c, len, MPFR_RNDN);
        out.normal[i] = turn * mpfr_get_d(c, MPFR_RNDN);
      }
      mpfr_clears(len, c, (mpfr_ptr)0);
    }
  }
  const auto le = round_rational(lo), ru = round_rational(u), rv = round_rational(v);
  const auto lx = open ? std::optional<double>(std::numeric_limits<double>::infinity()) : round_rational(hi);
  if (!le || !lx || !ru || !rv) return std::nullopt;
  out.lambda_enter = *le;
  out.lambda_exit = *lx;
  out.u = *ru;
  out.v = *rv;
  for (int i = 0; i < 3; ++i) {
    Rational t;
    mpq_mul(t.q, R[i].q, lo.q);
    mpq_add(t.q, S[i].q, t.q);
    const auto c = round_rational(t);
    if (!c) return std::nullopt;
    out.point[i] = *c;
  }
  return out;
}

// A certain hit's lambda_enter, lambda_exit, u, v, point and normal replaced by their exact
// values, rounded once, where exact_triangle_values gives them.
template <class Shot>
void take_exact_values(TriangleCast<double>& r, const Shot& shot, const Triangle<double>& tri, bool bounded) {
  std::optional<ExactTriangleValues> e;
  if constexpr (std::is_same_v<Shot, Ray<double>>)
    e = exact_triangle_values(shot.source, shot.direction, false, bounded, tri);
  else
    e = exact_triangle_values(shot.source, shot.target, true, bounded, tri);
  if (!e) return;
  r.lambda_enter = e->lambda_enter;
  r.lambda_exit = e->lambda_exit;
  r.u = e->u;
  r.v = e->v;
  r.point = e->point;
  r.normal = e->normal;
}

// At double, a certain hit's values exactly (exact_triangle_values) where any of the double
// words' lambda_enter, u, v or point is loose.
template <class Shot>
void sharpen(TriangleCast<double>& r, const TriangleCast<W>& w, const Shot& shot, const Triangle<double>& tri,
             bool bounded) {
  bool loose = !sharp(w.u) || !sharp(w.v) || !sharp(w.lambda_enter);
  for (int i = 0; i < 3; ++i) loose |= !sharp(w.point[i]);
  if (!loose) return;
  take_exact_values(r, shot, tri, bounded);
}

// The cast after the first stage's answer `first` (1, 0 or 2 as triangle_first_stage gives it).
template <class Shot, class F>
std::pair<TriangleCast<F>, Decision> triangle_cast_eval(const Shot& shot, const Triangle<F>& tri, bool bounded,
                                                        int first) {
  if (first == 0) return {TriangleCast<F>{}, {false, true}};
  Scale used;
  const auto words = on_words(shot, tri, [](const auto& a, const auto& b) { return cast_on_words(a, b); }, &used);
  if (words) {
    TriangleCast<F> r = triangle_cast_value<F>(*words);
    r.point = Scale{-used.k}.len(r.point);
    if constexpr (std::is_same_v<F, double>)
      if (r.hit) sharpen(r, *words, shot, tri, bounded);
    return {r, {r.hit, true}};
  }
  int o = first;  // 1: a proven hit
  if (o != 1) o = words_hit_or_orientation(shot, tri, bounded);
  if (o == 0) return {TriangleCast<F>{}, {false, true}};
  // WBW's values in F, the shot and the triangle scaled
  const Scale sc = scale_of(shot, tri);
  const Shot ss = scaled(shot, sc);
  const Vec3<F> d = [&] {
    if constexpr (std::is_same_v<Shot, Ray<F>>)
      return ss.direction;
    else
      return Vec3<F>(ss.target - ss.source);
  }();
  TriangleCast<F> r = stable::detail::watertight(ss.source, d, scaled(tri, sc), bounded, unsigned(want_all), true);
  r.hit = true;
  r.point = Scale{-sc.k}.len(r.point);
  // then the double words with lenient signs where they complete with a hit (words.hpp: the
  // entry point is continuous where the shot meets the triangle), WBW's value kept where it
  // lies within their enclosure
  if (const auto lw = on_words_lenient(shot, tri, [](const auto& a, const auto& b) { return cast_on_words(a, b); },
                                       &used);
      lw && lw->hit)
    take_lenient_values<F>(r, *lw, used.k);
  // a proven hit at double: its values exactly (the double words did not complete)
  if constexpr (std::is_same_v<F, double>)
    if (o == 1) take_exact_values(r, shot, tri, bounded);
  return {r, {true, o == 1}};
}

// decide() without the first stage: the double words alone. The book's hit() on double words
// first (cheaper than its cast, which computes the values), then its cast, then the orientation
// form: the same classification and certificate as triangle_cast_eval, which tries them in the
// other order (wherever either of the book's evaluations completes it is exact).
template <class Shot, class F>
Decision triangle_cast_decide_words(const Shot& shot, const Triangle<F>& tri, bool bounded) {
  if (const auto h = on_words(shot, tri, [](const auto& a, const auto& b) { return book::hit(a, b); })) return {*h, true};
  if (const auto c = on_words(shot, tri, [](const auto& a, const auto& b) { return book::cast(a, b, want_all).hit; }))
    return {*c, true};
  const auto w = on_words(shot, tri, [bounded](const auto& a, const auto& b) { return orientation_hit(a, b, bounded); });
  if (w && *w == 0) return {false, true};
  return {true, w && *w == 1};
}

// decide() on inputs already checked (the polygon's fan triangles: polygon.hpp).
template <class Shot, class F>
Decision triangle_decide_checked(const Shot& shot, const Triangle<F>& tri, bool bounded) {
  if (const int f = triangle_first_stage(shot, tri); f != filters::ray_triangle::unknown) return {f != 0, true};
  return triangle_cast_decide_words(shot, tri, bounded);
}

}  // namespace detail

template <class F>
TriangleCast<F> cast(const Segment<F>& seg, const Triangle<F>& tri) {
  check(seg, "segment");
  check(tri, "triangle");
  return detail::triangle_cast_eval(seg, tri, true, detail::triangle_first_stage(seg, tri)).first;
}
template <class F>
TriangleCast<F> cast(const Ray<F>& ray, const Triangle<F>& tri) {
  check(ray, "ray");
  check(tri, "triangle");
  return detail::triangle_cast_eval(ray, tri, false, detail::triangle_first_stage(ray, tri)).first;
}
template <class F>
Decision decide(const Segment<F>& seg, const Triangle<F>& tri) {
  check(seg, "segment");
  check(tri, "triangle");
  return detail::triangle_decide_checked(seg, tri, true);
}
template <class F>
Decision decide(const Ray<F>& ray, const Triangle<F>& tri) {
  check(ray, "ray");
  check(tri, "triangle");
  return detail::triangle_decide_checked(ray, tri, false);
}
template <class F>
bool hit(const Segment<F>& seg, const Triangle<F>& tri) {
  return decide(seg, tri).value;
}
template <class F>
bool hit(const Ray<F>& ray, const Triangle<F>& tri) {
  return decide(ray, tri).value;
}

namespace detail {
// sign(N_a D_b - N_b D_a) sign(D_a D_b) exactly, or 2 where a D is 0 (see enters_first).
template <class F>
int entry_order_exact(const Vec3<F>& s, const Vec3<F>& d, bool d_is_target, const Triangle<F>& a,
                      const Triangle<F>& b) {
  RVec S, R;
  Rational N[2], D[2];
  set_vec(S, s);
  set_vec(R, d);
  if (d_is_target) sub_vec(R, R, S);
  const Triangle<F>* tri[2] = {&a, &b};
  for (int k = 0; k < 2; ++k) {
    RVec v0, v1, v2, e1, e2, n, w;
    set_vec(v0, tri[k]->vertex[0]);
    set_vec(v1, tri[k]->vertex[1]);
    set_vec(v2, tri[k]->vertex[2]);
    sub_vec(e1, v1, v0);
    sub_vec(e2, v2, v0);
    cross_vec(n, e1, e2);
    sub_vec(w, v0, S);
    dot_vec(N[k], w, n);
    dot_vec(D[k], R, n);
  }
  const int da = mpq_sgn(D[0].q), db = mpq_sgn(D[1].q);
  if (da == 0 || db == 0) return 2;
  Rational x, y;
  mpq_mul(x.q, N[0].q, D[1].q);
  mpq_mul(y.q, N[1].q, D[0].q);
  return mpq_cmp(x.q, y.q) > 0 ? da * db : (mpq_cmp(x.q, y.q) < 0 ? -da * db : 0);
}
}  // namespace detail

// Whether a shot that hits triangles a and b through their planes enters a strictly before b,
// for a first hit among several triangles (a polygon's fan, a mesh) whose rounded lambda_enter
// are nearly equal: lambda = N / D with N = (v0 - s) . n, D = r . n, n = (v1 - v0) x (v2 - v0)
// (r the direction, or target - source), so lambda_a < lambda_b iff sign(D_a D_b) (N_a D_b -
// N_b D_a) < 0: decided on double words (words.hpp), else exactly over GMP rationals (an exact
// tie is common there: two fan triangles with a vertex-free plane through the entry point).
// Nothing where a D is exactly 0 (a shot in a triangle's plane enters at an edge, not through
// the plane): the caller then keeps the rounded order.
template <class Shot, class F>
std::optional<bool> enters_first(const Shot& shot, const Triangle<F>& a, const Triangle<F>& b) {
  const auto r = detail::on_words(shot, detail::TrianglePair<F>{a, b}, [](const auto& x, const auto& t) -> int {
    using V = std::decay_t<decltype(x.source)>;
    using Wd = std::decay_t<decltype(x.source[0])>;
    V d;
    if constexpr (requires { x.direction; })
      d = x.direction;
    else
      d = V(x.target - x.source);
    auto plane = [&](const auto& tri, Wd& N, Wd& D) {
      const V n = V(tri.vertex[1] - tri.vertex[0]).cross(V(tri.vertex[2] - tri.vertex[0]));
      N = V(tri.vertex[0] - x.source).dot(n);
      D = d.dot(n);
    };
    Wd Na, Da, Nb, Db;
    plane(t.a, Na, Da);
    plane(t.b, Nb, Db);
    const int sa = Da.sign(), sb = Db.sign();  // an uncertain sign ends the evaluation
    if (sa == 0 || sb == 0) return 2;
    return sa * sb * Wd(Na * Db - Nb * Da).sign();
  });
  int order = r ? *r : 2;
  if (!r) {
    if constexpr (requires { shot.direction; })
      order = detail::entry_order_exact(shot.source, shot.direction, false, a, b);
    else
      order = detail::entry_order_exact(shot.source, shot.target, true, a, b);
  }
  if (order == 2) return std::nullopt;
  return order < 0;
}

// Whether the shot enters triangle a before triangle b, both hit, their robust lambda_enter la
// and lb: la < lb, unless the two are equal or adjacent floats, where the exact parameters
// decide (enters_first) wherever they can. The first hit among several triangles (a polygon's
// fan, a mesh) takes it: the rounded fan is not planar, so near a diagonal two triangles give
// nearly the same parameter and different normals, and the rounded order is not always the
// exact one. (lambda_enter comes from double words rounded once, within an ulp in every
// campaign cell, so values further apart are in the exact order.)
template <class Shot, class F>
bool enters_before(const Shot& shot, const Triangle<F>& a, F la, const Triangle<F>& b, F lb) {
  if (la == lb || std::nextafter(la, lb) == lb)
    if (const auto first = enters_first(shot, a, b)) return *first;
  return la < lb;
}

}  // namespace cdref::robust
