// cdref/oracle/rational.hpp - double inputs moved exactly to CGAL::Gmpq: the oracles' last,
// rational stage.
#pragma once

#include <cdref/exact/rationals.hpp>

namespace cdref::oracle {

// Double inputs moved exactly to a number type T that holds every double (CGAL::Gmpq,
// oracle::Bounded2).
template <class T>
Vec3<T> exactly(const Vec3<double>& v) {
  return Vec3<T>(T(v[0]), T(v[1]), T(v[2]));
}
template <class T>
Sphere<T> exactly(const Sphere<double>& s) {
  return {exactly<T>(s.center), T(s.radius)};
}
template <class T>
Box<T> exactly(const Box<double>& b) {
  return {exactly<T>(b.center), exactly<T>(b.extent)};
}
template <class T>
Segment<T> exactly(const Segment<double>& s) {
  return {exactly<T>(s.source), exactly<T>(s.target)};
}
template <class T>
Ray<T> exactly(const Ray<double>& r) {
  return {exactly<T>(r.source), exactly<T>(r.direction)};
}
template <class T>
Triangle<T> exactly(const Triangle<double>& t) {
  return {{exactly<T>(t.vertex[0]), exactly<T>(t.vertex[1]), exactly<T>(t.vertex[2])}};
}
template <class T>
OrientedBox<T> exactly(const OrientedBox<double>& b) {
  return {exactly<T>(b.center), exactly<T>(b.extent), {exactly<T>(b.axis[0]), exactly<T>(b.axis[1]), exactly<T>(b.axis[2])}};
}

namespace rational_inputs {

using Q = CGAL::Gmpq;
template <class P>
auto toq(const P& p) -> decltype(exactly<Q>(p)) {
  return exactly<Q>(p);
}

}  // namespace rational_inputs

}  // namespace cdref::oracle
