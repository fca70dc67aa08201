/// \file
/// cdref/fan.hpp - a fan of triangles around a shared vertex: the mesh-level shot of Section 3.4
/// (ray-fan-cast, segment-fan-cast), where a shot that slips between two triangles of a closed
/// mesh through their shared edge or vertex is a leak.
///
///   `Fan<T>`    triangles (center, ring[k], ring[k + 1]) for k < n - 1, and (center, ring[n - 1],
///               ring[0]) when closed: n = 2 to 8 ring vertices, closed needs n >= 3. Each
///               triangle is closed and two-sided (primitives.hpp), so neighbours share their edge.
///   `FanCast<S>` the first hit over the fan (smallest lambda_enter, the first triangle on ties) and
///               the number of triangles the shot hits.
#pragma once

#include <array>
#include <string>

#include "primitives.hpp"
#include "results.hpp"

namespace cdref {

/// A fan of n triangles around `center` (see the file's comment).
template <class T>
struct Fan {
  static constexpr int max_ring = 8;  ///< at most this many ring vertices
  Vec3<T> center = zero_vec<T>();     ///< the vertex every triangle shares
  std::array<Vec3<T>, max_ring> ring{};  ///< ring vertices; those from n on are unused
  int n = 0;                          ///< ring vertices in use, 2 to 8
  bool closed = false;                ///< the last ring vertex joins the first
  /// The number of triangles: n when closed, n - 1 otherwise.
  int triangles() const { return closed ? n : n - 1; }
  /// Triangle k: (center, ring[k], ring[(k + 1) % n]).
  Triangle<T> triangle(int k) const { return {{center, ring[k], ring[(k + 1) % n]}}; }
  /// Whether f is true of any triangle (in order, stopping at the first).
  template <class Fn>
  bool any(Fn f) const {
    for (int k = 0; k < triangles(); ++k)
      if (f(triangle(k))) return true;
    return false;
  }
};

/// The first hit of a shot over a fan and the number of its triangles the shot hits.
template <class S>
struct FanCast {
  TriangleCast<S> first;  ///< the cast on the first triangle hit (smallest lambda_enter)
  int hits = 0;           ///< how many triangles the shot hits
};

/// Throws cdref::invalid_input naming `name` when n is outside 2..8, a closed fan has fewer than
/// 3 ring vertices, or a vertex in use is not finite.
template <class T>
void check(const Fan<T>& f, const char* name = "fan") {
  if (f.n < 2 || f.n > Fan<T>::max_ring)
    throw invalid_input(std::string(name) + " has " + std::to_string(f.n) + " ring vertices (2 to 8 are allowed)");
  if (f.closed && f.n < 3) throw invalid_input(std::string(name) + " is closed with 2 ring vertices (3 are needed)");
  detail::check_finite(f.center, name, "centre");
  static const char* const field[8] = {"ring vertex 0", "ring vertex 1", "ring vertex 2", "ring vertex 3",
                                       "ring vertex 4", "ring vertex 5", "ring vertex 6", "ring vertex 7"};
  for (int k = 0; k < f.n; ++k) detail::check_finite(f.ring[k], name, field[k]);
}

}  // namespace cdref
