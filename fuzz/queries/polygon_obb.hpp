// fuzz/queries/polygon_obb.hpp - the descriptor of polygon-obb (Section 3.4): a convex planar
// polygon against an oriented box, the one polygon-volume pair of the section beyond
// polygon-box. On the generic path: its book and truth (book/polygon_obb.hpp), its stable tier,
// a robust tier and an oracle that are the truth run through the bounded and exact stages
// (robust/staged.hpp, exact/staged.hpp); no hand-written filter.
#pragma once

#include <cdref/fuzz/families.hpp>
#include <cdref/fuzz/spec.hpp>
#include <cdref/robust/polygon_obb.hpp>
#include <cdref/stable/polygon_obb.hpp>

#include "polygons.hpp"

namespace cdref::fuzz::queries {

struct PolygonObb {
  static constexpr int id = 29;
  static constexpr const char* name = "polygon-obb";
  static constexpr CaseDigest case_digest{45, 0x9b5d0098206d6848u};
  static constexpr const char* cls_name = "intersect";
  static constexpr const char* pred_name = "Theorem 3.1 with the box's true face normals";
  static constexpr const char* describe =
      "Section 3.4: a polygon (the union of its fan triangles) and an oriented box: book::intersect, "
      "triangle-obb's separating axes in the box's frame on every fan triangle (assuming orthonormal axes); "
      "the predicate column and the truth are Theorem 3.1 on the parallelepiped (solid::intersect)";
  static constexpr bool book_is_truth = false;
  static constexpr const char* full_call = "intersect()";
  static constexpr const char* answer_help = "  (no values: the classification alone)\n";
  static std::vector<std::string> inputs() { return spec::concat(spec::polygon_cols(""), spec::obb_cols("")); }
  static std::vector<Output> outputs() { return {}; }
  // polygon-box's families with the box turned by a random rotation about its centre (the
  // polygon with it), the unused vertex slots left zero
  static std::vector<Family> families() {
    std::vector<int> vertices;
    for (int i = 0; i < Polygon<double>::max_vertices; ++i) vertices.push_back(1 + 3 * i);
    std::vector<Family> list = rotated_family_list(polygon_box_family_list(), vertices, {}, {0}, 25, 28, 25);
    for (Family& f : list)
      f.make = [make = f.make](CaseStream& next, int k, Inputs& in) {
        make(next, k, in);
        const int n = int(in[0]);
        for (int i = 1 + 3 * n; i < 1 + 3 * Polygon<double>::max_vertices; ++i) in[i] = 0;
      };
    return list;
  }
  template <class T>
  static std::pair<Polygon<T>, OrientedBox<T>> make(const Inputs& in) {
    return {spec::polygon<T>(in, 0), spec::obb<T>(in, 25)};
  }
  template <class T>
  static bool book(const Polygon<T>& a, const OrientedBox<T>& b, unsigned) { return cdref::book::intersect(a, b); }
  template <class T>
  static bool book_pred(const Polygon<T>& a, const OrientedBox<T>& b) { return solid::intersect(a, b); }
  template <class T>
  static bool bare(const Polygon<T>& a, const OrientedBox<T>& b) { return cdref::book::unchecked::intersect(a, b); }
  template <class T>
  static bool truth(const Polygon<T>& a, const OrientedBox<T>& b, unsigned) { return solid::intersect(a, b); }
  template <class T>
  static bool truth_pred(const Polygon<T>& a, const OrientedBox<T>& b) { return solid::intersect(a, b); }
  template <class F>
  static bool stable(const Polygon<F>& a, const OrientedBox<F>& b, unsigned) { return cdref::stable::intersect(a, b); }
  template <class F>
  static bool stable_pred(const Polygon<F>& a, const OrientedBox<F>& b) { return cdref::stable::intersect(a, b); }
  template <class T>
  static bool stable_bare(const Polygon<T>& a, const OrientedBox<T>& b) {
    return cdref::stable::unchecked::intersect(a, b);
  }
  template <class F>
  static bool robust(const Polygon<F>& a, const OrientedBox<F>& b) { return cdref::robust::intersect(a, b); }
  template <class F>
  static bool robust_pred(const Polygon<F>& a, const OrientedBox<F>& b) { return cdref::robust::intersect(a, b); }
  template <class F>
  static cdref::robust::Decision robust_decide(const Polygon<F>& a, const OrientedBox<F>& b) {
    return cdref::robust::decide(a, b);
  }
  static std::vector<Implementation> variants() { return {spec::book_exact_variant<PolygonObb>()}; }
};

}  // namespace cdref::fuzz::queries
