// fuzz/queries/fan_casts.hpp - the descriptors of ray-fan-cast and segment-fan-cast (Section 3.4,
// mesh level): a shot against a fan of triangles that share a vertex (or two that share an
// edge), each triangle cast by the triangle query's own book, stable, robust and oracle versions. The
// fan's classification is the union's: a false negative is a leak (the exact shot meets the
// fan's closed triangles and the implementation hits none of them), a false positive a phantom
// hit. Its values are the first hit's (the smallest lambda_enter, the first triangle on ties)
// and the number of triangles hit.
#pragma once

#include <cdref/fuzz/families.hpp>
#include <cdref/fuzz/spec.hpp>
#include <cdref/oracle/enter_triangle.hpp>
#include <cdref/oracle/ray_triangle.hpp>
#include <cdref/robust/ray_triangle.hpp>
#include <cdref/stable/ray_triangle.hpp>

namespace cdref::fuzz::queries {

template <bool Ray>
struct FanCastQuery {
  static constexpr int id = Ray ? 20 : 21;
  static constexpr const char* name = Ray ? "ray-fan-cast" : "segment-fan-cast";
  static constexpr CaseDigest case_digest = Ray ? CaseDigest{9, 0xbd005970964baa1cu} : CaseDigest{9, 0x5e7c6bff6d375d61u};
  static constexpr const char* cls_name = "hit";
  static constexpr const char* pred_name = "hit";
  static constexpr const char* describe =
      Ray ? "Section 3.4 at mesh level: the infinite ray on a fan of closed triangles around a shared vertex "
            "(triangles centre, r_i, r_i+1; closed: also r_n-1, r_0); hit = any triangle's book::cast, a false "
            "negative is a leak"
          : "Section 3.4 at mesh level: the segment source->target on a fan of closed triangles around a shared "
            "vertex (triangles centre, r_i, r_i+1; closed: also r_n-1, r_0); hit = any triangle's book::cast, a "
            "false negative is a leak";
  static constexpr bool book_is_truth = true;
  static constexpr bool mesh_level = true;
  static constexpr const char* full_call = "cast().hit on each triangle";
  static constexpr const char* answer_help =
      "  hit: the shot hits some triangle of the fan (a 0 where the truth says 1 is a leak)\n"
      "  lambda_enter, point_[xyz]: the first hit (smallest lambda_enter over the fan's triangles)\n"
      "  hits: how many of the fan's triangles the shot hits (graded where both say hit, as right or wrong)\n";
  template <class T>
  using Shot = std::conditional_t<Ray, cdref::Ray<T>, Segment<T>>;
  static std::vector<std::string> inputs() {
    auto c = spec::cols({{"source", 3}, {Ray ? "direction" : "target", 3}, {"n", 1}, {"closed", 1}, {"center", 3}});
    for (int i = 0; i < spec::Fan<double>::max_ring; ++i) {
      std::string r = "r";  // (not "r" + std::to_string(i): g++ 12 warns of a false overflow in it)
      r += std::to_string(i);
      c = spec::concat(c, spec::cols({{r.c_str(), 3}}));
    }
    return c;
  }
  static std::vector<Output> outputs() {
    return {{"lambda_enter", 1, Output::on_hit}, {"point", 3, Output::on_hit}, {"hits", 1, Output::on_hit, true}};
  }
  static std::vector<Family> families() { return fan_shot_family_list(Ray); }
  template <class T>
  static std::pair<Shot<T>, spec::Fan<T>> make(const Inputs& in) {
    return {{spec::col3<T>(in, 0), spec::col3<T>(in, 3)}, spec::fan<T>(in, 6)};
  }
  template <class T>
  static auto book(const Shot<T>& a, const spec::Fan<T>& f, unsigned w) {
    return spec::first_hit(f, [&](const Triangle<T>& t) { return cdref::book::cast(a, t, w | want_lambda_enter); });
  }
  // the stable tier on each triangle (float/cdref/stable/ray_triangle.hpp: watertight)
  template <class F>
  static auto stable(const Shot<F>& a, const spec::Fan<F>& f, unsigned w) {
    return spec::first_hit(f, [&](const Triangle<F>& t) { return cdref::stable::cast(a, t, w | want_lambda_enter); });
  }
  template <class F>
  static bool stable_pred(const Shot<F>& a, const spec::Fan<F>& f) {
    return f.any([&](const Triangle<F>& t) { return cdref::stable::hit(a, t); });
  }
  template <class T>
  static bool stable_bare(const Shot<T>& a, const spec::Fan<T>& f) {
    return f.any([&](const Triangle<T>& t) { return cdref::stable::unchecked::hit(a, t); });
  }
  // the book's classification without its input checks (the `bare` row: see book/common.hpp)
  template <class T>
  static bool bare(const Shot<T>& a, const spec::Fan<T>& b) { return b.any([&](const Triangle<T>& t) { return cdref::book::unchecked::hit(a, t); }); }
  template <class T>
  static bool book_pred(const Shot<T>& a, const spec::Fan<T>& f) {
    return f.any([&](const Triangle<T>& t) { return cdref::book::hit(a, t); });
  }
  template <class F>
  static auto robust(const Shot<F>& a, const spec::Fan<F>& f) {
    return spec::first_hit(f, [&](const Triangle<F>& t) { return cdref::robust::cast(a, t); },
                           [&](int k, int j, F lk, F lj) {
                             return cdref::robust::enters_before(a, f.triangle(k), lk, f.triangle(j), lj);
                           });
  }
  template <class F>
  static bool robust_pred(const Shot<F>& a, const spec::Fan<F>& f) {
    return f.any([&](const Triangle<F>& t) { return cdref::robust::hit(a, t); });
  }
  // the union: certain when some triangle is certainly hit, or every one certainly missed
  template <class F>
  static cdref::robust::Decision robust_decide(const Shot<F>& a, const spec::Fan<F>& f) {
    cdref::robust::Decision u{false, true};
    for (int k = 0; k < f.triangles(); ++k) {
      const cdref::robust::Decision d = cdref::robust::decide(a, f.triangle(k));
      if (d.value && d.certain) return d;
      u.value = u.value || d.value;
      u.certain = u.certain && d.certain;
    }
    return u;
  }
  // the smallest of the triangles' correctly rounded lambda_enter (each checks its inputs)
  static cdref::oracle::Entry oracle_enter(const Shot<double>& a, const spec::Fan<double>& f, bool* exact_used) {
    return cdref::oracle::enter_first(
        f.triangles(), [&](int k, bool* e) { return cdref::oracle::enter(a, f.triangle(k), e); }, exact_used);
  }
  static bool oracle(const Shot<double>& a, const spec::Fan<double>& f, cdref::oracle::Stage* st) {
    cdref::oracle::Stage worst = cdref::oracle::Stage::filter;
    for (int k = 0; k < f.triangles(); ++k) {
      cdref::oracle::Stage s = cdref::oracle::Stage::filter;
      const bool h = cdref::oracle::classify(a, f.triangle(k), &s);
      if (int(s) > int(worst)) worst = s;
      if (h) {
        if (st) *st = worst;
        return true;
      }
    }
    if (st) *st = worst;
    return false;
  }
  static int stage(cdref::oracle::Stage s, const Shot<double>& a, const spec::Fan<double>& f) {
    bool unknown = false;
    for (int k = 0; k < f.triangles(); ++k) {
      const int r = cdref::oracle::ray_triangle::at_stage(s, a, f.triangle(k));
      if (r == 1) return 1;
      unknown = unknown || r != 0;
    }
    return unknown ? cdref::oracle::ray_triangle::unknown : 0;
  }
};

}  // namespace cdref::fuzz::queries
