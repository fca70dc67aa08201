// fuzz/queries/segment_sphere.hpp - the descriptor of segment-sphere (Section 3.1.3,
// Algorithm 3.2).
#pragma once

#include <cdref/fuzz/families.hpp>
#include <cdref/fuzz/spec.hpp>
#include <cdref/oracle/sphere_casts.hpp>
#include <cdref/stable/segment_sphere.hpp>
#include <cdref/robust/segment_sphere.hpp>

namespace cdref::fuzz::queries {

struct SegmentSphere {
  static constexpr int id = 3;
  static constexpr const char* name = "segment-sphere";
  static constexpr CaseDigest case_digest{58, 0xc1375228bd2b12f8u};
  static constexpr const char* cls_name = "intersect";
  static constexpr const char* pred_name = "intersect";
  static constexpr const char* describe =
      "Algorithm 3.2: book::proximity(segment, sphere) and book::intersect (witness_a on the segment)";
  static constexpr bool book_is_truth = true;
  static constexpr const char* full_call = "proximity().intersect";
  static constexpr const char* answer_help = spec::prox_help;
  static std::vector<std::string> inputs() {
    return spec::cols({{"source", 3}, {"target", 3}, {"center", 3}, {"radius", 1}});
  }
  static std::vector<Output> outputs() { return spec::prox_outputs(); }
  static std::vector<Family> families() { return sphere_shot_family_list(false); }
  template <class T>
  static std::pair<Segment<T>, Sphere<T>> make(const Inputs& in) {
    return {{spec::col3<T>(in, 0), spec::col3<T>(in, 3)}, {spec::col3<T>(in, 6), T(in[9])}};
  }
  template <class T>
  static auto book(const Segment<T>& a, const Sphere<T>& b, unsigned w) { return cdref::book::proximity(a, b, w); }
  // the stable tier (float/cdref/stable/segment_sphere.hpp)
  template <class F>
  static auto stable(const Segment<F>& a, const Sphere<F>& b, unsigned w) { return cdref::stable::proximity(a, b, w); }
  template <class F>
  static bool stable_pred(const Segment<F>& a, const Sphere<F>& b) { return cdref::stable::intersect(a, b); }
  template <class T>
  static bool stable_bare(const Segment<T>& a, const Sphere<T>& b) { return cdref::stable::unchecked::intersect(a, b); }
  // the book's classification without its input checks (the `bare` row: see book/common.hpp)
  template <class T>
  static bool bare(const Segment<T>& a, const Sphere<T>& b) { return cdref::book::unchecked::intersect(a, b); }
  template <class T>
  static bool book_pred(const Segment<T>& a, const Sphere<T>& b) { return cdref::book::intersect(a, b); }
  template <class F>
  static auto robust(const Segment<F>& a, const Sphere<F>& b) { return cdref::robust::proximity(a, b); }
  template <class F>
  static bool robust_pred(const Segment<F>& a, const Sphere<F>& b) { return cdref::robust::intersect(a, b); }
  template <class F>
  static cdref::robust::Decision robust_decide(const Segment<F>& a, const Sphere<F>& b) {
    return cdref::robust::decide_closest(a, b);
  }
  static bool oracle(const Segment<double>& a, const Sphere<double>& b, cdref::oracle::Stage* st) {
    return cdref::oracle::classify_segment_sphere(a, b, st);
  }
  static int stage(cdref::oracle::Stage s, const Segment<double>& a, const Sphere<double>& b) {
    return cdref::oracle::staged::at_stage(s, a, b, cdref::oracle::staged::alg32{});
  }
  template <class K>
  static auto cgal_make(const Inputs& in) {
    return std::pair{typename K::Segment_3(spec::cgal_point<K>(in, 0), spec::cgal_point<K>(in, 3)),
                     spec::cgal_ball<K>(in, 6, 9)};
  }
  template <class A, class S3>
  static bool cgal(const A& a, const S3& b) {
    return CGAL::do_intersect(a, b) || b.has_on_bounded_side(a.source());
  }
  // Algorithm 3.1 and Algorithm 3.2 decide the same thing: at an exact type they agree.
  static const char* fuzz_extra(const Inputs& in) {
    const auto [s, sp] = make<CGAL::Gmpq>(in);
    if (cdref::book::hit(s, sp) != cdref::book::intersect(s, sp))
      return "Algorithm 3.1 and Algorithm 3.2 disagree at Gmpq";
    return nullptr;
  }
};

}  // namespace cdref::fuzz::queries
