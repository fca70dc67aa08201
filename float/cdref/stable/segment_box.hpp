// cdref/stable/segment_box.hpp - a segment (or an infinite ray) against an axis-aligned box as
// careful float code writes it. F = float, double, long double; same signatures and results as
// cdref::book.
//
// The chapter's six separating axes in the midpoint / half-vector form (book/segment_box.hpp)
// are what engines ship (Gottschalk; Ericson, Real-Time Collision Detection 5.3.3), so the
// stable tier's separation is book::separate, and its classification is the same test. The
// same question without cross products is the slab test of the box casts (stable::hit of
// stable/ray_box.hpp, Algorithm 3.3's question); it does not give a separating axis. Measured
// on this query's families at double: the separating axes misclassify 1,362 of 59,000 segments
// and 3,459 of 59,000 rays (`cdref campaign --query segment-box --query ray-box --impl
// stable-double --n 1000`), 1,245 and 3,332 of them on the magnitude family, where products of
// coordinates near 10^+-300 overflow and underflow; the slab test, on a smaller draw of the same
// families (`CDREF_TEST_REPORT=1 build/release/tests/cdref_tests "stable box casts*"`), 9 and 7
// of 5,576 (Algorithm 3.3's cross-multiplied hit() 85 and 175 of the same cases).
//
// Error bound of separate() (first order in u, the unit roundoff of F). m = (s + t)/2 - c is
// off by at most u (|s + t|/2 + |m|) per component, w = (t - s)/2 by u |w| (a ray: m = s - c
// off by u |m|, w = d exact). Face axis i: |m_i| > h_i + |w_i| is decided right unless the
// two sides are within u (|s_i + t_i|/2 + 2 |m_i| + h_i + 2 |w_i|). Cross axis r x e_0
// (the others cyclically): p = m_y w_z - m_z w_y, two products and a difference, is off by
// 2u (|m_y w_z| + |m_z w_y|) plus the inputs' own error u (|s + t|/2 + |m| + |w|)-weighted
// by |w|, and q = h_y |w_z| + h_z |w_y| by 2u q: |p| > q is decided right unless
// ||p| - q| <= u [(|s_y + t_y|/2 + 4 |m_y|) |w_z| + (|s_z + t_z|/2 + 4 |m_z|) |w_y| + 3 q].
// The band is relative to the segment's offset from the box times its length: at range
// (|m| >> h) a segment near the box is decided at random once u |m| reaches h, as for every
// formulation in F; near a box the products are of the size of h |w| and the band is a few u
// of it.
#pragma once

#include <cdref/book/segment_box.hpp>

namespace cdref::stable {

template <class F>
Separation<F> separate(const Segment<F>& seg, const Box<F>& box) {
  return book::separate(seg, box);
}
template <class F>
Separation<F> separate(const Ray<F>& ray, const Box<F>& box) {
  return book::separate(ray, box);
}

// The classification without the input checks (see book/common.hpp).
namespace unchecked {
template <class F>
Separation<F> separate(const Segment<F>& seg, const Box<F>& box) {
  return book::unchecked::separate(seg, box);
}
template <class F>
Separation<F> separate(const Ray<F>& ray, const Box<F>& box) {
  return book::unchecked::separate(ray, box);
}
}  // namespace unchecked

}  // namespace cdref::stable
