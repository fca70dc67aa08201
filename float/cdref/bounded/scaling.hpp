// cdref/bounded/scaling.hpp - a pair of primitives with every length scaled by one power of two,
// so that the largest lies in [1, 2): the robust tier's double-word evaluation
// (robust/words.hpp) and the filters' double-word stages (word_bounds.hpp, in_word_range) run
// on such pairs. The lengths are the coordinates, extents, radii and a ray's direction
// (fields.hpp's for_each_length); an oriented box's axes are not lengths and are left as they
// are. Every decision is unchanged (the solids scale by 2^k; a ray's set does not depend on its
// direction's length), and so are parameters and unit normals, while points and distances
// scale by 2^k and are scaled back. The scaling is exact unless a scaled value leaves the
// normal range: scale_of then answers k = 0.
#pragma once

#include <algorithm>
#include <cdref/bounded/eft.hpp>
#include <cdref/fields.hpp>
#include <cdref/vec.hpp>
#include <cmath>
#include <type_traits>

namespace cdref::scaling {

/// Every length scaled by 2^k.
struct Scale {
  int k = 0;  ///< the power of two
  /// x 2^k: at double a product with 2^k when that is a normal number (the same correctly
  /// rounded value as std::ldexp, underflow and overflow included, without the library call).
  template <class F>
  F len(F x) const {
    if constexpr (std::is_same_v<F, double>)
      if (k >= -1022 && k <= 1023) return x * eft::exp2_of<double>(k);
    return std::ldexp(x, k);
  }
  /// A vector's components, each as len(x).
  template <class F>
  Vec3<F> len(const Vec3<F>& v) const { return Vec3<F>(len(v[0]), len(v[1]), len(v[2])); }
};
/// m = max(m, |x|).
template <class F>
void largest(F x, F& m) { m = std::max(m, F(std::fabs(x))); }
/// ... over a vector's components.
template <class F>
void largest(const Vec3<F>& v, F& m) { for (int i = 0; i < 3; ++i) largest(v[i], m); }
/// ... over a primitive's lengths (an oriented box's axes are not lengths).
template <template <class> class P, class F>
void largest(const P<F>& p, F& m) {
  for_each_length(p, [&](const auto& x) { largest(x, m); });
}
/// A primitive with every length scaled by 2^k.
template <template <class> class P, class F>
P<F> scaled(P<F> p, const Scale& c) {
  for_each_length(p, [&](auto& x) { x = c.len(x); });
  return p;
}
/// The power of two that brings the largest length of a and b to [1, 2); k = 0 where there is
/// none (every length 0, or one not finite) or where scaling and scaling back would not give
/// both primitives again (a scaled length outside the normal range).
template <template <class> class A, template <class> class B, class F>
Scale scale_of(const A<F>& a, const B<F>& b) {
  F m = F(0);
  largest(a, m);
  largest(b, m);
  Scale sc;
  if (m > F(0) && std::isfinite(m)) {
    sc.k = -eft::exponent_of(m);
    const Scale back{-sc.k};
    if (!same_lengths(scaled(scaled(a, sc), back), a) || !same_lengths(scaled(scaled(b, sc), back), b)) sc.k = 0;
  }
  return sc;
}

}  // namespace cdref::scaling
