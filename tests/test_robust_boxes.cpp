// tests/test_robust_boxes.cpp - the robust float box queries (float/cdref/robust/box_box.hpp,
// ray_box.hpp) against the book at CGAL::Gmpq on the same float inputs, at float, double
// and long double: hard cases with every output checked against the error bound derived in
// the headers, and generated cases for the certificates of decide().
#include <bit>
#include <cdref/fuzz/campaign.hpp>
#include <cdref/robust/box_box.hpp>
#include <cdref/robust/ray_box.hpp>
#include <cdref/stable/obb.hpp>
#include <cdref/stable/ray_box.hpp>
#include <array>
#include <iostream>

#include "support.hpp"

// This file's names in a namespace of its own: the test files are compiled several to a unit
// (tests/CMakeLists.txt).
namespace cdref_test_robust_boxes {

using namespace cdref;
using namespace cdref::test;

namespace {

template <class F>
constexpr int digits = std::numeric_limits<F>::digits;

// The unit roundoff u = 2^-p, exactly.
template <class F>
Q unit_roundoff() {
  return p2(-digits<F>);
}

template <class F>
F round_exact(const Q& x) {
  if constexpr (std::is_same_v<F, long double>)
    return exact::round_long_double(x);
  else
    return round_to<F>(x);
}

// Representable values between a and b (both of type F).
template <class F>
std::uint64_t ulp_dist(F a, F b) {
  return fuzz::ulp_distance(static_cast<long double>(a), static_cast<long double>(b), digits<F>);
}

template <class F>
Vec3<F> vec(F x, F y, F z) {
  return Vec3<F>(x, y, z);
}

template <class F>
bool report() {
  return std::getenv("CDREF_TEST_REPORT") != nullptr;
}

template <class F>
std::string type_name() {
  if constexpr (std::is_same_v<F, float>) return "float";
  if constexpr (std::is_same_v<F, double>) return "double";
  return "long double";
}

// ---------------------------------------------------------------------------
// Ray casts on a box: hard cases.

template <class F>
struct ShotCase {
  std::string name;
  Vec3<F> s, t;  // source and target (segment) or source and direction (ray)
  Vec3<F> c, h;
  bool ray = false;
  bool book_hit_wrong = false;   // book::hit at F misclassifies here (asserted)
  bool book_cast_wrong = false;  // book::cast(...).hit at F misclassifies here (asserted)
  bool near = false;  // an exact tie, or parameters closer than the resolution of F (decided exactly all the same)
};

template <class F>
std::vector<ShotCase<F>> shot_cases() {
  std::vector<ShotCase<F>> v;
  const int p = digits<F>;
  const F one(1);
  // Box [-1,1] x [-2,2] x [-3,3] around a centre c.
  const Vec3<F> h123 = vec(F(1), F(2), F(3));
  for (int k : {10, p - 3}) {
    for (F sg : {F(1), F(-1)}) {
      const F g = sg * std::ldexp(one, -k);
      // Edge x = -1, y = -2 grazed by the line x + y = -3 - 2g (direction (1,-1,0)):
      // entering x- at (2 + g)/4, exiting y- at (2 - g)/4; hit iff g <= 0.
      const Vec3<F> a = vec(F(-1 - g), F(-2 - g), F(0.5));
      const Vec3<F> dv = vec(F(2), F(-2), F(0));
      // At k = p - 3 the parameters differ by g/2 = 4u: the filter leaves them to the exact step.
      const bool near = k == p - 3;
      v.push_back({"grazing edge g=2^-" + std::to_string(k) + (sg > 0 ? " (+)" : " (-)"), Vec3<F>(a - dv), Vec3<F>(a + dv),
                   vec(F(0), F(0), F(0)), h123, false, false, false, near});
      // The same with the box 2^(p-14) away from the origin (every coordinate exact).
      const F C = std::ldexp(one, p - 14);
      const Vec3<F> cc = vec(C, F(-C), C);
      if (k == 10)
        v.push_back({"grazing edge off the origin g=2^-" + std::to_string(k) + (sg > 0 ? " (+)" : " (-)"), Vec3<F>(cc + a - dv),
                     Vec3<F>(cc + a + dv), cc, h123});
      // Corner (-1,-2,-3) grazed along (1,-1,1): x- and z- enter at mu = g, y- exits at
      // mu = -g; as a segment a -+ 2 (1,-1,1), lambda = (mu + 2)/4.
      const Vec3<F> ak = vec(F(-1 - g), F(-2 - g), F(-3 - g));
      const Vec3<F> dk = vec(F(2), F(-2), F(2));
      v.push_back({"grazing corner g=2^-" + std::to_string(k) + (sg > 0 ? " (+)" : " (-)"), Vec3<F>(ak - dk), Vec3<F>(ak + dk),
                   vec(F(0), F(0), F(0)), h123, false, false, false, near});
      v.push_back({"grazing corner, ray, g=2^-" + std::to_string(k) + (sg > 0 ? " (+)" : " (-)"), Vec3<F>(ak - dk), dk,
                   vec(F(0), F(0), F(0)), h123, true, false, false, near});
    }
  }
  // Exact ties: through an edge and a corner.
  v.push_back({"through the edge exactly", vec(F(-3), F(0), F(0.5)), vec(F(1), F(-4), F(0.5)), vec(F(0), F(0), F(0)),
               h123, false, false, false, true});
  v.push_back({"through the corner exactly", vec(F(-3), F(0), F(-5)), vec(F(1), F(-4), F(-1)),
               vec(F(0), F(0), F(0)), h123, false, false, false, true});
  v.push_back({"ray through the corner exactly", vec(F(-3), F(0), F(-5)), vec(F(1), F(-1), F(1)),
               vec(F(0), F(0), F(0)), h123, true, false, false, true});
  // In a face plane, parallel to a face, source on a face, target on a face.
  v.push_back({"segment in the face plane z = 3", vec(F(-5), F(0.5), F(3)), vec(F(5), F(1), F(3)), vec(F(0), F(0), F(0)), h123});
  v.push_back({"ray in the face plane y = -2", vec(F(-5), F(-2), F(1)), vec(F(1), F(0), F(0.25)), vec(F(0), F(0), F(0)), h123, true});
  // s_y = fl(fl(0.2) - 2) lies just off the face plane c_y - 2 (the subtraction rounds); at
  // double it is outside, and the book's s - c rounds back onto -2: both its answers call
  // this miss a hit.
  v.push_back({"ray in the face plane y = -2 off the origin", vec(F(0.1) - F(5), F(0.2) - F(2), F(0.3) + F(1)),
               vec(F(1), F(0), F(0.25)), vec(F(0.1), F(0.2), F(0.3)), h123, true, std::is_same_v<F, double>,
               std::is_same_v<F, double>});
  v.push_back({"parallel to a face, outside by an ulp", vec(F(-5), F(std::nextafter(F(2), F(3))), F(0)),
               vec(F(5), F(std::nextafter(F(2), F(3))), F(1)), vec(F(0), F(0), F(0)), h123});
  v.push_back({"source on a face, pointing out", vec(F(1), F(0.5), F(0.5)), vec(F(2), F(0.7), F(0.5)),
               vec(F(0), F(0), F(0)), h123});
  v.push_back({"source on a face, pointing in", vec(F(-1), F(0.5), F(0.5)), vec(F(3), F(0.7), F(0.1)),
               vec(F(0), F(0), F(0)), h123});
  v.push_back({"ray from a face, pointing out", vec(F(0.25), F(0.5), F(3)), vec(F(0.1), F(0.1), F(1)),
               vec(F(0), F(0), F(0)), h123, true});
  v.push_back({"target on a face", vec(F(-3), F(0.3), F(0.7)), vec(F(-1), F(0.1), F(0.2)), vec(F(0), F(0), F(0)), h123});
  // Long range: from R box sizes away towards the box at a non-dyadic centre; s - c, t - s
  // and the numerators round in the book.
  for (double R : {1e8, 1e10, 1e12}) {
    const Vec3<F> c = vec(F(0.1), F(-0.2), F(0.3));
    const Vec3<F> h = vec(F(0.7), F(0.9), F(1.1));
    const Vec3<F> dir = vec(F(0.6), F(0.48), F(0.64));
    for (double off : {0.5, 0.95, 1.05}) {  // aimed at `off` extents from the centre along y
      const Vec3<F> aim = vec(c[0], F(c[1] + F(off) * h[1]), c[2]);
      const Vec3<F> s = vec(F(aim[0] - F(R) * dir[0]), F(aim[1] - F(R) * dir[1]), F(aim[2] - F(R) * dir[2]));
      const Vec3<F> t = vec(F(aim[0] + F(2) * dir[0]), F(aim[1] + F(2) * dir[1]), F(aim[2] + F(2) * dir[2]));
      const std::string nm = "long range R=" + std::to_string(R) + " aimed at " + std::to_string(off);
      // The parameters of the planes differ by about (box size) / R: below the filter's
      // margin 8u(|l_p| + |l_q|) once that is below ~16u (float from 1e8 on).
      const bool near = 1 / R < 64 * double(std::numeric_limits<F>::epsilon());
      v.push_back({nm, s, t, c, h, false, false, false, near});
      v.push_back({nm + ", ray", s, Vec3<F>(dir * F(3)), c, h, true, false, false, near});
    }
  }
  // Huge and tiny magnitudes: the book's hit() cross-multiplies parameters of size B, and
  // 2B * 5B overflows (2^(emax/2 + 20) squared), or b * b underflows to 0.
  const F B = std::ldexp(one, std::numeric_limits<F>::max_exponent / 2 + 20);
  const F b = std::ldexp(one, std::numeric_limits<F>::min_exponent / 2 - 40);
  for (F m : {B, b}) {
    const std::string nm = m == B ? "2^(emax/2+20)" : "2^(emin/2-40)";
    v.push_back({"miss with disjoint outcodes at " + nm, vec(F(-3 * m), F(0), F(0)), vec(F(0), F(5 * m), F(0)),
                 vec(F(0), F(0), F(0)), vec(m, F(2 * m), F(3 * m)), false, true});
    v.push_back({"hit along x at " + nm, vec(F(-3 * m), F(0), F(0)), vec(F(3 * m), F(m), F(0)), vec(F(0), F(0), F(0)),
                 vec(m, F(2 * m), F(3 * m))});
    v.push_back({"grazing edge at " + nm, vec(F(-3 * m), F(0.5 * m), F(0)), vec(F(1 * m), F(-3.5 * m), F(0)),
                 vec(F(0), F(0), F(0)), vec(m, F(2 * m), F(3 * m))});
    v.push_back({"through the edge exactly at " + nm, vec(F(-3 * m), F(0), F(0.5 * m)), vec(F(m), F(-4 * m), F(0.5 * m)),
                 vec(F(0), F(0), F(0)), vec(m, F(2 * m), F(3 * m)), false, false, false, true});
    v.push_back({"ray through the corner exactly at " + nm, vec(F(-3 * m), F(0), F(-5 * m)), vec(F(1), F(-1), F(1)),
                 vec(F(0), F(0), F(0)), vec(m, F(2 * m), F(3 * m)), true, false, false, true});
  }
  // Near overflow: s - c and t - s overflow in the book.
  {
    const F P = std::ldexp(one, std::numeric_limits<F>::max_exponent - 1);
    v.push_back({"s - c overflows", vec(F(-1.75 * P), F(0.5), F(0.5)), vec(F(1.75 * P), F(0.5), F(0.25)),
                 vec(F(0.75 * P), F(0), F(0)), vec(F(0.25 * P), F(1), F(1)), false, false, true});
  }
  // Subnormal inputs (exact: sums of subnormals do not round, and robust scales them up).
  {
    const F d = std::numeric_limits<F>::denorm_min();
    v.push_back({"subnormal box", vec(F(-30 * d), F(d), F(0)), vec(F(30 * d), F(3 * d), F(d)), vec(F(0), F(0), F(0)),
                 vec(F(10 * d), F(20 * d), F(30 * d))});
  }
  return v;
}

// Worst errors seen, per output, in ulps of F against the correctly rounded truth.
struct Worst {
  std::uint64_t enter = 0, exit = 0, point_face = 0, point_other = 0;
  double enter_rel = 0;  // |lambda^ - lambda| / (u |lambda|), worst
  double point_rel = 0;  // |p^_j - p_j| / (u (|p_j| + |lambda r_j|)), off the face axis, worst
};

template <class F, class Shot>
void check_shot(const ShotCase<F>& c, Worst& worst) {
  INFO("case: " << c.name << "  type: " << type_name<F>());
  const Box<F> box{c.c, c.h};
  const Shot shot{c.s, c.t};
  using ShotQ = std::conditional_t<std::is_same_v<Shot, Ray<F>>, Ray<Q>, Segment<Q>>;
  const ShotQ sq{exact_vec(c.s), exact_vec(c.t)};
  const Box<Q> bq{exact_vec(c.c), exact_vec(c.h)};
  const Cast<Q> ex = book::cast(sq, bq);
  const Cast<F> rb = robust::cast(shot, box);
  const robust::Decision dec = robust::decide(shot, box);
  // The classification: exact outcodes, parameters compared exactly (step 5). Every hard
  // case lies in the range where step 5 is exact, ties and near-ties included: certain.
  REQUIRE(dec.value == rb.hit);
  REQUIRE(robust::hit(shot, box) == rb.hit);
  REQUIRE(dec.certain);
  REQUIRE(dec.value == ex.hit);
  if (c.book_hit_wrong) REQUIRE(book::hit(shot, box) != ex.hit);
  if (c.book_cast_wrong) REQUIRE(book::cast(shot, box).hit != ex.hit);
  if (report<F>())
    std::cout << "[robust-boxes] " << c.name << " | " << type_name<F>() << " | hit " << ex.hit << " certain "
              << dec.certain << " | book hit() " << (book::hit(shot, box) == ex.hit ? "right" : "WRONG")
              << " cast() " << (book::cast(shot, box).hit == ex.hit ? "right" : "WRONG") << "\n";
  if (!ex.hit) return;
  REQUIRE(rb.enters == ex.enters);
  REQUIRE(rb.unbounded_exit == ex.unbounded_exit);
  // The same entering face as the book at Gmpq, on exact ties too (the first in plane order).
  bool same_face = true;
  for (int i = 0; i < 3; ++i) same_face = same_face && exact_q(rb.normal[i]) == ex.normal[i];
  REQUIRE(same_face);
  const Q u = unit_roundoff<F>();
  // lambda_enter, lambda_exit: (*) |lambda^ - lambda| <= u (1 + 18u) |lambda| (normal range).
  for (int which = 0; which < 2; ++which) {
    const Q lam = which == 0 ? ex.lambda_enter : ex.lambda_exit;
    const F got = which == 0 ? rb.lambda_enter : rb.lambda_exit;
    const Q err = CGAL::abs(exact_q(got) - lam);
    REQUIRE(err <= u * (1 + 18 * u) * CGAL::abs(lam));
    const std::uint64_t d = ulp_dist(got, round_exact<F>(lam));
    REQUIRE(d <= 1);  // follows: the correctly rounded value or its neighbour
    (which == 0 ? worst.enter : worst.exit) = std::max(which == 0 ? worst.enter : worst.exit, d);
    if (which == 0 && lam != 0) worst.enter_rel = std::max(worst.enter_rel, CGAL::to_double(err / (u * CGAL::abs(lam))));
  }
  // The point.
  const int face_axis = [&] {
    for (int i = 0; i < 3; ++i)
      if (ex.normal[i] != 0) return i;
    return -1;
  }();
  for (int j = 0; j < 3; ++j) {
    INFO("point coordinate " << j);
    if (!ex.enters) {  // the source, exactly
      REQUIRE(rb.point[j] == c.s[j]);
      continue;
    }
    const F want = round_exact<F>(ex.point[j]);
    const std::uint64_t d = ulp_dist(rb.point[j], want);
    if (j == face_axis) {  // on the face plane: fl(c_i +- eta_i), correctly rounded
      REQUIRE(d == 0);
      worst.point_face = std::max(worst.point_face, d);
    } else {  // |p^ - p| <= u (2 (1 + u) |p| + (1 + 64u) |lambda r|)
      const Q r = std::is_same_v<Shot, Ray<F>> ? exact_q(c.t[j]) : Q(exact_q(c.t[j]) - exact_q(c.s[j]));
      // (+ eta, half the smallest subnormal, where the point is scaled back into the subnormals)
      const Q eta = exact_q(std::numeric_limits<F>::denorm_min()) / 2;
      const Q bound =
          u * (2 * (1 + u) * CGAL::abs(ex.point[j]) + (1 + 64 * u) * CGAL::abs(ex.lambda_enter * r)) +
          eta;
      REQUIRE(CGAL::abs(exact_q(rb.point[j]) - ex.point[j]) <= bound);
      worst.point_other = std::max(worst.point_other, d);
      const Q scale = u * (CGAL::abs(ex.point[j]) + CGAL::abs(ex.lambda_enter * r));
      if (CGAL::abs(ex.point[j]) >= exact_q(std::numeric_limits<F>::min()))  // normal range
        worst.point_rel =
            std::max(worst.point_rel, CGAL::to_double(Q(CGAL::abs(exact_q(rb.point[j]) - ex.point[j]) / scale)));
    }
  }
}

}  // namespace

TEMPLATE_TEST_CASE("robust ray-box casts on hard cases, against the book at Gmpq", "[robust-boxes]", float, double,
                   long double) {
  using F = TestType;
  Worst worst;
  for (const ShotCase<F>& c : shot_cases<F>()) {
    if (c.ray)
      check_shot<F, Ray<F>>(c, worst);
    else
      check_shot<F, Segment<F>>(c, worst);
  }
  if (report<F>())
    std::cout << "[robust-boxes] worst ulps at " << type_name<F>() << ": lambda_enter " << worst.enter
              << " (|err|/(u|lambda|) " << worst.enter_rel << "), lambda_exit " << worst.exit << ", point on the face "
              << worst.point_face << ", point other axes " << worst.point_other << " (|err|/(u(|p|+|lambda r|)) " << worst.point_rel << ")\n";
}

// ---------------------------------------------------------------------------
// Box-box: hard cases, then every generated case of every family.

namespace {

template <class F>
struct BoxPair {
  std::string name;
  Box<F> a, b;
  bool book_wrong = false;  // the book's centre-extent test at F misclassifies (asserted)
};

template <class F>
Box<F> bx(F cx, F cy, F cz, F hx, F hy, F hz) {
  return {vec(cx, cy, cz), vec(hx, hy, hz)};
}

template <class F>
std::vector<BoxPair<F>> box_pairs() {
  std::vector<BoxPair<F>> v;
  const int p = digits<F>;
  const F one(1);
  const F P = std::ldexp(one, p - 1);
  // cA = -(P + 2), cB = P + 3: cA - cB = -(2^p + 5) rounds (tie, to even) to -(2^p + 4).
  // eA + eB = 2^p + 4 + k for k = 0 (apart by 1: the book says touching), 1 (touching, e
  // rounds), 2 (overlapping by 1); scaled by 2^m to reach large offsets.
  const int mx = std::numeric_limits<F>::max_exponent;
  for (int m : {0, 40, mx - p - 3}) {
    const F sc = std::ldexp(one, m);
    for (int k : {0, 1, 2}) {
      const F cA = -(P + 2) * sc, cB = (P + 3) * sc, eA = P * sc, eB = (P + F(4 + k)) * sc;
      v.push_back({"cA - cB rounds, 2^" + std::to_string(m) + ", k=" + std::to_string(k),
                   bx(cA, F(0), F(0), eA, one, one), bx(cB, F(0), F(0), eB, one, one), k == 0});
      v.push_back({"the same along z", bx(F(0), F(0), cA, one, one, eA), bx(F(0), F(0), cB, one, one, eB), k == 0});
    }
  }
  // Both sums overflow: |cA - cB| = 2H, eA + eB = 2H - ulp(H) (apart: the book's inf <= inf
  // says touching) or 2H (touching).
  {
    const F H = F(1.5) * std::ldexp(one, mx - 1);
    const F Hm = std::nextafter(H, F(0));
    v.push_back({"both sums overflow, apart", bx(F(-H), F(0), F(0), H, one, one), bx(H, F(0), F(0), Hm, one, one), true});
    v.push_back({"both sums overflow, touching", bx(F(-H), F(0), F(0), H, one, one), bx(H, F(0), F(0), H, one, one)});
  }
  // Touching +- 1 ulp 10^k away from the origin: cB = cA + fl(eA + eB) +- ulp.
  for (double off : {1e8, 1e10, 1e12}) {
    const F cA = F(off) + F(0.1), eA = F(0.3), eB = F(0.7);
    const F cB0 = cA + (eA + eB);
    for (int dir : {-1, 0, 1}) {
      F cB = cB0;
      if (dir < 0) cB = std::nextafter(cB0, F(0));
      if (dir > 0) cB = std::nextafter(cB0, F(2 * off));
      v.push_back({"touching +-1 ulp at " + std::to_string(off) + " dir " + std::to_string(dir),
                   bx(cA, F(0), F(0), eA, one, one), bx(cB, F(0.5), F(0), eB, one, one)});
    }
  }
  // Subnormal: exact anyway.
  const F d = std::numeric_limits<F>::denorm_min();
  v.push_back({"subnormal, apart by one", bx(F(0), F(0), F(0), F(3 * d), d, d), bx(F(8 * d), F(0), F(0), F(4 * d), d, d)});
  v.push_back({"subnormal, touching", bx(F(0), F(0), F(0), F(3 * d), d, d), bx(F(7 * d), F(0), F(0), F(4 * d), d, d)});
  return v;
}

template <class F>
Box<Q> exact_box(const Box<F>& b) {
  return {exact_vec(b.center), exact_vec(b.extent)};
}

}  // namespace

TEMPLATE_TEST_CASE("robust box-box classifies exactly on hard cases", "[robust-boxes]", float, double, long double) {
  using F = TestType;
  for (const BoxPair<F>& c : box_pairs<F>()) {
    INFO("case: " << c.name << "  type: " << type_name<F>());
    const bool truth = book::intersect(exact_box(c.a), exact_box(c.b));
    REQUIRE(robust::intersect(c.a, c.b) == truth);
    const robust::Decision dec = robust::decide(c.a, c.b);
    REQUIRE(dec.certain);
    REQUIRE(dec.value == truth);
    if (c.book_wrong) REQUIRE(book::intersect(c.a, c.b) != truth);
    // The min-max form on corners given exactly is exact at F.
    const MinMaxBox<F> am = to_min_max(c.a), bm = to_min_max(c.b);
    if (std::isfinite(am.min[0]) && std::isfinite(am.max[0]) && std::isfinite(bm.min[0]) && std::isfinite(bm.max[0])) {
      const MinMaxBox<Q> aq{exact_vec(am.min), exact_vec(am.max)}, bq{exact_vec(bm.min), exact_vec(bm.max)};
      REQUIRE(robust::intersect(am, bm) == book::intersect(aq, bq));
      REQUIRE(robust::decide(am, bm).value == book::intersect(aq, bq));
    }
  }
}

namespace {

template <class F>
Vec3<F> in3(const fuzz::Inputs& in, int k) {
  return vec(static_cast<F>(in[k]), static_cast<F>(in[k + 1]), static_cast<F>(in[k + 2]));
}

template <class F>
bool finite3(const Vec3<F>& v) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

}  // namespace

TEMPLATE_TEST_CASE("robust box-box equals the exact book on every generated case", "[robust-boxes]", float, double,
                   long double) {
  using F = TestType;
  const fuzz::Query q = fuzz::query_by_name("box-box");
  std::uint64_t n_cases = 0;
  for (const fuzz::Family& f : fuzz::families(q)) {
    for (int k : f.scales) {
      for (std::uint64_t i = 0; i < 300; ++i) {
        const fuzz::Inputs in = fuzz::make_case(11, q, f, k, i);
        const Box<F> a{in3<F>(in, 0), in3<F>(in, 3)}, b{in3<F>(in, 6), in3<F>(in, 9)};
        if (!finite3(a.center) || !finite3(a.extent) || !finite3(b.center) || !finite3(b.extent)) {
          REQUIRE_THROWS_AS(robust::intersect(a, b), invalid_input);
          continue;
        }
        INFO("family " << f.name << " scale " << k << " case " << i);
        const bool truth = book::intersect(exact_box(a), exact_box(b));
        REQUIRE(robust::intersect(a, b) == truth);
        ++n_cases;
      }
    }
  }
  if (report<F>()) std::cout << "[robust-boxes] box-box generated cases at " << type_name<F>() << ": " << n_cases << "\n";
}

// ---------------------------------------------------------------------------
// decide() for the ray casts on generated cases.
//
// Step 5 of ray_box.hpp compares the parameters exactly, so robust::hit and cast().hit
// equal the book at Gmpq on every case, and decide() is certain on every case except the
// documented ones: at double and long double, inputs whose nonzero magnitudes span more
// than K - dexp/2 binades (from the lowest set bit of any input to the leading bit of the
// largest; 1044 at double, 16409 at long double), where a product of expansion components
// may fall below the subnormal grid; never at float. The generated families stay far
// inside that range: the predicted number of exceptions is 0, and so is the number of
// uncertain answers (asserted; CDREF_TEST_REPORT=1 prints the counts).

namespace {

// The derivation's exception predicate: 2 (mu - lambda) > 2K - dexp (ray_box.hpp, step 5).
template <class F>
bool outside_exact_range(const Vec3<F>& s, const Vec3<F>& t, const Box<F>& b) {
  if constexpr (std::is_same_v<F, float>) {
    return false;
  } else {
    int mu = std::numeric_limits<int>::min(), lam = std::numeric_limits<int>::max();
    for (const Vec3<F>* v : {&s, &t, &b.center, &b.extent})
      for (int i = 0; i < 3; ++i) {
        const F x = (*v)[i];
        if (x == F(0)) continue;
        mu = std::max(mu, int(std::ilogb(x)));
        int e = 0;
        const F f = std::frexp(std::fabs(x), &e);
        const auto q = static_cast<std::uint64_t>(std::ldexp(f, digits<F>));
        lam = std::min(lam, e - digits<F> + std::countr_zero(q));
      }
    if (lam == std::numeric_limits<int>::max()) return false;
    const int K = (std::numeric_limits<F>::max_exponent - 10) / 2;
    const int dexp = std::numeric_limits<F>::min_exponent - digits<F>;
    return 2 * (mu - lam) > 2 * K - dexp;
  }
}

struct DecideCounts {
  std::uint64_t cases = 0, certain = 0, predicted = 0;
};

template <class F, class Shot>
void decide_family(fuzz::Query q, const fuzz::Family& f, std::uint64_t n_per_scale, DecideCounts& n) {
  for (int k : f.scales) {
    for (std::uint64_t i = 0; i < n_per_scale; ++i) {
      const fuzz::Inputs in = fuzz::make_case(11, q, f, k, i);
      const Vec3<F> s0 = in3<F>(in, 0), t0 = in3<F>(in, 3);
      const Shot shot{s0, t0};
      const Box<F> box{in3<F>(in, 6), in3<F>(in, 9)};
      if (!finite3(s0) || !finite3(t0) || !finite3(box.center) || !finite3(box.extent)) continue;
      if constexpr (std::is_same_v<Shot, Ray<F>>)
        if (t0[0] == F(0) && t0[1] == F(0) && t0[2] == F(0)) continue;  // refused
      bool neg = false;
      for (int j = 0; j < 3; ++j) neg = neg || box.extent[j] < F(0);
      if (neg) continue;
      INFO("family " << f.name << " scale " << k << " case " << i << " type " << type_name<F>());
      using ShotQ = std::conditional_t<std::is_same_v<Shot, Ray<F>>, Ray<Q>, Segment<Q>>;
      const ShotQ sq{exact_vec(s0), exact_vec(t0)};
      const Box<Q> bq{exact_vec(box.center), exact_vec(box.extent)};
      const bool truth = book::hit(sq, bq);
      REQUIRE(book::cast(sq, bq, 0).hit == truth);
      const robust::Decision d = robust::decide(shot, box);
      const bool predicted = outside_exact_range(s0, t0, box);
      REQUIRE(d.value == robust::hit(shot, box));
      REQUIRE(d.value == robust::cast(shot, box).hit);
      if (d.certain) {  // a certificate is never wrong
        REQUIRE(robust::hit(shot, box) == truth);
        REQUIRE(robust::cast(shot, box).hit == truth);
      } else {
        REQUIRE(predicted);  // uncertain only where the derivation says it may be
      }
      ++n.cases;
      if (d.certain) ++n.certain;
      if (predicted) ++n.predicted;
    }
  }
}

template <class F, class Shot>
void decide_query(fuzz::Query q, const char* qname) {
  for (const fuzz::Family& f : fuzz::families(q)) {
    const std::uint64_t n_per = f.name == "uniform" ? 3000 : (f.scales.size() > 1 ? 120 : 1000);
    DecideCounts n;
    decide_family<F, Shot>(q, f, n_per, n);
    if (report<F>())
      std::cout << "[robust-boxes] decide " << qname << " " << f.name << " at " << type_name<F>() << ": " << n.certain
                << "/" << n.cases << " certain, predicted exceptions " << n.predicted << "\n";
    // No generated case lies outside the exact range, and every case is certain.
    REQUIRE(n.predicted == 0);
    REQUIRE(n.certain == n.cases);
  }
}

}  // namespace

TEMPLATE_TEST_CASE("robust ray-box decide(): exact on every generated case, certain outside the documented range",
                   "[robust-boxes]", float, double, long double) {
  using F = TestType;
  decide_query<F, Segment<F>>(fuzz::query_by_name("segment-box-cast"), "segment-box");
  decide_query<F, Ray<F>>(fuzz::query_by_name("ray-box-cast"), "ray-box");
}

// Inputs beyond (**): magnitudes from near the smallest subnormal to far above 1 in one
// query. decide() may be uncertain only there (the predicate fires), and a certain answer
// is still the book's at Gmpq.
TEMPLATE_TEST_CASE("robust ray-box decide() beyond the exact range", "[robust-boxes]", double, long double) {
  using F = TestType;
  const F d = std::numeric_limits<F>::denorm_min();
  const int emax = std::numeric_limits<F>::max_exponent;
  int predicted = 0, certain = 0, cases = 0;
  for (int eb : {60, emax / 2, emax - 4}) {
    const F B = std::ldexp(F(1), eb);
    for (F b : {F(3 * d), F(std::ldexp(F(5), std::numeric_limits<F>::min_exponent - 2))}) {
      for (int k = -2; k <= 2; ++k) {
        const Box<F> box{vec(F(0), F(0), F(0)), vec(B, b, B)};
        const Segment<F> seg{vec(F(-3 * B), F(5 * b), F(0)), vec(F(3 * B), F((-5 + k) * b), F(b))};
        const Ray<F> ray{seg.source, vec(F(3 * B), F((-5 + k) * b), F(b))};
        const Box<Q> bq{exact_vec(box.center), exact_vec(box.extent)};
        INFO("eb " << eb << " k " << k << " type " << type_name<F>());
        const bool pred = outside_exact_range(seg.source, seg.target, box);
        const robust::Decision ds = robust::decide(seg, box), dr = robust::decide(ray, box);
        if (ds.certain) REQUIRE(ds.value == book::hit(Segment<Q>{exact_vec(seg.source), exact_vec(seg.target)}, bq));
        if (dr.certain) REQUIRE(dr.value == book::hit(Ray<Q>{exact_vec(ray.source), exact_vec(ray.direction)}, bq));
        if (!ds.certain || !dr.certain) REQUIRE(pred);
        predicted += pred;
        certain += ds.certain + dr.certain;
        cases += 2;
      }
    }
  }
  if (report<F>())
    std::cout << "[robust-boxes] beyond the exact range at " << type_name<F>() << ": " << certain << "/" << cases
              << " certain, " << predicted << " segment cases outside (**)\n";
  REQUIRE(predicted > 0);
}

// ---------------------------------------------------------------------------
// The stable tier of the box casts (float/cdref/stable/ray_box.hpp): the slab test in the
// box's frame, plain F arithmetic. Its header says where it can misclassify: a pair of the
// decisive values (0 or a near parameter against 1 or a far parameter) within the sum of their
// error bounds E(t) = 4u |t| + u |f_i| / |r_i| (f = source - centre), or, for a direction
// component 0, the source within u |f_i| of that plane. On generated cases of every family, every
// misclassified case lies in one of those bands, computed exactly (Gmpq); the cast's
// classification equals hit().
TEMPLATE_TEST_CASE("stable box casts: every misclassification lies in the header's bands", "[stable]", float, double) {
  using F = TestType;
  const long double u = std::ldexp(1.0L, -digits<F>);
  auto mag = [](const Q& x) { return std::fabs(static_cast<long double>(CGAL::to_double(x))); };
  // The casts' families, and those of segment-box and ray-box (Section 3.3: the same question,
  // same input columns), where stable/segment_box.hpp quotes the slab test beside the axes.
  for (const char* name : {"segment-box-cast", "ray-box-cast", "segment-box", "ray-box"}) {
    const fuzz::Query q = fuzz::query_by_name(name);
    const bool segment = std::string(name).rfind("segment", 0) == 0;
    long cases = 0, wrong = 0, book_wrong = 0;
    for (const fuzz::Family& fam : fuzz::families(q)) {
      const int per = std::max<int>(20, 800 / int(fam.scales.size()));
      for (int sc : fam.scales)
        for (int i = 0; i < per; ++i) {
          const fuzz::Inputs in = fuzz::make_case(17, q, fam, sc, std::uint64_t(i));
          const Vec3<F> s0 = in3<F>(in, 0), t0 = in3<F>(in, 3);
          const Box<F> box{in3<F>(in, 6), in3<F>(in, 9)};
          if (!finite3(s0) || !finite3(t0) || !finite3(box.center) || !finite3(box.extent)) continue;
          bool got = false, cast_hit = false, book_got = false, truth = false;
          Vec3<Q> src, r;
          auto run = [&](const auto& shot) {
            got = stable::hit(shot, box);
            cast_hit = stable::cast(shot, box, unsigned(want_all)).hit;
            book_got = book::hit(shot, box);
            const auto e = convert_prim_exact(shot);
            truth = book::hit(e, exact_box(box));
            src = e.source;
            if constexpr (requires { e.direction; })
              r = e.direction;
            else
              r = e.target - e.source;
          };
          try {
            if (segment)
              run(Segment<F>{s0, t0});
            else
              run(Ray<F>{s0, t0});
          } catch (const invalid_input&) {
            continue;
          }
          INFO(name << " family " << fam.name << " scale " << sc << " case " << i << " type " << type_name<F>());
          REQUIRE(cast_hit == got);
          ++cases;
          book_wrong += book_got != truth;
          if (got == truth) continue;
          ++wrong;
          // the decisive values with their bounds: a in {0, near_i}, b in {1, far_j}
          std::vector<std::pair<Q, long double>> as{{Q(0), 0.0L}}, bs;
          if (segment) bs.push_back({Q(1), 0.0L});
          bool in_band = false;
          for (int k = 0; k < 3; ++k) {
            const Q f = src[k] - exact_q(box.center[k]), h = exact_q(box.extent[k]);
            if (r[k] == Q(0)) {
              in_band = in_band || mag(h - f) <= 1.05L * u * mag(f) || mag(h + f) <= 1.05L * u * mag(f);
              continue;
            }
            const Q t_lo = (-h - f) / r[k], t_hi = (h - f) / r[k];
            const bool down = r[k] < Q(0);
            const long double ef = u * mag(f) / mag(r[k]);
            auto E = [&](const Q& t) { return 1.05L * (4 * u * mag(t) + ef); };
            as.push_back(down ? std::pair{t_hi, E(t_hi)} : std::pair{t_lo, E(t_lo)});
            bs.push_back(down ? std::pair{t_lo, E(t_lo)} : std::pair{t_hi, E(t_hi)});
          }
          for (const auto& [a, ea] : as)
            for (const auto& [b, eb] : bs) in_band = in_band || mag(a - b) <= ea + eb;
          REQUIRE(in_band);
        }
    }
    REQUIRE(cases > 2000);
    if (report<F>())
      std::cout << "stable " << type_name<F>() << " " << name << ": " << cases << " cases, " << wrong
                << " misclassified (the book " << book_wrong << ")\n";
  }
}

TEMPLATE_TEST_CASE("stable oriented-box casts: with the identity frame, the axis-aligned box's stable cast",
                   "[stable]", float, double) {
  // stable/obb.hpp moves the shot into the box's frame and runs stable/ray_box.hpp's slab there.
  // With the axes e_x, e_y, e_z every dot product is exact, so the frame point is s - c rounded
  // once, as the axis-aligned slab forms it: hit, both parameters, the entering face's normal and
  // the entry point's face coordinate (c -+ h, rounded once) must be the same bits, on every case
  // of the box casts' families. The other two coordinates are formed differently (in the frame,
  // then moved back) and are not compared.
  using F = TestType;
  for (const char* name : {"segment-box-cast", "ray-box-cast"}) {
    const fuzz::Query q = fuzz::query_by_name(name);
    const bool segment = std::string(name) == "segment-box-cast";
    long cases = 0, hits = 0;
    for (const fuzz::Family& fam : fuzz::families(q))
      for (int sc : fam.scales)
        for (int i = 0; i < 40; ++i) {
          const fuzz::Inputs in = fuzz::make_case(23, q, fam, sc, std::uint64_t(i));
          const Vec3<F> s0 = in3<F>(in, 0), t0 = in3<F>(in, 3);
          const Box<F> box{in3<F>(in, 6), in3<F>(in, 9)};
          if (!finite3(s0) || !finite3(t0) || !finite3(box.center) || !finite3(box.extent)) continue;
          const OrientedBox<F> obb{box.center, box.extent, {unit_vec<F>(0), unit_vec<F>(1), unit_vec<F>(2)}};
          Cast<F> a, o;
          bool ha = false, ho = false;
          try {
            if (segment) {
              const Segment<F> sh{s0, t0};
              a = stable::cast(sh, box), o = stable::cast(sh, obb), ha = stable::hit(sh, box), ho = stable::hit(sh, obb);
            } else {
              const Ray<F> sh{s0, t0};
              a = stable::cast(sh, box), o = stable::cast(sh, obb), ha = stable::hit(sh, box), ho = stable::hit(sh, obb);
            }
          } catch (const invalid_input&) {
            continue;
          }
          INFO(name << " family " << fam.name << " scale " << sc << " case " << i << " type " << type_name<F>());
          ++cases;
          REQUIRE(ho == ha);
          REQUIRE(o.hit == a.hit);
          if (!a.hit) continue;
          ++hits;
          REQUIRE(o.enters == a.enters);
          REQUIRE(std::bit_cast<std::array<unsigned char, sizeof(F)>>(o.lambda_enter) ==
                  std::bit_cast<std::array<unsigned char, sizeof(F)>>(a.lambda_enter));
          REQUIRE(std::bit_cast<std::array<unsigned char, sizeof(F)>>(o.lambda_exit) ==
                  std::bit_cast<std::array<unsigned char, sizeof(F)>>(a.lambda_exit));
          for (int k = 0; k < 3; ++k) REQUIRE(o.normal[k] == a.normal[k]);
          if (a.enters) {
            int axis = 0;
            while (a.normal[axis] == F(0)) ++axis;
            REQUIRE(o.point[axis] == a.point[axis]);
          }
        }
    REQUIRE(cases > 1000);
    REQUIRE(hits > 300);
  }
}

}  // namespace cdref_test_robust_boxes
