// fuzz/queries/sphere_box.hpp - the descriptor of sphere-box (Section 3.2.2).
#pragma once

#include <cdref/fuzz/families.hpp>
#include <cdref/fuzz/spec.hpp>
#include <cdref/oracle/sphere_box.hpp>
#include <cdref/stable/sphere_box.hpp>
#include <cdref/robust/sphere_box.hpp>

namespace cdref::fuzz::queries {

struct SphereBox {
  static constexpr int id = 7;
  static constexpr const char* name = "sphere-box";
  static constexpr CaseDigest case_digest{45, 0x9012485dd99872a2u};
  static constexpr const char* cls_name = "intersect";
  static constexpr const char* pred_name = "intersect";
  static constexpr const char* describe =
      "Section 3.2.2: book::proximity(sphere, box) and book::intersect (witness_a on the sphere)";
  static constexpr bool book_is_truth = true;
  static constexpr const char* full_call = "proximity().intersect";
  static constexpr const char* answer_help = spec::prox_help;
  static std::vector<std::string> inputs() {
    return spec::cols({{"center", 3}, {"radius", 1}, {"box_center", 3}, {"box_extent", 3}});
  }
  static std::vector<Output> outputs() { return spec::prox_outputs(); }
  static std::vector<Family> families() { return sphere_box_family_list(); }
  template <class T>
  static std::pair<Sphere<T>, Box<T>> make(const Inputs& in) {
    return {{spec::col3<T>(in, 0), T(in[3])}, {spec::col3<T>(in, 4), spec::col3<T>(in, 7)}};
  }
  template <class T>
  static auto book(const Sphere<T>& a, const Box<T>& b, unsigned w) { return cdref::book::proximity(a, b, w); }
  // the stable tier (float/cdref/stable/sphere_box.hpp)
  template <class F>
  static auto stable(const Sphere<F>& a, const Box<F>& b, unsigned w) { return cdref::stable::proximity(a, b, w); }
  template <class F>
  static bool stable_pred(const Sphere<F>& a, const Box<F>& b) { return cdref::stable::intersect(a, b); }
  template <class T>
  static bool stable_bare(const Sphere<T>& a, const Box<T>& b) { return cdref::stable::unchecked::intersect(a, b); }
  // the book's classification without its input checks (the `bare` row: see book/common.hpp)
  template <class T>
  static bool bare(const Sphere<T>& a, const Box<T>& b) { return cdref::book::unchecked::intersect(a, b); }
  template <class T>
  static bool book_pred(const Sphere<T>& a, const Box<T>& b) { return cdref::book::intersect(a, b); }
  template <class F>
  static auto robust(const Sphere<F>& a, const Box<F>& b) { return cdref::robust::proximity(a, b); }
  template <class F>
  static bool robust_pred(const Sphere<F>& a, const Box<F>& b) { return cdref::robust::intersect(a, b); }
  template <class F>
  static cdref::robust::Decision robust_decide(const Sphere<F>& a, const Box<F>& b) {
    return cdref::robust::decide(a, b);
  }
  static bool oracle(const Sphere<double>& a, const Box<double>& b, cdref::oracle::Stage* st) {
    return cdref::oracle::classify(a, b, st);
  }
  static int stage(cdref::oracle::Stage s, const Sphere<double>& a, const Box<double>& b) {
    return cdref::oracle::staged::at_stage(s, a, b);
  }
  template <class K>
  static auto cgal_make(const Inputs& in) {
    return std::pair{spec::cgal_ball<K>(in, 0, 3), spec::cgal_cuboid<K>(in, 4, 7)};
  }
  template <class S3, class C>
  static bool cgal(const S3& a, const C& b) { return CGAL::do_intersect(a, b); }
};

}  // namespace cdref::fuzz::queries
