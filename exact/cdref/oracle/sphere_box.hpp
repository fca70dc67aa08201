// cdref/oracle/sphere_box.hpp - the exact classification of a sphere and an axis-aligned box at
// double inputs: the filter, Q on double words, the robust tier's decision, the expansion and the
// rationals.
// The decision at an exact type (every difference exact, so a sign of a polynomial in the
// inputs; expansions.hpp: the model of the three stages):
//   sphere-box      v_i = clamp(c_i, -h_i, h_i) - c_i, |v|^2 <= rho^2 with c = centre - box
//                   centre. |v_i| = max(0, |c_i| - h_i) whichever branch the book takes.
//
// Its classify() is at the end of this file; <cdref/oracle/stages.hpp> runs the stages in order.
#pragma once

#include <cdref/oracle/expansions.hpp>
#include <cdref/oracle/stages.hpp>
#include <cdref/filters/sphere_filter.hpp>
#include <cdref/robust/sphere_box.hpp>

namespace cdref::oracle {

namespace staged {

// ======================= sphere-box =======================
// The filter: filters/sphere_filter.hpp.
inline int expansion(const Sphere<double>& sp0, const Box<double>& box0, plain = {}) {
  Sphere<double> sp;
  Box<double> box;
  if (!scaled(sp0, box0, sp, box)) return unknown;
  Exp<56> acc[2];
  int cur = 0;
  double x, y;
  two_prod(sp.radius, sp.radius, x, y);
  set2(acc[0], -x, -y);
  for (int i = 0; i < 3; ++i) {
    const double c = sp.center[i], b = box.center[i], h = box.extent[i];
    double hs;
    if (sign3(c, -b, h) < 0)
      hs = -h;  // c_i < -h_i: v_i = -h_i - c_i
    else if (sign3(c, -b, -h) > 0)
      hs = h;  // c_i > h_i: v_i = h_i - c_i
    else
      continue;  // v_i = 0
    Exp<2> cb;
    Exp<1> hh;
    Exp<3> v;
    Exp<18> sq;
    set2(cb, b, -c);
    set1(hh, hs);
    add(cb, hh, v);
    mul(v, v, sq);
    add(acc[cur], sq, acc[1 - cur]);
    cur ^= 1;
  }
  return int(sign(acc[cur]) <= 0);
}

inline bool rational(const Sphere<double>& a, const Box<double>& b, plain = {}) { return book::intersect(toq(a), toq(b)); }

// Sphere-box: Q = |v|^2 - rho^2 on double words (v the centre's offset from the box, as in
// sphere_filter.hpp), where the filter leaves its sign open (within about u (|c| + h)^2 of 0,
// near touching). On the scaled inputs c_i - b_i = ch + cl exactly (two_sum); the clamp is
// exact (c_i < b_i - h_i iff ch < -h_i, or ch = -h_i and cl < 0: rounding is monotone;
// likewise above); a clamped v_i = +-h_i - ch - cl = a + b + e exactly ((p, e) = two_sum(+-h_i,
// -ch), (a, b) = two_sum(p, -cl)), taken as X + L = two_sum(a, fl(b + e)), within eps = u |fl(b
// + e)| + eta of v_i (one rounding to nearest, at most u times the rounded value, plus eta where
// it is subnormal). rho: X = rho, L = 0, eps = 0. Q's sign by signed_squares; Q <= 0 is an
// intersection (the closed ball and the closed box), and no axis clamped puts the centre in
// the box: 1. Range: every nonzero input in [2^-300, 2^200] (scaled() leaves them in [2^-180,
// 2^100]), so that |v_i| < 2^202 and each square is a normal number or within eta (as sigma's).
// Inputs already in that range are taken as they are, unscaled.
inline bool sphere_box_words_range(const Sphere<double>& sp, const Box<double>& box) {
  const auto in_range = [](double x) {  // (int flags: no branch per input)
    const double a = std::fabs(x);
    return int(a <= 0x1p200) & (int(a >= 0x1p-300) | int(a == 0));
  };
  int ok = in_range(sp.radius);
  for (int i = 0; i < 3; ++i) ok &= in_range(sp.center[i]) & in_range(box.center[i]) & in_range(box.extent[i]);
  return ok != 0;
}
template <class Mul>
int sphere_box_words_with(const Sphere<double>& sp, const Box<double>& box) {
  using std::fabs;
  using P2 = eft::Pair<double>;
  constexpr double u = 0x1p-53, eta = 0x1p-1074;
  double X[4] = {0, 0, 0, sp.radius}, L[4] = {0, 0, 0, 0}, eps[4] = {0, 0, 0, 0}, sg[4] = {1, 1, 1, -1};
  bool outside = false;
  for (int i = 0; i < 3; ++i) {
    const P2 c = eft::two_sum(sp.center[i], -box.center[i]);
    const double h = box.extent[i];
    double side;
    if (c.hi < -h || (c.hi == -h && c.lo < 0))
      side = -h;
    else if (c.hi > h || (c.hi == h && c.lo > 0))
      side = h;
    else
      continue;  // v_i = 0
    outside = true;
    const P2 p = eft::two_sum(side, -c.hi);
    const P2 q = eft::two_sum(p.hi, -c.lo);
    const double lo = q.lo + p.lo;
    const P2 v = eft::two_sum(q.hi, lo);
    X[i] = v.hi, L[i] = v.lo, eps[i] = u * fabs(lo) + eta;
  }
  if (!outside) return 1;
  const int q = signed_squares<Mul>(X, L, eps, sg);
  return q == unknown ? unknown : int(q < 0);
}
inline int sphere_box_words(const Sphere<double>& sp0, const Box<double>& box0) {
  Sphere<double> sp = sp0;
  Box<double> box = box0;
  if (!sphere_box_words_range(sp, box) && !(scaled(sp0, box0, sp, box) && sphere_box_words_range(sp, box)))
    return unknown;
  return eft::with_products([&](auto mul) { return sphere_box_words_with<decltype(mul)>(sp, box); });
}
// After the robust tier's own filter (robust/sphere_box.hpp: it decides to within about u^2 of
// the scale from touching, for less), before its decision (2^-52 from touching it took about
// 200 ns a case, its expansions over 19 exact products).
inline int double_word(const Sphere<double>& a, const Box<double>& b, plain = {}) {
  if (const int f = robust::detail::sphere_box_filter_own(a, b)) return int(f < 0);
  if (const int r = sphere_box_words(a, b); r != unknown) return r;
  return certain_or_unknown(robust::decide(a, b));
}

}  // namespace staged

// ---- the oracle: the filter (the input checks folded into it: stages.hpp), then the stages ----
inline bool classify(const Sphere<double>& sp, const Box<double>& box, Stage* used = nullptr) {
  return staged::filter_first(used, sp, "sphere", box, "box");
}

}  // namespace cdref::oracle
