// fuzz/queries/triangle_triangle.hpp - the descriptor of triangle-triangle (Section 3.4):
// Moller's interval test with exact zero tests (book), on double words (robust), a plane and
// edge filter (oracle); the variant book-double-eps is Moller's code with its 1e-6 snap.
#pragma once

#include <CGAL/Intersections_3/Segment_3_Segment_3.h>
#include <CGAL/Intersections_3/Segment_3_Triangle_3.h>
#include <CGAL/Intersections_3/Triangle_3_Triangle_3.h>

#include <cdref/fuzz/families.hpp>
#include <cdref/fuzz/spec.hpp>
#include <cdref/oracle/triangle_triangle.hpp>
#include <cdref/robust/triangle_triangle.hpp>
#include <cdref/stable/triangle_triangle.hpp>

namespace cdref::fuzz::queries {

struct TriangleTriangle {
  static constexpr int id = 22;
  static constexpr const char* name = "triangle-triangle";
  static constexpr CaseDigest case_digest{61, 0xa5f6e1ce8ca2e5a2u};
  static constexpr const char* cls_name = "intersect";
  static constexpr const char* pred_name = "intersect";
  static constexpr const char* describe =
      "Section 3.4: book::intersect(triangle, triangle) (Moller's interval test, plane distances compared with 0; "
      "coplanar pairs by the side normals) and book::separate (Theorem 3.1, 17 axes)";
  static constexpr bool book_is_truth = true;
  static constexpr const char* full_call = "intersect().intersect";
  static constexpr const char* answer_help =
      "  coplanar: 1 when both triangles lie in one plane and meet (an area in common; p, q are then 0),\n"
      "  graded where both say intersect, as right or wrong\n"
      "  p_[xyz], q_[xyz]: the ends of the intersection segment, p first in lexicographic order (x, y, z)\n";
  static std::vector<std::string> inputs() {
    return spec::cols({{"a_v0", 3}, {"a_v1", 3}, {"a_v2", 3}, {"b_v0", 3}, {"b_v1", 3}, {"b_v2", 3}});
  }
  static std::vector<Output> outputs() {
    return {{"coplanar", 1, Output::on_hit, true}, {"p", 3, Output::on_hit}, {"q", 3, Output::on_hit}};
  }
  static std::vector<Family> families() { return triangle_triangle_family_list(); }
  template <class T>
  static std::pair<Triangle<T>, Triangle<T>> make(const Inputs& in) {
    return {{{spec::col3<T>(in, 0), spec::col3<T>(in, 3), spec::col3<T>(in, 6)}},
            {{spec::col3<T>(in, 9), spec::col3<T>(in, 12), spec::col3<T>(in, 15)}}};
  }
  template <class T>
  static auto book(const Triangle<T>& a, const Triangle<T>& b, unsigned) { return cdref::book::intersect(a, b); }
  // the stable tier (float/cdref/stable/triangle_triangle.hpp: the book's, no epsilon)
  template <class F>
  static auto stable(const Triangle<F>& a, const Triangle<F>& b, unsigned) { return cdref::stable::intersect(a, b); }
  template <class F>
  static bool stable_pred(const Triangle<F>& a, const Triangle<F>& b) { return cdref::stable::intersect(a, b).intersect; }
  template <class T>
  static bool stable_bare(const Triangle<T>& a, const Triangle<T>& b) { return cdref::stable::unchecked::intersect(a, b); }
  // the book's classification without its input checks (the `bare` row: see book/common.hpp)
  template <class T>
  static bool bare(const Triangle<T>& a, const Triangle<T>& b) { return cdref::book::unchecked::separate(a, b).intersect; }
  template <class T>
  static bool book_pred(const Triangle<T>& a, const Triangle<T>& b) { return cdref::book::separate(a, b).intersect; }
  template <class F>
  static auto robust(const Triangle<F>& a, const Triangle<F>& b) { return cdref::robust::intersect(a, b); }
  template <class F>
  static bool robust_pred(const Triangle<F>& a, const Triangle<F>& b) { return cdref::robust::decide(a, b).value; }
  template <class F>
  static cdref::robust::Decision robust_decide(const Triangle<F>& a, const Triangle<F>& b) {
    return cdref::robust::decide(a, b);
  }
  static bool oracle(const Triangle<double>& a, const Triangle<double>& b, cdref::oracle::Stage* st) {
    return cdref::oracle::classify(a, b, st);
  }
  static int stage(cdref::oracle::Stage s, const Triangle<double>& a, const Triangle<double>& b) {
    return cdref::oracle::triangle_triangle::at_stage(s, a, b);
  }
  // CGAL's Triangle_3 pair (a zero-area triangle: the segment or point it spans).
  template <class K>
  static auto cgal_make(const Inputs& in) {
    auto tri = [&](int k) {
      return typename K::Triangle_3(spec::cgal_point<K>(in, k), spec::cgal_point<K>(in, k + 3),
                                    spec::cgal_point<K>(in, k + 6));
    };
    return std::pair{tri(0), tri(9)};
  }
  template <class T3>
  static bool cgal(const T3& a, const T3& b) {
    using K = typename CGAL::Kernel_traits<T3>::Kernel;
    auto span = [](const T3& t) {
      const auto [s0, s1] = spec::cgal_span(t);
      return typename K::Segment_3(s0, s1);
    };
    const bool da = a.is_degenerate(), db = b.is_degenerate();
    if (!da && !db) return CGAL::do_intersect(a, b);
    if (da && db) {
      const auto sa = span(a), sb = span(b);
      if (sa.is_degenerate()) return sb.is_degenerate() ? sa.source() == sb.source() : sb.has_on(sa.source());
      if (sb.is_degenerate()) return sa.has_on(sb.source());
      return CGAL::do_intersect(sa, sb);
    }
    const auto s = span(da ? a : b);
    const T3& t = da ? b : a;
    return s.is_degenerate() ? t.has_on(s.source()) : CGAL::do_intersect(s, t);
  }
  // Moller's code as shipped: plane distances below 1e-6 in absolute value snapped to 0
  static std::vector<Implementation> variants() {
    return {{"book-double-eps", 53,
             [](Query, const Inputs& in) {
               const auto [a, b] = make<double>(in);
               Answer r;
               spec::put<TriangleTriangle, double>(r, cdref::book::intersect(a, b, 1e-6), true);
               r.pred = r.cls;
               return r;
             },
             {Query{id}}}};
  }
};

}  // namespace cdref::fuzz::queries
