// fuzz/queries/box_box.hpp - the descriptor of box-box (Section 3.2).
#pragma once

#include <cdref/fuzz/families.hpp>
#include <cdref/fuzz/spec.hpp>
#include <cdref/oracle/box_box.hpp>
#include <cdref/robust/box_box.hpp>
#include <cdref/stable/box_box.hpp>
#include <cmath>

namespace cdref::fuzz::queries {

struct BoxBox {
  static constexpr int id = 4;
  static constexpr const char* name = "box-box";
  static constexpr CaseDigest case_digest{45, 0x81d39b50d613a8d4u};
  static constexpr const char* cls_name = "intersect";
  static constexpr const char* pred_name = "intersect-min-max";
  static constexpr const char* describe =
      "Section 3.2: book::intersect in centre-extent form; the predicate column is the min-max form "
      "on corners rounded to the implementation's type";
  static constexpr bool book_is_truth = true;
  static constexpr const char* full_call = "intersect() in centre-extent form";
  static constexpr const char* answer_help = "";
  static std::vector<std::string> inputs() {
    return spec::cols({{"a_center", 3}, {"a_extent", 3}, {"b_center", 3}, {"b_extent", 3}});
  }
  static std::vector<Output> outputs() { return {}; }
  static std::vector<Family> families() { return box_box_family_list(); }
  template <class T>
  static std::pair<Box<T>, Box<T>> make(const Inputs& in) {
    return {{spec::col3<T>(in, 0), spec::col3<T>(in, 3)}, {spec::col3<T>(in, 6), spec::col3<T>(in, 9)}};
  }
  template <class T>
  static bool book(const Box<T>& a, const Box<T>& b, unsigned) { return cdref::book::intersect(a, b); }
  // the stable tier (float/cdref/stable/box_box.hpp: the book's centre-extent test)
  template <class F>
  static bool stable(const Box<F>& a, const Box<F>& b, unsigned) { return cdref::stable::intersect(a, b); }
  template <class F>
  static bool stable_pred(const Box<F>& a, const Box<F>& b) { return cdref::stable::intersect(a, b); }
  template <class T>
  static bool stable_bare(const Box<T>& a, const Box<T>& b) { return cdref::stable::unchecked::intersect(a, b); }
  // the book's classification without its input checks (the `bare` row: see book/common.hpp)
  template <class T>
  static bool bare(const Box<T>& a, const Box<T>& b) { return cdref::book::unchecked::intersect(a, b); }
  template <class T>
  static bool book_pred(const Box<T>& a, const Box<T>& b) { return cdref::book::intersect(to_min_max(a), to_min_max(b)); }
  template <class F>
  static bool robust(const Box<F>& a, const Box<F>& b) { return cdref::robust::intersect(a, b); }
  template <class F>
  static bool robust_pred(const Box<F>& a, const Box<F>& b) {
    return cdref::robust::intersect(to_min_max(a), to_min_max(b));
  }
  template <class F>
  static cdref::robust::Decision robust_decide(const Box<F>& a, const Box<F>& b) { return cdref::robust::decide(a, b); }
  static bool oracle(const Box<double>& a, const Box<double>& b, cdref::oracle::Stage* st) {
    return cdref::oracle::classify(a, b, st);
  }
  static int stage(cdref::oracle::Stage s, const Box<double>& a, const Box<double>& b) {
    return cdref::oracle::staged::at_stage(s, a, b);
  }
  template <class K>
  static auto cgal_make(const Inputs& in) {
    return std::pair{spec::cgal_cuboid<K>(in, 0, 3), spec::cgal_cuboid<K>(in, 6, 9)};
  }
  template <class C>
  static bool cgal(const C& a, const C& b) { return CGAL::do_intersect(a, b); }
  // The predicate column converts to min-max corners c +- e in the implementation's type; at
  // double they may overflow where the exact types hold them (the book at double then refuses
  // the min-max form: a documented limit of that conversion, not a disagreement).
  static bool double_may_refuse(const Inputs& in) {
    for (int k : {0, 1, 2, 6, 7, 8})
      if (!std::isfinite(in[k] + in[k + 3]) || !std::isfinite(in[k] - in[k + 3])) return true;
    return false;
  }
};

}  // namespace cdref::fuzz::queries
