// tests/test_robust_spheres.cpp - the robust sphere queries (float/cdref/robust/
// sphere_sphere.hpp, segment_sphere.hpp, sphere_box.hpp) and the certificates of every
// robust sphere query (decide), against the book at CGAL::Gmpq on the same F inputs.
//
// Errors are measured exactly: the exact value (a + b sqrt d over Gmpq) minus the F value,
// rounded correctly to long double, in ulps of F at max(|truth|, m), m the size of the terms
// that make the value (stated per output in each header). Each bound asserted here is the
// one derived in the header, evaluated for the case.
#include <cdref/exact.hpp>
#include <cdref/exact/long_double.hpp>
#include <cdref/fuzz/campaign.hpp>
#include <cdref/robust/ray_sphere.hpp>
#include <cdref/robust/segment_sphere.hpp>
#include <cdref/robust/sphere_box.hpp>
#include <cdref/robust/sphere_sphere.hpp>
#include <cdref/stable/ray_sphere.hpp>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <vector>

#include "support.hpp"

// This file's names in a namespace of its own: the test files are compiled several to a unit
// (tests/CMakeLists.txt).
namespace cdref_test_robust_spheres {

namespace {

using namespace cdref;
using namespace cdref::test;
long double ld(const QS& x) { return exact::round_long_double(x); }

template <class F>
constexpr long double unit() {
  return std::numeric_limits<F>::epsilon() / 2;
}

// |got - truth| in ulps of F at max(|truth|, m).
template <class F>
long double ulps(F got, const QS& truth, long double m = 0) {
  const long double err = std::fabs(ld(QS(exact_q(got)) - truth));
  if (err == 0) return 0;
  const long double mag = std::max(std::fabs(ld(truth)), m);
  if (mag == 0) return std::numeric_limits<long double>::infinity();
  return err / std::ldexp(1.0L, std::ilogb(mag) - std::numeric_limits<F>::digits + 1);
}

// A value computed within E of the truth before its one rounding (the headers' along_dw,
// plus_dw, div_pair paths) is within 1.5 ulps of the truth at max(|truth|, 2E/u): where the
// truth is at least 2E/u, E is at most half its ulp and the rounding adds one ulp of the
// computed value (at most twice the truth's); below, likewise at 2E/u.
template <class F>
long double ulps_beyond(F got, const QS& truth, long double E) {
  return ulps(got, truth, 2 * E / (std::numeric_limits<F>::epsilon() / 2));
}

template <class F>
Vec3<F> v3(long double x, long double y, long double z) {
  return Vec3<F>(F(x), F(y), F(z));
}

template <class F>
F p2(int k) {
  return std::ldexp(F(1), k);
}

// An exponent where the book's squares overflow in F (and its mirror underflows).
template <class F>
int huge_exp() {
  return std::numeric_limits<F>::max_exponent / 2 + 20;
}

}  // namespace

// ---------------------------------------------------------------------------
// sphere-sphere
namespace {

template <class F>
struct SS {
  std::string name;
  Sphere<F> a, b;
};

template <class F>
std::vector<SS<F>> sphere_sphere_hard() {
  std::vector<SS<F>> v;
  const int kmax = std::numeric_limits<F>::digits - 14;  // near touching: 2^-k with k up to p - 14
  for (long double R : {1e4L, 1e6L, 1e8L, 1e10L, 1e12L})
    for (int k : {10, kmax / 2, kmax})
      for (int sg : {-1, 1}) {
        const F r = F(R);
        const F d = F(2 * R * (1 + sg * std::ldexp(1.0L, -k)));
        v.push_back({"R " + std::to_string(double(R)) + " 2^-" + std::to_string(k) + (sg > 0 ? " apart" : " overlap"),
                     {v3<F>(0.25L * R, 1, -3), r},
                     {v3<F>(0.25L * R + d * 0.6L, d * 0.8L + 1, -3), F(r * F(1.5L))}});
      }
  v.push_back({"near touching 1e8, v = (2e8, 1, 0)", {v3<F>(0, 0, 0), F(1e8)}, {v3<F>(2e8, 1, 0), F(1e8)}});
  v.push_back({"concentric", {v3<F>(1, 2, 3), F(1)}, {v3<F>(1, 2, 3), F(2)}});
  v.push_back({"nearly concentric, tiny v", {v3<F>(1, 2, 3), F(1)}, {Vec3<F>(F(1), std::nextafter(F(2), F(3)), F(3)), F(2)}});
  v.push_back({"irrational overlap", {v3<F>(0, 0, 0), F(2)}, {v3<F>(1, 1, 0), F(1)}});
  const int e = huge_exp<F>();
  for (int sgn : {1, -1}) {
    const F m = p2<F>(sgn * e);
    v.push_back({sgn > 0 ? "huge 2^e" : "tiny 2^-e", {Vec3<F>(m, F(0), m), m}, {Vec3<F>(F(3 * m), m, F(0)), F(m / 2)}});
    v.push_back({sgn > 0 ? "huge, touching within 2^-20" : "tiny, touching within 2^-20",
                 {Vec3<F>(F(0), F(0), F(0)), m},
                 {Vec3<F>(F(F(2) * m * F(1 + std::ldexp(1.0L, -20))), F(0), F(0)), m}});
  }
  return v;
}

}  // namespace

TEMPLATE_TEST_CASE("robust sphere-sphere: every output within its derived bound on hard cases", "[robust-spheres]",
                   float, double, long double) {
  using F = TestType;
  const long double u = unit<F>();
  long double worst_d = 0, worst_w = 0;
  int book_bad = 0;
  for (const auto& c : sphere_sphere_hard<F>()) {
    INFO(c.name);
    const auto sa = convert_prim_exact(c.a), sb = convert_prim_exact(c.b);
    const auto ref = book::proximity(sa, sb);
    const auto got = robust::proximity(c.a, c.b);
    const auto dec = robust::decide(c.a, c.b);
    REQUIRE(dec.value == got.intersect);
    REQUIRE(robust::intersect(c.a, c.b) == got.intersect);
    // Q = |v|^2 - s^2 and the S of the bound, exactly
    const Vec3<Q> vq = sa.center - sb.center;
    const Q s = sa.radius + sb.radius;
    const Q qq = vq.squaredNorm() - s * s;
    const Q vv = vq.squaredNorm();
    // S / |Q| (the amplification of the bound), exactly then rounded
    const long double ratio = qq == 0 ? 0 : exact::round_long_double(Q((vv + s * s) / (qq < 0 ? Q(-qq) : qq))) * 1.001L;
    if (dec.certain) REQUIRE(dec.value == ref.intersect);
    // farther from touching than the certificate's bound (|Q| > 2u|Q| + 288 u^2 S), it must hold
    if (qq != 0 && 4 * 288 * u * u * ratio < 1) REQUIRE(dec.certain);
    if (dec.certain) {
      REQUIRE(got.intersect == ref.intersect);
      // distance and depth: half an ulp plus 1.07u relative, and gamma_46^3 S / |Q| where Q
      // was summed in triple precision (sphere_sphere.hpp, item 4)
      const long double bound = qq == 0 ? 0 : 2.1L + 1.1e5L * u * u * ratio;
      const long double ed = ulps(got.distance, ref.distance), ep = ulps(got.depth, ref.depth);
      REQUIRE(ed <= std::max(bound, 0.0L));
      REQUIRE(ep <= std::max(bound, 0.0L));
      worst_d = std::max({worst_d, ed, ep});
    }
    // witnesses: within 37u^2 max(|p_i|, rho |n_i|) before one rounding (item 7's first look,
    // 1/|v| by recip_pair; item 5's unit_dw: 31u^2)
    for (int i = 0; i < 3; ++i) {
      const long double ni = vv == 0 ? (i == 0 ? 1 : 0) : std::sqrt(exact::round_long_double(Q(vq[i] * vq[i] / vv)));
      const long double Ea = 37 * u * u * (std::fabs(ld(ref.on_a[i])) + (long double)c.a.radius * ni) * 1.01L;
      const long double Eb = 37 * u * u * (std::fabs(ld(ref.on_b[i])) + (long double)c.b.radius * ni) * 1.01L;
      REQUIRE(ulps_beyond(got.on_a[i], ref.on_a[i], Ea) <= 1.5L);
      REQUIRE(ulps_beyond(got.on_b[i], ref.on_b[i], Eb) <= 1.5L);
      worst_w = std::max({worst_w, ulps(got.on_a[i], ref.on_a[i]), ulps(got.on_b[i], ref.on_b[i])});
    }
    // the book at F on the same inputs
    if constexpr (!std::is_same_v<F, float>) {
      const auto bk = book::proximity(c.a, c.b);
      if (bk.intersect != ref.intersect || ulps(bk.distance, ref.distance) > 1e6L || !std::isfinite(bk.distance))
        ++book_bad;
    }
  }
  // The book at double and long double misclassifies or loses > 1e6 ulps on several of these
  // (near touching at range, huge and tiny magnitudes): 4 cases each, observed.
  if constexpr (!std::is_same_v<F, float>) REQUIRE(book_bad >= 3);
  if (std::getenv("CDREF_TEST_REPORT")) std::cout << "sphere-sphere " << typeid(F).name() << ": worst distance/depth " << double(worst_d) << " ulps, witnesses "
                        << double(worst_w) << " ulps; book off on " << book_bad << " cases" << "\n";
}

// ---------------------------------------------------------------------------
// segment-sphere
namespace {

template <class F>
struct SegS {
  std::string name;
  Segment<F> seg;
  Sphere<F> sp;
};

template <class F>
std::vector<SegS<F>> segment_sphere_hard() {
  std::vector<SegS<F>> v;
  const bool fl = std::is_same_v<F, float>;
  const int kmax = std::numeric_limits<F>::digits - 14;
  const Sphere<F> unit{v3<F>(0, 0, 0), F(1)};
  const Sphere<F> off{v3<F>(3, -5, 7), F(2)};
  for (long double R : {1e4L, 1e6L, 1e8L, 1e10L, 1e12L}) {
    if (fl && R > 1e4L) break;  // float: the 226 u^2 |s| term of the bound grows with the range
    for (int k : {10, kmax / 2, kmax})
      for (int sg : {-1, 1}) {
        const long double y = 1 + sg * std::ldexp(1.0L, -k);
        v.push_back({"interior, R " + std::to_string(double(R)) + " rho(1 " + (sg > 0 ? "+" : "-") + " 2^-" +
                         std::to_string(k) + ")",
                     {v3<F>(-R, y, 0.375L), v3<F>(R * 1.25L, y, 0.375L)},
                     {v3<F>(0, 0, 0.375L), F(1)}});
      }
    // endpoint branch far away: the segment ends near the sphere
    v.push_back({"ends near the sphere, from R " + std::to_string(double(R)),
                 {v3<F>(R, R * 0.5L, 0), v3<F>(3 + std::ldexp(1.0L, -20), 0, 0)},
                 {v3<F>(1, 0, 0), F(2)}});
  }
  v.push_back({"through the centre", {v3<F>(-1, 0, 0), v3<F>(1, 0, 0)}, unit});
  v.push_back({"through an off-origin centre", {v3<F>(3, -5, 5), v3<F>(3, -5, 9)}, off});
  v.push_back({"ending at the centre", {v3<F>(-1, -2, -3), v3<F>(0, 0, 0)}, unit});
  v.push_back({"zero length at the centre", {v3<F>(3, -5, 7), v3<F>(3, -5, 7)}, off});
  v.push_back({"zero length outside", {v3<F>(0, 0, 3), v3<F>(0, 0, 3)}, unit});
  v.push_back({"irrational depth", {v3<F>(-1, 1, 1), v3<F>(1, 1, 1)}, Sphere<F>{v3<F>(0, 0, 0), F(2)}});
  v.push_back({"touching at 1e8 radii", {v3<F>(-1e8, 1, 0), v3<F>(1e8 + 1, 1, 0)}, unit});
  const int e = huge_exp<F>();
  for (int sgn : {1, -1}) {
    const F m = p2<F>(sgn * e);
    v.push_back({sgn > 0 ? "huge" : "tiny", {Vec3<F>(F(-3 * m), F(0), F(2 * m)), Vec3<F>(F(3 * m), F(m / 4), F(2 * m))},
                 {Vec3<F>(F(0), F(0), F(0)), m}});
  }
  return v;
}

}  // namespace

TEMPLATE_TEST_CASE("robust segment-sphere: every output within its derived bound on hard cases", "[robust-spheres]",
                   float, double, long double) {
  using F = TestType;
  const long double u = unit<F>();
  long double worst_d = 0, worst_a = 0, worst_b = 0;
  int book_bad = 0;
  for (const auto& c : segment_sphere_hard<F>()) {
    INFO(c.name);
    const auto sq = convert_prim_exact(c.seg);
    const auto pq = convert_prim_exact(c.sp);
    const auto ref = book::proximity(sq, pq);
    const auto got = robust::proximity(c.seg, c.sp);
    const auto dec = robust::decide_closest(c.seg, c.sp);
    REQUIRE(dec.value == got.intersect);
    REQUIRE(robust::intersect(c.seg, c.sp) == got.intersect);
    // all of these but exact touching are farther from the boundary than the certificate's bound
    const bool touching = ref.distance.sign() == 0 && ref.depth.sign() == 0;
    if (!touching) REQUIRE(dec.certain);
    if (dec.certain) REQUIRE(dec.value == ref.intersect);
    REQUIRE(book::intersect(sq, pq) == ref.intersect);
    // the case's magnitudes: |x| (the closest point, local), max |s_i|, rho
    long double xn = 0, smax = 0;
    for (int i = 0; i < 3; ++i) {
      const long double xi = ld(ref.closest[i] - QS(pq.center[i]));
      xn += xi * xi;
      smax = std::max({smax, std::fabs((long double)c.seg.source[i] - (long double)c.sp.center[i]),
                       std::fabs((long double)c.seg.target[i] - (long double)c.sp.center[i])});
    }
    xn = std::sqrt(xn);
    const long double rho = c.sp.radius;
    // endpoint or interior? (the book's branch, exactly)
    const Vec3<Q> s = sq.source - pq.center, t = sq.target - pq.center;
    const Vec3<Q> r = t - s;
    const Q delta = -s.dot(r);
    const bool interior = delta > 0 && delta < r.squaredNorm();
    // distance, depth: within u^2 88 (|x| + rho) + u d / 16 + 1.2e5 u^3 |s| + (111 u^2 |s|)^2 /
    // (|x| + rho) before one rounding (segment_sphere.hpp, item 5); |s| <= sqrt3 max|s_i|
    const long double sn = std::sqrt(3.0L) * smax;
    const long double dref = ld(ref.distance) + ld(ref.depth);
    const long double Ed = (u * u * 88 * (xn + rho) + u * dref / 16 + 1.2e5L * u * u * u * sn +
                            std::pow(111 * u * u * sn, 2) / (xn + rho)) * 1.01L;
    const long double ed = ulps_beyond(got.distance, ref.distance, Ed), ep = ulps_beyond(got.depth, ref.depth, Ed);
    REQUIRE(ed <= 1.5L);
    REQUIRE(ep <= 1.5L);
    worst_d = std::max({worst_d, ulps(got.distance, ref.distance), ulps(got.depth, ref.depth)});
    for (int i = 0; i < 3; ++i) {
      // on the segment (= closest): exact at the endpoints; inside the foot's 144u^2 |s| and
      // u^2 (|x| + |closest_i|) before one rounding
      const long double Ea = u * u * (144 * sn + xn + std::fabs(ld(ref.closest[i]))) * 1.01L;
      const long double ea = ulps_beyond(got.on_a[i], ref.on_a[i], interior ? Ea : 0);
      const long double ec = ulps_beyond(got.closest[i], ref.closest[i], interior ? Ea : 0);
      REQUIRE(ea <= (interior ? 1.5L : 0));
      REQUIRE(ec <= (interior ? 1.5L : 0));
      // on the sphere: the direction of x within 27u^2 + 144u^2 |s| / |x| (exact pairs at the
      // endpoints and through the centre: 27u^2), then 4u^2 max(|p_i|, rho)
      const bool through = xn == 0;
      const long double dir = 27 * u * u + (interior && !through ? 144 * u * u * sn / xn : 0);
      const long double Eb = (rho * dir + 4 * u * u * (rho + std::fabs(ld(ref.on_b[i])))) * 1.01L;
      REQUIRE(ulps_beyond(got.on_b[i], ref.on_b[i], Eb) <= 1.5L);
      worst_a = std::max(worst_a, ulps(got.on_a[i], ref.on_a[i], xn));  // (reported in ulps of |x|)
      worst_b = std::max(worst_b, ulps(got.on_b[i], ref.on_b[i], rho));  // (and of rho)
    }
    if constexpr (!std::is_same_v<F, float>) {
      const auto bk = book::proximity(c.seg, c.sp);
      if (bk.intersect != ref.intersect || book::intersect(c.seg, c.sp) != ref.intersect ||
          !(ulps(bk.distance, ref.distance, interior ? xn : 0) <= 1e6L) ||
          !(ulps(bk.depth, ref.depth, interior ? xn : 0) <= 1e6L))
        ++book_bad;
    }
  }
  if constexpr (!std::is_same_v<F, float>) REQUIRE(book_bad >= 5);
  if (std::getenv("CDREF_TEST_REPORT")) std::cout << "segment-sphere " << typeid(F).name() << ": worst distance/depth " << double(worst_d)
                         << " ulps, witness on segment " << double(worst_a) << ", on sphere " << double(worst_b)
                         << "; book off on " << book_bad << " cases" << "\n";
}

// ---------------------------------------------------------------------------
// sphere-box
namespace {

template <class F>
struct SB {
  std::string name;
  Sphere<F> sp;
  Box<F> box;
};

template <class F>
std::vector<SB<F>> sphere_box_hard() {
  std::vector<SB<F>> v;
  const int kmax = std::numeric_limits<F>::digits - 14;
  const Box<F> b1{v3<F>(1, 2, 3), v3<F>(1, 2, 3)};
  for (long double R : {1e4L, 1e6L, 1e8L, 1e10L, 1e12L})
    for (int k : {10, kmax / 2, kmax})
      for (int sg : {-1, 1}) {
        const long double g = 1 + sg * std::ldexp(1.0L, -k);
        const Box<F> far{v3<F>(R, -R, 0.5L * R), v3<F>(1, 2, 3)};
        // near a face (x+), an edge (x+, y+) and a corner
        v.push_back({"face at R " + std::to_string(double(R)) + " 2^-" + std::to_string(k),
                     {v3<F>(R + 1 + g, -R + 0.5L, 0.5L * R), F(1)}, far});
        v.push_back({"edge at R " + std::to_string(double(R)) + " 2^-" + std::to_string(k),
                     {v3<F>(R + 1 + 0.6L * g, -R + 2 + 0.8L * g, 0.5L * R - 1), F(1)}, far});
        v.push_back({"corner at R " + std::to_string(double(R)) + " 2^-" + std::to_string(k),
                     {v3<F>(R + 1 + 0.48L * g, -R + 2 + 0.6L * g, 0.5L * R + 3 + 0.64L * g), F(1)}, far});
      }
  v.push_back({"centre at the box centre (tie on every axis)", {v3<F>(1, 2, 3), F(0.5L)}, Box<F>{v3<F>(1, 2, 3), v3<F>(2, 2, 2)}});
  v.push_back({"centre inside, nearest face y-", {v3<F>(1.5L, 0.5L, 3), F(0.25L)}, b1});
  v.push_back({"centre on a face", {v3<F>(2, 2, 3), F(0.25L)}, b1});
  v.push_back({"centre on an edge (tie)", {v3<F>(0, 0, 3), F(0.25L)}, b1});
  v.push_back({"centre on a corner", {v3<F>(2, 4, 6), F(0.25L)}, b1});
  v.push_back({"centre inside, far box", {v3<F>(1e8 + 0.75L, -1e8 + 1, 3), F(3)}, Box<F>{v3<F>(1e8, -1e8, 3), v3<F>(1, 2, 3)}});
  v.push_back({"touching a face exactly", {v3<F>(3, 2, 3), F(1)}, b1});
  // the witness on the sphere cancels to a few units against a radius of 5e7 (its direction's
  // error times the radius, item 7's 43u^2 rho |n_i|, is the whole bound there)
  for (long double gap : {10.0L, -10.0L})
    v.push_back({gap > 0 ? "witness cancelling, apart" : "witness cancelling, overlapping",
                 {v3<F>(3e7L + 1.25L, 4e7L + 2.5L, 0.5L), F(5e7L - gap)}, Box<F>{v3<F>(0, 0, 0), v3<F>(1, 1, 1)}});
  const int e = huge_exp<F>();
  for (int sgn : {1, -1}) {
    const F m = p2<F>(sgn * e);
    v.push_back({sgn > 0 ? "huge" : "tiny", {Vec3<F>(F(3 * m), F(3 * m), F(0)), F(m)}, {Vec3<F>(F(0), F(0), F(0)), Vec3<F>(m, m, m)}});
    v.push_back({sgn > 0 ? "huge, inside" : "tiny, inside", {Vec3<F>(F(m / 2), F(0), F(0)), F(m)},
                 {Vec3<F>(F(0), F(0), F(0)), Vec3<F>(m, m, m)}});
  }
  return v;
}

}  // namespace

TEMPLATE_TEST_CASE("robust sphere-box: every output within its derived bound on hard cases", "[robust-spheres]",
                   float, double, long double) {
  using F = TestType;
  const long double u = unit<F>();
  long double worst_d = 0, worst_a = 0, worst_b = 0;
  int book_bad = 0;
  for (const auto& c : sphere_box_hard<F>()) {
    INFO(c.name);
    const auto sq = convert_prim_exact(c.sp);
    const auto bq = convert_prim_exact(c.box);
    const auto ref = book::proximity(sq, bq);
    const auto got = robust::proximity(c.sp, c.box);
    const auto dec = robust::decide(c.sp, c.box);
    REQUIRE(dec.value == got.intersect);
    REQUIRE(robust::intersect(c.sp, c.box) == got.intersect);
    if (dec.certain) REQUIRE(dec.value == ref.intersect);
    const Vec3<Q> cc = sq.center - bq.center;
    Vec3<Q> vq;
    for (int i = 0; i < 3; ++i) {
      const Q& h = bq.extent[i];
      vq[i] = (cc[i] < -h ? Q(-h) : (cc[i] > h ? h : cc[i])) - cc[i];
    }
    const Q vv = vq.squaredNorm();
    const long double rho = c.sp.radius;
    Q cc2 = 0;
    long double cn = 0, hn = 0;
    for (int i = 0; i < 3; ++i) {
      cn = std::max(cn, std::fabs(exact::round_long_double(cc[i])));
      hn = std::max(hn, (long double)c.box.extent[i]);
      cc2 += cc[i] * cc[i];
    }
    const Q qq = vv - sq.radius * sq.radius;
    const Q aq = qq < 0 ? Q(-qq) : qq;
    // S / |Q| with S <= (1.01|v| + 3u|c|)^2 + rho^2 (sphere_box.hpp, item 5), from exact ratios
    const long double ratio =
        qq == 0 ? 0
                : std::pow(1.01L * std::sqrt(exact::round_long_double(Q(vv / aq))) +
                               3 * u * std::sqrt(exact::round_long_double(Q(cc2 / aq))),
                           2) * 1.001L +
                      exact::round_long_double(Q(sq.radius * sq.radius / aq)) * 1.001L;
    // farther from touching than the certificate's bound (2u|Q| + 722 u^2 S), it must hold
    if (vv != 0 && qq != 0 && 4 * 722 * u * u * ratio < 1) REQUIRE(dec.certain);
    if (vv == 0) REQUIRE(dec.certain);
    if (dec.certain) REQUIRE(got.intersect == ref.intersect);
    const bool inside = vv == 0;
    if (!inside) {
      // 4.5u + 362 u^2 S/|Q| relative (item 5)
      const long double bd = qq == 0 ? 4.5L : 4.5L + 362 * u * ratio;
      const long double ed = ulps(got.distance, ref.distance), ep = ulps(got.depth, ref.depth);
      REQUIRE(ed <= bd);
      REQUIRE(ep <= bd);
      worst_d = std::max({worst_d, ed, ep});
    } else {
      // depth = delta + rho by Sum2: 1 + 16.1 u (h + |c| + rho)/depth ulps (item 6)
      const long double dep = ld(ref.depth);
      const long double bd = 1 + 16.1L * u * (hn + cn + rho) / dep;
      const long double ep = ulps(got.depth, ref.depth);
      REQUIRE(ep <= bd);
      REQUIRE(got.distance == 0);
      worst_d = std::max(worst_d, ep);
    }
    for (int i = 0; i < 3; ++i) {
      const long double ni = inside ? 0 : std::sqrt(exact::round_long_double(Q(vq[i] * vq[i] / vv)));
      // on the sphere: within 43u^2 max(|p_i|, rho |n_i|) before one rounding outside (item 7's
      // first look; item 5: 34u^2); half an ulp (of the result) inside
      const long double Ea = 43 * u * u * (std::fabs(ld(ref.on_a[i])) + rho * ni) * 1.01L;
      REQUIRE(ulps_beyond(got.on_a[i], ref.on_a[i], inside ? 0 : Ea) <= (inside ? 1.0L : 1.5L));
      const long double ea = ulps(got.on_a[i], ref.on_a[i]);
      // on the box and closest: half an ulp of the result (<= 1 ulp at the truth's binade)
      const long double eb = ulps(got.on_b[i], ref.on_b[i]);
      const long double ec = ulps(got.closest[i], ref.closest[i]);
      REQUIRE(eb <= 1);
      REQUIRE(ec <= 1);
      worst_a = std::max(worst_a, ea);
      worst_b = std::max(worst_b, eb);
    }
    if constexpr (!std::is_same_v<F, float>) {
      const auto bk = book::proximity(c.sp, c.box);
      if (bk.intersect != ref.intersect || !(ulps(bk.distance, ref.distance) <= 1e6L) ||
          !(ulps(bk.depth, ref.depth) <= 1e6L))
        ++book_bad;
    }
  }
  if constexpr (!std::is_same_v<F, float>) REQUIRE(book_bad >= 5);
  if (std::getenv("CDREF_TEST_REPORT")) std::cout << "sphere-box " << typeid(F).name() << ": worst distance/depth " << double(worst_d) << " ulps, witness on sphere "
                     << double(worst_a) << ", on box " << double(worst_b) << "; book off on " << book_bad << " cases" << "\n";
}

// ---------------------------------------------------------------------------
// decide(): certain implies the book's exact classification, on generated cases.
namespace {

template <class F>
bool fin(const fuzz::Inputs& in, int n) {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(F(in[i]))) return false;
  return true;
}
template <class F>
Vec3<F> at(const fuzz::Inputs& in, int k) {
  return Vec3<F>(F(in[k]), F(in[k + 1]), F(in[k + 2]));
}

struct Tally {
  long n = 0, certain = 0;
};

// Runs decide over n cases of each listed family (every scale), asserting certain =>
// value == truth; returns the tally of the uniform family.
template <class F, class Run>
Tally sweep(fuzz::Query q, int n_inputs, const std::vector<std::string>& fams, int n, Run run) {
  Tally uni;
  for (const auto& name : fams) {
    const auto& fam = fuzz::family_by_name(q, name);
    const int per = std::max<int>(1, n / int(fam.scales.size()));
    for (int sc : fam.scales)
      for (int i = 0; i < per; ++i) {
        const fuzz::Inputs in = fuzz::make_case(7, q, fam, sc, std::uint64_t(i));
        if (!fin<F>(in, n_inputs)) continue;
        bool ok = true, certain = false;
        try {
          const auto [dec, truth, same] = run(in);
          certain = dec.certain;
          ok = !dec.certain || dec.value == truth;
          INFO("family " << name << " scale " << sc << " case " << i);
          REQUIRE(same);  // decide's value is the query's own classification
        } catch (const invalid_input&) {
          continue;  // e.g. a radius that rounds to a negative zero-crossing in F: refused by both
        }
        INFO("family " << name << " scale " << sc << " case " << i);
        REQUIRE(ok);
        if (name == "uniform") {
          ++uni.n;
          uni.certain += certain;
        }
      }
  }
  return uni;
}

}  // namespace

TEMPLATE_TEST_CASE("robust decide: certain answers equal the book at Gmpq", "[robust-spheres]", float, double,
                   long double) {
  using F = TestType;
  using fuzz::Query;
  // Observed share of certain answers on the uniform families (2000 cases each, g++ 12):
  // 100% for every query (sphere-sphere, sphere-box, segment-sphere, segment and ray casts)
  // at float, double and long double. No certain answer was wrong on any family.
  const int n = 2000;
  const Tally ss = sweep<F>(fuzz::query_by_name("sphere-sphere"), 8, {"uniform", "near-touching", "long-range", "degenerate", "magnitude"},
                            n, [](const fuzz::Inputs& in) {
                              const Sphere<F> a{at<F>(in, 0), F(in[3])}, b{at<F>(in, 4), F(in[7])};
                              const auto d = robust::decide(a, b);
                              return std::tuple{d, book::intersect(convert_prim_exact(a), convert_prim_exact(b)), d.value == robust::intersect(a, b)};
                            });
  const Tally sb = sweep<F>(fuzz::query_by_name("sphere-box"), 10, {"uniform", "near-touching", "long-range", "degenerate", "magnitude"},
                            n, [](const fuzz::Inputs& in) {
                              const Sphere<F> s{at<F>(in, 0), F(in[3])};
                              const Box<F> b{at<F>(in, 4), at<F>(in, 7)};
                              const auto d = robust::decide(s, b);
                              return std::tuple{d, book::intersect(convert_prim_exact(s), convert_prim_exact(b)), d.value == robust::intersect(s, b)};
                            });
  std::vector<std::string> segf;
  for (const auto& f : fuzz::families(fuzz::query_by_name("segment-sphere"))) segf.push_back(f.name);
  const Tally gs = sweep<F>(fuzz::query_by_name("segment-sphere"), 10, segf, n, [](const fuzz::Inputs& in) {
    const Segment<F> s{at<F>(in, 0), at<F>(in, 3)};
    const Sphere<F> p{at<F>(in, 6), F(in[9])};
    const auto d = robust::decide_closest(s, p);
    return std::tuple{d, book::intersect(convert_prim_exact(s), convert_prim_exact(p)), d.value == robust::intersect(s, p)};
  });
  std::vector<std::string> castf;
  for (const auto& f : fuzz::families(fuzz::query_by_name("segment-sphere-cast"))) castf.push_back(f.name);
  const Tally cs = sweep<F>(fuzz::query_by_name("segment-sphere-cast"), 10, castf, n, [](const fuzz::Inputs& in) {
    const Segment<F> s{at<F>(in, 0), at<F>(in, 3)};
    const Sphere<F> p{at<F>(in, 6), F(in[9])};
    const auto d = robust::decide(s, p);
    return std::tuple{d, book::hit(convert_prim_exact(s), convert_prim_exact(p)), d.value == robust::hit(s, p)};
  });
  std::vector<std::string> rayf;
  for (const auto& f : fuzz::families(fuzz::query_by_name("ray-sphere-cast"))) rayf.push_back(f.name);
  const Tally rs = sweep<F>(fuzz::query_by_name("ray-sphere-cast"), 10, rayf, n, [](const fuzz::Inputs& in) {
    const Ray<F> s{at<F>(in, 0), at<F>(in, 3)};
    const Sphere<F> p{at<F>(in, 6), F(in[9])};
    const auto d = robust::decide(s, p);
    return std::tuple{d, book::hit(convert_prim_exact(s), convert_prim_exact(p)), d.value == robust::hit(s, p)};
  });
  for (const Tally* t : {&ss, &sb, &gs, &cs, &rs}) {
    REQUIRE(t->n > 500);
    REQUIRE(double(t->certain) > 0.99 * double(t->n));
  }
  if (std::getenv("CDREF_TEST_REPORT")) std::cout << "certain share on uniform (" << typeid(F).name() << "): sphere-sphere " << ss.certain << "/" << ss.n
                                    << ", sphere-box " << sb.certain << "/" << sb.n << ", segment-sphere " << gs.certain
                                    << "/" << gs.n << ", segment cast " << cs.certain << "/" << cs.n << ", ray cast "
                                    << rs.certain << "/" << rs.n << "\n";
}

// ---------------------------------------------------------------------------
// ray-sphere casts (ray_sphere.hpp): lambda_enter within the bound derived in the header
// ("Accuracy of lambda_enter"), on hard cases and on generated uniform, long-range,
// near-tangent and tangent-at-range draws, segments and rays, at float, double, long double.
namespace {

template <class F>
struct CastIn {
  std::string name;
  Vec3<F> s, t;  // source, target (segment) or source, direction (ray)
  bool ray;
  Sphere<F> sp;
};

template <class F>
std::vector<CastIn<F>> ray_sphere_hard() {
  std::vector<CastIn<F>> v;
  const Sphere<F> unit{v3<F>(0, 0, 0), F(1)};
  const long double in = 1 - std::ldexp(1.0L, -40);
  v.push_back({"chord with irrational lambdas", v3<F>(-2, 0.5L, 0), v3<F>(2, 0.5L, 0), false, unit});
  v.push_back({"near tangency inside by 2^-40", v3<F>(-2, in, 0), v3<F>(2, in, 0), false, unit});
  v.push_back({"sphere off the origin", v3<F>(0, -20, 30), v3<F>(20, -20, 30), false, {v3<F>(10, -20, 30), F(5)}});
  v.push_back({"ray tangent", v3<F>(-5, 0, 1), v3<F>(1, 0, 0), true, unit});
  v.push_back({"ray with a non-unit direction", v3<F>(-3, 0, 0), v3<F>(2, 0, 0), true, unit});
  for (long double R : {1e4L, 1e6L, 1e8L, 1e10L, 1e12L}) {
    const std::string r = std::to_string(double(R));
    v.push_back({"long range through the centre " + r, v3<F>(-R, 0, 0), v3<F>(R, 0, 0), false, unit});
    v.push_back({"ray at range " + r, v3<F>(-R, 0, 0), v3<F>(1, 0, 0), true, unit});
    v.push_back({"ray at range, off-axis " + r, v3<F>(-R, 0.75L, 0.375L), v3<F>(1, 0, 0), true, unit});
    v.push_back({"segment at range, inside by 2^-40 " + r, v3<F>(-R, in, 0), v3<F>(R, in, 0), false, unit});
    v.push_back({"oblique segment at range " + r, v3<F>(R * 0.6L, -R * 0.8L, 0.5L), v3<F>(-R * 0.6L, R * 0.8L, 0.25L),
                 false, {v3<F>(3, -5, 7), F(2)}});
  }
  const int e = huge_exp<F>();
  for (int sgn : {1, -1}) {
    const F m = p2<F>(sgn * e);
    v.push_back({sgn > 0 ? "huge" : "tiny", Vec3<F>(F(-3 * m), F(m / 4), F(0)), Vec3<F>(F(3 * m), F(m / 4), F(0)), false,
                 {Vec3<F>(F(0), F(0), F(0)), m}});
  }
  return v;
}

struct CastStats {
  long graded = 0, unbounded = 0, misclassified = 0;
  long double worst = 0, worst_bound = 0;
};

// One case: the robust cast against the book at Gmpq on the same F inputs. Returns false
// when the header's bound does not apply (the case lies in the ill-conditioned region).
template <class F>
void check_cast(const CastIn<F>& c, CastStats& st) {
  using std::fabs;
  using std::sqrt;
  const long double u = unit<F>();
  const Cast<F> got = c.ray ? robust::cast(Ray<F>{c.s, c.t}, c.sp) : robust::cast(Segment<F>{c.s, c.t}, c.sp);
  const robust::Decision dec = c.ray ? robust::decide(Ray<F>{c.s, c.t}, c.sp) : robust::decide(Segment<F>{c.s, c.t}, c.sp);
  REQUIRE(dec.value == got.hit);
  const Sphere<Q> spq = convert_prim_exact(c.sp);
  const Vec3<Q> sq = exact_vec(c.s), tq = exact_vec(c.t);
  const Cast<QS> ref = c.ray ? book::cast(Ray<Q>{sq, tq}, spq) : book::cast(Segment<Q>{sq, tq}, spq);
  if (dec.certain) REQUIRE(got.hit == ref.hit);
  if (got.hit != ref.hit) ++st.misclassified;
  if (!(got.hit && ref.hit && ref.enters)) return;
  // the exact quantities of the header, in its scaled units (x 2^-scale, scale as in
  // scaled_dw): s, r, rho, a, b, c, D = (b^2 - a c) / a; eta covers underflow there
  F m = c.sp.radius;
  for (int i = 0; i < 3; ++i)
    m = std::max({m, F(fabs(F(c.s[i] - c.sp.center[i]))), F(fabs(c.ray ? c.t[i] : F(c.t[i] - c.s[i])))});
  const int sc = std::ilogb(m);
  auto down_signed = [sc](const Q& x) {  // x 2^-sc, exactly
    Q y;
    if (sc >= 0)
      mpq_div_2exp(y.mpq(), x.mpq(), sc);
    else
      mpq_mul_2exp(y.mpq(), x.mpq(), -sc);
    return y;
  };
  Vec3<Q> s, r;
  for (int i = 0; i < 3; ++i) {
    s[i] = down_signed(sq[i] - spq.center[i]);
    r[i] = down_signed(c.ray ? tq[i] : Q(tq[i] - sq[i]));
  }
  const Q rq = down_signed(spq.radius);
  const Q a = r.squaredNorm(), b = s.dot(r), cc = s.squaredNorm() - rq * rq;
  const Q D = (b * b - a * cc) / a;
  const long double la = exact::round_long_double(a), lb = exact::round_long_double(b),
                    lc = exact::round_long_double(cc), lD = exact::round_long_double(D);
  const long double ns = sqrt(exact::round_long_double(Q(s.squaredNorm()))), nr = sqrt(la);
  const long double rho = exact::round_long_double(rq);
  if (!(lc > 0) || !(lb < 0)) return;  // lambda_enter = 0 exactly (source inside or on the sphere)
  const long double E = std::numeric_limits<F>::denorm_min();
  // the header's error terms (item A), evaluated for the case
  const long double err_c = 55 * u * u * (ns * ns + rho * rho) + 32 * E;
  const long double err_b = 51 * u * u * ns * nr + 32 * E;
  const long double rel_a = 52 * u * u + 32 * E / la;
  const long double delta2a = 2 * err_b * err_b / la + 7200 * u * u * u * u * lb * lb / la;
  const long double el = 33 * u * u * ns;
  const long double err_D = 111 * u * u * rho * rho + 2 * (rho + sqrt(delta2a)) * el + el * el + delta2a + 64 * E;
  const long double rel_c = err_c / lc;
  const long double X = sqrt(la * std::max(lD, 0.0L)), qv = -lb + X;
  // |X^ - X|: sqrt(a err_D) (1.01) + (X + sqrt(a err_D)) (0.51 rel_a + 6.2 u^2) always; and
  // X (0.57 theta + 4.1 u^2) when theta = 1.01 (rel_a + err_D / D) + 4u^2 <= 0.4
  const long double sq_e = sqrt(la * err_D);
  long double eX = 1.01L * sq_e + (X + sq_e) * (0.51L * rel_a + 6.2L * u * u);
  if (lD > 0) {
    const long double theta = 1.01L * (rel_a + err_D / lD) + 4 * u * u;
    if (theta <= 0.4L) eX = std::min(eX, X * (0.57L * theta + 4.1L * u * u));
  }
  const long double rel_q = (err_b + eX) / qv + 3.1L * u * u;
  if (!(rel_c <= 0.1L) || !(rel_q <= 0.1L)) {
    ++st.unbounded;
    std::cout << "outside the bound's domain: " << c.name << "\n";
    return;
  }
  const long double rel_z = (rel_c + rel_q) / (1 - rel_q) + 8.1L * u * u;
  // ulps(lambda_enter) <= 1 + rel_z (1 + 1/u): a final rounding and the relative error
  // of the double-word quotient c / q before it (x 1.001 for this evaluation)
  const long double bound = 1 + 1.001L * rel_z * (1 + 1 / u);
  const long double err = ulps(got.lambda_enter, ref.lambda_enter);
  INFO(c.name << ": lambda_enter " << double(err) << " ulps, bound " << double(bound) << " (rel_c " << double(rel_c / u)
              << " u, D " << double(lD) << ", rel_q " << double(rel_q / u) << " u)");
  REQUIRE(err <= bound);
  ++st.graded;
  st.worst = std::max(st.worst, err);
  st.worst_bound = std::max(st.worst_bound, bound);
}

template <class F>
CastIn<F> cast_in(fuzz::Query q, const fuzz::Inputs& in, const std::string& name) {
  return {name, at<F>(in, 0), at<F>(in, 3), q == fuzz::query_by_name("ray-sphere-cast"), {at<F>(in, 6), F(in[9])}};
}

}  // namespace

TEMPLATE_TEST_CASE("robust ray-sphere casts: lambda_enter within the derived bound", "[robust-spheres]", float, double,
                   long double) {
  using F = TestType;
  CastStats hard;
  for (const auto& c : ray_sphere_hard<F>()) {
    INFO(c.name);
    check_cast(c, hard);
  }
  REQUIRE(hard.misclassified == 0);
  REQUIRE(hard.unbounded == 0);
  REQUIRE(hard.graded >= 12);
  for (fuzz::Query q : {fuzz::query_by_name("segment-sphere-cast"), fuzz::query_by_name("ray-sphere-cast")}) {
    for (const std::string fam_name : {"uniform", "long-range", "near-tangent", "tangent-at-range"}) {
      const auto& fam = fuzz::family_by_name(q, fam_name);
      const int per = std::max<int>(20, 400 / int(fam.scales.size()));
      CastStats st;
      for (int sc : fam.scales)
        for (int i = 0; i < per; ++i) {
          const fuzz::Inputs in = fuzz::make_case(5, q, fam, sc, std::uint64_t(i));
          if (!fin<F>(in, 10)) continue;
          const CastIn<F> c = cast_in<F>(q, in, fam_name + "/" + std::to_string(sc) + " case " + std::to_string(i));
          INFO(c.name);
          try {
            check_cast(c, st);
          } catch (const invalid_input&) {
            continue;
          }
        }
      // uniform and long-range draws never fall in the ill-conditioned region (observed: none
      // of them is within the header's distance of tangency or of the source on the sphere)
      if (fam_name == "uniform" || fam_name == "long-range") {
        REQUIRE(st.unbounded == 0);
        REQUIRE(st.misclassified == 0);
      }
      if (std::getenv("CDREF_TEST_REPORT"))
        std::cout << "ray-sphere cast " << typeid(F).name() << " " << fuzz::info(q).name << " " << fam_name << ": graded "
                  << st.graded << ", worst lambda_enter " << double(st.worst) << " ulps (largest bound "
                  << double(st.worst_bound) << "), outside the bound's domain " << st.unbounded << ", misclassified "
                  << st.misclassified << "\n";
    }
  }
}

// ---------------------------------------------------------------------------
// decide(Segment/Ray, Sphere) from the cast's double-word quantities (ray_sphere.hpp,
// "Certificates"): on generated cases of every ray-sphere and segment-sphere-cast family,
// certain => the book's classification at Gmpq, and decide().value == hit(); the certain
// share per family, with floors at double.
namespace {

struct FamilyShare {
  std::string family;
  long n = 0, certain = 0;
};

template <class F>
std::vector<FamilyShare> cast_certain_shares(fuzz::Query q, int n) {
  std::vector<FamilyShare> out;
  for (const auto& fam : fuzz::families(q)) {
    FamilyShare sh{fam.name};
    const int per = std::max<int>(20, n / int(fam.scales.size()));
    for (int sc : fam.scales)
      for (int i = 0; i < per; ++i) {
        const fuzz::Inputs in = fuzz::make_case(11, q, fam, sc, std::uint64_t(i));
        if (!fin<F>(in, 10)) continue;
        const Sphere<F> p{at<F>(in, 6), F(in[9])};
        robust::Decision d;
        bool value = false, truth = false;
        try {
          if (q == fuzz::query_by_name("ray-sphere-cast")) {
            const Ray<F> r{at<F>(in, 0), at<F>(in, 3)};
            d = robust::decide(r, p);
            value = robust::hit(r, p);
            truth = book::hit(convert_prim_exact(r), convert_prim_exact(p));
          } else {
            const Segment<F> s{at<F>(in, 0), at<F>(in, 3)};
            d = robust::decide(s, p);
            value = robust::hit(s, p);
            truth = book::hit(convert_prim_exact(s), convert_prim_exact(p));
          }
        } catch (const invalid_input&) {
          continue;
        }
        INFO(fuzz::info(q).name << " family " << fam.name << " scale " << sc << " case " << i);
        REQUIRE(d.value == value);
        if (d.certain) REQUIRE(d.value == truth);
        ++sh.n;
        sh.certain += d.certain;
      }
    out.push_back(sh);
  }
  return out;
}

}  // namespace

TEMPLATE_TEST_CASE("robust ray-sphere decide: certain answers equal the book at Gmpq on every family",
                   "[robust-spheres]", float, double, long double) {
  using F = TestType;
  // Measured (g++ 12, seed 11, about 1000 cases per family): certain on 100% of the
  // uniform, long-range, near-tangent and tangent-at-range draws at double (segments and
  // rays); the uncertain cases are degenerate ones with an exact zero (a source exactly
  // on the sphere, a line exactly through a point sphere), where no bound can decide.
  for (fuzz::Query q : {fuzz::query_by_name("segment-sphere-cast"), fuzz::query_by_name("ray-sphere-cast")}) {
    const std::vector<FamilyShare> shares = cast_certain_shares<F>(q, 1000);
    for (const FamilyShare& sh : shares) {
      if (std::getenv("CDREF_TEST_REPORT"))
        std::cout << "decide " << typeid(F).name() << " " << fuzz::info(q).name << " " << sh.family << ": certain "
                  << sh.certain << "/" << sh.n << "\n";
      if (std::is_same_v<F, double> && (sh.family == "uniform" || sh.family == "long-range" ||
                                        sh.family == "near-tangent" || sh.family == "tangent-at-range")) {
        INFO(fuzz::info(q).name << " " << sh.family << ": certain " << sh.certain << "/" << sh.n);
        REQUIRE(sh.n >= 500);
        // measured 100%; floor 99%
        REQUIRE(double(sh.certain) >= 0.99 * double(sh.n));
      }
    }
  }
}

// Directions whose squares lie near the bottom of F's normal range: a = |r|^2 then loses its
// low part to underflow (relative error up to 32 eta / a, not 52 u^2), and the quotient
// f = b / a with it. A line exactly through a point sphere or tangent to a sphere of radius u
// (D = 0), and lines passing u or 4u beside a point or a sphere of radius u: decide() may be
// uncertain, and where it is certain it equals the book at Gmpq. Once a >= 128 eta / u, f's
// error adds less than u^2 / 16 to D's bound (delta^2 a, header item A) and every line with
// D != 0 here (|D| >= u^2) is decided. (Found by fuzz_query on ray-sphere-cast at float: the
// certificate took f's error as 60 u^2 relative whatever a's size, and called a line through
// a point sphere a certain miss.)
TEMPLATE_TEST_CASE("robust ray-sphere decide: directions whose squares underflow", "[robust-spheres]", float, double,
                   long double) {
  using F = TestType;
  constexpr int emin = std::numeric_limits<F>::min_exponent;
  const F u = std::numeric_limits<F>::epsilon() / 2;
  const long double a_decided = 128.0L * std::numeric_limits<F>::denorm_min() / u;
  int certain = 0, n = 0, decided = 0;
  for (int k = emin / 2 - 6; k <= emin / 2 + 24; ++k)
    for (const long double m : {1.0L, 1.8225L, 1.3333333333L})
      for (const long double off : {0.0L, 1.0L, -1.0L, 4.0L})
        for (const long double rho : {0.0L, 1.0L}) {
          const F d = F(std::ldexp(m, k));
          const Ray<F> ray{Vec3<F>(F(0), F(0), F(0)), Vec3<F>(F(0), d, F(0))};
          const Sphere<F> sp{Vec3<F>(F(off * u), F(1), F(0)), F(rho * u)};  // the line |off| u from the centre
          const Segment<F> seg{Vec3<F>(F(0), F(0), F(0)), Vec3<F>(F(0), F(2), F(0))};
          const auto dr = robust::decide(ray, sp);
          const bool tr = book::hit(convert_prim_exact(ray), convert_prim_exact(sp));
          INFO("k " << k << " m " << double(m) << " off " << double(off) << " rho " << double(rho));
          REQUIRE(tr == (std::fabs(off) <= rho));
          ++n;
          if (dr.certain) {
            ++certain;
            REQUIRE(dr.value == tr);
          }
          REQUIRE(dr.value == robust::hit(ray, sp));
          const bool tangent = std::fabs(off) == rho;  // D = 0 exactly
          if (!tangent && (long double)d * d >= a_decided) {
            ++decided;
            REQUIRE(dr.certain);
          }
          const auto ds = robust::decide(seg, sp);
          if (ds.certain) REQUIRE(ds.value == book::hit(convert_prim_exact(seg), convert_prim_exact(sp)));
        }
  if (std::getenv("CDREF_TEST_REPORT"))
    std::cout << "underflowing directions (" << typeid(F).name() << "): certain " << certain << "/" << n
              << ", of which " << decided << " required\n";
  REQUIRE(decided > n / 3);  // the grid reaches well past the underflow (measured 330 of 744)
}

// ---------------------------------------------------------------------------
// The stable tier of the sphere casts (float/cdref/stable/ray_sphere.hpp): plain F arithmetic
// from the perpendicular foot, no certificate. Its header says where it can misclassify: near
// tangency (|D| within its derived error, D = rho^2 - |l|^2), with the source or the target on
// the sphere (c or c_t within theirs), or with the range tests' dot products b = f.r or b + a
// near zero. On generated cases of every family, every misclassified case lies in one of those
// bands, measured with the exact quantities (Gmpq); the cast's classification equals hit().
TEMPLATE_TEST_CASE("stable sphere casts: every misclassification lies in the header's bands", "[stable]", float,
                   double) {
  using F = TestType;
  const long double u = unit<F>();
  auto mag = [](const Q& x) { return std::fabs(static_cast<long double>(CGAL::to_double(x))); };
  for (fuzz::Query q : {fuzz::query_by_name("segment-sphere-cast"), fuzz::query_by_name("ray-sphere-cast")}) {
    const bool segment = q == fuzz::query_by_name("segment-sphere-cast");
    long cases = 0, wrong = 0, book_wrong = 0;
    for (const auto& fam : fuzz::families(q)) {
      const int per = std::max<int>(20, 600 / int(fam.scales.size()));
      for (int sc : fam.scales)
        for (int i = 0; i < per; ++i) {
          const fuzz::Inputs in = fuzz::make_case(13, q, fam, sc, std::uint64_t(i));
          if (!fin<F>(in, 10)) continue;
          const Sphere<F> sp{at<F>(in, 6), F(in[9])};
          bool got = false, cast_hit = false, truth = false, book_got = false;
          Vec3<Q> src, r;
          // the shot at F and at Gmpq; r the exact direction (t - s for a segment)
          auto run = [&](const auto& shot) {
            got = stable::hit(shot, sp);
            cast_hit = stable::cast(shot, sp, unsigned(want_all)).hit;
            book_got = book::hit(shot, sp);
            const auto e = convert_prim_exact(shot);
            truth = book::hit(e, convert_prim_exact(sp));
            src = e.source;
            if constexpr (requires { e.direction; })
              r = e.direction;
            else
              r = e.target - e.source;
          };
          try {
            if (segment)
              run(Segment<F>{at<F>(in, 0), at<F>(in, 3)});
            else
              run(Ray<F>{at<F>(in, 0), at<F>(in, 3)});
          } catch (const invalid_input&) {
            continue;
          }
          INFO(fuzz::info(q).name << " family " << fam.name << " scale " << sc << " case " << i);
          REQUIRE(cast_hit == got);
          ++cases;
          book_wrong += book_got != truth;
          if (got == truth) continue;
          ++wrong;
          // the exact quantities
          const Q rho = exact_q(sp.radius);
          const Vec3<Q> f = src - convert_prim_exact(sp).center;
          const Vec3<Q> t = f + r;
          const Q a = r.dot(r), b = f.dot(r), rho2 = rho * rho;
          const Vec3<Q> cr = f.cross(r);
          const Q D = a == Q(0) ? Q(0) : Q((rho2 * a - cr.dot(cr)) / a);
          const Q c = f.dot(f) - rho2, ct = t.dot(t) - rho2, ba = b + a;
          const long double F_ = std::sqrt(mag(f.dot(f))), R = std::sqrt(mag(a)), T = std::sqrt(mag(t.dot(t))),
                            rh = mag(rho), L = std::sqrt(std::max(0.0L, rh * rh - static_cast<long double>(CGAL::to_double(D))));
          // the header's bounds (first order; the inputs' own roundings added: f = source -
          // centre, and for a segment r = target - source), with 5% for second-order terms
          const long double el = (segment ? 13 : 10) * u * F_ + u * L;
          const long double BD = 1.05L * (el * (2 * L + el) + 4 * u * (rh * rh + (L + el) * (L + el)));
          const long double Bc = 1.05L * 6 * u * (F_ * F_ + rh * rh);
          const long double Bb = 1.05L * 6 * u * F_ * R;
          const long double Bct = 1.05L * (2 * u * T * (F_ + R + T) + 4 * u * (T * T + rh * rh));
          const long double Bba = 1.05L * (6 * u * F_ * R + 6 * u * R * R + u * mag(ba));
          const bool in_band = mag(D) <= BD || mag(c) <= Bc || mag(b) <= Bb ||
                               (segment && (mag(ct) <= Bct || mag(ba) <= Bba));
          INFO("D " << double(CGAL::to_double(D)) << " (band " << double(BD) << "), c " << double(CGAL::to_double(c))
                    << " (" << double(Bc) << "), b " << double(CGAL::to_double(b)) << " (" << double(Bb) << ")");
          REQUIRE(in_band);
        }
    }
    REQUIRE(cases > 2000);
    if (std::getenv("CDREF_TEST_REPORT"))
      std::cout << "stable " << typeid(F).name() << " " << fuzz::info(q).name << ": " << cases << " cases, "
                << wrong << " misclassified (the book " << book_wrong << ")\n";
  }
}

}  // namespace cdref_test_robust_spheres
