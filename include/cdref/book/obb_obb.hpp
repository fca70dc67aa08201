/// \file
/// cdref/book/obb_obb.hpp - Section 3.3: two oriented boxes by separating axes, in the
/// 15-axis formulation of Gottschalk, Lin and Manocha (OBBTree, SIGGRAPH 1996), as RAPID,
/// PQP, FCL, GTE, Ericson's Real-Time Collision Detection (4.4.1) and most engines ship it.
///
/// With R_ij = a_i . b_j (B's axes in A's frame), t_i = a_i . (c_B - c_A) (the centres'
/// offset in A's frame) and |R_ij|:
///   axis i (a_i)            |t_i| > hA_i + sum_j hB_j |R_ij|;
///   axis 3 + j (b_j)        |sum_i t_i R_ij| > sum_i hA_i |R_ij| + hB_j;
///   axis 6 + 3i + j         (a_i x b_j, with i1 = i+1, i2 = i+2, j1 = j+1, j2 = j+2 mod 3)
///                           |t_i2 R_i1j - t_i1 R_i2j| > hA_i1 |R_i2j| + hA_i2 |R_i1j|
///                                                     + hB_j1 |R_ij2| + hB_j2 |R_ij1|.
/// These are Theorem 3.1 exactly when both frames are orthonormal (the projections of b_j and
/// of a_i x b_j are read off R in A's frame). Axes that reach cdref as floats are orthonormal
/// only to rounding, and the box is then the parallelepiped its axes span (primitives.hpp):
/// this formulation is an approximation of that solid even at an exact type, where
/// book::separate(polytope(A), polytope(B)) (separating_axes.hpp) is exact. Campaigns report
/// the two effects apart (the book at double against the book at an exact type, and that
/// against the truth).
///
/// Near-parallel edges make a_i x b_j tiny and its test a comparison of rounding errors. Float
/// code patches this; two patches are here as variants, each adding false positives only,
/// with absolute constants whatever the boxes' size:
///   separate_rapid      adds 1e-6 to every |R_ij| (RAPID's and PQP's obb_disjoint; FCL; RTCD
///                       4.4.1 adds an EPSILON there, three.js's port Number.EPSILON = 2^-52:
///                       separate_rapid(a, b, 0x1p-52));
///   separate_parallel   reports an intersection after the six face axes when some |R_ij| >=
///                       1 - 1e-8, skipping the nine edge axes (Wild Magic's IntrBox3Box3,
///                       ZERO_TOLERANCE = 1e-8 for double; GTE's TIQuery with its epsilon).
/// Boxes are closed: touching intersects. Separation::direction is a_i, b_j or a_i x b_j.
#pragma once

#include "common.hpp"

namespace cdref::book {

namespace detail {

template <class T>
Separation<T> obb_obb(const OrientedBox<T>& A, const OrientedBox<T>& B, const T& eps, const T& cutoff,
                      bool skip_parallel) {
  T R[3][3], AbsR[3][3], t[3];
  const Vec3<T> D = B.center - A.center;
  bool parallel = false;
  for (int i = 0; i < 3; ++i) {
    t[i] = A.axis[i].dot(D);
    for (int j = 0; j < 3; ++j) {
      R[i][j] = A.axis[i].dot(B.axis[j]);
      AbsR[i][j] = abs_of(R[i][j]) + eps;
      if (skip_parallel && AbsR[i][j] >= cutoff) parallel = true;
    }
  }
  const Vec3<T>&ha = A.extent, &hb = B.extent;
  Separation<T> s;
  auto found = [&](int axis, const Vec3<T>& dir) {
    s.axis = axis;
    s.direction = dir;
    return s;
  };
  for (int i = 0; i < 3; ++i) {
    const T rb = hb[0] * AbsR[i][0] + hb[1] * AbsR[i][1] + hb[2] * AbsR[i][2];
    if (abs_of(t[i]) > ha[i] + rb) return found(i, A.axis[i]);
  }
  for (int j = 0; j < 3; ++j) {
    const T ra = ha[0] * AbsR[0][j] + ha[1] * AbsR[1][j] + ha[2] * AbsR[2][j];
    const T p = t[0] * R[0][j] + t[1] * R[1][j] + t[2] * R[2][j];
    if (abs_of(p) > ra + hb[j]) return found(3 + j, B.axis[j]);
  }
  if (!parallel)
    for (int i = 0; i < 3; ++i) {
      const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
      for (int j = 0; j < 3; ++j) {
        const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
        const T ra = ha[i1] * AbsR[i2][j] + ha[i2] * AbsR[i1][j];
        const T rb = hb[j1] * AbsR[i][j2] + hb[j2] * AbsR[i][j1];
        const T p = t[i2] * R[i1][j] - t[i1] * R[i2][j];
        if (abs_of(p) > ra + rb) return found(6 + 3 * i + j, Vec3<T>(A.axis[i].cross(B.axis[j])));
      }
    }
  s.intersect = true;
  return s;
}

}  // namespace detail

namespace unchecked {
/// The same as the checked `separate` of these arguments, on input already checked: no input
/// checks (see book/common.hpp). For loops over bodies checked once.
template <class T>
Separation<T> separate(const OrientedBox<T>& a, const OrientedBox<T>& b) {
  return detail::obb_obb(a, b, T(0), T(0), false);
}
}  // namespace unchecked

/// Theorem 3.1 on the oriented box and the oriented box: whether they intersect, else the first
/// separating axis in this file's order and its direction (a cdref::Separation). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
Separation<T> separate(const OrientedBox<T>& a, const OrientedBox<T>& b) {
  check(a, "oriented box A");
  check(b, "oriented box B");
  return unchecked::separate(a, b);
}

/// Whether the closed oriented box and oriented box share a point (touching counts). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
bool intersect(const OrientedBox<T>& a, const OrientedBox<T>& b) {
  return separate(a, b).intersect;
}

/// RAPID's patch: eps added to every |R_ij| (1e-6 in RAPID, PQP and FCL).
template <class T>
Separation<T> separate_rapid(const OrientedBox<T>& a, const OrientedBox<T>& b, const T& eps = T(1e-6)) {
  check(a, "oriented box A");
  check(b, "oriented box B");
  return detail::obb_obb(a, b, eps, T(0), false);
}

/// Wild Magic's patch: no edge axis when some pair of axes is within the cutoff of parallel.
template <class T>
Separation<T> separate_parallel(const OrientedBox<T>& a, const OrientedBox<T>& b, const T& cutoff = T(1) - T(1e-8)) {
  check(a, "oriented box A");
  check(b, "oriented box B");
  return detail::obb_obb(a, b, T(0), cutoff, true);
}

}  // namespace cdref::book
