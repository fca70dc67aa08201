// fuzz/queries/box_casts.hpp - the descriptors of the casts on an axis-aligned box (Section
// 3.2.1, Algorithm 3.3): segment-box-cast and ray-box-cast.
#pragma once

#include <cdref/fuzz/families.hpp>
#include <cdref/fuzz/spec.hpp>
#include <cdref/oracle/box_casts.hpp>
#include <cdref/oracle/enter_box.hpp>
#include <cdref/robust/ray_box.hpp>
#include <cdref/stable/ray_box.hpp>

namespace cdref::fuzz::queries {

// Ray: true for the infinite ray (source, direction), false for the segment (source, target).
template <bool Ray>
struct BoxCast {
  static constexpr int id = Ray ? 6 : 5;
  static constexpr const char* name = Ray ? "ray-box-cast" : "segment-box-cast";
  static constexpr CaseDigest case_digest = Ray ? CaseDigest{46, 0x06b01d20a59c3d14u} : CaseDigest{46, 0xb2d3aab6ed195352u};
  static constexpr const char* cls_name = "hit";
  static constexpr const char* pred_name = "hit";
  static constexpr const char* describe = Ray ? "Algorithm 3.3 on the infinite ray: book::cast and book::hit"
                                              : "Algorithm 3.3 on the segment source->target: book::cast and book::hit";
  static constexpr bool book_is_truth = true;
  static constexpr const char* full_call = "cast().hit";
  static constexpr const char* answer_help = spec::cast_help;
  template <class T>
  using Shot = std::conditional_t<Ray, cdref::Ray<T>, Segment<T>>;
  static std::vector<std::string> inputs() {
    return spec::cols({{"source", 3}, {Ray ? "direction" : "target", 3}, {"center", 3}, {"extent", 3}});
  }
  static std::vector<Output> outputs() { return spec::cast_outputs(); }
  static std::vector<Family> families() { return box_shot_family_list(Ray); }
  template <class T>
  static std::pair<Shot<T>, Box<T>> make(const Inputs& in) {
    return {{spec::col3<T>(in, 0), spec::col3<T>(in, 3)}, {spec::col3<T>(in, 6), spec::col3<T>(in, 9)}};
  }
  template <class T>
  static auto book(const Shot<T>& a, const Box<T>& b, unsigned w) { return cdref::book::cast(a, b, w); }
  // the stable tier (float/cdref/stable/ray_box.hpp)
  template <class F>
  static auto stable(const Shot<F>& a, const Box<F>& b, unsigned w) { return cdref::stable::cast(a, b, w); }
  template <class F>
  static bool stable_pred(const Shot<F>& a, const Box<F>& b) { return cdref::stable::hit(a, b); }
  template <class T>
  static bool stable_bare(const Shot<T>& a, const Box<T>& b) { return cdref::stable::unchecked::hit(a, b); }
  // the book's classification without its input checks (the `bare` row: see book/common.hpp)
  template <class T>
  static bool bare(const Shot<T>& a, const Box<T>& b) { return cdref::book::unchecked::hit(a, b); }
  template <class T>
  static bool book_pred(const Shot<T>& a, const Box<T>& b) { return cdref::book::hit(a, b); }
  template <class F>
  static auto robust(const Shot<F>& a, const Box<F>& b) { return cdref::robust::cast(a, b); }
  template <class F>
  static bool robust_pred(const Shot<F>& a, const Box<F>& b) { return cdref::robust::hit(a, b); }
  template <class F>
  static cdref::robust::Decision robust_decide(const Shot<F>& a, const Box<F>& b) { return cdref::robust::decide(a, b); }
  static bool oracle(const Shot<double>& a, const Box<double>& b, cdref::oracle::Stage* st) {
    return cdref::oracle::classify(a, b, st);
  }
  static cdref::oracle::Entry oracle_enter(const Shot<double>& a, const Box<double>& b, bool* exact_used) {
    return cdref::oracle::enter(a, b, exact_used);
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
