// fuzz/queries/sphere_sphere.hpp - the descriptor of sphere-sphere (Section 3.1.1).
#pragma once

#include <cdref/fuzz/families.hpp>
#include <cdref/fuzz/spec.hpp>
#include <cdref/oracle/sphere_sphere.hpp>
#include <cdref/stable/sphere_sphere.hpp>
#include <cdref/robust/sphere_sphere.hpp>

namespace cdref::fuzz::queries {

struct SphereSphere {
  static constexpr int id = 0;
  static constexpr const char* name = "sphere-sphere";
  static constexpr CaseDigest case_digest{45, 0xf9733b8eefc3f067u};
  static constexpr const char* cls_name = "intersect";
  static constexpr const char* pred_name = "intersect";
  static constexpr const char* describe = "Section 3.1.1: book::proximity(A, B) and book::intersect(A, B)";
  static constexpr bool book_is_truth = true;
  static constexpr const char* full_call = "proximity().intersect";
  static constexpr const char* answer_help = spec::prox_help;
  static std::vector<std::string> inputs() {
    return spec::cols({{"a_center", 3}, {"a_radius", 1}, {"b_center", 3}, {"b_radius", 1}});
  }
  static std::vector<Output> outputs() { return spec::prox_outputs(); }
  static std::vector<Family> families() { return sphere_sphere_family_list(); }
  template <class T>
  static std::pair<Sphere<T>, Sphere<T>> make(const Inputs& in) {
    return {{spec::col3<T>(in, 0), T(in[3])}, {spec::col3<T>(in, 4), T(in[7])}};
  }
  template <class T>
  static auto book(const Sphere<T>& a, const Sphere<T>& b, unsigned w) { return cdref::book::proximity(a, b, w); }
  // the stable tier (float/cdref/stable/sphere_sphere.hpp)
  template <class F>
  static auto stable(const Sphere<F>& a, const Sphere<F>& b, unsigned w) { return cdref::stable::proximity(a, b, w); }
  template <class F>
  static bool stable_pred(const Sphere<F>& a, const Sphere<F>& b) { return cdref::stable::intersect(a, b); }
  template <class T>
  static bool stable_bare(const Sphere<T>& a, const Sphere<T>& b) { return cdref::stable::unchecked::intersect(a, b); }
  // the book's classification without its input checks (the `bare` row: see book/common.hpp)
  template <class T>
  static bool bare(const Sphere<T>& a, const Sphere<T>& b) { return cdref::book::unchecked::intersect(a, b); }
  template <class T>
  static bool book_pred(const Sphere<T>& a, const Sphere<T>& b) { return cdref::book::intersect(a, b); }
  template <class F>
  static auto robust(const Sphere<F>& a, const Sphere<F>& b) { return cdref::robust::proximity(a, b); }
  template <class F>
  static bool robust_pred(const Sphere<F>& a, const Sphere<F>& b) { return cdref::robust::intersect(a, b); }
  template <class F>
  static cdref::robust::Decision robust_decide(const Sphere<F>& a, const Sphere<F>& b) {
    return cdref::robust::decide(a, b);
  }
  static bool oracle(const Sphere<double>& a, const Sphere<double>& b, cdref::oracle::Stage* st) {
    return cdref::oracle::classify(a, b, st);
  }
  static int stage(cdref::oracle::Stage s, const Sphere<double>& a, const Sphere<double>& b) {
    return cdref::oracle::staged::at_stage(s, a, b);
  }
  template <class K>
  static auto cgal_make(const Inputs& in) {
    return std::pair{spec::cgal_ball<K>(in, 0, 3), spec::cgal_ball<K>(in, 4, 7)};
  }
  // CGAL's spheres are surfaces: the balls meet iff the surfaces do or a centre lies inside
  // the other ball
  template <class S3>
  static bool cgal(const S3& a, const S3& b) {
    return CGAL::do_intersect(a, b) || a.bounded_side(b.center()) != CGAL::ON_UNBOUNDED_SIDE ||
           b.bounded_side(a.center()) != CGAL::ON_UNBOUNDED_SIDE;
  }
};

}  // namespace cdref::fuzz::queries
