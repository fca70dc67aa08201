// cdref/robust/length_scale.hpp - a query's inputs scaled by a power of two, exactly, when
// their lengths lie far from 1, for the filters at double whose static bounds hold only in a
// range (the oriented-box casts' and the separating axes' first looks, and the certified
// decisions, separating_axes.hpp, stages_before_whole, that must classify as they do).
//
// Every length of a pair of shapes (the points of a segment or a triangle, a ray's source, a
// box's centre and extents) is multiplied by 2^-k, k = ilogb of the largest of them, and a
// ray's direction by its own 2^-j: the largest of each then lies in [1, 2). Multiplying every
// point by the same power of two is a similarity, and a ray is the same set whatever its
// direction's length, so whether the shapes meet, which separating axis comes first and which
// faces a shot crosses do not change; an oriented box's axes are directions and stay as they
// are. Each product is exact unless it leaves the normal range (ldexp rounds subnormals); the
// scaling is refused then, as it is for lengths that are all zero or not finite.
//
// Where the lengths already lie within 2^+-100 of 1 (and a ray's direction does) nothing is
// scaled: the filters' ranges hold there.
#pragma once

#include <algorithm>
#include <cdref/primitives.hpp>
#include <cmath>

namespace cdref::robust::detail {

struct LengthScale {
  int k = 0, j = 0;  // lengths by 2^-k, a ray's direction by 2^-j
  bool exact = true;
  double scaled(double v, int e) {
    const double r = std::ldexp(v, -e);
    exact = exact && std::ldexp(r, e) == v;
    return r;
  }
  Vec3<double> len(const Vec3<double>& v, int e) { return {scaled(v[0], e), scaled(v[1], e), scaled(v[2], e)}; }
  Segment<double> operator()(const Segment<double>& x) { return {len(x.source, k), len(x.target, k)}; }
  Ray<double> operator()(const Ray<double>& x) { return {len(x.source, k), len(x.direction, j)}; }
  Triangle<double> operator()(const Triangle<double>& x) {
    return {{len(x.vertex[0], k), len(x.vertex[1], k), len(x.vertex[2], k)}};
  }
  Box<double> operator()(const Box<double>& x) { return {len(x.center, k), len(x.extent, k)}; }
  OrientedBox<double> operator()(const OrientedBox<double>& x) { return {len(x.center, k), len(x.extent, k), x.axis}; }
};

inline double largest_of(const Vec3<double>& v) { return std::max({std::fabs(v[0]), std::fabs(v[1]), std::fabs(v[2])}); }
inline double largest_length(const Segment<double>& x) { return std::max(largest_of(x.source), largest_of(x.target)); }
inline double largest_length(const Ray<double>& x) { return largest_of(x.source); }
inline double largest_length(const Triangle<double>& x) {
  return std::max({largest_of(x.vertex[0]), largest_of(x.vertex[1]), largest_of(x.vertex[2])});
}
inline double largest_length(const Box<double>& x) { return std::max(largest_of(x.center), largest_of(x.extent)); }
inline double largest_length(const OrientedBox<double>& x) { return std::max(largest_of(x.center), largest_of(x.extent)); }

enum class Scaling { near_one, scaled, refused };

// The pair (a, b) with its lengths scaled (header): near_one where nothing needs it (as, bs
// untouched), scaled (as, bs and s set), or refused (no exact scaling brings them near 1).
template <class A, class B>
Scaling scale_lengths(const A& a, const B& b, LengthScale& s, A& as, B& bs) {
  constexpr bool ray = std::is_same_v<A, Ray<double>>;
  const double m = std::max(largest_length(a), largest_length(b));
  double md = 0;
  if constexpr (ray) md = largest_of(a.direction);
  const auto near_one = [](double v) { return v >= 0x1p-100 && v <= 0x1p100; };
  if (near_one(m) && (!ray || near_one(md))) return Scaling::near_one;
  if (!(m > 0 && std::isfinite(m)) || (ray && !(md > 0 && std::isfinite(md)))) return Scaling::refused;
  s = LengthScale{};
  s.k = std::ilogb(m);
  s.j = ray ? std::ilogb(md) : 0;
  as = s(a);
  bs = s(b);
  return s.exact ? Scaling::scaled : Scaling::refused;
}

}  // namespace cdref::robust::detail
