// cdref/stable/obb_obb.hpp - two oriented boxes as careful float code writes them: the 15
// separating axes of Gottschalk, Lin and Manocha read off R = A^T B in A's frame
// (book/obb_obb.hpp), as RAPID, PQP, FCL, GTE and Ericson's Real-Time Collision Detection
// (4.4.1) ship them. F = float, double, long double; same signatures and results as
// cdref::book.
//
// The chapter's formulation is already this one, so the stable tier is book::separate. What it
// leaves out on purpose: the engines' epsilon added to |R_ij| (book::separate_rapid) and the
// cut-off that skips the edge axes of near-parallel boxes (book::separate_parallel). Both are
// absolute constants, right for boxes of one size only; the campaigns measure them as the
// book's variants, and this tier reports the plain test's answer.
//
// Error bound (first order in u, the unit roundoff of F; axes unit to rounding). R_ij = a_i .
// b_j is off by 3u (|R_ij| <= 1), t_i = a_i . (c_B - c_A) by 4u |D| (D = c_B - c_A rounded
// once, then a dot product). Face axis i: |t_i| > hA_i + sum_j hB_j |R_ij| is decided right
// unless the two sides are within 4u |D| + 3u (hA_i + 2 sum_j hB_j); axis b_j the same with
// p = sum_i t_i R_ij (off by 7u |D|) and the roles swapped. Edge axis a_i x b_j:
// p = t_i2 R_i1j - t_i1 R_i2j is off by about 10u |D| (4u |D| per t, 3u |t| per R, one
// rounding per product and one for the difference), the radius ra + rb by 3u (hA + hB)
// relative to the extents plus 3u of every extent for the R it reads: decided right unless
// |p| and ra + rb are within about 10u |D| + 9u (|hA| + |hB|). The edge axis's exact length
// is |a_i x b_j| = sin(theta) for the angle theta between the edges: where theta is below
// about u (|D| + |h|) / (|D| + |h|) the whole test is of the size of its own rounding, and
// near-parallel edges are decided at random, on either side: a false separation is possible
// (the case the engines' epsilon hides by answering "intersect" for parallel edges).
// Against the exact parallelepipeds (the truth: float axes are orthonormal only to rounding)
// this formulation also differs by A^T A - I, a few u |D|: the campaigns report the two
// effects apart (the book at an exact type against the truth).
#pragma once

#include <cdref/book/obb_obb.hpp>

namespace cdref::stable {

template <class F>
Separation<F> separate(const OrientedBox<F>& a, const OrientedBox<F>& b) {
  return book::separate(a, b);
}

// The classification without the input checks (see book/common.hpp).
namespace unchecked {
template <class F>
Separation<F> separate(const OrientedBox<F>& a, const OrientedBox<F>& b) {
  return book::unchecked::separate(a, b);
}
}  // namespace unchecked

}  // namespace cdref::stable
