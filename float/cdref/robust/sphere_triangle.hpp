// cdref/robust/sphere_triangle.hpp - the robust sphere-triangle query (Section 3.4) at float,
// double and long double: proximity, intersect and decide.
//
// At double the oracle's first stage runs first (filters/triangle_filter.hpp: two certificates
// from one point of the triangle, static error bounds): where it decides, the classification
// is exact and certain, and decide() returns at once.
//
// Formulation: the book's (book/sphere_triangle.hpp: the closest point region by region, a
// zero-area triangle as its segment) evaluated on double words (robust/words.hpp: exact inputs,
// every length scaled by a power of two, a rigorous running error bound), relative to the
// sphere's centre (words.hpp, about_centre: the vertices' differences from it are exact double
// words, so the closest point carries u^2 of its distance from the centre, not of its
// coordinates). The region tests compare dot products of exact differences (degree 2) and va,
// vb, vc (degree 4), each held to about u^2 of its size, and the classification compares
// |x - c|^2 with rho^2; each is certain when its double word's sign is. The scaling keeps the
// degree-4 terms in range where the book in double overflows or underflows (coordinates near
// 2^500 or 2^-500). decide() is certain when the double-word evaluation of intersect
// completed: then the classification equals the book's at an exact type (at double the first
// stage comes first, the first look's g its last step: sphere_triangle_first_stage). Otherwise the book
// runs in F and the answer is uncertain (a centre on a region boundary, a tangent sphere, a
// triangle whose area is too small to call). proximity() takes its values from the double
// words rounded to F when its own evaluation completes, else from the double words with
// lenient signs (a region test too close to call takes the double word's sign: the closest
// point is continuous across region boundaries; F's value kept where it lies within the double
// word's enclosure), else from F, and always classifies as decide() does. The values are not
// claimed correctly rounded (that is the oracle's job); `cdref campaign --query sphere-triangle
// --impl robust-double` measures them: the distance sqrt|x - c|^2 - rho cancels when it is far
// below the radius (the double words' error is about u^2 of the triangle's size: 40 ulps at
// worst at 2^-52 of the radius from touching), so where its enclosure is wider than u/16 of it
// the distance or depth comes from |x - c|^2 exactly (sphere_triangle_eval, triangle_xx and
// rational.hpp's sharpen_gap: within an ulp on every family; at double, where the first look of
// item F certified x's feature, from that feature alone: feature_xx). In the face region
// the outputs come from the triangle's normal (proximity_by_face below): the sphere's witness
// c + rho (x - c) / |x - c| took its direction from x - c, which cancels when the centre lies
// near the plane (2.3e4 ulps on the degenerate family; now every output within 1 ulp there).
//
// F. The first look (proximity() at double, every value asked). The closest
// point is unique, and x is it iff c - x lies in the normal cone of x's feature; the region is
// taken where that is certain, and x there in double words with a rigorous error bound:
//  1. P_k = v_k - c and the edges e_k = v_k+1 - v_k as exact pairs (two_sum); where the
//     largest of them and rho lies outside [2^-100, 2^100], scaled by the power of two that
//     brings it into [1, 2). (An underflowing product errs by 2^-1074 at most, and no product
//     of degree 4 then exceeds 2^404: tiny below covers them.)
//  2. In double on the highs, each with the bound 6u sum |x_i y_i| (the lows u of the highs,
//     three products and two sums) plus tiny = 2^-800 (underflow): ee_k = e_k.e_k, alpha_k =
//     -P_k.e_k, beta_k = -P_k+1.e_k, ce_k = e_k.e_k-1, and q_k = alpha_k ce_k - ee_k beta_k-1 =
//     (e_k x (c - v_k)).(e_k x (v_k-1 - v_k)) (Lagrange's identity), whose bound adds the
//     products' errors and 2u of the two products. The region: vertex k where alpha_k < 0 and
//     beta_k-1 > 0 certainly ((c - v_k).(y - v_k) <= 0 at both other vertices); edge k where
//     alpha_k > 0, beta_k < 0 (the foot within the edge) and q_k < 0 (c beyond the edge's line
//     within the plane, so c - x . (v_k-1 - v_k) = q_k / ee_k <= 0); the face where every q_k
//     > 0 (then n != 0). Anything else (a boundary within the bounds, a zero-area triangle):
//     the path below.
//  3. v = x - c: a vertex's P_k exactly; an edge's P_k + t e_k, t = alpha / ee from double-word
//     dots (dot_words: 48u^2 sum |x_i y_i|), div_pair (8u^2) and mul_pair (5u^2), the sum with
//     P_k by two_sum (4u^2 of the terms); the face's n s / n.n with n = e_0 x (v_2 - v_0) in
//     double words (the highs' products exact, 32u^2 of their magnitudes), s = P_0 . n. Each
//     component carries a bound that follows every error through (the quotients' by
//     (E_num + |q| E_den) / den_lo).
//  4. g = |v| - rho summed once from |v| as a double word (18u^2 plus the sum of v's bounds):
//     the classification from g's sign where the bound makes it certain (else the first
//     stage's), the distance or the depth where the bound is below u |g| / 16.
//  5. The witnesses c + rho v / |v| (along_dw; in the face region v / |v| = sign(s) n / |n|,
//     which does not carry s / n.n's error) and x = c + v (plus_dw; a vertex exactly, and a
//     coordinate that every vertex of x's edge or face shares exactly: it is x's) where
//     each coordinate's error before its last rounding is below a quarter of u times it: then
//     within 3/4 of an ulp of the truth.
// Every value asked, or the path below for all of them. For the oracle's every-output path
// (sphere_triangle_rounded; polygon.hpp's first look for a fan) each value is kept instead
// where the interval of its double word before the last rounding and its bound rounds to one
// double (cdref::Bounded2::try_rounded): then it is the truth correctly rounded.
#pragma once

#include <cdref/book/sphere_triangle.hpp>
#include <cdref/filters/triangle_filter.hpp>
#include <cdref/filters/triangle_words.hpp>

#include "first_look.hpp"
#include "rational.hpp"
#include "sphere_sphere.hpp"
#include "words.hpp"

namespace cdref::robust {

namespace detail {

// The oracle's first stage (filters/triangle_filter.hpp: two certificates from one point of the
// triangle, static bounds), then the same two certificates on double words
// (filters/triangle_words.hpp): 1 (they meet), 0 (disjoint) or 2 (undecided).
inline int sphere_triangle_certificates(const Sphere<double>& s, const Triangle<double>& t) {
  const int f = filters::sphere_triangle::filter(s, t);
  return f != filters::sphere_triangle::unknown ? f : filters::sphere_triangle::certificates_on_words(s, t);
}
inline int sphere_triangle_first_look_class(const Sphere<double>& s, const Triangle<double>& t);
// At double, before the double words: the certificates, then the first look's g where its sign
// is certain (item F; on a triangle with a vertex at 2^210 and a subnormal coordinate the double
// words were uncertain and wrong where g was certain); 2 (undecided) at float and long double.
// Where it decides, its answer is the book's at an exact type, so every entry point takes it
// (decide(), the predicate and proximity's classification, polygon.hpp's union), and they
// classify alike.
template <class F>
int sphere_triangle_first_stage(const Sphere<F>& s, const Triangle<F>& t) {
  if constexpr (std::is_same_v<F, double>) {
    const int f = sphere_triangle_certificates(s, t);
    return f != filters::sphere_triangle::unknown ? f : sphere_triangle_first_look_class(s, t);
  } else {
    return filters::sphere_triangle::unknown;
  }
}

// The book's proximity, its outputs in the face region from the triangle's normal. There the
// closest point is the centre's projection on the plane: with n = ab x ac and
// side = (a - c) . n, x - c = n side / |n|^2 exactly, so |x - c| = |side| / |n|, the sphere's
// witness is c + rho sign(side) n / |n| (n when side = 0: the book's x == c case), and the
// classification |x - c|^2 <= rho^2 reads side^2 <= rho^2 |n|^2: the same values as the
// book's in exact arithmetic. On the double words n carries u^2 of its size wherever the
// centre lies, and side is exact where the inputs make it so, while the book's x - c is the
// difference of two nearly equal points when the centre lies near the plane: a centre an ulp
// off the triangle gave the witness direction u relative error (thousands of ulps of a
// coordinate that cancels), and a centre exactly on it a closest point an ulp off, from F,
// where x == c was too close to call (the degenerate families).
template <class T>
Proximity<sqrt_t<T>> proximity_by_face(const Sphere<T>& sp, const Triangle<T>& tri, unsigned w) {
  using S = sqrt_t<T>;
  Vec3<T> dir = zero_vec<T>();
  bool face = false;
  const Vec3<T> x = book::detail::closest_on_triangle(tri, sp.center, &dir, &face);
  if (!face) return book::detail::sphere_triangle_outputs(sp, tri, x, dir, w);
  const Vec3<T> n = Vec3<T>(tri.vertex[1] - tri.vertex[0]).cross(Vec3<T>(tri.vertex[2] - tri.vertex[0]));
  const T nn = n.squaredNorm();
  const T side = Vec3<T>(tri.vertex[0] - sp.center).dot(n);
  const T& rho = sp.radius;
  Proximity<S> res;
  res.intersect = side * side <= rho * rho * nn;
  const bool on = side == T(0);  // the centre lies on the triangle
  const Vec3<T> v = on ? zero_vec<T>() : Vec3<T>(n * T(side / nn));
  if (w & (want_closest | want_witnesses)) {
    const Vec3<S> at = on ? lift<S>(sp.center) : lift<S>(Vec3<T>(sp.center + v));
    if (w & want_closest) res.closest = at;
    if (w & want_witnesses) res.on_b = at;
  }
  if (!(w & (want_distance | want_depth | want_witnesses))) return res;
  const S nl = root(nn);
  const S len = on ? S(0) : S(S(side < T(0) ? T(-side) : side) / nl);
  if (w & want_distance) res.distance = book::detail::max_of(S(len - S(rho)), S(0));
  if (w & want_depth) res.depth = book::detail::max_of(S(S(rho) - len), S(0));
  if (w & want_witnesses) res.on_a = offset(sp.center, S(side < T(0) ? T(-rho) : rho), book::detail::divided(n, nl));
  return res;
}

// |x - c|^2 exactly, x the point of the closed triangle closest to c: the projection of c on
// the plane where it lies in the triangle (n = e1 x e2 != 0 and every edge's
// ((v_k+1 - v_k) x (c - v_k)) . n >= 0: then |x - c|^2 = ((c - v_0) . n)^2 / n.n), else the
// nearest of the three edges' closest points (segment_xx; a zero-area triangle is its edges).
template <class F>
void triangle_xx(Rational& xx, const Vec3<F>& c, const Triangle<F>& t) {
  RVec p, v[3], e1, e2, n;
  set_vec(p, c);
  for (int k = 0; k < 3; ++k) set_vec(v[k], t.vertex[k]);
  sub_vec(e1, v[1], v[0]);
  sub_vec(e2, v[2], v[0]);
  cross_vec(n, e1, e2);
  Rational nn, side;
  dot_vec(nn, n, n);
  if (mpq_sgn(nn.q) != 0) {
    bool inside = true;
    for (int k = 0; k < 3 && inside; ++k) {
      RVec e, pk, m;
      sub_vec(e, v[(k + 1) % 3], v[k]);
      sub_vec(pk, p, v[k]);
      cross_vec(m, e, pk);
      dot_vec(side, m, n);
      inside = mpq_sgn(side.q) >= 0;
    }
    if (inside) {
      RVec pv;
      sub_vec(pv, p, v[0]);
      dot_vec(side, pv, n);
      mpq_mul(xx.q, side.q, side.q);
      mpq_div(xx.q, xx.q, nn.q);
      return;
    }
  }
  Rational d;
  for (int k = 0; k < 3; ++k) {
    segment_xx(k == 0 ? xx : d, p, v[k], v[(k + 1) % 3]);
    if (k > 0 && mpq_cmp(d.q, xx.q) < 0) mpq_set(xx.q, d.q);
  }
}

// The proximity on double words relative to the centre (words.hpp, about_centre), one type for
// every F (words.hpp, HotWords).
struct SphereTriangleWords : HotWords {
  unsigned w;
  template <class S, class T>
  auto operator()(const S& x, const T& y) const {
    const unsigned want = w;
    return about_centre(x, y, want, [want](const auto& a, const auto& b) { return proximity_by_face(a, b, want); },
                        [](auto tri, const auto& c) {
                          for (auto& v : tri.vertex) v = std::decay_t<decltype(c)>(v - c);
                          return tri;
                        });
  }
};

// The double words alone (the oracle's second stage).
template <class F>
std::pair<Proximity<F>, Decision> sphere_triangle_words(const Sphere<F>& s, const Triangle<F>& t, unsigned w,
                                                        WordValues* kept = nullptr) {
  return proximity_on_words(
      s, t, SphereTriangleWords{{}, w},
      [](const auto& x, const auto& y) { return book::intersect(x, y); }, kept);
}
// Proximity's values from the double words, its classification from them where they are
// certain, else from the first stage where it decides.
// The distance and the depth then sharpened where the double words leave them loose
// (rational.hpp, sharpen_gap: |x - c|^2 exactly, triangle_xx).
// xx: |x - c|^2 exactly (by default triangle_xx; the first look's certified feature gives it
// for less: sphere_triangle_proximity).
template <class F, class XX>
std::pair<Proximity<F>, Decision> sphere_triangle_eval(const Sphere<F>& s, const Triangle<F>& t, unsigned w,
                                                       WordValues* kept, XX xx) {
  WordValues local;
  WordValues& kv = kept ? *kept : local;
  auto r = sphere_triangle_words(s, t, w, &kv);
  if (!r.second.certain)
    if (const int f = sphere_triangle_first_stage(s, t); f != filters::sphere_triangle::unknown) {
      r.first.intersect = f != 0;
      r.second = {f != 0, true};
    }
  sharpen_gap(r.first, kv, s.radius, w, xx);
  return r;
}
template <class F>
std::pair<Proximity<F>, Decision> sphere_triangle_eval(const Sphere<F>& s, const Triangle<F>& t, unsigned w,
                                                       WordValues* kept = nullptr) {
  return sphere_triangle_eval(s, t, w, kept, [&](Rational& xx) { return triangle_xx(xx, s.center, t), true; });
}

// ---- The first look at double (item F of the header; first_look.hpp) -----------------------

// Item F, steps 1-3: the region certified and v there; false where a test cannot tell.
template <class Mul>
bool first_look_point(const Sphere<double>& sp, const Triangle<double>& t, FirstLookPoint& out) {
  constexpr double u = first_look_u, tiny = first_look_tiny, grow = first_look_grow;
  // 1. the vertices about the centre and the edges, exact pairs, scaled by 2^-scale
  double Ph[3][3], Pl[3][3], Eh[3][3], El[3][3];
  double top = sp.radius;
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i) {
      const Pair<double> p = two_sum(t.vertex[k][i], -sp.center[i]);
      const Pair<double> e = two_sum(t.vertex[(k + 1) % 3][i], -t.vertex[k][i]);
      Ph[k][i] = p.hi, Pl[k][i] = p.lo, Eh[k][i] = e.hi, El[k][i] = e.lo;
      top = std::max({top, std::fabs(p.hi), std::fabs(e.hi)});
    }
  if (!(top > 0x1p-1000 && top < 0x1p1000)) return false;
  const int scale = top >= 0x1p-100 && top <= 0x1p100 ? 0 : exponent_of(top);
  if (scale != 0) {
    const Pow2<double> down(scale);
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i) {
        Ph[k][i] = down(Ph[k][i]), Pl[k][i] = down(Pl[k][i]);
        Eh[k][i] = down(Eh[k][i]), El[k][i] = down(El[k][i]);
      }
  }
  // 2. the region tests on the highs, each with its bound
  const auto dot = [](const double (&x)[3], const double (&y)[3], double& err) {
    err = (6 * u) * ((std::fabs(x[0] * y[0]) + std::fabs(x[1] * y[1])) + std::fabs(x[2] * y[2])) + tiny;
    return (x[0] * y[0] + x[1] * y[1]) + x[2] * y[2];
  };
  double ee[3], Eee[3], al[3], Eal[3], be[3], Ebe[3], ce[3], Ece[3];
  for (int k = 0; k < 3; ++k) {
    const int n = (k + 1) % 3, p = (k + 2) % 3;
    ee[k] = dot(Eh[k], Eh[k], Eee[k]);
    al[k] = -dot(Ph[k], Eh[k], Eal[k]);  // (c - P_k) . e_k
    be[k] = -dot(Ph[n], Eh[k], Ebe[k]);  // (c - P_k+1) . e_k
    ce[k] = dot(Eh[k], Eh[p], Ece[k]);   // e_k . e_k-1
  }
  const auto certain_pos = [](double x, double e) { return x > e; };
  const auto certain_neg = [](double x, double e) { return x < -e; };
  double q[3], Eq[3];
  for (int k = 0; k < 3; ++k) {
    const int p = (k + 2) % 3;
    const double a = al[k] * ce[k], b = ee[k] * be[p];
    q[k] = a - b;
    Eq[k] = (Eal[k] * std::fabs(ce[k]) + (std::fabs(al[k]) + Eal[k]) * Ece[k] + Eee[k] * std::fabs(be[p]) +
             (std::fabs(ee[k]) + Eee[k]) * Ebe[p] + 2 * u * (std::fabs(a) + std::fabs(b))) *
                grow +
            tiny;
  }
  out.scale = scale;
  for (int k = 0; k < 3; ++k) {
    const int p = (k + 2) % 3;
    if (certain_neg(al[k], Eal[k]) && certain_pos(be[p], Ebe[p])) {  // vertex k
      for (int i = 0; i < 3; ++i) out.h[i] = Ph[k][i], out.l[i] = Pl[k][i], out.err[i] = tiny;
      out.vertex = k;
      return true;
    }
    if (certain_pos(al[k], Eal[k]) && certain_neg(be[k], Ebe[k]) && certain_neg(q[k], Eq[k])) {  // edge k
      // 3. v = P_k + t e_k, t = alpha / (e.e) (first_look.hpp, first_look_edge)
      static constexpr double exact[3] = {0, 0, 0};
      if (!first_look_edge<Mul>(Ph[k], Pl[k], exact, Eh[k], El[k], out)) return false;
      out.edge = k;
      return true;
    }
  }
  if (!(certain_pos(q[0], Eq[0]) && certain_pos(q[1], Eq[1]) && certain_pos(q[2], Eq[2]))) return false;
  // 3. the face: v = n s / n.n, n = e_0 x (-e_2) = (v1 - v0) x (v2 - v0), s = P_0 . n
  double nh[3], nl[3], En[3];
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, m = (i + 2) % 3;
    // n_i = e0_j f_m - e0_m f_j with f = -e_2
    const double fjh = -Eh[2][j], fjl = -El[2][j], fmh = -Eh[2][m], fml = -El[2][m];
    const Pair<double> a = Mul::prod(Eh[0][j], fmh), b = Mul::prod(Eh[0][m], fjh);
    const Pair<double> s = two_sum(a.hi, -b.hi);
    const double low = (s.lo + (a.lo - b.lo)) + ((Eh[0][j] * fml + El[0][j] * fmh) - (Eh[0][m] * fjl + El[0][m] * fjh));
    const Pair<double> n = two_sum(s.hi, low);
    nh[i] = n.hi, nl[i] = n.lo;
    En[i] = 32 * u * u * (std::fabs(a.hi) + std::fabs(b.hi)) + tiny;
  }
  static constexpr double exact[3] = {0, 0, 0};
  return first_look_face<Mul>(Ph[0], Pl[0], exact, nh, nl, En, out);
}
// Item F, steps 4-5 (first_look.hpp, first_look_values): the values from v where its bounds
// certify them; which of the asked values it set. cls, key and Correct as there; the
// classification left open by g's bound is the first stage's. A vertex of the triangle is
// exact, and so is a coordinate that every vertex of x's edge or face shares (an axis-aligned
// face or edge: a floor's height).
// (feature: where given, the first look's point, its feature certified where *certified)
template <class Mul, bool Correct = false>
unsigned sphere_triangle_fast(const Sphere<double>& sp, const Triangle<double>& t, int& cls, unsigned w,
                              Proximity<double>& res, double* key = nullptr, FirstLookPoint* feature = nullptr,
                              bool* certified = nullptr) {
  FirstLookPoint local;
  FirstLookPoint& P = feature ? *feature : local;
  const bool point = first_look_point<Mul>(sp, t, P);
  if (certified) *certified = point;
  const auto exact = [&](int i, double& x) {
    const int a = P.vertex >= 0 ? P.vertex : P.edge >= 0 ? P.edge : 0;
    const double same = t.vertex[a][i];
    if (P.vertex >= 0 || (t.vertex[(a + 1) % 3][i] == same && (P.edge >= 0 || t.vertex[(a + 2) % 3][i] == same))) {
      x = same + 0.0;  // (+0 for -0, as the exact value rounds)
      return true;
    }
    return false;
  };
  return first_look_values<Mul, Correct>(sp, P, point, cls, filters::sphere_triangle::unknown, w, res, key,
                                         [&] { return sphere_triangle_certificates(sp, t); }, exact);
}

// |x - c|^2 exactly for the first look's certified feature: a vertex's, an edge's (segment_xx),
// the face's ((v_0 - c) . n)^2 / n.n: a fraction of triangle_xx's work, which tries every feature.
inline void feature_xx(const Sphere<double>& sp, const Triangle<double>& t, const FirstLookPoint& P, Rational& x) {
  RVec c, a, b, d;
  set_vec(c, sp.center);
  if (P.vertex >= 0 || P.edge >= 0) {
    set_vec(a, t.vertex[P.vertex >= 0 ? P.vertex : P.edge]);
    if (P.edge >= 0) return set_vec(b, t.vertex[(P.edge + 1) % 3]), segment_xx(x, c, a, b);
    return sub_vec(d, a, c), dot_vec(x, d, d);
  }
  RVec v1, v2, n;
  set_vec(a, t.vertex[0]), set_vec(v1, t.vertex[1]), set_vec(v2, t.vertex[2]);
  sub_vec(b, v1, a), sub_vec(d, v2, a), cross_vec(n, b, d), sub_vec(d, a, c);
  Rational side, nn;
  dot_vec(side, d, n), dot_vec(nn, n, n);
  mpq_mul(x.q, side.q, side.q);
  mpq_div(x.q, x.q, nn.q);
}

// The oracle's every-output path first (fuzz/queries/sphere_triangle.hpp): every value of the
// book's proximity at an exact type rounded correctly, from the first look where its bounds
// prove each rounding; false where they do not (or the inputs are refused: the caller's path
// refuses them by name).
template <class Mul>
bool sphere_triangle_rounded(const Sphere<double>& s, const Triangle<double>& t, Proximity<double>& res) {
  int cls = filters::sphere_triangle::unknown;
  if ((sphere_triangle_fast<Mul, true>(s, t, cls, want_proximity, res) & want_proximity) != want_proximity) return false;
  res.intersect = cls != 0;
  return true;
}

// The first look's classification alone: g's certain sign, else unknown (decide()'s last step).
// (the certificates having left it: no other stage behind g)
inline int sphere_triangle_first_look_class(const Sphere<double>& s, const Triangle<double>& t) {
  return with_products<true>([&](auto mul) {
    int cls = filters::sphere_triangle::unknown;
    FirstLookPoint P;
    const bool point = first_look_point<decltype(mul)>(s, t, P);
    Proximity<double> r;
    first_look_values<decltype(mul), false>(s, P, point, cls, filters::sphere_triangle::unknown, 0u, r, nullptr,
                                            [] { return filters::sphere_triangle::unknown; },
                                            [](int, double&) { return false; });
    return cls;
  });
}

// proximity() at double: the first look (item F), its classification from g or the first stage;
// else the double words. The classification alone: the first stage.
template <class Mul>
Proximity<double> sphere_triangle_proximity(const Sphere<double>& s, const Triangle<double>& t, unsigned w) {
  const unsigned asked = w & (want_distance | want_depth | want_witnesses | want_closest);
  int cls = asked ? filters::sphere_triangle::unknown : sphere_triangle_first_stage(s, t);
  Proximity<double> res;
  FirstLookPoint P;
  bool certified = false;
  const unsigned done = asked ? sphere_triangle_fast<Mul>(s, t, cls, w, res, nullptr, &P, &certified) : 0u;
  if (cls != filters::sphere_triangle::unknown && (done & asked) == asked) {
    res.intersect = cls != 0;
    return res;
  }
  // the double words, their distance or depth sharpened where loose from the certified feature's
  // |x - c|^2 (a sphere within about 2^-44 of its radius from touching: at 2^-48 and 2^-52,
  // 12.7 and 14.8 us a case before, with triangle_xx; README)
  return sphere_triangle_eval(s, t, w, nullptr, [&](Rational& xx) {
           if (certified) feature_xx(s, t, P, xx);
           else triangle_xx(xx, s.center, t);
           return true;
         }).first;
}

}  // namespace detail

template <class F>
Proximity<F> proximity(const Sphere<F>& s, const Triangle<F>& t, unsigned w = want_proximity) {
  check(s, "sphere");
  check(t, "triangle");
  if constexpr (std::is_same_v<F, double>)
    return with_products([&](auto mul) { return detail::sphere_triangle_proximity<decltype(mul)>(s, t, w); });
  else
    return with_fma([&] { return detail::sphere_triangle_eval(s, t, w).first; });
}
// The oracle's every-output path at double first (fuzz/cdref/fuzz/spec.hpp, oracle_truth_of):
// every value the truth correctly rounded where the first look proves it (item F), else false.
// The inputs checked as proximity() checks them.
inline bool proximity_rounded(const Sphere<double>& s, const Triangle<double>& t, Proximity<double>& res) {
  check(s, "sphere");
  check(t, "triangle");
  return with_products([&](auto mul) { return detail::sphere_triangle_rounded<decltype(mul)>(s, t, res); });
}

template <class F>
Decision decide(const Sphere<F>& s, const Triangle<F>& t) {
  check(s, "sphere");
  check(t, "triangle");
  if (const int f = detail::sphere_triangle_first_stage(s, t); f != filters::sphere_triangle::unknown)
    return {f != 0, true};
  return detail::sphere_triangle_words(s, t, want_proximity).second;
}
template <class F>
bool intersect(const Sphere<F>& s, const Triangle<F>& t) {
  return decide(s, t).value;
}

}  // namespace cdref::robust
