// cdref/oracle/rational.hpp - double inputs moved exactly to CGAL::Gmpq: the oracles' last,
// rational stage.
#pragma once

#include <cdref/exact.hpp>

namespace cdref::oracle::rational_inputs {

using Q = CGAL::Gmpq;
inline Vec3<Q> q3(const Vec3<double>& v) { return Vec3<Q>(Q(v[0]), Q(v[1]), Q(v[2])); }
inline Sphere<Q> toq(const Sphere<double>& s) { return {q3(s.center), Q(s.radius)}; }
inline Box<Q> toq(const Box<double>& b) { return {q3(b.center), q3(b.extent)}; }
inline Segment<Q> toq(const Segment<double>& s) { return {q3(s.source), q3(s.target)}; }
inline Ray<Q> toq(const Ray<double>& r) { return {q3(r.source), q3(r.direction)}; }
inline Triangle<Q> toq(const Triangle<double>& t) { return {{q3(t.vertex[0]), q3(t.vertex[1]), q3(t.vertex[2])}}; }
inline OrientedBox<Q> toq(const OrientedBox<double>& b) {
  return {q3(b.center), q3(b.extent), {q3(b.axis[0]), q3(b.axis[1]), q3(b.axis[2])}};
}

}  // namespace cdref::oracle::rational_inputs
