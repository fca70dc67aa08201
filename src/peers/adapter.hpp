// src/peers/adapter.hpp - what `cdref peers` knows of one library function: the adapter that
// maps a query's case onto it in the library's own conventions, and the exact helpers its
// convention tests use. One header per library (src/peers/<library>.hpp) returns its
// adapters; src/peers/peers.cpp grades them through the campaign engine.
#pragma once

#include <CGAL/Gmpq.h>

#include <cdref/fuzz/campaign.hpp>
#include <cdref/validate.hpp>
#include <array>
#include <cdref/error.hpp>
#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

namespace cdref::peers {

using fuzz::Answer;
using fuzz::Inputs;
using fuzz::Query;

/// One library function on one of cdref's queries.
struct Adapter {
  std::string library;   ///< "ODE 0.16.2 (double)": the library, its version and its number type
  std::string function;  ///< the call, as its users write it
  std::string query;     ///< cdref's query it answers
  std::string convention;  ///< where the library's meaning differs from cdref's, in words
  std::vector<std::string> graded;  ///< the output groups it answers
  /// The case's meaning differs under the library's convention, decided exactly on the case as
  /// the function sees it and the engine's exact answer to it: set apart, not graded.
  std::function<bool(const Inputs& in, const Answer& truth)> differs;
  /// The library call on the case (columns as `cdref cases --describe QUERY` lists them).
  std::function<Answer(const Inputs& in)> run;
  /// The type whose ulps measure its error: 24 float, 53 double (0: the executable's own type,
  /// float in `cdref`, double in Bullet's float64 helper).
  int precision = 0;
  /// Optional: told a block of cases before they are run one by one (an adapter whose library
  /// runs in another process answers them in one exchange; fuzz::Implementation::prefetch).
  std::function<void(const Inputs* in, std::size_t n)> prefetch{};
};

/// An output group's index in the query's outputs (its first value's index in *first).
inline int group(Query q, const std::string& g, int* first) { return validate::output_group(fuzz::info(q), g, first); }

/// An answer built group by group: Out(q, hit).set("point", {x, y, z}).a
struct Out {
  Query q;
  Answer a;
  explicit Out(Query q_, bool cls) : q(q_) {
    a.cls = a.pred = cls;
    a.given = 0;
  }
  Out& set(const std::string& g, std::initializer_list<double> v) {
    int first = 0;
    const int k = group(q, g, &first);
    int i = 0;
    for (double x : v) a.v[first + i++] = x;
    a.given |= std::uint64_t(1) << k;
    return *this;
  }
};

// ---- exact helpers: rationals from the doubles of the case ----
using Q = CGAL::Gmpq;
struct QV {
  Q x, y, z;
};
inline QV qv(const Inputs& in, int k) { return {Q(in[k]), Q(in[k + 1]), Q(in[k + 2])}; }
inline QV sub(const QV& a, const QV& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline QV cross(const QV& a, const QV& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline Q dot(const QV& a, const QV& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

/// A ray's source inside or on the sphere (columns: source 0, direction 3, centre 6, radius 9).
inline bool source_inside(const Inputs& in) {
  const QV m = sub(qv(in, 0), qv(in, 6));
  const Q r(in[9]);
  return dot(m, m) <= r * r;
}
/// A ray's or segment's source inside or on the box (columns: source 0, centre 6, extents 9).
inline bool source_in_box(const Inputs& in) {
  for (int i = 0; i < 3; ++i) {
    const Q d = Q(in[i]) - Q(in[6 + i]), h(in[9 + i]);
    if (d > h || -d > h) return false;
  }
  return true;
}
/// A ray lies in the triangle's plane (columns: source 0, direction 3, v0 6, v1 9, v2 12).
inline bool in_plane(const Inputs& in) {
  const QV v0 = qv(in, 6), n = cross(sub(qv(in, 9), v0), sub(qv(in, 12), v0));
  return dot(n, sub(qv(in, 0), v0)) == 0 && dot(n, qv(in, 3)) == 0;
}
/// The reversed ray hits (a line test that also reports hits behind the source), exactly.
inline bool reversed_hits(Query q, const Inputs& in, int precision) {
  Inputs r = in;
  for (int i = 3; i < 6; ++i) r[i] = -r[i];
  return fuzz::oracle_truth(q, r, precision).cls;
}

// ---- a fan's triangles (ray-fan-cast), for the libraries that cast on meshes ----
/// The fan's vertices (the centre, then the ring) and triangles (centre, r_i, r_i+1; closed: also
/// r_n-1, r_0), from ray-fan-cast's columns (n 6, closed 7, centre 8, r_i 11 + 3i).
inline void fan(const Inputs& in, std::vector<float>& v, std::vector<unsigned>& tri) {
  const int n = int(in[6]);
  if (!(in[6] == double(n)) || n < 2 || n > 8) throw invalid_input("the fan's ring has no 2 to 8 vertices");
  for (int k = 8; k < 11 + 3 * n; ++k) v.push_back(float(in[std::size_t(k)]));
  for (unsigned i = 0; i + 1 < unsigned(n); ++i) tri.insert(tri.end(), {0u, 1 + i, 2 + i});
  if (in[7] != 0) tri.insert(tri.end(), {0u, unsigned(n), 1u});
}

/// The fan's triangles as rationals, centre and ring (exact helpers for the conventions).
inline std::vector<std::array<QV, 3>> fan_triangles(const Inputs& in) {
  const int n = int(in[6]);
  std::vector<std::array<QV, 3>> t;
  if (!(in[6] == double(n)) || n < 2 || n > 8) return t;
  const QV c = qv(in, 8);
  for (int i = 0; i + 1 < n; ++i) t.push_back({c, qv(in, 11 + 3 * i), qv(in, 14 + 3 * i)});
  if (in[7] != 0) t.push_back({c, qv(in, 11 + 3 * (n - 1)), qv(in, 11)});
  return t;
}
/// Where Embree's meaning differs on a triangle (and so Open3D's, which casts through it), for
/// the ray source s + t d: a triangle of zero area (never hit), the ray in the triangle's plane
/// (never a hit there), and in default mode (t > tnear = 0) a source in the triangle's plane (a
/// hit at 0 is none).
inline bool triangle_differs(const std::array<QV, 3>& t, const QV& s, const QV& d, bool robust) {
  const QV nrm = cross(sub(t[1], t[0]), sub(t[2], t[0]));
  if (nrm.x == 0 && nrm.y == 0 && nrm.z == 0) return true;
  return dot(nrm, sub(s, t[0])) == 0 && (dot(nrm, d) == 0 || !robust);
}
/// ... and on a fan: on any of its triangles.
inline bool fan_differs(const Inputs& in, bool robust) {
  const QV s = qv(in, 0), d = qv(in, 3);
  for (const auto& t : fan_triangles(in))
    if (triangle_differs(t, s, d, robust)) return true;
  return false;
}

}  // namespace cdref::peers
