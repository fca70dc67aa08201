// fuzz/queries/sphere_triangle.hpp - the descriptor of sphere-triangle (Section 3.4).
#pragma once

#include <CGAL/Distance_3/Point_3_Triangle_3.h>

#include <cdref/fuzz/families.hpp>
#include <cdref/fuzz/spec.hpp>
#include <cdref/oracle/sphere_triangle.hpp>
#include <cdref/robust/sphere_triangle.hpp>
#include <cdref/stable/sphere_triangle.hpp>

namespace cdref::fuzz::queries {

struct SphereTriangle {
  static constexpr int id = 17;
  static constexpr const char* name = "sphere-triangle";
  static constexpr CaseDigest case_digest{45, 0xefa4af5b63b66545u};
  static constexpr const char* cls_name = "intersect";
  static constexpr const char* pred_name = "intersect";
  static constexpr const char* describe =
      "Section 3.4: book::proximity(sphere, triangle) and book::intersect, the closest point region by region "
      "(witness_a on the sphere)";
  static constexpr bool book_is_truth = true;
  static constexpr const char* full_call = "proximity().intersect";
  static constexpr const char* answer_help = spec::prox_help;
  static std::vector<std::string> inputs() {
    return spec::cols({{"center", 3}, {"radius", 1}, {"v0", 3}, {"v1", 3}, {"v2", 3}});
  }
  static std::vector<Output> outputs() { return spec::prox_outputs(); }
  static std::vector<Family> families() { return sphere_triangle_family_list(); }
  template <class T>
  static std::pair<Sphere<T>, Triangle<T>> make(const Inputs& in) {
    return {{spec::col3<T>(in, 0), T(in[3])}, {{spec::col3<T>(in, 4), spec::col3<T>(in, 7), spec::col3<T>(in, 10)}}};
  }
  template <class T>
  static auto book(const Sphere<T>& a, const Triangle<T>& b, unsigned w) { return cdref::book::proximity(a, b, w); }
  // the stable tier (float/cdref/stable/sphere_triangle.hpp: the book's Voronoi regions)
  template <class F>
  static auto stable(const Sphere<F>& a, const Triangle<F>& b, unsigned w) { return cdref::stable::proximity(a, b, w); }
  template <class F>
  static bool stable_pred(const Sphere<F>& a, const Triangle<F>& b) { return cdref::stable::intersect(a, b); }
  template <class T>
  static bool stable_bare(const Sphere<T>& a, const Triangle<T>& b) { return cdref::stable::unchecked::intersect(a, b); }
  // the book's classification without its input checks (the `bare` row: see book/common.hpp)
  template <class T>
  static bool bare(const Sphere<T>& a, const Triangle<T>& b) { return cdref::book::unchecked::intersect(a, b); }
  template <class T>
  static bool book_pred(const Sphere<T>& a, const Triangle<T>& b) { return cdref::book::intersect(a, b); }
  template <class F>
  static auto robust(const Sphere<F>& a, const Triangle<F>& b) { return cdref::robust::proximity(a, b); }
  template <class F>
  static bool robust_pred(const Sphere<F>& a, const Triangle<F>& b) { return cdref::robust::intersect(a, b); }
  template <class F>
  static cdref::robust::Decision robust_decide(const Sphere<F>& a, const Triangle<F>& b) {
    return cdref::robust::decide(a, b);
  }
  static bool oracle(const Sphere<double>& a, const Triangle<double>& b, cdref::oracle::Stage* st) {
    return cdref::oracle::classify(a, b, st);
  }
  // every output correctly rounded at double, first from the robust tier's first look where its
  // bounds prove each rounding (spec.hpp, oracle_truth_of)
  static bool oracle_rounded(const Sphere<double>& a, const Triangle<double>& b, Proximity<double>& out) {
    return cdref::robust::proximity_rounded(a, b, out);
  }
  static int stage(cdref::oracle::Stage s, const Sphere<double>& a, const Triangle<double>& b) {
    return cdref::oracle::sphere_triangle::at_stage(s, a, b);
  }
  // CGAL's Sphere_3 is a surface: the closed ball against the triangle is squared_distance of
  // the centre to the triangle against rho^2 (CGAL's Triangle_3 must not be degenerate: a
  // degenerate case is answered by the segment or point it spans).
  template <class K>
  static auto cgal_make(const Inputs& in) {
    return std::pair{spec::cgal_ball<K>(in, 0, 3),
                     typename K::Triangle_3(spec::cgal_point<K>(in, 4), spec::cgal_point<K>(in, 7), spec::cgal_point<K>(in, 10))};
  }
  template <class S3, class T3>
  static bool cgal(const S3& s, const T3& t) {
    if (t.is_degenerate()) {
      const auto [s0, s1] = spec::cgal_span(t);
      using Seg = typename CGAL::Kernel_traits<T3>::Kernel::Segment_3;
      return s0 == s1 ? CGAL::squared_distance(s.center(), s0) <= s.squared_radius()
                      : CGAL::squared_distance(s.center(), Seg(s0, s1)) <= s.squared_radius();
    }
    return CGAL::squared_distance(s.center(), t) <= s.squared_radius();
  }
};

}  // namespace cdref::fuzz::queries
