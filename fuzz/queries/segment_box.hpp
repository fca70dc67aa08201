// fuzz/queries/segment_box.hpp - the descriptors of segment-box and ray-box (Section 3.3: a
// segment or an infinite ray against an axis-aligned box by 6 separating axes).
#pragma once

#include <cdref/fuzz/families.hpp>
#include <cdref/fuzz/spec.hpp>
#include <cdref/oracle/box_casts.hpp>
#include <cdref/robust/ray_box.hpp>
#include <cdref/robust/separating_axes.hpp>
#include <cdref/stable/segment_box.hpp>

namespace cdref::fuzz::queries {

template <bool Ray>
struct SegmentBox {
  static constexpr int id = Ray ? 9 : 8;
  static constexpr const char* name = Ray ? "ray-box" : "segment-box";
  static constexpr CaseDigest case_digest = Ray ? CaseDigest{59, 0xe72b9537eb51d086u} : CaseDigest{59, 0xac574917cad1deb4u};
  static constexpr const char* cls_name = "intersect";
  static constexpr const char* pred_name = "hit (Algorithm 3.3)";
  static constexpr const char* describe =
      Ray ? "Section 3.3: the infinite ray against an axis-aligned box by separating axes (faces 0-2, d x e_i 3-5): "
            "book::separate; the predicate column is Algorithm 3.3's hit"
          : "Section 3.3: the segment against an axis-aligned box by separating axes (faces 0-2, (t-s) x e_i 3-5): "
            "book::separate; the predicate column is Algorithm 3.3's hit";
  static constexpr bool book_is_truth = true;
  static constexpr const char* full_call = "separate().intersect";
  static constexpr const char* answer_help = spec::sat_help;
  template <class T>
  using Shot = std::conditional_t<Ray, cdref::Ray<T>, Segment<T>>;
  static std::vector<std::string> inputs() {
    return spec::cols({{"source", 3}, {Ray ? "direction" : "target", 3}, {"box_center", 3}, {"box_extent", 3}});
  }
  static std::vector<Output> outputs() { return spec::sat_outputs(); }
  static std::vector<Family> families() { return segment_box_family_list(Ray); }
  template <class T>
  static std::pair<Shot<T>, Box<T>> make(const Inputs& in) {
    return {{spec::col3<T>(in, 0), spec::col3<T>(in, 3)}, {spec::col3<T>(in, 6), spec::col3<T>(in, 9)}};
  }
  template <class T>
  static auto book(const Shot<T>& a, const Box<T>& b, unsigned) { return cdref::book::separate(a, b); }
  // the stable tier (float/cdref/stable/segment_box.hpp: the book's separating axes)
  template <class F>
  static auto stable(const Shot<F>& a, const Box<F>& b, unsigned) { return cdref::stable::separate(a, b); }
  template <class F>
  static bool stable_pred(const Shot<F>& a, const Box<F>& b) { return cdref::stable::separate(a, b).intersect; }
  template <class T>
  static bool stable_bare(const Shot<T>& a, const Box<T>& b) { return cdref::stable::unchecked::separate(a, b).intersect; }
  // the book's classification without its input checks (the `bare` row: see book/common.hpp)
  template <class T>
  static bool bare(const Shot<T>& a, const Box<T>& b) { return cdref::book::unchecked::separate(a, b).intersect; }
  template <class T>
  static bool book_pred(const Shot<T>& a, const Box<T>& b) { return cdref::book::hit(a, b); }
  // the oracle's every output at double from the robust tier's first look where it proves the
  // direction's rounding (robust/sat_first_look.hpp)
  static bool oracle_rounded(const Shot<double>& a, const Box<double>& b, Separation<double>& out) {
    return cdref::robust::separate_rounded(a, b, out);
  }
  template <class F>
  static auto robust(const Shot<F>& a, const Box<F>& b) { return cdref::robust::separate(a, b); }
  template <class F>
  static bool robust_pred(const Shot<F>& a, const Box<F>& b) { return cdref::robust::hit(a, b); }
  template <class F>
  static cdref::robust::Decision robust_decide(const Shot<F>& a, const Box<F>& b) {
    return cdref::robust::decide_separation(a, b);
  }
  // the segment (ray) meets the box exactly when Algorithm 3.3 hits: its oracle decides both
  static bool oracle(const Shot<double>& a, const Box<double>& b, cdref::oracle::Stage* st) {
    return cdref::oracle::classify(a, b, st);
  }
  static int stage(cdref::oracle::Stage s, const Shot<double>& a, const Box<double>& b) {
    return cdref::oracle::staged::at_stage(s, a, b);
  }
  template <class K>
  static auto cgal_make(const Inputs& in) {
    if constexpr (Ray)
      return std::pair{typename K::Ray_3(spec::cgal_point<K>(in, 0), spec::cgal_vector<K>(in, 3)),
                       spec::cgal_cuboid<K>(in, 6, 9)};
    else
      return std::pair{typename K::Segment_3(spec::cgal_point<K>(in, 0), spec::cgal_point<K>(in, 3)),
                       spec::cgal_cuboid<K>(in, 6, 9)};
  }
  template <class A, class C>
  static bool cgal(const A& a, const C& b) { return CGAL::do_intersect(a, b); }
};

}  // namespace cdref::fuzz::queries
