// fuzz/queries/obb_obb.hpp - the descriptor of obb-obb (Section 3.3: two oriented boxes by 15
// separating axes).
#pragma once

#include <cdref/fuzz/families.hpp>
#include <cdref/fuzz/spec.hpp>
#include <cdref/oracle/separating_axes.hpp>
#include <cdref/robust/separating_axes.hpp>
#include <cdref/stable/obb_obb.hpp>

namespace cdref::fuzz::queries {

struct ObbObb {
  static constexpr int id = 11;
  static constexpr const char* name = "obb-obb";
  static constexpr CaseDigest case_digest{73, 0xce5d16f281acc470u};
  static constexpr const char* cls_name = "intersect";
  static constexpr const char* pred_name = "Theorem 3.1 with the true face normals";
  static constexpr const char* describe =
      "Section 3.3: two oriented boxes by 15 separating axes (A's faces 0-2, B's 3-5, a_i x b_j 6+3i+j): "
      "book::separate (Gottschalk's test, which assumes orthonormal axes); the predicate column and the truth "
      "are Theorem 3.1 on the parallelepipeds the axes span (solid::separate)";
  static constexpr bool book_is_truth = false;
  static constexpr const char* full_call = "separate().intersect";
  static constexpr const char* answer_help = spec::sat_help;
  static std::vector<std::string> inputs() { return spec::concat(spec::obb_cols("a_"), spec::obb_cols("b_")); }
  static std::vector<Output> outputs() { return spec::sat_outputs(); }
  static std::vector<Family> families() { return obb_obb_family_list(); }
  template <class T>
  static std::pair<OrientedBox<T>, OrientedBox<T>> make(const Inputs& in) {
    return {spec::obb<T>(in, 0), spec::obb<T>(in, 15)};
  }
  template <class T>
  static auto book(const OrientedBox<T>& a, const OrientedBox<T>& b, unsigned) { return cdref::book::separate(a, b); }
  // the stable tier (float/cdref/stable/obb_obb.hpp: the book's 15 axes, no epsilon)
  template <class F>
  static auto stable(const OrientedBox<F>& a, const OrientedBox<F>& b, unsigned) { return cdref::stable::separate(a, b); }
  template <class F>
  static bool stable_pred(const OrientedBox<F>& a, const OrientedBox<F>& b) { return cdref::stable::separate(a, b).intersect; }
  template <class T>
  static bool stable_bare(const OrientedBox<T>& a, const OrientedBox<T>& b) {
    return cdref::stable::unchecked::separate(a, b).intersect;
  }
  // the book's classification without its input checks (the `bare` row: see book/common.hpp)
  template <class T>
  static bool bare(const OrientedBox<T>& a, const OrientedBox<T>& b) { return cdref::book::unchecked::separate(a, b).intersect; }
  template <class T>
  static bool book_pred(const OrientedBox<T>& a, const OrientedBox<T>& b) { return solid::separate(a, b).intersect; }
  template <class T>
  static auto truth(const OrientedBox<T>& a, const OrientedBox<T>& b, unsigned) { return solid::separate(a, b); }
  template <class T>
  static bool truth_pred(const OrientedBox<T>& a, const OrientedBox<T>& b) { return solid::separate(a, b).intersect; }
  // the oracle's every output at double from the robust tier's first look where it proves the
  // direction's rounding (robust/sat_first_look.hpp)
  static bool oracle_rounded(const OrientedBox<double>& a, const OrientedBox<double>& b, Separation<double>& out) {
    return cdref::robust::separate_rounded(a, b, out);
  }
  template <class F>
  static auto robust(const OrientedBox<F>& a, const OrientedBox<F>& b) { return cdref::robust::separate(a, b); }
  template <class F>
  static bool robust_pred(const OrientedBox<F>& a, const OrientedBox<F>& b) { return cdref::robust::intersect(a, b); }
  template <class F>
  static cdref::robust::Decision robust_decide(const OrientedBox<F>& a, const OrientedBox<F>& b) {
    return cdref::robust::decide(a, b);
  }
  static bool oracle(const OrientedBox<double>& a, const OrientedBox<double>& b, cdref::oracle::Stage* st) {
    return cdref::oracle::classify(a, b, st);
  }
  static int stage(cdref::oracle::Stage s, const OrientedBox<double>& a, const OrientedBox<double>& b) {
    return cdref::oracle::sat::at_stage(s, a, b);
  }
  // The patches engines ship for near-parallel edges (book/obb_obb.hpp), at double, and the
  // book at an exact type.
  template <class Test>
  static Implementation patched(const char* name, Test test) {
    return {name, 53,
            [test](Query, const Inputs& in) {
              const auto [a, b] = make<double>(in);
              Answer r;
              spec::put<ObbObb, double>(r, test(a, b), true);
              r.pred = book_pred(a, b);
              return r;
            },
            {Query{id}}};
  }
  static std::vector<Implementation> variants() {
    using B = OrientedBox<double>;
    return {spec::book_exact_variant<ObbObb>(),
            patched("book-double-eps", [](const B& a, const B& b) { return cdref::book::separate_rapid(a, b); }),
            patched("book-double-eps-ulp", [](const B& a, const B& b) { return cdref::book::separate_rapid(a, b, 0x1p-52); }),
            patched("book-double-skip", [](const B& a, const B& b) { return cdref::book::separate_parallel(a, b); })};
  }
};

}  // namespace cdref::fuzz::queries
