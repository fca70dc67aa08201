// fuzz/queries/sphere_obb.hpp - the descriptor of sphere-obb: Section 3.2.2 on an oriented
// box, as engines write it (the centre moved into the box's frame) and as the solid its inputs
// define.
#pragma once

#include <cdref/fuzz/families.hpp>
#include <cdref/fuzz/spec.hpp>
#include <cdref/oracle/separating_axes.hpp>
#include <cdref/robust/separating_axes.hpp>
#include <cdref/stable/obb.hpp>

namespace cdref::fuzz::queries {

struct SphereObb {
  static constexpr int id = 16;
  static constexpr const char* name = "sphere-obb";
  static constexpr CaseDigest case_digest{45, 0x1ef55cf64a22a3f3u};
  static constexpr const char* cls_name = "intersect";
  static constexpr const char* pred_name = "intersect";
  static constexpr const char* describe =
      "Section 3.2.2 on an oriented box: book::proximity and book::intersect in the box's frame (assuming "
      "orthonormal axes); the truth is the parallelepiped's (solid::proximity); witness_a on the sphere";
  static constexpr bool book_is_truth = false;
  static constexpr const char* full_call = "proximity().intersect";
  static constexpr const char* answer_help = spec::prox_help;
  static std::vector<std::string> inputs() {
    return spec::concat(spec::cols({{"center", 3}, {"radius", 1}}), spec::obb_cols("box_"));
  }
  static std::vector<Output> outputs() { return spec::prox_outputs(); }
  static std::vector<Family> families() { return rotated_family_list(sphere_box_family_list(), {0}, {}, {3}, 4, 7, 4); }
  template <class T>
  static std::pair<Sphere<T>, OrientedBox<T>> make(const Inputs& in) {
    return {{spec::col3<T>(in, 0), T(in[3])}, spec::obb<T>(in, 4)};
  }
  template <class T>
  static auto book(const Sphere<T>& a, const OrientedBox<T>& b, unsigned w) { return cdref::book::proximity(a, b, w); }
  // the stable tier (float/cdref/stable/obb.hpp: the book's Section 3.2.2 in the box's frame)
  template <class F>
  static auto stable(const Sphere<F>& a, const OrientedBox<F>& b, unsigned w) { return cdref::stable::proximity(a, b, w); }
  template <class F>
  static bool stable_pred(const Sphere<F>& a, const OrientedBox<F>& b) { return cdref::stable::intersect(a, b); }
  template <class T>
  static bool stable_bare(const Sphere<T>& a, const OrientedBox<T>& b) { return cdref::stable::unchecked::intersect(a, b); }
  // the book's classification without its input checks (the `bare` row: see book/common.hpp)
  template <class T>
  static bool bare(const Sphere<T>& a, const OrientedBox<T>& b) { return cdref::book::unchecked::intersect(a, b); }
  template <class T>
  static bool book_pred(const Sphere<T>& a, const OrientedBox<T>& b) { return cdref::book::intersect(a, b); }
  template <class T>
  static auto truth(const Sphere<T>& a, const OrientedBox<T>& b, unsigned w) { return solid::proximity(a, b, w); }
  template <class T>
  static bool truth_pred(const Sphere<T>& a, const OrientedBox<T>& b) { return solid::intersect(a, b); }
  template <class F>
  static auto robust(const Sphere<F>& a, const OrientedBox<F>& b) { return cdref::robust::proximity(a, b); }
  template <class F>
  static bool robust_pred(const Sphere<F>& a, const OrientedBox<F>& b) { return cdref::robust::intersect(a, b); }
  template <class F>
  static cdref::robust::Decision robust_decide(const Sphere<F>& a, const OrientedBox<F>& b) {
    return cdref::robust::decide(a, b);
  }
  static bool oracle(const Sphere<double>& a, const OrientedBox<double>& b, cdref::oracle::Stage* st) {
    return cdref::oracle::classify(a, b, st);
  }
  // the oracle's every output at double from the robust tier's first look where it proves each
  // rounding (robust/sphere_obb.hpp)
  static bool oracle_rounded(const Sphere<double>& a, const OrientedBox<double>& b, Proximity<double>& out) {
    return cdref::robust::proximity_rounded(a, b, out);
  }
  static int stage(cdref::oracle::Stage s, const Sphere<double>& a, const OrientedBox<double>& b) {
    return cdref::oracle::sphere_obb::at_stage(s, a, b);
  }
  static std::vector<Implementation> variants() { return {spec::book_exact_variant<SphereObb>()}; }
};

}  // namespace cdref::fuzz::queries
