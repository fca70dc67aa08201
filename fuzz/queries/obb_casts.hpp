// fuzz/queries/obb_casts.hpp - the descriptors of segment-obb-cast and ray-obb-cast: Algorithm
// 3.3 on an oriented box, as engines write it (moved into the box's frame) and as the solid
// its inputs define.
#pragma once

#include <cdref/fuzz/families.hpp>
#include <cdref/fuzz/spec.hpp>
#include <cdref/oracle/enter_obb.hpp>
#include <cdref/oracle/separating_axes.hpp>
#include <cdref/robust/separating_axes.hpp>
#include <cdref/stable/obb.hpp>

namespace cdref::fuzz::queries {

template <bool Ray>
struct ObbCast {
  static constexpr int id = Ray ? 15 : 14;
  static constexpr const char* name = Ray ? "ray-obb-cast" : "segment-obb-cast";
  static constexpr CaseDigest case_digest = Ray ? CaseDigest{46, 0xab237d9ead7435f5u} : CaseDigest{46, 0xb95b971cf243b1dau};
  static constexpr const char* cls_name = "hit";
  static constexpr const char* pred_name = "hit";
  static constexpr const char* describe =
      Ray ? "Algorithm 3.3 on an oriented box, the infinite ray: book::cast and book::hit in the box's frame "
            "(assuming orthonormal axes); the truth is the parallelepiped's (solid::cast)"
          : "Algorithm 3.3 on an oriented box, the segment source->target: book::cast and book::hit in the box's "
            "frame (assuming orthonormal axes); the truth is the parallelepiped's (solid::cast)";
  static constexpr bool book_is_truth = false;
  static constexpr const char* full_call = "cast().hit";
  static constexpr const char* answer_help = spec::cast_help;
  template <class T>
  using Shot = std::conditional_t<Ray, cdref::Ray<T>, Segment<T>>;
  static std::vector<std::string> inputs() {
    return spec::concat(spec::cols({{"source", 3}, {Ray ? "direction" : "target", 3}}), spec::obb_cols(""));
  }
  static std::vector<Output> outputs() { return spec::cast_outputs(); }
  static std::vector<Family> families() {
    return Ray ? rotated_family_list(box_shot_family_list(true), {0}, {3}, {}, 6, 9, 6)
               : rotated_family_list(box_shot_family_list(false), {0, 3}, {}, {}, 6, 9, 6);
  }
  template <class T>
  static std::pair<Shot<T>, OrientedBox<T>> make(const Inputs& in) {
    return {{spec::col3<T>(in, 0), spec::col3<T>(in, 3)}, spec::obb<T>(in, 6)};
  }
  template <class T>
  static auto book(const Shot<T>& a, const OrientedBox<T>& b, unsigned w) { return cdref::book::cast(a, b, w); }
  // the stable tier (float/cdref/stable/obb.hpp: the slab test in the box's frame)
  template <class F>
  static auto stable(const Shot<F>& a, const OrientedBox<F>& b, unsigned w) { return cdref::stable::cast(a, b, w); }
  template <class F>
  static bool stable_pred(const Shot<F>& a, const OrientedBox<F>& b) { return cdref::stable::hit(a, b); }
  template <class T>
  static bool stable_bare(const Shot<T>& a, const OrientedBox<T>& b) { return cdref::stable::unchecked::hit(a, b); }
  // the book's classification without its input checks (the `bare` row: see book/common.hpp)
  template <class T>
  static bool bare(const Shot<T>& a, const OrientedBox<T>& b) { return cdref::book::unchecked::hit(a, b); }
  template <class T>
  static bool book_pred(const Shot<T>& a, const OrientedBox<T>& b) { return cdref::book::hit(a, b); }
  template <class T>
  static auto truth(const Shot<T>& a, const OrientedBox<T>& b, unsigned w) { return solid::cast(a, b, w); }
  template <class T>
  static bool truth_pred(const Shot<T>& a, const OrientedBox<T>& b) { return solid::hit(a, b); }
  template <class F>
  static auto robust(const Shot<F>& a, const OrientedBox<F>& b) { return cdref::robust::cast(a, b); }
  template <class F>
  static bool robust_pred(const Shot<F>& a, const OrientedBox<F>& b) { return cdref::robust::hit(a, b); }
  template <class F>
  static cdref::robust::Decision robust_decide(const Shot<F>& a, const OrientedBox<F>& b) {
    return cdref::robust::decide_cast(a, b);
  }
  // the cast hits exactly when the segment (ray) meets the solid: Theorem 3.1 decides it
  static bool oracle(const Shot<double>& a, const OrientedBox<double>& b, cdref::oracle::Stage* st) {
    return cdref::oracle::classify(a, b, st);
  }
  // the oracle's every output at double from the robust tier's first look where it proves each
  // rounding (robust/obb_cast.hpp)
  static bool oracle_rounded(const Shot<double>& a, const OrientedBox<double>& b, Cast<double>& out) {
    return cdref::robust::cast_rounded(a, b, out);
  }
  static cdref::oracle::Entry oracle_enter(const Shot<double>& a, const OrientedBox<double>& b, bool* exact_used) {
    return cdref::oracle::enter(a, b, exact_used);
  }
  static int stage(cdref::oracle::Stage s, const Shot<double>& a, const OrientedBox<double>& b) {
    return cdref::oracle::sat::at_stage(s, a, b);
  }
  static std::vector<Implementation> variants() { return {spec::book_exact_variant<ObbCast>()}; }
};

}  // namespace cdref::fuzz::queries
