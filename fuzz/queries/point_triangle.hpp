// fuzz/queries/point_triangle.hpp - the descriptor of point-triangle (Section 3.4): the point of
// a closed triangle closest to a point, its distance, and whether the point lies on the
// triangle. A query on the generic path: its book (book/point_triangle.hpp), its stable tier,
// a robust tier and an oracle that are the book run through the bounded and exact stages
// (robust/staged.hpp, exact/staged.hpp), its families below; no hand-written filter.
#pragma once

#include <CGAL/Distance_3/Point_3_Segment_3.h>
#include <CGAL/Distance_3/Point_3_Triangle_3.h>

#include <cdref/fuzz/spec.hpp>
#include <cdref/robust/point_triangle.hpp>
#include <cdref/stable/point_triangle.hpp>

#include "../family_tools.hpp"

namespace cdref::fuzz::queries {

namespace point_triangle_families {
using namespace family;

// columns: p, v0, v1, v2
inline void point_tri(Inputs& in, V p, V a, V b, V c) {
  put(in, 0, p);
  put(in, 3, a);
  put(in, 6, b);
  put(in, 9, c);
}
inline void uniform(Inputs& in, Next& next) {
  const V p = uvec(next, -3, 3);
  const V a = uvec(next, -2, 2);
  const V b = uvec(next, -2, 2);
  const V c = uvec(next, -2, 2);
  point_tri(in, p, a, b, c);
}
// A point at `dist` from the point x of a triangle, along a direction of x's normal cone, x an
// interior point of the face, of an edge or a vertex (kind 0, 1, 2): x is then p's closest point
// (up to the rounding of p's coordinates).
inline void near_on(Inputs& in, Next& next, double dist, V offset, int kind) {
  V a, b, c, n;
  do {
    a = offset + uvec(next, -2, 2);
    b = offset + uvec(next, -2, 2);
    c = offset + uvec(next, -2, 2);
    n = cross(b - a, c - a);
  } while (dot(n, n) < 1e-2);
  n = normalized(n);
  const double up = sign(next);
  V x, dir;
  switch (kind) {
    case 0: {  // the face, along +-n
      double s = uni(next, 0.05, 0.9);
      double t = uni(next, 0.05, 0.9);
      if (s + t > 0.95) s *= 0.5, t *= 0.5;
      x = a + s * (b - a) + t * (c - a);
      dir = up * n;
      break;
    }
    case 1: {  // the edge ab, along a mix of +-n and the edge's outward normal
      x = a + uni(next, 0.05, 0.95) * (b - a);
      const double theta = uni(next, 0, 1.5);
      dir = std::cos(theta) * normalized(cross(b - a, n)) + (up * std::sin(theta)) * n;
      break;
    }
    default: {  // the vertex a, along a mix of +-n and the bisector pointing away
      x = a;
      const V out = normalized(-1.0 * (normalized(b - a) + normalized(c - a)));
      const double theta = uni(next, 0, 1.5);
      dir = std::cos(theta) * out + (up * std::sin(theta)) * n;
      break;
    }
  }
  point_tri(in, x + dist * dir, a, b, c);
}
// A point exactly on a triangle of the integer lattice [-2^k, 2^k]^3: a vertex, the midpoint of
// an edge, or a dyadic point of the face ((a + b + 2c) / 4): every coordinate a double, p on the
// closed triangle exactly.
inline void on_lattice(Inputs& in, Next& next, int k) {
  const double m = std::ldexp(1.0, k);
  const auto lattice = [&next, m]() {
    const double x = std::floor(uni(next, -m, m));
    const double y = std::floor(uni(next, -m, m));
    const double z = std::floor(uni(next, -m, m));
    return V{x, y, z};
  };
  const V a = lattice();
  const V b = lattice();
  const V c = lattice();
  switch (pick(next, 3)) {
    case 0: return point_tri(in, c, a, b, c);
    case 1: return point_tri(in, 0.5 * (a + b), a, b, c);
    default: return point_tri(in, 0.25 * (a + b + 2.0 * c), a, b, c);
  }
}
// A point in the triangle's plane z = h (exact), outside it by 2^-k of its size across an edge or
// at a vertex: the region tests are decided in the plane, where the Voronoi boundaries meet.
inline void in_plane(Inputs& in, Next& next, int k) {
  const double h = uni(next, -2, 2);
  const V a{uni(next, -2, 0), uni(next, -2, 0), h};
  const V b{uni(next, 0, 2), uni(next, -2, 0), h};
  const V c{uni(next, -1, 1), uni(next, 0.5, 2), h};
  const double gap = std::ldexp(1.0, -k);
  switch (pick(next, 3)) {
    case 0: {  // across ab (its outward normal is -y-ish in this layout)
      const V x = a + uni(next, 0.05, 0.95) * (b - a);
      const V out = normalized(cross(b - a, V{0, 0, 1}));
      return point_tri(in, x + gap * out, a, b, c);
    }
    case 1: {  // beside the vertex c, along ca's direction continued
      const V d = normalized(c - a);
      return point_tri(in, c + gap * d, a, b, c);
    }
    default: {  // on the boundary of b's Voronoi region: along ab continued, then off it
      const V d = normalized(b - a);
      const V side = normalized(cross(d, V{0, 0, 1}));
      return point_tri(in, b + gap * d + (gap * uni(next, -1, 1)) * side, a, b, c);
    }
  }
}

inline std::vector<Family> list() {
  std::vector<Family> f;
  f.push_back({"uniform", "point in [-3,3]^3, vertices in [-2,2]^3", {0},
               [](Next& next, int, Inputs& in) { uniform(in, next); }});
  f.push_back({"near-touching", "at 2^-k from the face, an edge or a vertex, along its normal cone", tangency_scales(),
               [](Next& next, int k, Inputs& in) {
                 const int kind = pick(next, 3);
                 near_on(in, next, std::ldexp(1.0, -k), V{0, 0, 0}, kind);
               }});
  f.push_back({"on-lattice", "exactly on a triangle of the integer lattice [-2^k,2^k]^3 (a vertex, an edge's midpoint, "
                             "a dyadic face point)",
               range(1, 49, 4), [](Next& next, int k, Inputs& in) { on_lattice(in, next, k); }});
  f.push_back({"in-plane", "in the plane z = h, 2^-k outside an edge or a vertex", tangency_scales(),
               [](Next& next, int k, Inputs& in) { in_plane(in, next, k); }});
  f.push_back({"long-range", "within 1e-9 of the triangle, 10^k from the origin", decades(),
               [](Next& next, int k, Inputs& in) {
                 const int kind = pick(next, 3);
                 const V offset = std::pow(10.0, k) * unit(next);
                 near_on(in, next, uni(next, 0, 1e-9), offset, kind);
               }});
  f.push_back({"degenerate", "zero-area triangles (a segment, a point), slivers, the point on a degenerate triangle",
               {0}, [](Next& next, int, Inputs& in) {
                 const V a = uvec(next, -2, 2);
                 const V b = uvec(next, -2, 2);
                 const V c = uvec(next, -2, 2);
                 switch (pick(next, 5)) {
                   case 0: {  // collinear
                     const V e = a + uni(next, -1, 2) * (b - a);
                     return point_tri(in, uvec(next, -3, 3), a, b, e);
                   }
                   case 1: return point_tri(in, uvec(next, -3, 3), a, a, a);  // a point
                   case 2: return point_tri(in, a, a, b, a + 0.5 * (b - a));  // on a segment's end
                   case 3: return point_tri(in, a, a, a, a);                  // the point itself
                   default: return point_tri(in, uvec(next, -3, 3), a, b, b + std::ldexp(1.0, -40) * (c - b));  // a sliver
                 }
               }});
  f.push_back({"magnitude", "the uniform family scaled by 10^k", magnitudes(),
               [](Next& next, int k, Inputs& in) {
                 uniform(in, next);
                 scaled(in, 12, k);
               }});
  return f;
}
}  // namespace point_triangle_families

struct PointTriangle {
  static constexpr int id = 28;
  static constexpr const char* name = "point-triangle";
  static constexpr CaseDigest case_digest{73, 0x1f52eda1acb0cf14u};
  static constexpr const char* cls_name = "intersect";
  static constexpr const char* pred_name = "intersect";
  static constexpr const char* describe =
      "Section 3.4: book::proximity(point, triangle), the triangle's point closest to p region by region "
      "(witness_a = p, witness_b the closest point, depth 0), and book::intersect (p lies on the triangle)";
  static constexpr bool book_is_truth = true;
  static constexpr const char* full_call = "proximity().intersect";
  static constexpr const char* answer_help =
      "  distance: |x - p|, x the triangle's point closest to p; depth: 0\n"
      "  witness_a_[xyz]: p; witness_b_[xyz]: x\n";
  static std::vector<std::string> inputs() { return spec::cols({{"p", 3}, {"v0", 3}, {"v1", 3}, {"v2", 3}}); }
  static std::vector<Output> outputs() { return spec::prox_outputs(); }
  static std::vector<Family> families() { return point_triangle_families::list(); }
  template <class T>
  static std::pair<Vec3<T>, Triangle<T>> make(const Inputs& in) {
    return {spec::col3<T>(in, 0), {{spec::col3<T>(in, 3), spec::col3<T>(in, 6), spec::col3<T>(in, 9)}}};
  }
  template <class T>
  static auto book(const Vec3<T>& p, const Triangle<T>& t, unsigned w) { return cdref::book::proximity(p, t, w); }
  template <class T>
  static bool book_pred(const Vec3<T>& p, const Triangle<T>& t) { return cdref::book::intersect(p, t); }
  template <class T>
  static bool bare(const Vec3<T>& p, const Triangle<T>& t) { return cdref::book::unchecked::intersect(p, t); }
  template <class F>
  static auto stable(const Vec3<F>& p, const Triangle<F>& t, unsigned w) { return cdref::stable::proximity(p, t, w); }
  template <class F>
  static bool stable_pred(const Vec3<F>& p, const Triangle<F>& t) { return cdref::stable::intersect(p, t); }
  template <class T>
  static bool stable_bare(const Vec3<T>& p, const Triangle<T>& t) { return cdref::stable::unchecked::intersect(p, t); }
  template <class F>
  static auto robust(const Vec3<F>& p, const Triangle<F>& t) { return cdref::robust::proximity(p, t); }
  template <class F>
  static bool robust_pred(const Vec3<F>& p, const Triangle<F>& t) { return cdref::robust::intersect(p, t); }
  template <class F>
  static cdref::robust::Decision robust_decide(const Vec3<F>& p, const Triangle<F>& t) {
    return cdref::robust::decide(p, t);
  }
  // CGAL's exact squared distance from the point to the closed triangle (a zero-area triangle
  // as the segment between its farthest vertices, or its point): 0 iff p lies on it.
  template <class P3, class T3>
  static auto cgal_squared_distance(const P3& p, const T3& t) {
    if (!t.is_degenerate()) return CGAL::squared_distance(p, t);
    const auto [s0, s1] = spec::cgal_span(t);
    using Seg = typename CGAL::Kernel_traits<P3>::Kernel::Segment_3;
    return s0 == s1 ? CGAL::squared_distance(p, s0) : CGAL::squared_distance(p, Seg(s0, s1));
  }
  template <class K>
  static auto cgal_make(const Inputs& in) {
    return std::pair{spec::cgal_point<K>(in, 0),
                     typename K::Triangle_3(spec::cgal_point<K>(in, 3), spec::cgal_point<K>(in, 6), spec::cgal_point<K>(in, 9))};
  }
  // CGAL's predicates (exact in Epick too): Triangle_3::has_on, and for a zero-area triangle
  // Segment_3::has_on on the segment between its farthest vertices, or point equality.
  template <class P3, class T3>
  static bool cgal(const P3& p, const T3& t) {
    if (!t.is_degenerate()) return t.has_on(p);
    const auto [s0, s1] = spec::cgal_span(t);
    using Seg = typename CGAL::Kernel_traits<P3>::Kernel::Segment_3;
    return s0 == s1 ? p == s0 : Seg(s0, s1).has_on(p);
  }
};

}  // namespace cdref::fuzz::queries
