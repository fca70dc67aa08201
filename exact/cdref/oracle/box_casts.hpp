// cdref/oracle/box_casts.hpp - the exact classification of a ray or a segment cast on an
// axis-aligned box (Algorithm 3.3) at double inputs: the filter, the plane pairs on double words,
// the expansions and the rationals.
// The decision at an exact type (every difference exact, so a sign of a polynomial in the
// inputs; expansions.hpp: the model of the three stages):
//   ray/segment cast on a box (Algorithm 3.3): outcodes are signs of p - c + h and p - c - h.
//                   The book keeps the largest entering parameter (starting at 0) and the
//                   smallest exiting one (starting at 1 for a segment) and hits iff
//                   enter <= exit. Every entering parameter lies in [0, 1] (the source is
//                   outside that plane, the target is not) and every exiting one in [0, 1]
//                   ([0, inf) for a ray), so the decision is: for every entering plane p and
//                   exiting plane q, lambda_p <= lambda_q, i.e. with lambda = n / d, d > 0
//                   (sign of d known from the outcodes),  n_p d_q - n_q d_p <= 0.
//                   n = -(s - c) -+ h (3 inputs), d = |target - source| or |direction|.
//                   Ties between planes change which plane the book keeps, never the decision.
//
// Its classify() is at the end of this file; <cdref/oracle/stages.hpp> runs the stages in order.
#pragma once

#include <cdref/oracle/expansions.hpp>
#include <cdref/oracle/stages.hpp>
#include <cdref/filters/box_cast_filter.hpp>
#include <cdref/filters/box_cast_words.hpp>

namespace cdref::oracle {

namespace staged {

// ======================= ray / segment on a box =======================
// Stage 1 (outcodes and the plane pairs in double): filters/box_cast_filter.hpp, which the robust
// tier runs first too. Stage 2 below: the same logic on exact signs.
struct BoxExact {
  const Vec3<double> &src, &rt;
  const Box<double>& box;
  bool bounded;
  BoxExact(const Vec3<double>& s, const Vec3<double>& t, const Box<double>& b, bool segment)
      : src(s), rt(t), box(b), bounded(segment) {}
  int src_lo(int i) const { return sign3(src[i], -box.center[i], box.extent[i]); }
  int src_hi(int i) const { return sign3(src[i], -box.center[i], -box.extent[i]); }
  int tgt_lo(int i) const { return sign3(rt[i], -box.center[i], box.extent[i]); }
  int tgt_hi(int i) const { return sign3(rt[i], -box.center[i], -box.extent[i]); }
  int dir_sign(int i) const {
    const double a = rt[i], b = bounded ? src[i] : 0.0;
    return a > b ? 1 : (a < b ? -1 : 0);
  }
  // n' and d' of plane p as expansions.
  void plane(int p, Exp<3>& n, Exp<2>& d) const {
    const int i = p / 2;
    Exp<2> x;
    Exp<1> h;
    set2(x, -src[i], box.center[i]);
    set1(h, p % 2 == 0 ? -box.extent[i] : box.extent[i]);
    add(x, h, n);
    if (bounded)
      set2(d, rt[i], -src[i]);
    else
      set1(d, rt[i]);
    if (dir_sign(i) < 0) negate(n), negate(d);
  }
  int compare(int p, int q) const {
    Exp<3> np, nq;
    Exp<2> dp, dq;
    plane(p, np, dp);
    plane(q, nq, dq);
    Exp<12> a, b;
    Exp<24> c;
    mul(np, dq, a);
    mul(nq, dp, b);
    add(a, b, c, true);
    return sign(c);
  }
};
// The filter's signs, the plane pairs on double words (filters/box_cast_words.hpp, AabbWords), then
// the expansions. (The pairs on words: 2^-52 from grazing, a cast the filter left took about 500
// ns a case, nine exact pairs at most, each a product of expansions.)
template <class Mul>
struct BoxStaged {
  BoxFilter f;
  filters::box_cast_words::AabbWords<Mul> w;
  BoxExact x;
  bool bounded;
  BoxStaged(const Vec3<double>& s, const Vec3<double>& t, const Box<double>& b, bool segment)
      : f(s, t, b, segment), w(s, t, b, segment), x(s, t, b, segment), bounded(segment) {}
  // (the filter's outcodes only within its range test, BoxFilter::ok)
  int src_lo(int i) const { const int s = f.ok ? f.src_lo(i) : unknown; return s != unknown ? s : x.src_lo(i); }
  int src_hi(int i) const { const int s = f.ok ? f.src_hi(i) : unknown; return s != unknown ? s : x.src_hi(i); }
  int tgt_lo(int i) const { const int s = f.ok ? f.tgt_lo(i) : unknown; return s != unknown ? s : x.tgt_lo(i); }
  int tgt_hi(int i) const { const int s = f.ok ? f.tgt_hi(i) : unknown; return s != unknown ? s : x.tgt_hi(i); }
  int dir_sign(int i) const { return x.dir_sign(i); }
  int compare(int p, int q) const {
    int s = f.compare(p, q);
    if (s == unknown) s = w.compare(p, q);
    return s != unknown ? s : x.compare(p, q);
  }
};

inline int expansion(const Segment<double>& seg0, const Box<double>& box0, plain = {}) {
  Segment<double> seg;
  Box<double> box;
  if (!scaled(seg0, box0, seg, box)) return unknown;
  return eft::with_products(
      [&](auto mul) { return hit_box_logic(BoxStaged<decltype(mul)>(seg.source, seg.target, box, true)); });
}
inline int expansion(const Ray<double>& ray0, const Box<double>& box0, plain = {}) {
  Ray<double> ray;
  Box<double> box;
  if (!scaled(ray0, box0, ray, box)) return unknown;
  return eft::with_products(
      [&](auto mul) { return hit_box_logic(BoxStaged<decltype(mul)>(ray.source, ray.direction, box, false)); });
}

inline bool rational(const Segment<double>& s, const Box<double>& b, plain = {}) { return book::hit(toq(s), toq(b)); }
inline bool rational(const Ray<double>& s, const Box<double>& b, plain = {}) { return book::hit(toq(s), toq(b)); }

// Before the box casts' filter: the extents' signs and, for a ray, its direction (finite, not
// zero), which the outcodes' range tests do not see (stages.hpp).
inline bool unseen_valid(const Ray<double>& r, const Box<double>& b, plain) {
  return filters::staged::signs_valid(b) && filters::staged::direction_valid(r.direction);
}

}  // namespace staged

// ---- the oracle: the filter (the input checks folded into it: stages.hpp), then the stages ----
inline bool classify(const Segment<double>& seg, const Box<double>& box, Stage* used = nullptr) {
  return staged::filter_first(used, seg, "segment", box, "box");
}
inline bool classify(const Ray<double>& ray, const Box<double>& box, Stage* used = nullptr) {
  return staged::filter_first(used, ray, "ray", box, "box");
}

}  // namespace cdref::oracle
