/// \file
/// cdref/vec.hpp - 3-vectors over any number type, and the few operations the
/// chapter's algorithms use on them.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace cdref {

/// A 3-vector over T: a point or a direction.
template <class T>
using Vec3 = Eigen::Matrix<T, 3, 1>;

/// Component-wise conversion, used to move a vector of T into the sqrt type S.
template <class S, class T>
Vec3<S> lift(const Vec3<T>& v) {
  return Vec3<S>(S(v[0]), S(v[1]), S(v[2]));
}

/// s + lambda * r with s, r over T and lambda over S (S may be T).
template <class S, class T>
Vec3<S> affine(const Vec3<T>& s, const S& lambda, const Vec3<T>& r) {
  return Vec3<S>(S(s[0]) + lambda * S(r[0]), S(s[1]) + lambda * S(r[1]), S(s[2]) + lambda * S(r[2]));
}

/// c + k * v with c over T and v over S: a point plus a scaled direction.
template <class S, class T>
Vec3<S> offset(const Vec3<T>& c, const S& k, const Vec3<S>& v) {
  return Vec3<S>(S(c[0]) + k * v[0], S(c[1]) + k * v[1], S(c[2]) + k * v[2]);
}

/// The zero vector over S.
template <class S>
Vec3<S> zero_vec() {
  return Vec3<S>(S(0), S(0), S(0));
}

/// The coordinate unit vector sign * e_axis (axis 0, 1, 2 for x, y, z) over S.
template <class S>
Vec3<S> unit_vec(int axis, int sign = 1) {
  Vec3<S> v = zero_vec<S>();
  v[axis] = S(sign);
  return v;
}

}  // namespace cdref
