// fuzz/queries/polygons.hpp - the descriptors of the Section 3.4 polygon queries: ray and segment
// casts on a polygon, polygon-polygon, polygon-box and polygon-sphere, each the triangle query
// over the polygon's fan (book/polygon.hpp), in the three tiers.
#pragma once

#include <CGAL/Intersections_3/Iso_cuboid_3_Triangle_3.h>
#include <CGAL/Intersections_3/Ray_3_Triangle_3.h>
#include <CGAL/Intersections_3/Segment_3_Triangle_3.h>
#include <CGAL/Intersections_3/Triangle_3_Triangle_3.h>

#include <cdref/fuzz/families.hpp>
#include <cdref/fuzz/spec.hpp>
#include <cdref/oracle/enter_triangle.hpp>
#include <cdref/oracle/polygon.hpp>
#include <cdref/robust/polygon.hpp>
#include <cdref/stable/polygon.hpp>

#include "triangle_triangle.hpp"

namespace cdref::fuzz::spec {

// A polygon's columns: n, then p0_[xyz] .. p7_[xyz] (after `prefix`).
inline std::vector<std::string> polygon_cols(const std::string& prefix) {
  std::vector<std::string> out{prefix + "n"};
  for (int i = 0; i < Polygon<double>::max_vertices; ++i)
    for (const char* ax : {"x", "y", "z"}) out.push_back(prefix + "p" + std::to_string(i) + "_" + ax);
  return out;
}
template <class T>
Polygon<T> polygon(const Inputs& in, int k, const std::string& prefix = "") {
  const double n = in[k];
  if (!(n >= 3 && n <= Polygon<T>::max_vertices && n == std::floor(n)))
    throw invalid_input((prefix.empty() ? std::string("polygon: n") : "polygon " + prefix.substr(0, prefix.size() - 1) + ": " + prefix + "n") +
                        " must be a whole number of vertices from 3 to 8 (" + shown(n) + ")");
  Polygon<T> p;
  p.n = int(n);
  unused_finite(in, k + 1 + 3 * p.n, k + 1 + 3 * Polygon<T>::max_vertices, k + 1 + 3 * p.n, "p", p.n, prefix);
  for (int i = 0; i < p.n; ++i) p.vertex[i] = col3<T>(in, k + 1 + 3 * i);
  return p;
}
// CGAL's fan triangles of a polygon's columns (zero-area ones as the segments or points they span).
template <class K>
std::vector<typename K::Triangle_3> cgal_fan(const Inputs& in, int k) {
  std::vector<typename K::Triangle_3> out;
  const int n = int(in[k]);
  for (int i = 1; i + 1 < n; ++i)
    out.emplace_back(cgal_point<K>(in, k + 1), cgal_point<K>(in, k + 1 + 3 * i), cgal_point<K>(in, k + 4 + 3 * i));
  return out;
}

}  // namespace cdref::fuzz::spec

namespace cdref::fuzz::queries {

template <bool Ray>
struct PolygonCast {
  static constexpr int id = Ray ? 23 : 24;
  static constexpr const char* name = Ray ? "ray-polygon-cast" : "segment-polygon-cast";
  static constexpr CaseDigest case_digest = Ray ? CaseDigest{45, 0xc4f2835a7cbb433au} : CaseDigest{45, 0x284537f00a075f3du};
  static constexpr const char* cls_name = "hit";
  static constexpr const char* pred_name = "hit";
  static constexpr const char* describe =
      Ray ? "Section 3.4: the infinite ray on a polygon (the union of its fan triangles v0, v_i, v_i+1): "
            "book::cast over the fan (first hit, last exit) and book::hit"
          : "Section 3.4: the segment source->target on a polygon (the union of its fan triangles v0, v_i, "
            "v_i+1): book::cast over the fan (first hit, last exit) and book::hit";
  static constexpr bool book_is_truth = true;
  static constexpr const char* full_call = "cast().hit";
  static constexpr const char* answer_help =
      "  lambda_enter, lambda_exit: the hit interval over the polygon (graded only where both say hit)\n"
      "  point_[xyz]: the entry point; normal_[xyz]: the unit normal there of the fan triangle first hit,\n"
      "  facing the source (0 when the source lies in its plane)\n";
  template <class T>
  using Shot = std::conditional_t<Ray, cdref::Ray<T>, Segment<T>>;
  static std::vector<std::string> inputs() {
    return spec::concat(spec::cols({{"source", 3}, {Ray ? "direction" : "target", 3}}), spec::polygon_cols(""));
  }
  static std::vector<Output> outputs() { return spec::cast_outputs(); }
  static std::vector<Family> families() { return polygon_shot_family_list(Ray); }
  template <class T>
  static std::pair<Shot<T>, Polygon<T>> make(const Inputs& in) {
    return {{spec::col3<T>(in, 0), spec::col3<T>(in, 3)}, spec::polygon<T>(in, 6)};
  }
  template <class T>
  static auto book(const Shot<T>& a, const Polygon<T>& b, unsigned w) { return cdref::book::cast(a, b, w); }
  // the stable tier (float/cdref/stable/polygon.hpp: the watertight cast on each fan triangle)
  template <class F>
  static auto stable(const Shot<F>& a, const Polygon<F>& b, unsigned w) { return cdref::stable::cast(a, b, w); }
  template <class F>
  static bool stable_pred(const Shot<F>& a, const Polygon<F>& b) { return cdref::stable::hit(a, b); }
  template <class T>
  static bool stable_bare(const Shot<T>& a, const Polygon<T>& b) { return cdref::stable::unchecked::hit(a, b); }
  // the book's classification without its input checks (the `bare` row: see book/common.hpp)
  template <class T>
  static bool bare(const Shot<T>& a, const Polygon<T>& b) { return cdref::book::unchecked::hit(a, b); }
  template <class T>
  static bool book_pred(const Shot<T>& a, const Polygon<T>& b) { return cdref::book::hit(a, b); }
  template <class F>
  static auto robust(const Shot<F>& a, const Polygon<F>& b) { return cdref::robust::cast(a, b); }
  template <class F>
  static bool robust_pred(const Shot<F>& a, const Polygon<F>& b) { return cdref::robust::hit(a, b); }
  template <class F>
  static cdref::robust::Decision robust_decide(const Shot<F>& a, const Polygon<F>& b) {
    return cdref::robust::decide(a, b);
  }
  static bool oracle(const Shot<double>& a, const Polygon<double>& b, cdref::oracle::Stage* st) {
    return cdref::oracle::classify(a, b, st);
  }
  static cdref::oracle::Entry oracle_enter(const Shot<double>& a, const Polygon<double>& b, bool* exact_used) {
    return cdref::oracle::enter(a, b, exact_used);
  }
  static int stage(cdref::oracle::Stage s, const Shot<double>& a, const Polygon<double>& b) {
    return cdref::oracle::polygon::at_stage(s, a, b);
  }
};

struct PolygonPolygon {
  static constexpr int id = 25;
  static constexpr const char* name = "polygon-polygon";
  static constexpr CaseDigest case_digest{45, 0x1f81512a574ca674u};
  static constexpr const char* cls_name = "intersect";
  static constexpr const char* pred_name = "intersect";
  static constexpr const char* describe =
      "Section 3.4: two polygons (each the union of its fan triangles): book::intersect, triangle-triangle over "
      "every pair of fan triangles";
  static constexpr bool book_is_truth = true;
  static constexpr const char* full_call = "intersect()";
  static constexpr const char* answer_help = "  (no values: the classification alone)\n";
  static std::vector<std::string> inputs() { return spec::concat(spec::polygon_cols("a_"), spec::polygon_cols("b_")); }
  static std::vector<Output> outputs() { return {}; }
  static std::vector<Family> families() { return polygon_polygon_family_list(); }
  template <class T>
  static std::pair<Polygon<T>, Polygon<T>> make(const Inputs& in) {
    return {spec::polygon<T>(in, 0, "a_"), spec::polygon<T>(in, 25, "b_")};
  }
  template <class T>
  static bool book(const Polygon<T>& a, const Polygon<T>& b, unsigned) { return cdref::book::intersect(a, b); }
  // the stable tier (float/cdref/stable/polygon.hpp: the book's, triangle-triangle over the fan pairs)
  template <class F>
  static bool stable(const Polygon<F>& a, const Polygon<F>& b, unsigned) { return cdref::stable::intersect(a, b); }
  template <class F>
  static bool stable_pred(const Polygon<F>& a, const Polygon<F>& b) { return cdref::stable::intersect(a, b); }
  template <class T>
  static bool stable_bare(const Polygon<T>& a, const Polygon<T>& b) { return cdref::book::unchecked::intersect(a, b); }
  // the book's classification without its input checks (the `bare` row: see book/common.hpp)
  template <class T>
  static bool bare(const Polygon<T>& a, const Polygon<T>& b) { return cdref::book::unchecked::intersect(a, b); }
  template <class T>
  static bool book_pred(const Polygon<T>& a, const Polygon<T>& b) { return cdref::book::intersect(a, b); }
  template <class F>
  static bool robust(const Polygon<F>& a, const Polygon<F>& b) { return cdref::robust::intersect(a, b); }
  template <class F>
  static bool robust_pred(const Polygon<F>& a, const Polygon<F>& b) { return cdref::robust::intersect(a, b); }
  template <class F>
  static cdref::robust::Decision robust_decide(const Polygon<F>& a, const Polygon<F>& b) {
    return cdref::robust::decide(a, b);
  }
  static bool oracle(const Polygon<double>& a, const Polygon<double>& b, cdref::oracle::Stage* st) {
    return cdref::oracle::classify(a, b, st);
  }
  static int stage(cdref::oracle::Stage s, const Polygon<double>& a, const Polygon<double>& b) {
    return cdref::oracle::polygon::at_stage(s, a, b);
  }
  template <class K>
  static auto cgal_make(const Inputs& in) {
    return std::pair{spec::cgal_fan<K>(in, 0), spec::cgal_fan<K>(in, 25)};
  }
  template <class V>
  static bool cgal(const V& a, const V& b) {
    for (const auto& x : a)
      for (const auto& y : b)
        if (TriangleTriangle::cgal(x, y)) return true;
    return false;
  }
};

struct PolygonBox {
  static constexpr int id = 26;
  static constexpr const char* name = "polygon-box";
  static constexpr CaseDigest case_digest{45, 0xd73b4b5dbd8c1783u};
  static constexpr const char* cls_name = "intersect";
  static constexpr const char* pred_name = "intersect";
  static constexpr const char* describe =
      "Section 3.4: a polygon (the union of its fan triangles) and an axis-aligned box: book::intersect, the "
      "triangle-box separating-axis test (13 axes) on every fan triangle";
  static constexpr bool book_is_truth = true;
  static constexpr const char* full_call = "intersect()";
  static constexpr const char* answer_help = "  (no values: the classification alone)\n";
  static std::vector<std::string> inputs() {
    return spec::concat(spec::polygon_cols(""), spec::cols({{"box_center", 3}, {"box_extent", 3}}));
  }
  static std::vector<Output> outputs() { return {}; }
  static std::vector<Family> families() { return polygon_box_family_list(); }
  template <class T>
  static std::pair<Polygon<T>, Box<T>> make(const Inputs& in) {
    return {spec::polygon<T>(in, 0), {spec::col3<T>(in, 25), spec::col3<T>(in, 28)}};
  }
  template <class T>
  static bool book(const Polygon<T>& a, const Box<T>& b, unsigned) { return cdref::book::intersect(a, b); }
  // the stable tier (float/cdref/stable/polygon.hpp: the book's, triangle-box over the fan)
  template <class F>
  static bool stable(const Polygon<F>& a, const Box<F>& b, unsigned) { return cdref::stable::intersect(a, b); }
  template <class F>
  static bool stable_pred(const Polygon<F>& a, const Box<F>& b) { return cdref::stable::intersect(a, b); }
  template <class T>
  static bool stable_bare(const Polygon<T>& a, const Box<T>& b) { return cdref::book::unchecked::intersect(a, b); }
  // the book's classification without its input checks (the `bare` row: see book/common.hpp)
  template <class T>
  static bool bare(const Polygon<T>& a, const Box<T>& b) { return cdref::book::unchecked::intersect(a, b); }
  template <class T>
  static bool book_pred(const Polygon<T>& a, const Box<T>& b) { return cdref::book::intersect(a, b); }
  template <class F>
  static bool robust(const Polygon<F>& a, const Box<F>& b) { return cdref::robust::intersect(a, b); }
  template <class F>
  static bool robust_pred(const Polygon<F>& a, const Box<F>& b) { return cdref::robust::intersect(a, b); }
  template <class F>
  static cdref::robust::Decision robust_decide(const Polygon<F>& a, const Box<F>& b) {
    return cdref::robust::decide(a, b);
  }
  static bool oracle(const Polygon<double>& a, const Box<double>& b, cdref::oracle::Stage* st) {
    return cdref::oracle::classify(a, b, st);
  }
  static int stage(cdref::oracle::Stage s, const Polygon<double>& a, const Box<double>& b) {
    return cdref::oracle::polygon::at_stage(s, a, b);
  }
  template <class K>
  static auto cgal_make(const Inputs& in) {
    return std::pair{spec::cgal_fan<K>(in, 0), spec::cgal_cuboid<K>(in, 25, 28)};
  }
  template <class V, class C>
  static bool cgal(const V& fan, const C& box) {
    using K = typename CGAL::Kernel_traits<C>::Kernel;
    for (const auto& t : fan) {
      if (!t.is_degenerate()) {
        if (CGAL::do_intersect(t, box)) return true;
        continue;
      }
      const auto [s0, s1] = spec::cgal_span(t);
      if (s0 == s1 ? box.has_on_bounded_side(s0) || box.has_on_boundary(s0)
                   : CGAL::do_intersect(typename K::Segment_3(s0, s1), box))
        return true;
    }
    return false;
  }
};

struct PolygonSphere {
  static constexpr int id = 27;
  static constexpr const char* name = "polygon-sphere";
  static constexpr CaseDigest case_digest{45, 0xdeec5f72e74bfe80u};
  static constexpr const char* cls_name = "intersect";
  static constexpr const char* pred_name = "intersect";
  static constexpr const char* describe =
      "Section 3.4: a polygon (the union of its fan triangles) and a sphere: book::proximity(sphere, polygon), "
      "the sphere-triangle query on the fan triangle nearest the centre (witness_a on the sphere), and "
      "book::intersect";
  static constexpr bool book_is_truth = true;
  static constexpr const char* full_call = "proximity().intersect";
  static constexpr const char* answer_help = spec::prox_help;
  static std::vector<std::string> inputs() {
    return spec::concat(spec::polygon_cols(""), spec::cols({{"center", 3}, {"radius", 1}}));
  }
  static std::vector<Output> outputs() { return spec::prox_outputs(); }
  static std::vector<Family> families() { return polygon_sphere_family_list(); }
  template <class T>
  static std::pair<Sphere<T>, Polygon<T>> make(const Inputs& in) {
    return {{spec::col3<T>(in, 25), T(in[28])}, spec::polygon<T>(in, 0)};
  }
  template <class T>
  static auto book(const Sphere<T>& a, const Polygon<T>& b, unsigned w) { return cdref::book::proximity(a, b, w); }
  // the stable tier (float/cdref/stable/polygon.hpp: the book's, the nearest fan triangle)
  template <class F>
  static auto stable(const Sphere<F>& a, const Polygon<F>& b, unsigned w) { return cdref::stable::proximity(a, b, w); }
  template <class F>
  static bool stable_pred(const Sphere<F>& a, const Polygon<F>& b) { return cdref::stable::intersect(a, b); }
  template <class T>
  static bool stable_bare(const Sphere<T>& a, const Polygon<T>& b) { return cdref::stable::unchecked::intersect(a, b); }
  // the book's classification without its input checks (the `bare` row: see book/common.hpp)
  template <class T>
  static bool bare(const Sphere<T>& a, const Polygon<T>& b) { return cdref::book::unchecked::intersect(a, b); }
  template <class T>
  static bool book_pred(const Sphere<T>& a, const Polygon<T>& b) { return cdref::book::intersect(a, b); }
  template <class F>
  static auto robust(const Sphere<F>& a, const Polygon<F>& b) { return cdref::robust::proximity(a, b); }
  template <class F>
  static bool robust_pred(const Sphere<F>& a, const Polygon<F>& b) { return cdref::robust::intersect(a, b); }
  template <class F>
  static cdref::robust::Decision robust_decide(const Sphere<F>& a, const Polygon<F>& b) {
    return cdref::robust::decide(a, b);
  }
  static bool oracle(const Sphere<double>& a, const Polygon<double>& b, cdref::oracle::Stage* st) {
    return cdref::oracle::classify(a, b, st);
  }
  // every output correctly rounded at double, first from the robust tier's first look where its
  // bounds prove each rounding (spec.hpp, oracle_truth_of)
  static bool oracle_rounded(const Sphere<double>& a, const Polygon<double>& b, Proximity<double>& out) {
    return cdref::robust::proximity_rounded(a, b, out);
  }
  static int stage(cdref::oracle::Stage s, const Sphere<double>& a, const Polygon<double>& b) {
    return cdref::oracle::polygon::at_stage(s, a, b);
  }
};

}  // namespace cdref::fuzz::queries
