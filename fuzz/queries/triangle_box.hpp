// fuzz/queries/triangle_box.hpp - the descriptor of triangle-box (Section 3.3: Akenine-Moller's
// 13 separating axes).
#pragma once

#include <cdref/fuzz/families.hpp>
#include <cdref/fuzz/spec.hpp>
#include <cdref/oracle/separating_axes.hpp>
#include <cdref/robust/separating_axes.hpp>
#include <cdref/stable/triangle_box.hpp>

namespace cdref::fuzz::queries {

struct TriangleBox {
  static constexpr int id = 10;
  static constexpr const char* name = "triangle-box";
  static constexpr CaseDigest case_digest{73, 0x7dce537c19ce1839u};
  static constexpr const char* cls_name = "intersect";
  static constexpr const char* pred_name = "Theorem 3.1 on the polytopes";
  static constexpr const char* describe =
      "Section 3.3: a triangle against an axis-aligned box by 13 separating axes (normal 0, box faces 1-3, "
      "edge k x e_j 4+3k+j): book::separate (Akenine-Moller); the predicate column is Theorem 3.1 on the two "
      "polytopes (book::separate on polytope())";
  static constexpr bool book_is_truth = true;
  static constexpr const char* full_call = "separate().intersect";
  static constexpr const char* answer_help = spec::sat_help;
  static std::vector<std::string> inputs() {
    return spec::cols({{"v0", 3}, {"v1", 3}, {"v2", 3}, {"box_center", 3}, {"box_extent", 3}});
  }
  static std::vector<Output> outputs() { return spec::sat_outputs(); }
  static std::vector<Family> families() { return triangle_box_family_list(); }
  template <class T>
  static std::pair<Triangle<T>, Box<T>> make(const Inputs& in) {
    return {{{spec::col3<T>(in, 0), spec::col3<T>(in, 3), spec::col3<T>(in, 6)}},
            {spec::col3<T>(in, 9), spec::col3<T>(in, 12)}};
  }
  template <class T>
  static auto book(const Triangle<T>& a, const Box<T>& b, unsigned) { return cdref::book::separate(a, b); }
  // the stable tier (float/cdref/stable/triangle_box.hpp: the book's 13 axes)
  template <class F>
  static auto stable(const Triangle<F>& a, const Box<F>& b, unsigned) { return cdref::stable::separate(a, b); }
  template <class F>
  static bool stable_pred(const Triangle<F>& a, const Box<F>& b) { return cdref::stable::separate(a, b).intersect; }
  template <class T>
  static bool stable_bare(const Triangle<T>& a, const Box<T>& b) { return cdref::stable::unchecked::separate(a, b).intersect; }
  // the book's classification without its input checks (the `bare` row: see book/common.hpp)
  template <class T>
  static bool bare(const Triangle<T>& a, const Box<T>& b) { return cdref::book::unchecked::separate(a, b).intersect; }
  template <class T>
  static bool book_pred(const Triangle<T>& a, const Box<T>& b) {
    return cdref::book::separate_polytopes(a, b, "triangle", "box").intersect;
  }
  // the oracle's every output at double from the robust tier's first look where it proves the
  // direction's rounding (robust/sat_first_look.hpp)
  static bool oracle_rounded(const Triangle<double>& a, const Box<double>& b, Separation<double>& out) {
    return cdref::robust::separate_rounded(a, b, out);
  }
  template <class F>
  static auto robust(const Triangle<F>& a, const Box<F>& b) { return cdref::robust::separate(a, b); }
  template <class F>
  static bool robust_pred(const Triangle<F>& a, const Box<F>& b) { return cdref::robust::intersect(a, b); }
  template <class F>
  static cdref::robust::Decision robust_decide(const Triangle<F>& a, const Box<F>& b) {
    return cdref::robust::decide(a, b);
  }
  static bool oracle(const Triangle<double>& a, const Box<double>& b, cdref::oracle::Stage* st) {
    return cdref::oracle::classify(a, b, st);
  }
  static int stage(cdref::oracle::Stage s, const Triangle<double>& a, const Box<double>& b) {
    return cdref::oracle::sat::at_stage(s, a, b);
  }
  template <class K>
  static auto cgal_make(const Inputs& in) {
    return std::pair{typename K::Triangle_3(spec::cgal_point<K>(in, 0), spec::cgal_point<K>(in, 3), spec::cgal_point<K>(in, 6)),
                     spec::cgal_cuboid<K>(in, 9, 12)};
  }
  template <class A, class C>
  static bool cgal(const A& a, const C& b) { return CGAL::do_intersect(a, b); }
};

}  // namespace cdref::fuzz::queries
