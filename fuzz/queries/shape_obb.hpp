// fuzz/queries/shape_obb.hpp - the descriptors of segment-obb and triangle-obb (Section 3.3: a
// segment or a triangle against an oriented box by separating axes).
#pragma once

#include <cdref/fuzz/families.hpp>
#include <cdref/fuzz/spec.hpp>
#include <cdref/oracle/separating_axes.hpp>
#include <cdref/robust/separating_axes.hpp>
#include <cdref/stable/obb.hpp>

namespace cdref::fuzz::queries {

// Tri: a triangle (13 axes), or a segment (6 axes).
template <bool Tri>
struct ShapeObb {
  static constexpr int id = Tri ? 13 : 12;
  static constexpr const char* name = Tri ? "triangle-obb" : "segment-obb";
  static constexpr CaseDigest case_digest = Tri ? CaseDigest{73, 0x94b21a12af452957u} : CaseDigest{59, 0xba6e050d161acaa3u};
  static constexpr const char* cls_name = "intersect";
  static constexpr const char* pred_name = "Theorem 3.1 with the box's true face normals";
  static constexpr const char* describe =
      Tri ? "Section 3.3: a triangle against an oriented box (normal 0, box faces 1-3, edge k x a_j 4+3k+j): "
            "book::separate moves the triangle into the box's frame (assuming orthonormal axes); the predicate "
            "column and the truth are Theorem 3.1 on the parallelepiped (solid::separate)"
          : "Section 3.3: a segment against an oriented box (box faces 0-2, (t-s) x a_i 3-5): book::separate moves "
            "the segment into the box's frame (assuming orthonormal axes); the predicate column and the truth are "
            "Theorem 3.1 on the parallelepiped (solid::separate)";
  static constexpr bool book_is_truth = false;
  static constexpr const char* full_call = "separate().intersect";
  static constexpr const char* answer_help = spec::sat_help;
  template <class T>
  using Shape = std::conditional_t<Tri, Triangle<T>, Segment<T>>;
  static constexpr int box_at = Tri ? 9 : 6;
  static std::vector<std::string> inputs() {
    return spec::concat(Tri ? spec::cols({{"v0", 3}, {"v1", 3}, {"v2", 3}}) : spec::cols({{"source", 3}, {"target", 3}}),
                        spec::obb_cols(""));
  }
  static std::vector<Output> outputs() { return spec::sat_outputs(); }
  static std::vector<Family> families() {
    if constexpr (Tri)
      return rotated_family_list(triangle_box_family_list(), {0, 3, 6}, {}, {}, 9, 12, 9);
    else
      return rotated_family_list(segment_box_family_list(false), {0, 3}, {}, {}, 6, 9, 6);
  }
  template <class T>
  static std::pair<Shape<T>, OrientedBox<T>> make(const Inputs& in) {
    if constexpr (Tri)
      return {{{spec::col3<T>(in, 0), spec::col3<T>(in, 3), spec::col3<T>(in, 6)}}, spec::obb<T>(in, box_at)};
    else
      return {{spec::col3<T>(in, 0), spec::col3<T>(in, 3)}, spec::obb<T>(in, box_at)};
  }
  template <class T>
  static auto book(const Shape<T>& a, const OrientedBox<T>& b, unsigned) { return cdref::book::separate(a, b); }
  // the stable tier (float/cdref/stable/obb.hpp: the book's separating axes in the box's frame)
  template <class F>
  static auto stable(const Shape<F>& a, const OrientedBox<F>& b, unsigned) { return cdref::stable::separate(a, b); }
  template <class F>
  static bool stable_pred(const Shape<F>& a, const OrientedBox<F>& b) { return cdref::stable::separate(a, b).intersect; }
  template <class T>
  static bool stable_bare(const Shape<T>& a, const OrientedBox<T>& b) {
    return cdref::book::unchecked::separate(a, b).intersect;
  }
  // the book's classification without its input checks (the `bare` row: see book/common.hpp)
  template <class T>
  static bool bare(const Shape<T>& a, const OrientedBox<T>& b) { return cdref::book::unchecked::separate(a, b).intersect; }
  template <class T>
  static bool book_pred(const Shape<T>& a, const OrientedBox<T>& b) { return solid::separate(a, b).intersect; }
  template <class T>
  static auto truth(const Shape<T>& a, const OrientedBox<T>& b, unsigned) { return solid::separate(a, b); }
  template <class T>
  static bool truth_pred(const Shape<T>& a, const OrientedBox<T>& b) { return solid::separate(a, b).intersect; }
  // the oracle's every output at double from the robust tier's first look where it proves the
  // direction's rounding (robust/sat_first_look.hpp)
  static bool oracle_rounded(const Shape<double>& a, const OrientedBox<double>& b, Separation<double>& out) {
    return cdref::robust::separate_rounded(a, b, out);
  }
  template <class F>
  static auto robust(const Shape<F>& a, const OrientedBox<F>& b) { return cdref::robust::separate(a, b); }
  template <class F>
  static bool robust_pred(const Shape<F>& a, const OrientedBox<F>& b) { return cdref::robust::intersect(a, b); }
  template <class F>
  static cdref::robust::Decision robust_decide(const Shape<F>& a, const OrientedBox<F>& b) {
    return cdref::robust::decide(a, b);
  }
  static bool oracle(const Shape<double>& a, const OrientedBox<double>& b, cdref::oracle::Stage* st) {
    return cdref::oracle::classify(a, b, st);
  }
  static int stage(cdref::oracle::Stage s, const Shape<double>& a, const OrientedBox<double>& b) {
    return cdref::oracle::sat::at_stage(s, a, b);
  }
  static std::vector<Implementation> variants() { return {spec::book_exact_variant<ShapeObb>()}; }
};

}  // namespace cdref::fuzz::queries
