// tests/test_boxes.cpp - Section 3.2 at every number type: box-box in both forms, the
// segment and infinite-ray casts of Algorithm 3.3, and sphere-box. Expected answers are
// exact, written as rationals or a + b sqrt(d).
#include "prox_check.hpp"

// This file's names in a namespace of its own: the test files are compiled several to a unit
// (tests/CMakeLists.txt).
namespace cdref_test_boxes {

using namespace cdref;
using namespace cdref::test;

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
// Powers of two near 1e160 and 1e-162, so that small multiples are exact: products of
// two such coordinates overflow (or underflow to 0) in double.
const double big = std::ldexp(1.0, 532);     // ~1.4e160
const double tiny = std::ldexp(1.0, -540);   // ~2.8e-163

Box<double> box(double cx, double cy, double cz, double hx, double hy, double hz) {
  return {Vec3<double>(cx, cy, cz), Vec3<double>(hx, hy, hz)};
}

struct BoxCast {
  Box<double> box;
  CastCase c;
};

const Box<double> b123 = box(0, 0, 0, 1, 2, 3);

std::vector<BoxCast> ray_box_cases() {
  std::vector<BoxCast> v;
  auto add = [&](Box<double> b, CastCase c) { v.push_back({b, std::move(c)}); };
  add(b123, {"along x through the centre", {-3, 0, 0}, {3, 0, 0}, false, true, true, "1/3", "2/3", D3{-1, 0, 0}});
  add(b123, {"entering the lower y face", {0, -4, 0}, {0, 4, 1}, false, true, true, "1/4", "3/4", D3{0, -1, 0}});
  add(b123, {"entering the upper z face", {0, 0, 5}, {0, 0, -5}, false, true, true, "1/5", "4/5", D3{0, 0, 1}});
  add(b123, {"both endpoints beyond one plane", {2, 0, 0}, {3, 5, 0}, false, false});
  // Outcodes share no bit, yet the segment misses: entering 2/3 > exiting 2/5.
  add(b123, {"miss with disjoint outcodes", {-3, 0, 0}, {0, 5, 0}, false, false});
  // Through the edge x = -1, y = -2 at lambda 1/2; both lower planes tie, x comes first.
  add(b123, {"through an edge, tie of two planes", {-2, -3, 0}, {0, -1, 0}, false, true, true, "1/2", Q(1),
             D3{-1, 0, 0}});
  add(b123, {"through a corner", {-2, -3, -4}, {0, -1, -2}, false, true, true, "1/2", Q(1), D3{-1, 0, 0}});
  add(b123, {"along an edge line", {-3, 2, 3}, {3, 2, 3}, false, true, true, "1/3", "2/3", D3{-1, 0, 0}});
  add(b123, {"parallel to a face, outside", {-3, 2.5, 0}, {3, 2.5, 0}, false, false});
  add(b123, {"lying in a face plane", {-3, 0, 3}, {3, 0, 3}, false, true, true, "1/3", "2/3", D3{-1, 0, 0}});
  add(b123, {"source inside", {0, 0, 0}, {5, 0, 0}, false, true, false, Q(0), "1/5"});
  add(b123, {"source on a face, pointing out", {1, 0, 0}, {2, 0, 0}, false, true, false, Q(0), Q(0)});
  add(b123, {"target on a face plane", {-3, 0, 0}, {-1, 0, 0}, false, true, true, Q(1), Q(1), D3{-1, 0, 0}});
  add(box(0, 0, 0, 1, 1, 0), {"box of zero extent along z", {0, 0, -1}, {0, 0, 1}, false, true, true, "1/2", "1/2",
                              D3{0, 0, -1}});
  add(box(0, 0, 0, 1, 1, 0), {"segment in the plane of a flat box", {-2, 0, 0}, {2, 0, 0}, false, true, true, "1/4",
                              "3/4", D3{-1, 0, 0}});
  add(b123, {"zero-length segment inside", {0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, false, true, false, Q(0), Q(1)});
  add(b123, {"zero-length segment outside", {5, 0, 0}, {5, 0, 0}, false, false});
  add(box(10, 20, 30, 1, 1, 1), {"box off the origin", {5, 20, 30}, {15, 20, 30}, false, true, true, "2/5", "3/5",
                                 D3{-1, 0, 0}});
  add(box(0, 0, 0, 1, 1, 1), {"long range 1e8", {-1e8, 0.5, 0.5}, {1e8, 0.5, 0.5}, false, true, true,
                              Q(1e8 - 1) / Q(2e8), Q(1e8 + 1) / Q(2e8), D3{-1, 0, 0}});
  add(box(0, 0, 0, big, 2 * big, 3 * big),
      {"coordinates near 1e160", {-3 * big, 0, 0}, {3 * big, 0, 0}, false, true, true, "1/3", "2/3", D3{-1, 0, 0}});
  // The division-free hit() compares the crossing parameters by cross-multiplication:
  // 2B * 5B and 2B * 3B both overflow to infinity in double, inf <= inf, and it reports
  // a hit. cast(), which divides as the listing does, gets 2/3 > 2/5 right.
  add(box(0, 0, 0, big, 2 * big, 3 * big),
      {"miss with disjoint outcodes near 1e160",
       {-3 * big, 0, 0},
       {0, 5 * big, 0},
       false,
       false,
       false,
       {},
       {},
       std::nullopt,
       {{"double", {std::nullopt, 0, 4, true}}}});
  // The same near 1e-163: the products underflow to 0 and 0 <= 0 reports a hit.
  add(box(0, 0, 0, tiny, 2 * tiny, 3 * tiny),
      {"miss with disjoint outcodes near 1e-163",
       {-3 * tiny, 0, 0},
       {0, 5 * tiny, 0},
       false,
       false,
       false,
       {},
       {},
       std::nullopt,
       {{"double", {std::nullopt, 0, 4, true}}}});
  // infinite rays
  add(b123, {"ray along x", {-3, 0, 0}, {1, 0, 0}, true, true, true, Q(2), Q(4), D3{-1, 0, 0}});
  add(b123, {"ray with a non-unit direction", {-3, 0, 0}, {4, 0, 0}, true, true, true, "1/2", Q(1), D3{-1, 0, 0}});
  add(b123, {"ray from inside", {0, 0, 0}, {0, 1, 0}, true, true, false, Q(0), Q(2)});
  add(b123, {"ray parallel to a face, outside", {-3, 5, 0}, {1, 0, 0}, true, false});
  add(b123, {"ray pointing away", {3, 0, 0}, {1, 0, 0}, true, false});
  add(b123, {"ray diagonal", {-3, -3, 0}, {1, 1, 0}, true, true, true, Q(2), Q(4), D3{-1, 0, 0}});
  add(b123, {"ray in a face plane", {-3, 2, 0}, {1, 0, 0}, true, true, true, Q(2), Q(4), D3{-1, 0, 0}});
  add(b123, {"ray from a face, pointing out", {0, 0, 3}, {0, 0, 1}, true, true, false, Q(0), Q(0)});
  return v;
}

}  // namespace

TEMPLATE_TEST_CASE("ray-box casts (Algorithm 3.3) on hard cases", "[ray-box]", CDREF_ALL_TYPES) {
  for (const auto& bc : ray_box_cases()) {
    check_cast_case<TestType>(
        bc.c, bc.box, bc.box.center, 0.0,
        [](const auto& s, const auto& t, const auto& b, bool infinite) {
          using U = typename std::decay_t<decltype(s)>::Scalar;
          return infinite ? book::cast(Ray<U>{s, t}, b) : book::cast(Segment<U>{s, t}, b);
        },
        [](const auto& s, const auto& t, const auto& b, bool infinite) {
          using U = typename std::decay_t<decltype(s)>::Scalar;
          return infinite ? book::hit(Ray<U>{s, t}, b) : book::hit(Segment<U>{s, t}, b);
        });
  }
}

TEST_CASE("Algorithm 3.3 tests both planes of every axis inside the loop (errata)", "[ray-box]") {
  // One segment per plane, entering or exiting through that plane alone: each of the 12
  // (plane, direction) combinations must give its own parameter, which a listing with the
  // upper-plane block outside the loop gets wrong.
  using T = CGAL::Gmpq;
  const Box<T> b{Vec3<T>(T(0), T(0), T(0)), Vec3<T>(T(1), T(2), T(3))};
  for (int axis = 0; axis < 3; ++axis)
    for (int upper = 0; upper < 2; ++upper) {
      const T eta = b.extent[axis];
      const T out = upper ? T(eta + 4) : T(-eta - 4);
      Vec3<T> s(T(0), T(0), T(0)), t(T(0), T(0), T(0));
      s[axis] = out;  // enters through this plane, from outside
      t[axis] = T(0);
      const auto in_cast = book::cast(Segment<T>{s, t}, b);
      REQUIRE(in_cast.hit);
      // lower: (-sigma - eta) / (tau - sigma); upper: (-sigma + eta) / (tau - sigma)
      const T expect_in = upper ? T((-out + eta) / (T(0) - out)) : T((-out - eta) / (T(0) - out));
      REQUIRE(in_cast.lambda_enter == expect_in);
      REQUIRE(in_cast.normal[axis] == T(upper ? 1 : -1));
      const auto out_cast = book::cast(Segment<T>{t, s}, b);  // exits through it
      REQUIRE(out_cast.hit);
      REQUIRE(out_cast.lambda_enter == T(0));
      const T expect_out = upper ? T((T(0) + eta) / (out - T(0))) : T((T(0) - eta) / (out - T(0)));
      REQUIRE(out_cast.lambda_exit == expect_out);
    }
}

// ---------------------------------------------------------------------------
namespace {

struct BoxBoxCase {
  std::string name;
  Box<double> a, b;
  bool intersect;
  std::map<std::string, bool> centre_extent_floats{};  // centre-extent answer at a float type, where it drifts
};

std::vector<BoxBoxCase> box_box_cases() {
  const double p53 = std::ldexp(1.0, 53);
  return {
      {"overlapping", box(0, 0, 0, 1, 1, 1), box(1, 1, 1, 1, 1, 1), true},
      {"separated along x", box(0, 0, 0, 1, 1, 1), box(3, 0, 0, 1, 1, 1), false},
      {"touching faces", box(0, 0, 0, 1, 1, 1), box(2, 0, 0, 1, 1, 1), true},
      {"touching edges", box(0, 0, 0, 1, 1, 1), box(2, 2, 0, 1, 1, 1), true},
      {"touching corners", box(0, 0, 0, 1, 1, 1), box(2, -2, 2, 1, 1, 1), true},
      {"gap of 2^-51", box(0, 0, 0, 1, 1, 1), box(2 + std::ldexp(1.0, -51), 0, 0, 1, 1, 1), false},
      {"contained", box(0, 0, 0, 5, 5, 5), box(1, 1, 1, 1, 1, 1), true},
      {"zero extent touching", box(0, 0, 0, 0, 0, 0), box(1, 0, 0, 1, 1, 1), true},
      {"zero extent apart", box(0, 0, 0, 0, 0, 0), box(1, 0, 0, 0.5, 1, 1), false},
      {"near 1e160", box(0, 0, 0, big, big, big), box(2 * big, 0, 0, big, big, big), true},
      // h1 + h2 = 2^53 + 3 rounds (tie, to even) up to 2^53 + 4 = |c1 - c2| in double:
      // disjoint by 1, the centre-extent form says they touch. The min-max form compares
      // the corners, exactly.
      {"extent sum rounding at 2^53", box(0, 0, 0, 1, 1, 1), box(p53 + 4, 0, 0, p53 + 2, 1, 1), false,
       {{"double", true}}},
  };
}

}  // namespace

TEMPLATE_TEST_CASE("box-box (3.2) in both forms", "[box-box]", CDREF_ALL_TYPES) {
  using T = TestType;
  for (const auto& c : box_box_cases()) {
    INFO("case: " << c.name << "  type: " << tag<T>());
    const Box<T> a = convert_prim<T>(c.a), b = convert_prim<T>(c.b);
    if (!prim_finite<T>(c.a) || !prim_finite<T>(c.b)) {  // overflows this type: refused by name
      REQUIRE_THROWS_AS(book::intersect(a, b), invalid_input);
      continue;
    }
    // corners in double; in these cases the corners that decide the answer are exact
    const MinMaxBox<double> am = to_min_max(c.a), bm = to_min_max(c.b);
    const MinMaxBox<T> amt{v3<T>(am.min[0], am.min[1], am.min[2]), v3<T>(am.max[0], am.max[1], am.max[2])};
    const MinMaxBox<T> bmt{v3<T>(bm.min[0], bm.min[1], bm.min[2]), v3<T>(bm.max[0], bm.max[1], bm.max[2])};
    if constexpr (is_exact_v<T>) {
      REQUIRE(book::intersect(a, b) == c.intersect);
      REQUIRE(book::intersect(amt, bmt) == c.intersect);
      REQUIRE(book::intersect(to_min_max(a), to_min_max(b)) == c.intersect);
      REQUIRE(book::intersect(to_center_extent(amt), to_center_extent(bmt)) == c.intersect);
    } else {
      // truth on this type's own rounding of the inputs
      const bool truth = book::intersect(convert_prim_exact(a), convert_prim_exact(b));
      const auto it = c.centre_extent_floats.find(tag<T>());
      REQUIRE(book::intersect(a, b) == (it != c.centre_extent_floats.end() ? it->second : truth));
      // min-max only compares, so it is exact at any type on the corners it is given
      const MinMaxBox<Q> aq{exact_vec(amt.min), exact_vec(amt.max)}, bq{exact_vec(bmt.min), exact_vec(bmt.max)};
      REQUIRE(book::intersect(amt, bmt) == book::intersect(aq, bq));
    }
  }
}

// ---------------------------------------------------------------------------
namespace {

Sphere<double> sph(double x, double y, double z, double r) { return {Vec3<double>(x, y, z), r}; }
X3 x3(X a, X b, X c) { return {a, b, c}; }

struct SphereBoxCase {
  PairOf<Sphere<double>, Box<double>> in;
  ProxCase c;
};

std::vector<SphereBoxCase> sphere_box_cases() {
  std::vector<SphereBoxCase> v;
  auto add = [&](Sphere<double> s, Box<double> b, ProxCase c) { v.push_back({{s, b}, std::move(c)}); };
  add(sph(3, 0, 0, 1), b123,
      {"apart, nearest a face", false, Q(1), Q(0), x3(Q(2), Q(0), Q(0)), x3(Q(1), Q(0), Q(0)),
       x3(Q(1), Q(0), Q(0))});
  add(sph(2, 0, 0, 1), b123,
      {"touching a face", true, Q(0), Q(0), x3(Q(1), Q(0), Q(0)), x3(Q(1), Q(0), Q(0)), x3(Q(1), Q(0), Q(0))});
  add(sph(4, 6, 0, 5), b123,
      {"touching an edge", true, Q(0), Q(0), x3(Q(1), Q(2), Q(0)), x3(Q(1), Q(2), Q(0)), x3(Q(1), Q(2), Q(0))});
  add(sph(3, 5, 9, 7), b123,
      {"touching a corner", true, Q(0), Q(0), x3(Q(1), Q(2), Q(3)), x3(Q(1), Q(2), Q(3)), x3(Q(1), Q(2), Q(3))});
  add(sph(3, 5, 9, 6.5), b123,
      {"apart from a corner", false, "1/2", Q(0), x3("16/14", "31/14", "48/14"), x3(Q(1), Q(2), Q(3)),
       x3(Q(1), Q(2), Q(3))});
  // x = (1,2,0), v = (-1,-1,0), |v| = sqrt 2: depth 2 - sqrt 2, witness c + 2 v/|v|.
  add(sph(2, 3, 0, 2), b123,
      {"overlapping, centre outside", true, Q(0), X(Q(2), Q(-1), Q(2)), x3(X(Q(2), Q(-1), Q(2)), X(Q(3), Q(-1), Q(2)), Q(0)),
       x3(Q(1), Q(2), Q(0)), x3(Q(1), Q(2), Q(0))});
  add(sph(0.5, 0, 0, 1), b123,
      {"centre inside, nearest x face", true, Q(0), "3/2", x3("-1/2", Q(0), Q(0)), x3(Q(1), Q(0), Q(0)),
       x3("1/2", Q(0), Q(0))});
  add(sph(0, 0, -2.5, 1), b123,
      {"centre inside, nearest lower z face", true, Q(0), "3/2", x3(Q(0), Q(0), "-3/2"), x3(Q(0), Q(0), Q(-3)),
       x3(Q(0), Q(0), "-5/2")});
  add(sph(0, 0, 0, 1), b123,
      {"centre at the box centre", true, Q(0), Q(2), x3(Q(-1), Q(0), Q(0)), x3(Q(1), Q(0), Q(0)),
       x3(Q(0), Q(0), Q(0))});
  add(sph(1, 0, 0, 0.5), b123,
      {"centre on a face", true, Q(0), "1/2", x3("1/2", Q(0), Q(0)), x3(Q(1), Q(0), Q(0)), x3(Q(1), Q(0), Q(0))});
  add(sph(3, 0, 0, 0), b123,
      {"zero radius, outside", false, Q(2), Q(0), x3(Q(3), Q(0), Q(0)), x3(Q(1), Q(0), Q(0)), x3(Q(1), Q(0), Q(0))});
  add(sph(0, 0, 0, 1), box(0, 0, 0, 0, 0, 0),
      {"box of zero extent at the centre", true, Q(0), Q(1), x3(Q(-1), Q(0), Q(0)), x3(Q(0), Q(0), Q(0)),
       x3(Q(0), Q(0), Q(0))});
  add(sph(12, 21, 30, 1), box(10, 20, 30, 1, 1, 1),
      {"box off the origin, touching", true, Q(0), Q(0), x3(Q(11), Q(21), Q(30)), x3(Q(11), Q(21), Q(30)),
       x3(Q(11), Q(21), Q(30))});
  // v = (-1e8, -1, 0): |v|^2 = 1e16 + 1 rounds to 1e16 = rho^2 in double: disjoint by
  // 5e-9, double says touching with distance 0. |v| - rho cancels at every precision:
  // long double and MPFR-128 classify right, with distances off by over 1e15 ulps.
  const Q vv = Q(1e16) + Q(1);
  add(sph(1e8 + 1, 2, 0.5, 1e8), box(0, 0, 0, 1, 1, 1),
      {"near-touching at 1e8",
       false,
       X(Q(-1e8), Q(1), vv),
       Q(0),
       x3(X(Q(1e8 + 1), Q(-1e16) / vv, vv), X(Q(2), Q(-1e8) / vv, vv), "1/2"),
       x3(Q(1), Q(1), "1/2"),
       x3(Q(1), Q(1), "1/2"),
       {{"float", {true, true, 1e6, inf, inf}},
        {"double", {true, true, 1e15, inf, inf}},
        {"long double", {std::nullopt, std::nullopt, 1e15, inf, inf}},
        {"mpfr", {std::nullopt, std::nullopt, 1e15, inf, inf}}},
       1e8});
  // 1e160: |v|^2 = 4B^2 and rho^2 overflow to infinity in double: inf <= inf.
  add(sph(3 * big, 0, 0, big), box(0, 0, 0, big, big, big),
      {"coordinates near 1e160",
       false,
       Q(big),
       Q(0),
       x3(Q(2 * big), Q(0), Q(0)),
       x3(Q(big), Q(0), Q(0)),
       x3(Q(big), Q(0), Q(0)),
       {{"double", {true, true, 0, inf, inf}}},
       big});
  return v;
}

}  // namespace

TEMPLATE_TEST_CASE("sphere-box (3.2.2) on hard cases", "[sphere-box]", CDREF_ALL_TYPES) {
  for (const auto& sc : sphere_box_cases())
    check_prox_case<TestType>(sc.c, sc.in, [](const auto& in) {
      return std::pair{book::proximity(in.first, in.second), book::intersect(in.first, in.second)};
    });
}

}  // namespace cdref_test_boxes
