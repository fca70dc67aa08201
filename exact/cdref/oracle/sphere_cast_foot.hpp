// cdref/oracle/sphere_cast_foot.hpp - Algorithm 3.1's every output in the perpendicular foot's
// formulation: equal to book::cast at every exact type, and the one the every-output oracle
// evaluates on oracle::Bounded2 (double words with a rigorous error bound, certain or it throws)
// before the exact path (fuzz/cdref/fuzz/spec.hpp, oracle_truth_of).
//
// Why another formulation. The book's (book/ray_sphere.hpp), with s = source - centre and r the
// direction (target - source for a segment), a = |r|^2, b = s.r, c = |s|^2 - rho^2:
//   sigma = b^2 - a c,  lambda_1 = (-b - sqrt(sigma)) / a,  x = s + lambda_1 r,
//   point = centre + x, normal = x / rho.
// At range (|s| = R rho) b^2 and a c are both about R^2 rho^2 a and cancel to sigma ~ rho^2 a:
// a double word's 106 bits keep about 106 - 2 log2(R^2) of sigma, 26 at R = 10^12, too few to
// round anything correctly; and x = s + lambda_1 r cancels R rho against R rho once more. The
// every-output oracle then fell through to the rationals and square roots at CGAL::Gmpq, about
// 150 us a case at 10^12 radii (`cdref_bench --benchmark_filter=sphere-cast/long-range`).
//
// The formulation here (exactly equal to the book's at exact types, term by term):
//   q = s x r,  sigma = a rho^2 - |q|^2            (Lagrange: |s|^2 |r|^2 - (s.r)^2 = |s x r|^2,
//                                                   so b^2 - a c = a rho^2 - |q|^2 exactly);
//   lambda_1 = (-b - sqrt(sigma)) / a, lambda_2 = (-b + sqrt(sigma)) / a   (the book's own);
//   x = (h - sqrt(sigma) r) / a,  h = r x q        (r x (s x r) = a s - b r, so
//                                                   h / a = s - (b / a) r, the perpendicular foot,
//                                                   and x = s + lambda_1 r exactly).
// q's components cancel R rho |r| against products of size R rho |r| once (a double word keeps
// about 106 - log2(R) bits of them: 66 at 10^12), and nothing after that cancels more than the
// problem itself does (sigma near tangency, a coordinate of x near 0). The decisions are the
// book's, on the same exact values (sigma, lambda_1, b and the roots compared with 0 and 1), so
// the classification, enters, the roots and every output agree at exact types; the test
// (tests/test_oracle_classify.cpp) checks it at CGAL::Gmpq on every family of both casts.
//
// Boundary cases, as the book: a zero-length segment (a = 0) is a point test, its exit 1 and its
// point the source; a source inside or on the sphere (lambda_1 < 0 on a hit) enters at 0, at
// the source itself (x = s), with no normal; a sphere of radius 0 has no normal.
#pragma once

#include <cdref/book/common.hpp>
#include <cdref/primitives.hpp>
#include <cdref/results.hpp>

namespace cdref::oracle {

namespace detail {

template <class T>
Cast<sqrt_t<T>> foot_cast_local(const Vec3<T>& s, const Vec3<T>& r, const Sphere<T>& sp, bool bounded, unsigned w) {
  using S = sqrt_t<T>;
  Cast<S> res;
  const T& rho = sp.radius;
  const T rr = r.squaredNorm();
  const T rho2 = rho * rho;
  if (rr == T(0)) {  // a zero-length segment: a point
    res.hit = s.squaredNorm() <= rho2;
    if (res.hit && (w & want_lambda_exit)) res.lambda_exit = S(1);
    if (res.hit && (w & want_point)) res.point = lift<S>(Vec3<T>(s + sp.center));
    return res;
  }
  const T sr = s.dot(r);
  const Vec3<T> q = s.cross(r);
  const T sigma = rr * rho2 - q.squaredNorm();
  if (!(sigma >= T(0))) return res;
  const S root_sigma = root(sigma);
  const S lambda1 = (S(-sr) - root_sigma) / S(rr);
  const S num2 = S(-sr) + root_sigma;  // lambda_2 * |r|^2
  if (bounded && !(lambda1 <= S(1))) return res;
  if (!(num2 >= S(0))) return res;
  res.hit = true;
  res.enters = lambda1 >= S(0);
  res.lambda_enter = res.enters ? lambda1 : S(0);
  if (w & want_lambda_exit) {
    const S lambda2 = num2 / S(rr);
    res.lambda_exit = bounded ? book::detail::min_of(lambda2, S(1)) : lambda2;
  }
  if (!(w & (want_point | want_normal))) return res;
  if (!res.enters) {  // entering at 0: the source itself
    if (w & want_point) res.point = lift<S>(Vec3<T>(s + sp.center));
    return res;
  }
  const Vec3<T> h = r.cross(q);  // |r|^2 times the foot of the perpendicular
  Vec3<S> ax;                    // |r|^2 x
  for (int i = 0; i < 3; ++i) ax[i] = S(h[i]) - root_sigma * S(r[i]);
  if (w & want_point) {
    const S inv = S(1) / S(rr);  // one quotient, three products (exact types: the same values)
    for (int i = 0; i < 3; ++i) res.point[i] = ax[i] * inv + S(sp.center[i]);
  }
  if ((w & want_normal) && rho != T(0)) {
    const S inv = S(1) / S(T(rr * rho));
    for (int i = 0; i < 3; ++i) res.normal[i] = ax[i] * inv;
  }
  return res;
}

}  // namespace detail

// The same signatures, checks and results as book::cast.
template <class T>
Cast<sqrt_t<T>> foot_cast(const Segment<T>& seg, const Sphere<T>& sp, unsigned w = want_cast) {
  check(seg, "segment");
  check(sp, "sphere");
  const Vec3<T> s = seg.source - sp.center;
  const Vec3<T> t = seg.target - sp.center;
  return detail::foot_cast_local(s, Vec3<T>(t - s), sp, true, w);
}

template <class T>
Cast<sqrt_t<T>> foot_cast(const Ray<T>& ray, const Sphere<T>& sp, unsigned w = want_cast) {
  check(ray, "ray");
  check(sp, "sphere");
  return detail::foot_cast_local(Vec3<T>(ray.source - sp.center), ray.direction, sp, false, w);
}

}  // namespace cdref::oracle
