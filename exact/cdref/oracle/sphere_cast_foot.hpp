// cdref/oracle/sphere_cast_foot.hpp - Algorithm 3.1's every output in the perpendicular foot's
// formulation: equal to book::cast at every exact type, and the one the every-output oracle
// evaluates on cdref::Bounded2 (double words with a rigorous error bound, certain or it throws)
// where the book's own formulation is not certain there, before the exact path
// (fuzz/cdref/fuzz/spec.hpp, oracle_truth_of).
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

#include <cdref/book/ray_sphere.hpp>
#include <cdref/primitives.hpp>
#include <cdref/results.hpp>

namespace cdref::oracle {

// The foot's sigma and entry point, for book::detail::cast_sphere_local (which takes every
// decision and computes the roots as the book does).
struct FootForm {
  template <class T>
  static T sigma(const Vec3<T>& s, const Vec3<T>& r, const T& rr, const T& /*sr*/, const T& rho2) {
    return rr * rho2 - s.cross(r).squaredNorm();
  }
  template <class S, class T>
  static Vec3<S> entry(const Vec3<T>& s, const Vec3<T>& r, const T& rr, const S& root_sigma, const S& /*lambda1*/) {
    const Vec3<T> h = r.cross(Vec3<T>(s.cross(r)));  // |r|^2 times the foot of the perpendicular
    const S inv = S(1) / S(rr);                      // one quotient, three products
    return Vec3<S>((S(h[0]) - root_sigma * S(r[0])) * inv, (S(h[1]) - root_sigma * S(r[1])) * inv,
                   (S(h[2]) - root_sigma * S(r[2])) * inv);
  }
};

// The same signatures, checks and results as book::cast.
template <class T>
Cast<sqrt_t<T>> foot_cast(const Segment<T>& seg, const Sphere<T>& sp, unsigned w = want_cast) {
  check(seg, "segment");
  check(sp, "sphere");
  const Vec3<T> s = seg.source - sp.center;
  const Vec3<T> t = seg.target - sp.center;
  return book::detail::cast_sphere_local<T, FootForm>(s, Vec3<T>(t - s), sp, true, w);
}

template <class T>
Cast<sqrt_t<T>> foot_cast(const Ray<T>& ray, const Sphere<T>& sp, unsigned w = want_cast) {
  check(ray, "ray");
  check(sp, "sphere");
  return book::detail::cast_sphere_local<T, FootForm>(Vec3<T>(ray.source - sp.center), ray.direction, sp, false, w);
}

}  // namespace cdref::oracle
