/// \file
/// cdref/book/triangle_box.hpp - Section 3.3: a triangle against an axis-aligned box by
/// separating axes, in the formulation of Akenine-Moller ("Fast 3D triangle-box overlap
/// testing", JGT 2001), which nearly every voxelizer and BVH builder ships.
///
/// Theorem 3.1 for a triangle (one face normal n = e_0 x (v_2 - v_0), edge directions
/// e_0 = v_1 - v_0, e_1 = v_2 - v_1, e_2 = v_0 - v_2) and a box (faces and edges e_x, e_y,
/// e_z): 13 axes, tried in this order (cdref's documented order: faces of the triangle, faces
/// of the box, then edge pairs):
///   axis 0            the normal: the plane n . (x - v_0) = 0 misses the box iff
///                     |n . v_0| > sum_i h_i |n_i| (vertices relative to the box centre);
///   axes 1, 2, 3      the box's faces: min_k v_k,i > h_i or max_k v_k,i < -h_i (the
///                     triangle's bounding box against the box);
///   axis 4 + 3k + j   e_k x e_j: the triangle projects onto [min, max] of v . L over its
///                     three vertices (the two ends of edge k project alike), the box onto
///                     +- sum_i h_i |L_i|; e.g. e x e_x = (0, e_z, -e_y): p = v_y e_z - v_z e_y,
///                     r = h_y |e_z| + h_z |e_y|.
/// Zero-area triangles: the normal is 0 and drops out; the edges that remain make it the
/// segment or point test it then is. The triangle is closed and two-sided; the box is
/// closed: touching intersects.
#pragma once

#include "common.hpp"

namespace cdref::book {

namespace detail {

/// e x e_j for an edge e and a box axis j.
template <class T>
Vec3<T> cross_axis(const Vec3<T>& e, int j) {
  if (j == 0) return Vec3<T>(T(0), e[2], T(-e[1]));
  if (j == 1) return Vec3<T>(T(-e[2]), T(0), e[0]);
  return Vec3<T>(e[1], T(-e[0]), T(0));
}

/// The first separating axis of a triangle (vertices relative to the box centre) and the box
/// [-h, h], or -1; `normal` gets the triangle's normal.
template <class T>
int triangle_box_axis(const std::array<Vec3<T>, 3>& v, const Vec3<T>& h, Vec3<T>& normal) {
  const Vec3<T> e[3] = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
  normal = e[0].cross(Vec3<T>(v[2] - v[0]));
  {
    const T p = normal.dot(v[0]);
    const T r = h[0] * abs_of(normal[0]) + h[1] * abs_of(normal[1]) + h[2] * abs_of(normal[2]);
    if (abs_of(p) > r) return 0;
  }
  for (int i = 0; i < 3; ++i) {
    T lo = v[0][i], hi = v[0][i];
    for (int k = 1; k < 3; ++k) {
      if (v[k][i] < lo) lo = v[k][i];
      if (hi < v[k][i]) hi = v[k][i];
    }
    if (lo > h[i] || hi < T(-h[i])) return 1 + i;
  }
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j) {
      const Vec3<T> L = cross_axis(e[k], j);
      // vertices k and k+1 project alike (L is orthogonal to e_k): the other one decides
      const T p0 = v[k].dot(L), p1 = v[(k + 2) % 3].dot(L);
      const T lo = p0 < p1 ? p0 : p1, hi = p0 < p1 ? p1 : p0;
      const T r = h[0] * abs_of(L[0]) + h[1] * abs_of(L[1]) + h[2] * abs_of(L[2]);
      if (lo > r || hi < T(-r)) return 4 + 3 * k + j;
    }
  return -1;
}

}  // namespace detail

namespace detail {
/// The separation on checked input (also the oriented box's, in its frame).
template <class T>
Separation<T> triangle_box(const Triangle<T>& tri, const Box<T>& box) {
  const std::array<Vec3<T>, 3> v = {tri.vertex[0] - box.center, tri.vertex[1] - box.center,
                                    tri.vertex[2] - box.center};
  Vec3<T> n;
  Separation<T> s;
  s.axis = triangle_box_axis(v, box.extent, n);
  s.intersect = s.axis < 0;
  if (s.axis == 0)
    s.direction = n;
  else if (s.axis > 0 && s.axis < 4)
    s.direction = unit_vec<T>(s.axis - 1);
  else if (s.axis >= 4)
    s.direction = cross_axis(Vec3<T>(v[((s.axis - 4) / 3 + 1) % 3] - v[(s.axis - 4) / 3]), (s.axis - 4) % 3);
  return s;
}
}  // namespace detail

namespace unchecked {
/// The same as the checked `separate` of these arguments, on input already checked: no input
/// checks (see book/common.hpp). For loops over bodies checked once.
template <class T>
Separation<T> separate(const Triangle<T>& tri, const Box<T>& box) {
  return detail::triangle_box(tri, box);
}
}  // namespace unchecked

/// Theorem 3.1 on the triangle and the axis-aligned box: whether they intersect, else the first
/// separating axis in this file's order and its direction (a cdref::Separation). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
Separation<T> separate(const Triangle<T>& tri, const Box<T>& box) {
  check(tri, "triangle");
  check(box, "box");
  return unchecked::separate(tri, box);
}

/// Whether the closed triangle and axis-aligned box share a point (touching counts). Throws
/// cdref::invalid_input naming a bad argument.
template <class T>
bool intersect(const Triangle<T>& tri, const Box<T>& box) {
  return separate(tri, box).intersect;
}

}  // namespace cdref::book
