// fuzz/queries/triangle_casts.hpp - the descriptors of ray-triangle-cast and
// segment-triangle-cast (Section 3.4): Moller-Trumbore with the exact flat cases (book),
// Woop-Benthin-Wald (stable, and robust's values), the orientation filter (oracle).
#pragma once

#include <CGAL/Intersections_3/Ray_3_Triangle_3.h>
#include <CGAL/Intersections_3/Segment_3_Triangle_3.h>

#include <cdref/fuzz/families.hpp>
#include <cdref/fuzz/spec.hpp>
#include <cdref/oracle/enter_triangle.hpp>
#include <cdref/oracle/ray_triangle.hpp>
#include <cdref/robust/ray_triangle.hpp>
#include <cdref/stable/ray_triangle.hpp>

namespace cdref::fuzz::queries {

template <bool Ray>
struct TriangleCast {
  static constexpr int id = Ray ? 18 : 19;
  static constexpr const char* name = Ray ? "ray-triangle-cast" : "segment-triangle-cast";
  static constexpr CaseDigest case_digest = Ray ? CaseDigest{61, 0x8f9e5b5b2a05b159u} : CaseDigest{61, 0x7347b8178c28d613u};
  static constexpr const char* cls_name = "hit";
  static constexpr const char* pred_name = "hit";
  static constexpr const char* describe =
      Ray ? "Section 3.4: the infinite ray on a closed two-sided triangle: book::cast (Moller-Trumbore, with the "
            "flat cases exact) and book::hit (signs of triple products)"
          : "Section 3.4: the segment source->target on a closed two-sided triangle: book::cast (Moller-Trumbore, "
            "with the flat cases exact) and book::hit (signs of triple products)";
  static constexpr bool book_is_truth = true;
  static constexpr const char* full_call = "cast().hit";
  static constexpr const char* answer_help = spec::triangle_cast_help;
  template <class T>
  using Shot = std::conditional_t<Ray, cdref::Ray<T>, Segment<T>>;
  static std::vector<std::string> inputs() {
    return spec::cols({{"source", 3}, {Ray ? "direction" : "target", 3}, {"v0", 3}, {"v1", 3}, {"v2", 3}});
  }
  static std::vector<Output> outputs() { return spec::triangle_cast_outputs(); }
  static std::vector<Family> families() { return triangle_shot_family_list(Ray); }
  template <class T>
  static std::pair<Shot<T>, Triangle<T>> make(const Inputs& in) {
    return {{spec::col3<T>(in, 0), spec::col3<T>(in, 3)},
            {{spec::col3<T>(in, 6), spec::col3<T>(in, 9), spec::col3<T>(in, 12)}}};
  }
  template <class T>
  static auto book(const Shot<T>& a, const Triangle<T>& b, unsigned w) { return cdref::book::cast(a, b, w); }
  // the stable tier (float/cdref/stable/ray_triangle.hpp)
  template <class F>
  static auto stable(const Shot<F>& a, const Triangle<F>& b, unsigned w) { return cdref::stable::cast(a, b, w); }
  template <class F>
  static bool stable_pred(const Shot<F>& a, const Triangle<F>& b) { return cdref::stable::hit(a, b); }
  template <class T>
  static bool stable_bare(const Shot<T>& a, const Triangle<T>& b) { return cdref::stable::unchecked::hit(a, b); }
  // the book's classification without its input checks (the `bare` row: see book/common.hpp)
  template <class T>
  static bool bare(const Shot<T>& a, const Triangle<T>& b) { return cdref::book::unchecked::hit(a, b); }
  template <class T>
  static bool book_pred(const Shot<T>& a, const Triangle<T>& b) { return cdref::book::hit(a, b); }
  template <class F>
  static auto robust(const Shot<F>& a, const Triangle<F>& b) { return cdref::robust::cast(a, b); }
  template <class F>
  static bool robust_pred(const Shot<F>& a, const Triangle<F>& b) { return cdref::robust::hit(a, b); }
  template <class F>
  static cdref::robust::Decision robust_decide(const Shot<F>& a, const Triangle<F>& b) {
    return cdref::robust::decide(a, b);
  }
  static bool oracle(const Shot<double>& a, const Triangle<double>& b, cdref::oracle::Stage* st) {
    return cdref::oracle::classify(a, b, st);
  }
  static cdref::oracle::Entry oracle_enter(const Shot<double>& a, const Triangle<double>& b, bool* exact_used) {
    return cdref::oracle::enter(a, b, exact_used);
  }
  static int stage(cdref::oracle::Stage s, const Shot<double>& a, const Triangle<double>& b) {
    return cdref::oracle::ray_triangle::at_stage(s, a, b);
  }
  // CGAL's Ray_3 / Segment_3 against Triangle_3 (a zero-area triangle: the segment or point it
  // spans, as cdref reads it).
  template <class K>
  static auto cgal_make(const Inputs& in) {
    using P = typename K::Point_3;
    const P s = spec::cgal_point<K>(in, 0);
    const typename K::Triangle_3 t(spec::cgal_point<K>(in, 6), spec::cgal_point<K>(in, 9), spec::cgal_point<K>(in, 12));
    if constexpr (Ray)
      return std::pair{typename K::Ray_3(s, spec::cgal_vector<K>(in, 3)), t};
    else
      return std::pair{typename K::Segment_3(s, spec::cgal_point<K>(in, 3)), t};
  }
  template <class S3, class T3>
  static bool cgal(const S3& shot, const T3& t) {
    using K = typename CGAL::Kernel_traits<T3>::Kernel;
    if constexpr (std::is_same_v<S3, typename K::Segment_3>) {
      if (shot.is_degenerate() && !t.is_degenerate()) return t.has_on(shot.source());
    }
    if (!t.is_degenerate()) return CGAL::do_intersect(shot, t);
    const auto [s0, s1] = spec::cgal_span(t);
    if (s0 == s1) return shot.has_on(s0);
    if constexpr (std::is_same_v<S3, typename K::Segment_3>) {
      if (shot.is_degenerate()) return typename K::Segment_3(s0, s1).has_on(shot.source());
    }
    return CGAL::do_intersect(shot, typename K::Segment_3(s0, s1));
  }
};

}  // namespace cdref::fuzz::queries
