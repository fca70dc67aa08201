// fuzz/queries/sphere_casts.hpp - the descriptors of the casts on a sphere (Section 3.1.2,
// Algorithm 3.1): segment-sphere-cast and ray-sphere-cast.
#pragma once

#include <cdref/fuzz/families.hpp>
#include <cdref/fuzz/spec.hpp>
#include <cdref/oracle/sphere_casts.hpp>
#include <cdref/oracle/enter_sphere.hpp>
#include <cdref/oracle/sphere_cast_foot.hpp>
#include <cdref/stable/ray_sphere.hpp>
#include <cdref/robust/ray_sphere.hpp>

namespace cdref::fuzz::queries {

// Ray: true for the infinite ray (source, direction), false for the segment (source, target).
template <bool Ray>
struct SphereCast {
  static constexpr int id = Ray ? 2 : 1;
  static constexpr const char* name = Ray ? "ray-sphere-cast" : "segment-sphere-cast";
  static constexpr CaseDigest case_digest = Ray ? CaseDigest{58, 0xa6c17de0a632fac8u} : CaseDigest{58, 0xfa3c988542bd5a06u};
  static constexpr const char* cls_name = "hit";
  static constexpr const char* pred_name = "hit";
  static constexpr const char* describe =
      Ray ? "Algorithm 3.1 on the infinite ray source + lambda direction: book::cast and book::hit"
          : "Algorithm 3.1 on the segment source->target: book::cast and book::hit";
  static constexpr bool book_is_truth = true;
  static constexpr const char* full_call = "cast().hit";
  static constexpr const char* answer_help = spec::cast_help;
  template <class T>
  using Shot = std::conditional_t<Ray, cdref::Ray<T>, Segment<T>>;
  static std::vector<std::string> inputs() {
    return spec::cols({{"source", 3}, {Ray ? "direction" : "target", 3}, {"center", 3}, {"radius", 1}});
  }
  static std::vector<Output> outputs() { return spec::cast_outputs(); }
  static std::vector<Family> families() { return sphere_shot_family_list(Ray); }
  template <class T>
  static std::pair<Shot<T>, Sphere<T>> make(const Inputs& in) {
    return {{spec::col3<T>(in, 0), spec::col3<T>(in, 3)}, {spec::col3<T>(in, 6), T(in[9])}};
  }
  template <class T>
  static auto book(const Shot<T>& a, const Sphere<T>& b, unsigned w) { return cdref::book::cast(a, b, w); }
  // the stable tier (float/cdref/stable/ray_sphere.hpp)
  template <class F>
  static auto stable(const Shot<F>& a, const Sphere<F>& b, unsigned w) { return cdref::stable::cast(a, b, w); }
  template <class F>
  static bool stable_pred(const Shot<F>& a, const Sphere<F>& b) { return cdref::stable::hit(a, b); }
  template <class T>
  static bool stable_bare(const Shot<T>& a, const Sphere<T>& b) { return cdref::stable::unchecked::hit(a, b); }
  // the book's classification without its input checks (the `bare` row: see book/common.hpp)
  template <class T>
  static bool bare(const Shot<T>& a, const Sphere<T>& b) { return cdref::book::unchecked::hit(a, b); }
  template <class T>
  static bool book_pred(const Shot<T>& a, const Sphere<T>& b) { return cdref::book::hit(a, b); }
  template <class F>
  static auto robust(const Shot<F>& a, const Sphere<F>& b) { return cdref::robust::cast(a, b); }
  template <class F>
  static bool robust_pred(const Shot<F>& a, const Sphere<F>& b) { return cdref::robust::hit(a, b); }
  template <class F>
  static cdref::robust::Decision robust_decide(const Shot<F>& a, const Sphere<F>& b) {
    return cdref::robust::decide(a, b);
  }
  static bool oracle(const Shot<double>& a, const Sphere<double>& b, cdref::oracle::Stage* st) {
    return cdref::oracle::classify(a, b, st);
  }
  // every output in the perpendicular foot's formulation, the book's at exact types, for the
  // every-output oracle's double words (oracle/sphere_cast_foot.hpp)
  template <class T>
  static auto oracle_formulation(const Shot<T>& a, const Sphere<T>& b, unsigned w) {
    return cdref::oracle::foot_cast(a, b, w);
  }
  // ... tried first where the source is more than 2^17 radii from the centre. There the book's
  // formulation is seldom certain on Bounded2 and its failed attempt costs more than the foot's;
  // nearer, the book's is certain and the cheaper. Measured (seed 1, 400 draws per scale, ns per
  // case of the certain attempts and the failed ones, 2-core AMD EPYC, g++ 12.2 -O2, 2026-11-28),
  // book / foot, ray: long-range at 10^5 radii certain 400 / 400, 685 / 927 ns; at 10^6 388 / 400,
  // 734 / 914; at 10^7 133 / 400, 1924 / 954; at 10^12 80 / 396, 2371 / 1192; tangent-at-range
  // at 10^4 373 / 400, 700 / 866; at 10^5 202 / 400, 1662 / 735; at 10^12 193 / 283, 1426 / 1250.
  // The segment's alike.
  static bool oracle_formulation_first(const Shot<double>& a, const Sphere<double>& b) {
    double ss = 0;
    for (int k = 0; k < 3; ++k) ss += (a.source[k] - b.center[k]) * (a.source[k] - b.center[k]);
    return ss > 0x1p34 * (b.radius * b.radius);
  }
  static cdref::oracle::Entry oracle_enter(const Shot<double>& a, const Sphere<double>& b, bool* exact_used) {
    return cdref::oracle::enter(a, b, exact_used);
  }
  static int stage(cdref::oracle::Stage s, const Shot<double>& a, const Sphere<double>& b) {
    return cdref::oracle::staged::at_stage(s, a, b);
  }
  template <class K>
  static auto cgal_make(const Inputs& in) {
    if constexpr (Ray)
      return std::pair{typename K::Ray_3(spec::cgal_point<K>(in, 0), spec::cgal_vector<K>(in, 3)),
                       spec::cgal_ball<K>(in, 6, 9)};
    else
      return std::pair{typename K::Segment_3(spec::cgal_point<K>(in, 0), spec::cgal_point<K>(in, 3)),
                       spec::cgal_ball<K>(in, 6, 9)};
  }
  // CGAL's spheres are surfaces: a segment meets the ball iff it meets the surface or lies
  // in the open ball; a ray from inside always leaves through the surface
  template <class A, class S3>
  static bool cgal(const A& a, const S3& b) {
    if constexpr (Ray)
      return CGAL::do_intersect(a, b);
    else
      return CGAL::do_intersect(a, b) || b.has_on_bounded_side(a.source());
  }
};

}  // namespace cdref::fuzz::queries
