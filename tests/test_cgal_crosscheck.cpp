// tests/test_cgal_crosscheck.cpp - an independent check of cdref's exact answers: every
// boolean decision of Sections 3.1-3.2 (intersect, hit, cast().hit, proximity().intersect)
// at CGAL::Gmpq and CGAL::Epeck::FT is compared with CGAL::do_intersect in the exact
// kernel CGAL::Epeck, on inputs written in doubles and moved exactly into both.
//
// What CGAL's do_intersect decides (CGAL 5.5, Intersections_3/internal/*_do_intersect.h),
// and how it is turned into the closed-solid semantics of cdref (closed balls, closed
// boxes, closed segments and rays):
//
//   Sphere_3 / Sphere_3: the SPHERES (surfaces) meet. For equal centres: iff the squared
//     radii are equal; otherwise iff the radical plane meets the first sphere, which is
//     |rhoA - rhoB| <= |cA - cB| <= rhoA + rhoB. One ball strictly inside the other gives
//     false. The closed balls meet iff |cA - cB| <= rhoA + rhoB, and
//       balls meet  <=>  surfaces meet  or  cB lies in ball A  or  cA lies in ball B:
//     if |cA - cB| < |rhoA - rhoB| the centre of the smaller ball is strictly inside the
//     larger one; conversely a centre in the other ball, or a common surface point, is a
//     common point of the balls. So the test compares cdref with
//       do_intersect(A, B) || A.bounded_side(cB) != ON_UNBOUNDED_SIDE
//                          || B.bounded_side(cA) != ON_UNBOUNDED_SIDE.
//   Segment_3 / Sphere_3: decided by the sides of the endpoints: endpoints on different
//     sides, or both on the sphere: true; both strictly inside: FALSE (the segment misses
//     the surface); both strictly outside: the squared distance from the centre to the
//     segment is <= rho^2. A segment inside the open ball is therefore no intersection for
//     CGAL, but one for cdref (it lies in the closed ball). The closed-ball answer is
//       do_intersect(seg, S) || S.has_on_bounded_side(source):
//     the only CGAL "false" with a point of the segment in the ball is the case of both
//     endpoints strictly inside, and a source strictly inside always gives the ball a
//     point of the segment. (A zero-length segment falls under the same rules.)
//   Ray_3 / Sphere_3: squared distance from the centre to the ray <= rho^2: the closed
//     ball, as in cdref (a source inside the ball is a hit).
//   Sphere_3 / Iso_cuboid_3: squared distance from the centre to the closed box <= rho^2:
//     closed ball against closed box, as in cdref.
//   Segment_3 or Ray_3 / Iso_cuboid_3: an endpoint in the closed box, or a nonempty
//     parameter interval in the three closed slabs: the closed box, as in cdref.
//   Iso_cuboid_3 / Iso_cuboid_3: the closed intervals overlap on every axis, as in cdref.
//
// CGAL's Sphere_3 takes the squared radius: it is built with rho * rho computed in
// Epeck::FT (exact). A centre-extent box [c - h, c + h] becomes the Iso_cuboid_3 with
// corners c - h and c + h computed in Epeck::FT (exact); the MinMaxBox is cdref's
// to_min_max of the same box at the exact type (exact).
//
// Every pair runs four families of 2500 inputs each, all from a fixed-seed mt19937_64:
//   random    uniform coordinates in a cube;
//   integer   small integer coordinates: exact touchings and tangencies, coplanar and
//             collinear configurations, zero radii, zero extents, zero-length segments,
//             rays parallel to box faces, endpoints on box planes;
//   near      exact touching built from integers on a 2^-10 grid (radii equal to exact
//             distances taken from integer vectors of integer length, a^2 + b^2 + c^2 = n^2;
//             tangent lines; segments and rays through boundary points of boxes, in their
//             face planes or not), then one value moved by one ulp up or down (or, one
//             time in four, none) so that the answer hangs on the last bit;
//   long      half: the same exact constructions with coordinates up to ~1e12 and
//             lengths ~1e6..1e11; half: sources or centres 1e8..1e12 away, aimed at the
//             other primitive near grazing, or radii / offsets equal to a rounded
//             distance give or take a few ulps.
// cdref runs at Gmpq on all 2500 and at Epeck::FT on the first 250 of each family. Each
// family must agree with CGAL everywhere and must have produced both answers.

#include <cdref/exact/cgal_kernels.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "support.hpp"

// This file's names in a namespace of its own: the test files are compiled several to a unit
// (tests/CMakeLists.txt).
namespace cdref_test_cgal_crosscheck {

using namespace cdref;
using namespace cdref::test;

namespace {

using K = CGAL::Epeck;
using D3 = Vec3<double>;
using Rng = std::mt19937_64;
using I3 = std::array<long long, 3>;

constexpr int family_size = 2500;  // per family, at Gmpq
constexpr int lazy_size = 250;     // per family, at Epeck::FT
constexpr double inf = std::numeric_limits<double>::infinity();

// ---------------------------------------------------------------------------
// Inputs: pairs of primitives written in doubles, moved exactly into T.

template <class A, class B>
struct In2 {
  A a;
  B b;
};

template <class T>
Vec3<T> at(const D3& v) {
  return Vec3<T>(T(v[0]), T(v[1]), T(v[2]));
}
template <class T>
Sphere<T> at(const Sphere<double>& s) {
  return {at<T>(s.center), T(s.radius)};
}
template <class T>
Box<T> at(const Box<double>& b) {
  return {at<T>(b.center), at<T>(b.extent)};
}
template <class T>
Segment<T> at(const Segment<double>& s) {
  return {at<T>(s.source), at<T>(s.target)};
}
template <class T>
Ray<T> at(const Ray<double>& r) {
  return {at<T>(r.source), at<T>(r.direction)};
}

std::string num(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}
std::string str(const D3& v) { return "(" + num(v[0]) + ", " + num(v[1]) + ", " + num(v[2]) + ")"; }
std::string str(const Sphere<double>& s) {
  return "sphere{centre " + str(s.center) + ", radius " + num(s.radius) + "}";
}
std::string str(const Box<double>& b) { return "box{centre " + str(b.center) + ", extent " + str(b.extent) + "}"; }
std::string str(const Segment<double>& s) { return "segment{" + str(s.source) + " -> " + str(s.target) + "}"; }
std::string str(const Ray<double>& r) {
  return "ray{source " + str(r.source) + ", direction " + str(r.direction) + "}";
}
template <class A, class B>
std::string str(const In2<A, B>& in) {
  return str(in.a) + "; " + str(in.b);
}

// ---------------------------------------------------------------------------
// The same inputs as CGAL Epeck objects (all constructions exact).

K::Point_3 cpoint(const D3& v) { return K::Point_3(Lazy(v[0]), Lazy(v[1]), Lazy(v[2])); }
K::Vector_3 cvector(const D3& v) { return K::Vector_3(Lazy(v[0]), Lazy(v[1]), Lazy(v[2])); }
K::Sphere_3 csphere(const Sphere<double>& s) {
  const Lazy rho(s.radius);
  return K::Sphere_3(cpoint(s.center), rho * rho);
}
K::Iso_cuboid_3 ccuboid(const Box<double>& b) {
  const Vec3<Lazy> c = at<Lazy>(b.center);
  const Vec3<Lazy> h = at<Lazy>(b.extent);
  return K::Iso_cuboid_3(K::Point_3(c[0] - h[0], c[1] - h[1], c[2] - h[2]),
                         K::Point_3(c[0] + h[0], c[1] + h[1], c[2] + h[2]));
}
K::Segment_3 csegment(const Segment<double>& s) { return K::Segment_3(cpoint(s.source), cpoint(s.target)); }
K::Ray_3 cray(const Ray<double>& r) { return K::Ray_3(cpoint(r.source), cvector(r.direction)); }

// CGAL's answer in closed-solid semantics; `translated` marks the inputs where CGAL's own
// do_intersect (surface semantics) said false and the containment clause decided.
struct Verdict {
  bool value;
  bool translated = false;
};

using SS = In2<Sphere<double>, Sphere<double>>;
using SegS = In2<Segment<double>, Sphere<double>>;
using RayS = In2<Ray<double>, Sphere<double>>;
using SegB = In2<Segment<double>, Box<double>>;
using RayB = In2<Ray<double>, Box<double>>;
using BB = In2<Box<double>, Box<double>>;
using SB = In2<Sphere<double>, Box<double>>;

// CGAL's answers, in closed-solid semantics (see the top of the file).
Verdict cgal_verdict_ss(const SS& in) {
  const K::Sphere_3 a = csphere(in.a), b = csphere(in.b);
  const bool surfaces = CGAL::do_intersect(a, b);
  const bool nested =
      a.bounded_side(b.center()) != CGAL::ON_UNBOUNDED_SIDE || b.bounded_side(a.center()) != CGAL::ON_UNBOUNDED_SIDE;
  return Verdict{surfaces || nested, !surfaces && nested};
}
Verdict cgal_verdict_segs(const SegS& in) {
  const K::Segment_3 seg = csegment(in.a);
  const K::Sphere_3 sp = csphere(in.b);
  const bool surface = CGAL::do_intersect(seg, sp);
  const bool inside = sp.has_on_bounded_side(seg.source());
  return Verdict{surface || inside, !surface && inside};
}
Verdict cgal_verdict_rays(const RayS& in) { return Verdict{CGAL::do_intersect(cray(in.a), csphere(in.b))}; }
Verdict cgal_verdict_segb(const SegB& in) { return Verdict{CGAL::do_intersect(csegment(in.a), ccuboid(in.b))}; }
Verdict cgal_verdict_rayb(const RayB& in) { return Verdict{CGAL::do_intersect(cray(in.a), ccuboid(in.b))}; }
Verdict cgal_verdict_bb(const BB& in) { return Verdict{CGAL::do_intersect(ccuboid(in.a), ccuboid(in.b))}; }
Verdict cgal_verdict_sb(const SB& in) { return Verdict{CGAL::do_intersect(csphere(in.a), ccuboid(in.b))}; }

// ---------------------------------------------------------------------------
// The harness.

template <class T>
struct tag {
  using type = T;
};

struct Answer {
  const char* name;
  bool value;
};
using Answers = std::vector<Answer>;

struct Tally {
  long cases = 0, lazy_cases = 0, yes = 0, no = 0, bad = 0, translated = 0;
  std::string first;  // the first disagreement
};

template <class In>
using Generator = std::function<In(Rng&)>;

template <class In>
struct Family {
  const char* name;
  Generator<In> gen;
};

template <class In, class Truth, class Cd>
Tally run_family(std::uint64_t seed, const Generator<In>& gen, const Truth& truth, const Cd& cd) {
  Rng rng(seed);
  Tally t;
  for (int i = 0; i < family_size; ++i) {
    const In in = gen(rng);
    const Verdict v = truth(in);
    ++t.cases;
    ++(v.value ? t.yes : t.no);
    if (v.translated) ++t.translated;
    const auto compare = [&](const Answers& as, const char* type) {
      for (const Answer& a : as) {
        if (a.value == v.value) continue;
        ++t.bad;
        if (t.first.empty())
          t.first = "input #" + std::to_string(i) + ": " + str(in) + ": CGAL " + (v.value ? "true" : "false") +
                    ", cdref " + a.name + " at " + type + " " + (a.value ? "true" : "false");
      }
    };
    compare(cd(tag<Q>{}, in), "Gmpq");
    if (i < lazy_size) {
      ++t.lazy_cases;
      compare(cd(tag<Lazy>{}, in), "Epeck::FT");
    }
  }
  return t;
}

template <class In, class Truth, class Cd>
Tally run_pair(int pair, const std::vector<Family<In>>& families, const Truth& truth, const Cd& cd) {
  Tally total;
  for (std::size_t f = 0; f < families.size(); ++f) {
    const Tally t =
        run_family<In>(0x9e3779b97f4a7c15ull + 64u * static_cast<std::uint64_t>(pair) + f, families[f].gen, truth, cd);
    INFO("family " << families[f].name << ": " << t.cases << " inputs (" << t.lazy_cases << " at Epeck::FT), " << t.yes
                   << " true, " << t.no << " false, " << t.bad << " disagreements; first: " << t.first);
    REQUIRE(t.bad == 0);
    REQUIRE(t.yes > 0);
    REQUIRE(t.no > 0);
    total.cases += t.cases;
    total.lazy_cases += t.lazy_cases;
    total.translated += t.translated;
  }
  REQUIRE(total.cases >= 10000);
  REQUIRE(total.lazy_cases >= 1000);
  return total;
}

// ---------------------------------------------------------------------------
// Random numbers and exact constructions.

double uni(Rng& r, double a, double b) { return std::uniform_real_distribution<double>(a, b)(r); }
long long irand(Rng& r, long long a, long long b) { return std::uniform_int_distribution<long long>(a, b)(r); }
bool one_in(Rng& r, int k) { return irand(r, 0, k - 1) == 0; }
int sign_pm(Rng& r) { return one_in(r, 2) ? 1 : -1; }
// (Draws go into named variables one by one, so that their order is fixed.)
D3 uvec(Rng& r, double a, double b) {
  D3 v;
  for (int i = 0; i < 3; ++i) v[i] = uni(r, a, b);
  return v;
}
D3 ivec(Rng& r, long long a, long long b) {
  D3 v;
  for (int i = 0; i < 3; ++i) v[i] = static_cast<double>(irand(r, a, b));
  return v;
}
D3 unit_dir(Rng& r) {
  std::normal_distribution<double> g;
  D3 v;
  do
    for (int i = 0; i < 3; ++i) v[i] = g(r);
  while (v.norm() < 1e-3);
  return v / v.norm();
}
double log_uniform(Rng& r, double lo, double hi) { return std::exp(uni(r, std::log(lo), std::log(hi))); }
// c + D u: D log-uniform in [1e8, 1e12], u a random unit vector.
D3 far_from(Rng& r, const D3& c) {
  const double dist = log_uniform(r, 1e8, 1e12);
  const D3 u = unit_dir(r);
  return c + dist * u;
}

// The far end of a segment from s aimed at `aim`: ending there, running on past it by
// its own length, or stopping a hair (1e-12 to 1e-9 of its length) beyond it.
D3 end_near_aim(Rng& r, const D3& s, const D3& aim) {
  switch (irand(r, 0, 2)) {
    case 0:
      return aim;
    case 1:
      return aim + (aim - s);
    default:
      return aim + uni(r, 1e-12, 1e-9) * (aim - s);
  }
}
// c + g rho u with g in [0.9, 1.1]: a point near the sphere (c, rho).
D3 near_surface(Rng& r, const D3& c, double rho) {
  const double g = uni(r, 0.9, 1.1);
  const D3 u = unit_dir(r);
  return c + g * rho * u;
}
D3 nonzero_ivec(Rng& r, long long a, long long b) {
  D3 v;
  do v = ivec(r, a, b);
  while (v.isZero());
  return v;
}

// The 2^-10 grid: an integer k below 2^53 in magnitude is the double k / 1024, exactly.
double grid(long long k) { return std::ldexp(static_cast<double>(k), -10); }
D3 grid(const I3& v) { return D3(grid(v[0]), grid(v[1]), grid(v[2])); }
I3 operator+(const I3& a, const I3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
I3 operator-(const I3& a, const I3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
I3 operator*(long long k, const I3& a) { return {k * a[0], k * a[1], k * a[2]}; }
I3 cross(const I3& a, const I3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
I3 irand3(Rng& r, long long a, long long b) {
  I3 v;
  for (long long& x : v) x = irand(r, a, b);
  return v;
}
bool is_zero(const I3& v) { return v[0] == 0 && v[1] == 0 && v[2] == 0; }

// Integer vectors (a, b, c) of integer length n, nonzero components first.
constexpr std::array<std::array<long long, 4>, 19> pythagorean = {{
    {1, 0, 0, 1},    {3, 4, 0, 5},   {5, 12, 0, 13}, {8, 15, 0, 17},  {7, 24, 0, 25}, {1, 2, 2, 3},   {2, 3, 6, 7},
    {1, 4, 8, 9},    {4, 4, 7, 9},   {2, 6, 9, 11},  {6, 6, 7, 11},   {3, 4, 12, 13}, {2, 5, 14, 15}, {2, 10, 11, 15},
    {1, 12, 12, 17}, {8, 9, 12, 17}, {1, 6, 18, 19}, {6, 13, 18, 23}, {4, 5, 20, 21},
}};
constexpr bool pythagorean_ok() {
  for (const auto& p : pythagorean)
    if (p[0] * p[0] + p[1] * p[1] + p[2] * p[2] != p[3] * p[3]) return false;
  return true;
}
static_assert(pythagorean_ok());

int nonzeros(const std::array<long long, 4>& p) { return (p[0] != 0) + (p[1] != 0) + (p[2] != 0); }

// An integer vector of integer length with exactly nz nonzero components (nz = 0: any),
// components in random order and with random signs. Returns the vector and its length.
std::pair<I3, long long> pyth_dir(Rng& r, int nz = 0) {
  std::array<long long, 4> p;
  do p = pythagorean[static_cast<std::size_t>(irand(r, 0, pythagorean.size() - 1))];
  while (nz != 0 && nonzeros(p) != nz);
  I3 v = {p[0], p[1], p[2]};
  std::shuffle(v.begin(), v.end(), r);
  for (long long& x : v) x *= sign_pm(r);
  return {v, p[3]};
}

// Moves one of the fields by one ulp up or down, or (one time in four) none. A field in
// `nonneg` (radius, extent) at 0 only moves up.
void perturb(Rng& r, std::vector<double*> fields, std::vector<double*> nonneg = {}) {
  const long long n = static_cast<long long>(fields.size() + nonneg.size());
  const long long pick = irand(r, 0, n + n / 3);
  if (pick >= n) return;
  const bool up = one_in(r, 2);
  if (pick < static_cast<long long>(fields.size())) {
    double& x = *fields[static_cast<std::size_t>(pick)];
    x = std::nextafter(x, up ? inf : -inf);
  } else {
    double& x = *nonneg[static_cast<std::size_t>(pick) - fields.size()];
    x = std::nextafter(x, up || x == 0 ? inf : -inf);
  }
}
void add_fields(std::vector<double*>& f, D3& v) {
  for (int i = 0; i < 3; ++i) f.push_back(&v[i]);
}

// A boundary point of the box with integer centre c and extent h: on the face, edge or
// corner given by sigma (component +-1: on that plane; 0: anywhere in the slab).
I3 box_boundary_point(Rng& r, const I3& c, const I3& h, const I3& sigma) {
  I3 k;
  for (int i = 0; i < 3; ++i) k[i] = c[i] + (sigma[i] != 0 ? sigma[i] * h[i] : irand(r, -h[i], h[i]));
  return k;
}
I3 random_sigma(Rng& r, int nz) {  // exactly nz components +-1
  I3 s = {0, 0, 0};
  for (int i = 0; i < nz; ++i) s[static_cast<std::size_t>(i)] = sign_pm(r);
  std::shuffle(s.begin(), s.end(), r);
  return s;
}
// The size of an exact construction on the grid: centres up to c in magnitude, scale
// factors k (lengths k n) and direction multipliers f in [lo, hi] (log-uniform for the
// long-range ones), extents up to h.
struct Scale {
  long long c, k_lo, k_hi, h, f_lo, f_hi;
  bool log;
};
constexpr Scale near_scale{1ll << 22, 1, 1ll << 16, 1ll << 16, 1, 1ll << 12, false};
// Centres up to 2^40 ~ 1.1e12, lengths and offsets 2^20..2^32 ~ 1e6..4e9 after the 2^-10
// of the grid; every integer stays below 2^52, so every double is exact.
constexpr Scale far_scale{1ll << 50, 1ll << 30, 1ll << 42, 1ll << 40, 1ll << 30, 1ll << 40, true};

long long draw(Rng& r, long long lo, long long hi, bool log) {
  if (!log) return irand(r, lo, hi);
  const long long x = std::llround(log_uniform(r, static_cast<double>(lo), static_cast<double>(hi)));
  return std::min(std::max(x, lo), hi);
}
long long draw_k(Rng& r, const Scale& sc) { return draw(r, sc.k_lo, sc.k_hi, sc.log); }
long long draw_f(Rng& r, const Scale& sc) { return draw(r, sc.f_lo, sc.f_hi, sc.log); }
I3 random_extent(Rng& r, const Scale& sc) {
  I3 h;
  for (long long& x : h) x = one_in(r, 8) ? 0 : draw(r, 1, sc.h, sc.log);
  return h;
}

// ---------------------------------------------------------------------------
// Sphere-sphere.

SS sphere_sphere_exact(Rng& r, const Scale& sc) {
  // |cA - cB| = k n exactly; external tangency rhoA + rhoB = k n or internal
  // tangency |rhoA - rhoB| = k n, then one ulp.
  const I3 ca = irand3(r, -sc.c, sc.c);
  const long long k = draw_k(r, sc);
  const auto [v, n] = pyth_dir(r);
  const long long d = k * n;
  long long ra, rb;
  if (one_in(r, 3)) {
    rb = irand(r, 0, d);
    ra = d + rb;
  } else {
    ra = irand(r, 0, d);
    rb = d - ra;
  }
  SS in{{grid(ca), grid(ra)}, {grid(ca + k * v), grid(rb)}};
  if (one_in(r, 2)) std::swap(in.a, in.b);
  std::vector<double*> f;
  add_fields(f, in.a.center);
  add_fields(f, in.b.center);
  perturb(r, f, {&in.a.radius, &in.b.radius, &in.a.radius, &in.b.radius});
  return in;
}

std::vector<Family<SS>> sphere_sphere_families() {
  return {
      {"random",
       [](Rng& r) {
         return SS{{uvec(r, -10, 10), uni(r, 0, 8)}, {uvec(r, -10, 10), uni(r, 0, 8)}};
       }},
      {"integer",
       [](Rng& r) {
         return SS{{ivec(r, -4, 4), static_cast<double>(irand(r, 0, 4))},
                   {ivec(r, -4, 4), static_cast<double>(irand(r, 0, 4))}};
       }},
      {"near", [](Rng& r) { return sphere_sphere_exact(r, near_scale); }},
      {"long",
       [](Rng& r) {
         if (one_in(r, 2)) return sphere_sphere_exact(r, far_scale);
         // Centres 1e8..1e12 apart, radii summing (or differing) to about the distance.
         const D3 ca = uvec(r, -1, 1);
         const D3 cb = far_from(r, ca);
         const double d = (cb - ca).norm();
         const double ra = uni(r, 0, d);
         double rb = one_in(r, 4) ? ra - d : d - ra;
         if (rb < 0) rb = ra + d;
         rb *= 1 + std::ldexp(static_cast<double>(irand(r, -4, 4)), -52);
         return SS{{ca, ra}, {cb, rb}};
       }},
  };
}

TEST_CASE("cgal crosscheck: sphere-sphere", "[cgal]") {
  const auto cd = [](auto tg, const SS& in) {
    using T = typename decltype(tg)::type;
    const Sphere<T> a = at<T>(in.a), b = at<T>(in.b);
    return Answers{{"intersect(A, B)", book::intersect(a, b)},
                   {"intersect(B, A)", book::intersect(b, a)},
                   {"proximity(A, B).intersect", book::proximity(a, b).intersect}};
  };
  const Tally t = run_pair<SS>(1, sphere_sphere_families(), cgal_verdict_ss, cd);
  REQUIRE(t.translated > 0);  // nested balls whose surfaces do not meet did occur
}

// ---------------------------------------------------------------------------
// Segment-sphere.

SegS segment_sphere_exact(Rng& r, const Scale& sc) {
  // P = C + k N on the sphere of radius k n; U orthogonal to N (tangent).
  const I3 c = irand3(r, -sc.c, sc.c);
  const long long k = draw_k(r, sc);
  const auto [nv, n] = pyth_dir(r);
  const I3 p = c + k * nv;
  int j = 0;
  for (int i = 1; i < 3; ++i)
    if (std::llabs(nv[static_cast<std::size_t>(i)]) < std::llabs(nv[static_cast<std::size_t>(j)])) j = i;
  I3 e = {0, 0, 0};
  e[static_cast<std::size_t>(j)] = 1;
  const I3 u = irand(r, 1, k) * cross(nv, e);
  const long long f = irand(r, 1, k);
  I3 s, t;
  switch (irand(r, 0, 3)) {
    case 0:  // tangent line, the tangent point in or out of the segment
      s = p - irand(r, -2, 4) * u;
      t = p + irand(r, -2, 4) * u;
      break;
    case 1:  // on the normal line through P
      s = p + irand(r, -3, 3) * f * nv;
      t = p + irand(r, -3, 3) * f * nv;
      break;
    case 2:  // to a point of this sphere (a chord) or of a concentric one
      s = p;
      if (one_in(r, 2)) {
        I3 w = nv;
        std::shuffle(w.begin(), w.end(), r);
        for (long long& x : w) x *= sign_pm(r);
        t = c + k * w;
      } else {
        t = c + k * pyth_dir(r).first;
      }
      break;
    default:  // an endpoint on the sphere, any direction
      s = p;
      t = p + f * irand3(r, -3, 3);
      break;
  }
  SegS in{{grid(s), grid(t)}, {grid(c), grid(k * n)}};
  if (one_in(r, 2)) std::swap(in.a.source, in.a.target);
  std::vector<double*> fl;
  add_fields(fl, in.a.source);
  add_fields(fl, in.a.target);
  add_fields(fl, in.b.center);
  perturb(r, fl, {&in.b.radius, &in.b.radius, &in.b.radius, &in.b.radius, &in.b.radius});
  return in;
}

std::vector<Family<SegS>> segment_sphere_families() {
  return {
      {"random",
       [](Rng& r) {
         return SegS{{uvec(r, -10, 10), uvec(r, -10, 10)}, {uvec(r, -6, 6), uni(r, 0, 6)}};
       }},
      {"integer",
       [](Rng& r) {
         const D3 s = ivec(r, -5, 5);
         const D3 t = one_in(r, 8) ? s : ivec(r, -5, 5);
         return SegS{{s, t}, {ivec(r, -3, 3), static_cast<double>(irand(r, 0, 3))}};
       }},
      {"near", [](Rng& r) { return segment_sphere_exact(r, near_scale); }},
      {"long",
       [](Rng& r) {
         if (one_in(r, 2)) return segment_sphere_exact(r, far_scale);
         // A far source aimed at a point near the sphere's surface.
         const D3 c = uvec(r, -1, 1);
         const double rho = uni(r, 0.5, 2);
         const D3 s = far_from(r, c);
         const D3 aim = near_surface(r, c, rho);
         const D3 t = end_near_aim(r, s, aim);
         return one_in(r, 2) ? SegS{{s, t}, {c, rho}} : SegS{{t, s}, {c, rho}};
       }},
  };
}

TEST_CASE("cgal crosscheck: segment-sphere", "[cgal]") {
  const auto cd = [](auto tg, const SegS& in) {
    using T = typename decltype(tg)::type;
    const Segment<T> seg = at<T>(in.a);
    const Segment<T> rev{seg.target, seg.source};
    const Sphere<T> sp = at<T>(in.b);
    return Answers{{"intersect(segment, sphere)", book::intersect(seg, sp)},
                   {"intersect(reversed segment, sphere)", book::intersect(rev, sp)},
                   {"hit(segment, sphere)", book::hit(seg, sp)},
                   {"hit(reversed segment, sphere)", book::hit(rev, sp)},
                   {"cast(segment, sphere).hit", book::cast(seg, sp).hit},
                   {"proximity(segment, sphere).intersect", book::proximity(seg, sp).intersect}};
  };
  const Tally t = run_pair<SegS>(2, segment_sphere_families(), cgal_verdict_segs, cd);
  REQUIRE(t.translated > 0);  // segments inside the open ball did occur
}

// ---------------------------------------------------------------------------
// Ray-sphere.

RayS ray_sphere_exact(Rng& r, const Scale& sc) {
  const I3 c = irand3(r, -sc.c, sc.c);
  const long long k = draw_k(r, sc);
  const auto [nv, n] = pyth_dir(r);
  const I3 p = c + k * nv;
  int j = 0;
  for (int i = 1; i < 3; ++i)
    if (std::llabs(nv[static_cast<std::size_t>(i)]) < std::llabs(nv[static_cast<std::size_t>(j)])) j = i;
  I3 e = {0, 0, 0};
  e[static_cast<std::size_t>(j)] = 1;
  const I3 u = cross(nv, e);
  const I3 w = cross(nv, u);
  const long long f = irand(r, 1, k);
  I3 s, d;
  switch (irand(r, 0, 2)) {
    case 0:  // along the tangent line, from before or after the tangent point
      s = p - irand(r, -3, 3) * f * u;
      d = (one_in(r, 2) ? 1 : -1) * irand(r, 1, 3) * u;
      break;
    case 1:  // from P, outward, inward or in the tangent plane
      s = p;
      do d = irand(r, -2, 2) * nv + irand(r, -2, 2) * u + irand(r, -2, 2) * w;
      while (is_zero(d));
      break;
    default:  // from the normal line through P
      s = p + irand(r, -2, 3) * f * nv;
      do d = irand(r, -1, 1) * nv + irand(r, -1, 1) * u;
      while (is_zero(d));
      break;
  }
  RayS in{{grid(s), grid(d)}, {grid(c), grid(k * n)}};
  std::vector<double*> fl;
  add_fields(fl, in.a.source);
  add_fields(fl, in.b.center);
  perturb(r, fl, {&in.b.radius, &in.b.radius, &in.b.radius, &in.b.radius});
  return in;
}

std::vector<Family<RayS>> ray_sphere_families() {
  return {
      {"random",
       [](Rng& r) {
         D3 d;
         do d = uvec(r, -1, 1);
         while (d.isZero());
         return RayS{{uvec(r, -10, 10), d}, {uvec(r, -6, 6), uni(r, 0, 4)}};
       }},
      {"integer",
       [](Rng& r) {
         return RayS{{ivec(r, -5, 5), nonzero_ivec(r, -2, 2)}, {ivec(r, -3, 3), static_cast<double>(irand(r, 0, 3))}};
       }},
      {"near", [](Rng& r) { return ray_sphere_exact(r, near_scale); }},
      {"long",
       [](Rng& r) {
         if (one_in(r, 2)) return ray_sphere_exact(r, far_scale);
         const D3 c = uvec(r, -1, 1);
         const double rho = uni(r, 0.5, 2);
         const D3 s = far_from(r, c);
         const D3 aim = near_surface(r, c, rho);
         const D3 d = one_in(r, 5) ? D3(s - aim) : D3(aim - s);
         return RayS{{s, d}, {c, rho}};
       }},
  };
}

TEST_CASE("cgal crosscheck: ray-sphere", "[cgal]") {
  const auto cd = [](auto tg, const RayS& in) {
    using T = typename decltype(tg)::type;
    const Ray<T> ray = at<T>(in.a);
    const Sphere<T> sp = at<T>(in.b);
    return Answers{{"hit(ray, sphere)", book::hit(ray, sp)}, {"cast(ray, sphere).hit", book::cast(ray, sp).hit}};
  };
  run_pair<RayS>(3, ray_sphere_families(), cgal_verdict_rays, cd);
}

// ---------------------------------------------------------------------------
// Segment-box and ray-box.

// A box on the grid, a point on its boundary (face, edge or corner, or one time in eight
// anywhere in the closed box) and a direction: random, or (one time in two) with zero
// components on some of the axes whose planes hold the point, so that it runs in them.
struct BoxProbe {
  I3 c, h, k, w;
};
BoxProbe box_probe(Rng& r, const Scale& sc) {
  BoxProbe b;
  b.c = irand3(r, -sc.c, sc.c);
  b.h = random_extent(r, sc);
  const I3 sigma = random_sigma(r, one_in(r, 8) ? 0 : static_cast<int>(irand(r, 1, 3)));
  b.k = box_boundary_point(r, b.c, b.h, sigma);
  const long long f = draw_f(r, sc);
  do {
    b.w = irand3(r, -3, 3);
    if (one_in(r, 2))
      for (int i = 0; i < 3; ++i)
        if (sigma[static_cast<std::size_t>(i)] != 0 && one_in(r, 2)) b.w[static_cast<std::size_t>(i)] = 0;
  } while (is_zero(b.w));
  b.w = f * b.w;
  return b;
}

SegB segment_box_exact(Rng& r, const Scale& sc) {
  const BoxProbe b = box_probe(r, sc);
  const I3 s = b.k - irand(r, -2, 3) * b.w;
  const I3 t = one_in(r, 10) ? s : I3(b.k + irand(r, -2, 3) * b.w);
  SegB in{{grid(s), grid(t)}, {grid(b.c), grid(b.h)}};
  std::vector<double*> fl, nn;
  add_fields(fl, in.a.source);
  add_fields(fl, in.a.target);
  add_fields(fl, in.b.center);
  add_fields(nn, in.b.extent);
  perturb(r, fl, nn);
  return in;
}

std::vector<Family<SegB>> segment_box_families() {
  return {
      {"random",
       [](Rng& r) {
         return SegB{{uvec(r, -10, 10), uvec(r, -10, 10)}, {uvec(r, -6, 6), uvec(r, 0, 4)}};
       }},
      {"integer",
       [](Rng& r) {
         const D3 s = ivec(r, -5, 5);
         const D3 t = one_in(r, 8) ? s : ivec(r, -5, 5);
         return SegB{{s, t}, {ivec(r, -3, 3), ivec(r, 0, 2)}};
       }},
      {"near", [](Rng& r) { return segment_box_exact(r, near_scale); }},
      {"long",
       [](Rng& r) {
         if (one_in(r, 2)) return segment_box_exact(r, far_scale);
         const D3 c = uvec(r, -1, 1);
         const D3 h = uvec(r, 0.1, 2);
         const D3 s = far_from(r, c);
         const D3 aim = c + D3(uvec(r, -1.2, 1.2).cwiseProduct(h));
         const D3 t = end_near_aim(r, s, aim);
         return one_in(r, 2) ? SegB{{s, t}, {c, h}} : SegB{{t, s}, {c, h}};
       }},
  };
}

TEST_CASE("cgal crosscheck: segment-box", "[cgal]") {
  const auto cd = [](auto tg, const SegB& in) {
    using T = typename decltype(tg)::type;
    const Segment<T> seg = at<T>(in.a);
    const Segment<T> rev{seg.target, seg.source};
    const Box<T> box = at<T>(in.b);
    return Answers{{"hit(segment, box)", book::hit(seg, box)},
                   {"hit(reversed segment, box)", book::hit(rev, box)},
                   {"cast(segment, box).hit", book::cast(seg, box).hit}};
  };
  run_pair<SegB>(4, segment_box_families(), cgal_verdict_segb, cd);
}

RayB ray_box_exact(Rng& r, const Scale& sc) {
  const BoxProbe b = box_probe(r, sc);
  const I3 s = b.k - irand(r, -2, 3) * b.w;
  const I3 d = (one_in(r, 2) ? 1 : -1) * b.w;
  RayB in{{grid(s), grid(d)}, {grid(b.c), grid(b.h)}};
  std::vector<double*> fl, nn;
  add_fields(fl, in.a.source);
  add_fields(fl, in.b.center);
  add_fields(nn, in.b.extent);
  perturb(r, fl, nn);
  return in;
}

std::vector<Family<RayB>> ray_box_families() {
  return {
      {"random",
       [](Rng& r) {
         D3 d;
         do d = uvec(r, -1, 1);
         while (d.isZero());
         return RayB{{uvec(r, -10, 10), d}, {uvec(r, -6, 6), uvec(r, 0, 4)}};
       }},
      {"integer",
       [](Rng& r) {
         return RayB{{ivec(r, -5, 5), nonzero_ivec(r, -2, 2)}, {ivec(r, -3, 3), ivec(r, 0, 2)}};
       }},
      {"near", [](Rng& r) { return ray_box_exact(r, near_scale); }},
      {"long",
       [](Rng& r) {
         if (one_in(r, 2)) return ray_box_exact(r, far_scale);
         const D3 c = uvec(r, -1, 1);
         const D3 h = uvec(r, 0.1, 2);
         const D3 s = far_from(r, c);
         const D3 aim = c + D3(uvec(r, -1.2, 1.2).cwiseProduct(h));
         const D3 d = one_in(r, 5) ? D3(s - aim) : D3(aim - s);
         return RayB{{s, d}, {c, h}};
       }},
  };
}

TEST_CASE("cgal crosscheck: ray-box", "[cgal]") {
  const auto cd = [](auto tg, const RayB& in) {
    using T = typename decltype(tg)::type;
    const Ray<T> ray = at<T>(in.a);
    const Box<T> box = at<T>(in.b);
    return Answers{{"hit(ray, box)", book::hit(ray, box)}, {"cast(ray, box).hit", book::cast(ray, box).hit}};
  };
  run_pair<RayB>(5, ray_box_families(), cgal_verdict_rayb, cd);
}

// ---------------------------------------------------------------------------
// Box-box.

BB box_box_exact(Rng& r, const Scale& sc) {
  // Per axis: touching (|cA - cB| = hA + hB), overlapping or apart.
  const I3 ca = irand3(r, -sc.c, sc.c);
  const I3 ha = random_extent(r, sc), hb = random_extent(r, sc);
  I3 cb;
  for (std::size_t i = 0; i < 3; ++i) {
    const long long reach = ha[i] + hb[i];
    switch (irand(r, 0, 3)) {
      case 0:
      case 1:
        cb[i] = ca[i] + sign_pm(r) * reach;
        break;
      case 2:
        cb[i] = ca[i] + irand(r, -reach, reach);
        break;
      default:
        cb[i] = ca[i] + sign_pm(r) * (reach + irand(r, 1, 4));
        break;
    }
  }
  BB in{{grid(ca), grid(ha)}, {grid(cb), grid(hb)}};
  std::vector<double*> fl, nn;
  add_fields(fl, in.a.center);
  add_fields(fl, in.b.center);
  add_fields(nn, in.a.extent);
  add_fields(nn, in.b.extent);
  perturb(r, fl, nn);
  return in;
}

std::vector<Family<BB>> box_box_families() {
  return {
      {"random",
       [](Rng& r) {
         return BB{{uvec(r, -8, 8), uvec(r, 0, 4)}, {uvec(r, -8, 8), uvec(r, 0, 4)}};
       }},
      {"integer",
       [](Rng& r) {
         return BB{{ivec(r, -4, 4), ivec(r, 0, 3)}, {ivec(r, -4, 4), ivec(r, 0, 3)}};
       }},
      {"near", [](Rng& r) { return box_box_exact(r, near_scale); }},
      {"long",
       [](Rng& r) {
         if (one_in(r, 2)) return box_box_exact(r, far_scale);
         // Centres 1e8..1e12 from the origin; per axis cB = cA +- (hA + hB) rounded, or
         // overlapping.
         D3 ca;
         for (int i = 0; i < 3; ++i) {
           const int sg = sign_pm(r);
           ca[i] = sg * log_uniform(r, 1e8, 1e12);
         }
         const D3 ha = uvec(r, 0, 1e6), hb = uvec(r, 0, 1e6);
         D3 cb;
         for (int i = 0; i < 3; ++i) {
           const double reach = (ha[i] + hb[i]) * (1 + std::ldexp(static_cast<double>(irand(r, -2, 2)), -52));
           cb[i] = one_in(r, 3) ? ca[i] + uni(r, -1, 1) * reach : ca[i] + sign_pm(r) * reach;
         }
         return BB{{ca, ha}, {cb, hb}};
       }},
  };
}

TEST_CASE("cgal crosscheck: box-box", "[cgal]") {
  const auto cd = [](auto tg, const BB& in) {
    using T = typename decltype(tg)::type;
    const Box<T> a = at<T>(in.a), b = at<T>(in.b);
    const MinMaxBox<T> ma = to_min_max(a), mb = to_min_max(b);
    return Answers{{"intersect(Box A, Box B)", book::intersect(a, b)},
                   {"intersect(Box B, Box A)", book::intersect(b, a)},
                   {"intersect(MinMaxBox A, MinMaxBox B)", book::intersect(ma, mb)}};
  };
  run_pair<BB>(6, box_box_families(), cgal_verdict_bb, cd);
}

// ---------------------------------------------------------------------------
// Sphere-box.

SB sphere_box_exact(Rng& r, const Scale& sc) {
  // The centre at K + k v, K on a face, edge or corner, v an outward integer vector
  // of integer length n, nonzero exactly on the axes whose planes hold K: the
  // closest point of the box is K, at distance k n = rho. Or the centre in the box.
  const I3 c = irand3(r, -sc.c, sc.c);
  const I3 h = random_extent(r, sc);
  const int nz = static_cast<int>(irand(r, 1, 3));
  const I3 sigma = random_sigma(r, nz);
  const I3 k = box_boundary_point(r, c, h, sigma);
  const long long scale = draw_k(r, sc);
  SB in;
  if (one_in(r, 10)) {
    in = {{grid(k), grid(irand(r, 0, 4))}, {grid(c), grid(h)}};
  } else {
    const auto [v0, n] = pyth_dir(r, nz);
    I3 v = {0, 0, 0};
    std::size_t next = 0;
    for (std::size_t i = 0; i < 3; ++i)
      if (sigma[i] != 0) {
        while (v0[next] == 0) ++next;
        v[i] = sigma[i] * std::llabs(v0[next++]);
      }
    in = {{grid(k + scale * v), grid(scale * n)}, {grid(c), grid(h)}};
  }
  std::vector<double*> fl, nn;
  add_fields(fl, in.a.center);
  add_fields(fl, in.b.center);
  add_fields(nn, in.b.extent);
  for (int i = 0; i < 6; ++i) nn.push_back(&in.a.radius);
  perturb(r, fl, nn);
  return in;
}

std::vector<Family<SB>> sphere_box_families() {
  return {
      {"random",
       [](Rng& r) {
         return SB{{uvec(r, -8, 8), uni(r, 0, 5)}, {uvec(r, -6, 6), uvec(r, 0, 4)}};
       }},
      {"integer",
       [](Rng& r) {
         return SB{{ivec(r, -4, 4), static_cast<double>(irand(r, 0, 3))}, {ivec(r, -2, 2), ivec(r, 0, 2)}};
       }},
      {"near", [](Rng& r) { return sphere_box_exact(r, near_scale); }},
      {"long",
       [](Rng& r) {
         if (one_in(r, 2)) return sphere_box_exact(r, far_scale);
         // A huge sphere whose centre is 1e8..1e12 out from a corner region, its radius
         // about the distance to the corner.
         const D3 c = uvec(r, -1, 1);
         const D3 h = uvec(r, 0.1, 2);
         D3 sigma;
         for (int i = 0; i < 3; ++i) sigma[i] = sign_pm(r);
         const D3 corner = c + D3(sigma.cwiseProduct(h));
         const D3 u = sigma.cwiseProduct(unit_dir(r).cwiseAbs());
         const D3 centre = corner + log_uniform(r, 1e8, 1e12) * u;
         const double rho = (centre - corner).norm() * (1 + std::ldexp(static_cast<double>(irand(r, -4, 4)), -52));
         return SB{{centre, rho}, {c, h}};
       }},
  };
}

TEST_CASE("cgal crosscheck: sphere-box", "[cgal]") {
  const auto cd = [](auto tg, const SB& in) {
    using T = typename decltype(tg)::type;
    const Sphere<T> sp = at<T>(in.a);
    const Box<T> box = at<T>(in.b);
    return Answers{{"intersect(sphere, box)", book::intersect(sp, box)},
                   {"proximity(sphere, box).intersect", book::proximity(sp, box).intersect}};
  };
  run_pair<SB>(7, sphere_box_families(), cgal_verdict_sb, cd);
}

}  // namespace

}  // namespace cdref_test_cgal_crosscheck
