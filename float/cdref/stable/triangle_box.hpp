// cdref/stable/triangle_box.hpp - a triangle against an axis-aligned box as careful float code
// writes it: Akenine-Moller's 13 separating axes on the vertices moved to the box's centre
// (book/triangle_box.hpp), the test voxelizers and BVH builders ship. F = float, double, long
// double; same signatures and results as cdref::book.
//
// The chapter's formulation is already this one, so the stable tier is book::separate.
// Error bound (first order in u, the unit roundoff of F). The vertices relative to the box,
// v_k = p_k - c, round once (u |v_k|); the edges e_k = v_k+1 - v_k once more (u |e_k| plus
// the vertices' u (|v_k| + |v_k+1|)).
//  - Box faces (axes 1-3): min_k v_k,i > h_i or max_k v_k,i < -h_i compares rounded
//    coordinates: decided right unless a vertex's coordinate is within u |v_k,i| of -+h_i.
//  - Edge axes e_k x e_j (axes 4-12): p = v_y e_z - v_z e_y over the three vertices against
//    r = h_y |e_z| + h_z |e_y|: each p off by 2u (|v_y e_z| + |v_z e_y|) plus the inputs'
//    rounding (u (|v| + 2 |V|) |e|, V the largest vertex), r by 2u r: decided right unless
//    |p| and r are within about 4u (|v| + |V|) |e| + 2u r.
//  - The normal (axis 0): n = e_0 x (v_2 - v_0) off by about 4u |e|^2 (plus the vertices'
//    rounding times |e|), n . v_0 off by 3u |n| |v_0| + |v_0| |n^ - n|, against
//    sum_i h_i |n_i|: decided right unless they are within about u |e| (7 |e| |v_0| + 4 |V|
//    |v_0| + 4 |e| h) - a band that grows with the triangle's distance from the box times its
//    size squared.
// At range (|v| >> h) every band is u |v| times the edges, so a triangle near the box is decided
// at random once u |v| reaches the box's size, as for every formulation in F. The campaigns
// measure it on the long-range and grazing families.
#pragma once

#include <cdref/book/triangle_box.hpp>

namespace cdref::stable {

template <class F>
Separation<F> separate(const Triangle<F>& tri, const Box<F>& box) {
  return book::separate(tri, box);
}

// The classification without the input checks (see book/common.hpp).
namespace unchecked {
template <class F>
Separation<F> separate(const Triangle<F>& tri, const Box<F>& box) {
  return book::unchecked::separate(tri, box);
}
}  // namespace unchecked

}  // namespace cdref::stable
