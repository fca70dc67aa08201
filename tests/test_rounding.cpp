// tests/test_rounding.cpp - correct rounding of exact values to double and float.
//
// Three independent witnesses that round_double / round_float are right:
//   - the definition, checked exactly: the result r satisfies m- <= v <= m+ for the
//     midpoints m- = (r- + r)/2, m+ = (r + r+)/2 with its neighbours, and on a tie r has
//     an even significand (overflow to infinity past max + ulp/2);
//   - IEEE 754 itself: +, *, / and sqrt of doubles and floats are correctly rounded, so
//     round_double(exact a op b) must equal a op b, and round_double(sqrt(x)) = sqrt(x);
//   - MPFR's mpfr_set_q with the double exponent range and subnormals.
// CGAL::to_double(CORE::Expr), which truncates, is shown to differ where it must.
#include <random>
#include <thread>

#include <gmpxx.h>

#include <cdref/bounded/bounded2.hpp>
#include <cdref/exact/gmp_pool.hpp>

#include "support.hpp"

// This file's names in a namespace of its own: the test files are compiled several to a unit
// (tests/CMakeLists.txt).
namespace cdref_test_rounding {

using namespace cdref;
using namespace cdref::test;

namespace {

template <class F>
F next_up(F x) {
  return std::nextafter(x, std::numeric_limits<F>::infinity());
}
template <class F>
F next_down(F x) {
  return std::nextafter(x, -std::numeric_limits<F>::infinity());
}

template <class F>
bool even_significand(F r) {
  if (std::isinf(r)) return true;
  if constexpr (std::is_same_v<F, double>)
    return (std::bit_cast<std::uint64_t>(r) & 1u) == 0;
  else
    return (std::bit_cast<std::uint32_t>(r) & 1u) == 0;
}

// The definition of round-to-nearest-even, checked with exact arithmetic.
template <class F>
bool is_nearest(const Expr& v, F r) {
  const F mx = std::numeric_limits<F>::max();
  if (std::isinf(r)) {  // only past the overflow threshold max + ulp(max)/2 (ties go to inf)
    const Expr threshold = Expr(double(mx)) + (Expr(double(mx)) - Expr(double(next_down(mx)))) / 2;
    return r > 0 ? v >= threshold : v <= -threshold;
  }
  const Expr er = Expr(double(r));
  const F up = next_up(r), down = next_down(r);
  const Expr m_hi = std::isinf(up) ? er + (er - Expr(double(down))) / 2 : (er + Expr(double(up))) / 2;
  const Expr m_lo = std::isinf(down) ? er - (Expr(double(up)) - er) / 2 : (er + Expr(double(down))) / 2;
  if (v < m_lo || v > m_hi) return false;
  if ((v == m_lo || v == m_hi) && v != er) return even_significand(r);
  return true;
}

// Random doubles over the whole range, subnormals and both signs included.
double random_double(std::mt19937_64& g) {
  for (;;) {
    const double x = std::bit_cast<double>(g());
    if (std::isfinite(x)) return x;
  }
}

}  // namespace

TEST_CASE("rationals round to the nearest double and float, ties to even", "[rounding]") {
  std::mt19937_64 g(20261121);
  mpfr_t m;
  mpfr_init2(m, 53);
  const auto saved_emin = mpfr_get_emin(), saved_emax = mpfr_get_emax();
  mpfr_set_emin(-1073);  // IEEE double: subnormals down to 2^-1074
  mpfr_set_emax(1024);
  int n = 0, ties = 0;
  for (int i = 0; i < 20000; ++i) {
    Q v;
    switch (i % 4) {
      case 0: v = Q(random_double(g)) / Q(random_double(g) + (i % 7 == 0 ? 0.0 : 1.0)); break;
      case 1: v = Q(random_double(g)) * Q(random_double(g)); break;
      case 2: {  // an exact midpoint between two neighbours: a tie
        const double x = random_double(g);
        v = (Q(x) + Q(std::nextafter(x, 0.0) == x ? x : std::nextafter(x, HUGE_VAL))) / Q(2);
        ++ties;
        break;
      }
      default: v = Q(random_double(g)) + Q(random_double(g)); break;
    }
    const double r = round_double(v);
    REQUIRE(is_nearest(to_expr(v), r));
    // MPFR's own correct rounding, with IEEE's range
    int t = mpfr_set_q(m, v.mpq(), MPFR_RNDN);
    t = mpfr_check_range(m, t, MPFR_RNDN);
    mpfr_subnormalize(m, t, MPFR_RNDN);
    REQUIRE(mpfr_get_d(m, MPFR_RNDN) == r);
    REQUIRE(is_nearest(to_expr(v), round_float(v)));
    REQUIRE(round_double(Lazy(mpq_class(v.mpq()))) == r);  // Epeck::FT: the same value, the same way
    ++n;
  }
  mpfr_set_emin(saved_emin);
  mpfr_set_emax(saved_emax);
  mpfr_clear(m);
  REQUIRE(n == 20000);
  REQUIRE(ties == 5000);
}

TEST_CASE("exact results of IEEE operations round to what IEEE computes", "[rounding]") {
  std::mt19937_64 g(7);
  for (int i = 0; i < 20000; ++i) {
    const double a = random_double(g), b = random_double(g);
    REQUIRE(round_double(Q(a) + Q(b)) == a + b);
    REQUIRE(round_double(Q(a) * Q(b)) == a * b);
    if (b != 0) REQUIRE(round_double(Q(a) / Q(b)) == a / b);
    const float fa = static_cast<float>(a / std::ldexp(1.0, std::ilogb(a) - (int(g() % 200) - 100)));
    const float fb = static_cast<float>(std::ldexp(1.0, int(g() % 60) - 30)) * 1.5f + fa;
    if (std::isfinite(fa) && std::isfinite(fb)) {
      REQUIRE(round_float(Q(double(fa)) * Q(double(fb))) == fa * fb);
      if (fb != 0) REQUIRE(round_float(Q(double(fa)) / Q(double(fb))) == fa / fb);
    }
  }
}

TEST_CASE("square roots kept exactly round to IEEE's correctly rounded sqrt", "[rounding]") {
  std::mt19937_64 g(11);
  for (int i = 0; i < 5000; ++i) {
    const double x = std::fabs(random_double(g));
    // as a quadratic-field value over Gmpq and over Epeck::FT
    REQUIRE(round_double(QS::sqrt_of(Q(x))) == std::sqrt(x));
    REQUIRE(round_double(Quad<Lazy>::sqrt_of(Lazy(x))) == std::sqrt(x));
    const float fx = static_cast<float>(std::ldexp(std::fabs(x) / std::ldexp(1.0, std::ilogb(x)), int(g() % 250) - 140));
    REQUIRE(round_float(QS::sqrt_of(Q(double(fx)))) == std::sqrt(fx));
    if (i < 500) REQUIRE(round_double(CGAL::sqrt(Expr(x))) == std::sqrt(x));  // CORE::Expr
  }
}

TEST_CASE("a + b sqrt(d) rounds to nearest, checked exactly", "[rounding]") {
  std::mt19937_64 g(13);
  std::uniform_int_distribution<int> small(-1000, 1000);
  for (int i = 0; i < 3000; ++i) {
    const Q a = Q(small(g)) / Q(small(g) == 0 ? 1 : 7);
    const Q b = Q(small(g)) / Q(3);
    const Q d = Q(std::abs(small(g)) + 1) * p2(int(g() % 40) - 20);
    const QS v(a, b, d);
    const Expr e = to_expr(v);
    const double r = round_double(v);
    REQUIRE(is_nearest(e, r));
    REQUIRE(is_nearest(e, round_float(v)));
    REQUIRE(round_double(e) == r);  // the same value through CORE::Expr
  }
  // cancellation: a + b sqrt(d) with a = -b sqrt(d) to 60 digits
  const Q d = Q(2);
  const Q a = -q("14142135623730950488016887242096980785696718753769/10000000000000000000000000000000000000000000000000");
  const QS v(a, Q(1), d);
  REQUIRE(v.sign() > 0);
  REQUIRE(is_nearest(to_expr(v), round_double(v)));
  REQUIRE(round_double(v) > 0);
  REQUIRE(round_double(v) < 1e-48);
}

TEST_CASE("values of different quadratic fields are ordered exactly (compare_fields)", "[rounding]") {
  std::mt19937_64 g(29);
  std::uniform_int_distribution<int> small(-60, 60);
  auto sign = [](const Expr& e) { return e > Expr(0) ? 1 : (e < Expr(0) ? -1 : 0); };
  for (int i = 0; i < 3000; ++i) {
    const QS x(Q(small(g)) / Q(7), Q(small(g)) / Q(3), Q(std::abs(small(g)) + 1));
    const QS y(Q(small(g)) / Q(5), Q(small(g)) / Q(11), Q(std::abs(small(g)) + 1));
    REQUIRE(compare_fields(x, y) == sign(to_expr(x) - to_expr(y)));
    REQUIRE(compare_fields(y, x) == -compare_fields(x, y));
  }
  // equal values written in two fields: sqrt(8) = 2 sqrt(2)
  CHECK(compare_fields(QS(Q(0), Q(1), Q(8)), QS(Q(0), Q(2), Q(2))) == 0);
  // 10^-41 apart: sqrt(2) against (sqrt(2) - sqrt(3)) to 41 digits + sqrt(3)
  const Q c = -q("31783724519578224472575761729617428837313/100000000000000000000000000000000000000000");
  const QS x = QS::sqrt_of(Q(2)), y(c, Q(1), Q(3));
  CHECK(compare_fields(x, y) == sign(to_expr(x) - to_expr(y)));
  CHECK(compare_fields(x, y) != 0);
}

TEST_CASE("edges of the double range", "[rounding]") {
  const double mx = std::numeric_limits<double>::max();
  const Q qmax(mx);
  const Q half_ulp = (qmax - Q(next_down(mx))) / Q(2);
  REQUIRE(round_double(qmax) == mx);
  REQUIRE(round_double(Q(qmax + half_ulp - p2(-10))) == mx);
  REQUIRE(std::isinf(round_double(Q(qmax + half_ulp))));  // the tie goes to infinity (even)
  REQUIRE(round_double(Q(-(qmax + half_ulp))) == -HUGE_VAL);
  const double den = std::numeric_limits<double>::denorm_min();
  REQUIRE(round_double(Q(den)) == den);
  REQUIRE(round_double(Q(Q(den) / Q(2))) == 0.0);         // tie between 0 and 2^-1074: 0 is even
  REQUIRE(round_double(Q(Q(den) * Q(3) / Q(2))) == 2 * den);  // tie between 1 and 2 ulps: 2 is even
  REQUIRE(round_double(Q(Q(den) / Q(3))) == 0.0);
  REQUIRE(round_double(Q(Q(den) * Q(2) / Q(3))) == den);
  REQUIRE(round_float(Q(1e300)) == HUGE_VALF);
  REQUIRE(round_float(Q(std::ldexp(1.0, -150))) == 0.0f);  // tie with 0
  REQUIRE(round_float(Q(std::ldexp(1.0, -150) * 1.5)) == std::ldexp(1.0f, -149));
  REQUIRE(round_double(Q(0)) == 0.0);
}

TEST_CASE("CGAL::to_double(CORE::Expr) truncates; cdref rounds", "[rounding]") {
  // sqrt(2) = 1.41421356237309504880..., the nearest double is 1.4142135623730951 (above).
  const Expr r2 = CGAL::sqrt(Expr(2));
  REQUIRE(round_double(r2) == std::sqrt(2.0));
  REQUIRE(is_nearest(r2, round_double(r2)));
  // find values where the two conversions disagree, and check cdref is the nearest
  int differ = 0;
  for (int k = 2; k < 200; ++k) {
    const Expr v = CGAL::sqrt(Expr(k));
    const double t = CGAL::to_double(v);
    const double r = round_double(v);
    REQUIRE(r == std::sqrt(double(k)));
    if (t != r) {
      ++differ;
      REQUIRE_FALSE(is_nearest(v, t));
    }
  }
  REQUIRE(differ > 0);
}

namespace {
struct Three {
  double x, y, z;
};
[[gnu::noinline]] Three through_float(const Three& v) {
  return Three{double(float(v.x)), double(float(v.y)), double(float(v.z))};
}
}  // namespace

TEST_CASE("the build keeps the rounding of double -> float -> double", "[rounding][build]") {
  // g++ 12.2 at -O2 with its SLP vectorizer drops this round trip for the first two
  // fields; CMakeLists.txt turns that pass off. 1 + 2^-40 has no float: it must become 1.
  const double y = 1.0 + std::ldexp(1.0, -40);
  const Three r = through_float(Three{y, y, y});
  REQUIRE(r.x == 1.0);
  REQUIRE(r.y == 1.0);
  REQUIRE(r.z == 1.0);
}

TEST_CASE("rationals and a + b sqrt(d) round to the nearest long double", "[rounding]") {
  // Witnesses: MPFR's mpfr_set_q at 64 bits (an independent correct rounding; the values
  // stay inside long double's normal range), and for a + b sqrt d the definition, checked
  // exactly against the midpoints with both neighbours.
  std::mt19937_64 g(17);
  mpfr_t m;
  mpfr_init2(m, 64);
  for (int i = 0; i < 5000; ++i) {
    const Q v = Q(random_double(g)) / Q(random_double(g)) + Q(random_double(g)) * Q(random_double(g));
    mpfr_set_q(m, v.mpq(), MPFR_RNDN);
    REQUIRE(exact::round_long_double(v) == mpfr_get_ld(m, MPFR_RNDN));
  }
  mpfr_clear(m);
  std::uniform_int_distribution<int> small(-1000, 1000);
  for (int i = 0; i < 2000; ++i) {
    const QS v(Q(small(g)) / Q(7), Q(small(g)) / Q(3), Q(std::abs(small(g)) + 1) * p2(int(g() % 40) - 20));
    const long double r = exact::round_long_double(v);
    const long double lo = std::nextafter(r, -HUGE_VALL), hi = std::nextafter(r, HUGE_VALL);
    const Q m_lo = (exact::gmpq_of(lo) + exact::gmpq_of(r)) / Q(2), m_hi = (exact::gmpq_of(r) + exact::gmpq_of(hi)) / Q(2);
    REQUIRE(v.compare(m_lo) >= 0);
    REQUIRE(v.compare(m_hi) <= 0);
  }
  // a tie between two long doubles goes to the even significand
  const long double one = 1.0L, up = std::nextafter(one, 2.0L);
  const Q tie = (exact::gmpq_of(one) + exact::gmpq_of(up)) / Q(2);
  REQUIRE(exact::round_long_double(tie) == one);
  const Q tie2 = (exact::gmpq_of(up) + exact::gmpq_of(std::nextafter(up, 2.0L))) / Q(2);
  REQUIRE(exact::round_long_double(tie2) == std::nextafter(up, 2.0L));
}

// ---- cdref::Bounded2: every operation's bound holds, checked exactly ----

namespace {

using cdref::Bounded2;

// Exact value hi + lo of a Bounded2, and the check |X - (hi + lo)| <= e for an exact X.
Q dw_value(const Bounded2& b) { return Q(b.hi()) + Q(b.lo()); }
bool dw_encloses(const Bounded2& b, const Q& x) {
  const Q d = x - dw_value(b);
  return (d < 0 ? Q(-d) : d) <= Q(b.bound());
}
// sqrt(X) within [v - e, v + e], X >= 0, decided by squaring.
bool dw_encloses_root(const Bounded2& b, const Q& x) {
  const Q lo = dw_value(b) - Q(b.bound()), hi = dw_value(b) + Q(b.bound());
  return (lo <= 0 || lo * lo <= x) && hi >= 0 && hi * hi >= x;
}

struct Tracked {
  Bounded2 b;
  Q x;  // the exact value b stands for
};

}  // namespace

TEST_CASE("cdref::Bounded2 encloses the exact value after + - * / sqrt", "[rounding][oracle]") {
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> mant(-1, 1);
  std::uniform_int_distribution<int> expo(-60, 60), pick(0, 5);
  auto draw = [&] { return std::ldexp(mant(rng), expo(rng)); };
  int checked = 0, roots = 0, quotients = 0, exact_ties = 0, long_doubles = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    // a chain of operations with cancellation on purpose: values near one another
    std::vector<Tracked> pool;
    for (int k = 0; k < 4; ++k) {
      const double d = draw();
      pool.push_back({Bounded2(d), Q(d)});
    }
    for (int step = 0; step < 12; ++step) {
      const Tracked& a = pool[rng() % pool.size()];
      const Tracked& b = pool[rng() % pool.size()];
      Tracked r;
      try {
        switch (pick(rng)) {
          case 0: r = {a.b + b.b, a.x + b.x}; break;
          case 1: r = {a.b - b.b, a.x - b.x}; break;
          case 2: r = {a.b * b.b, a.x * b.x}; break;
          case 3: r = {a.b / b.b, a.x / b.x}; ++quotients; break;
          case 4: {  // near-cancellation: a - (a + tiny)
            const double t = std::ldexp(mant(rng), expo(rng) - 80);
            r = {a.b - (a.b + Bounded2(t)), Q(-t)};
            break;
          }
          default: {
            const Tracked& s = a.x >= 0 ? a : b;
            if (s.x < 0) continue;
            const Bounded2 root = Bounded2::root(s.b);
            REQUIRE(dw_encloses_root(root, s.x));
            ++roots;
            try {
              const long double l = root.rounded_long_double();
              REQUIRE(l == exact::round_long_double(QS::sqrt_of(s.x)));
              ++long_doubles;
            } catch (const cdref::uncertain&) {
            }
            continue;  // the root is not rational: not kept in the pool
          }
        }
      } catch (const cdref::uncertain&) {
        continue;  // a divisor that may be zero, a root of a maybe-negative value
      }
      if (!r.b.finite()) continue;
      REQUIRE(dw_encloses(r.b, r.x));
      REQUIRE(r.b.hi() == r.b.hi() + r.b.lo());  // normalized
      ++checked;
      // a certain sign is the exact sign; a certain rounding is the exact rounding
      // (each evaluated outside the assertion: uncertain is a fine answer)
      auto certain = [](auto f) -> std::optional<decltype(f())> {
        try {
          return f();
        } catch (const cdref::uncertain&) {
          return std::nullopt;
        }
      };
      if (const auto s = certain([&] { return r.b.sign(); })) {
        REQUIRE(*s == CGAL::sign(r.x));
        exact_ties += *s == 0;
      }
      if (const auto d = certain([&] { return r.b.rounded(); })) REQUIRE(*d == round_double(r.x));
      if (const auto f = certain([&] { return r.b.rounded_float(); })) REQUIRE(*f == round_float(r.x));
      if (const auto l = certain([&] { return r.b.rounded_long_double(); })) {
        REQUIRE(*l == exact::round_long_double(r.x));
        ++long_doubles;
      }
      pool.push_back(r);
    }
  }
  CHECK(checked > 30000);
  CHECK(roots > 3000);
  CHECK(quotients > 3000);
  CHECK(exact_ties > 100);
  CHECK(long_doubles > 20000);  // long double roundings the double word certifies
}

TEST_CASE("cdref::Bounded2 rounds to long double: midpoints uncertain, either side decided", "[rounding][oracle]") {
  if (std::numeric_limits<long double>::digits != 64) {  // (then rounded_long_double is rounded() or uncertain)
    WARN("long double is not the x87 extended format here: nothing to check");
    return;
  }
  // 1 and 1 + 2^-63 are neighbours; 1 + 2^-64 is the midpoint between them, a double word
  const long double up = 1.0L + std::ldexp(1.0L, -63);
  CHECK_THROWS_AS(Bounded2::exact_pair(1.0, 0x1p-64).rounded_long_double(), cdref::uncertain);
  CHECK(Bounded2::exact_pair(1.0, 0x1p-64 + 0x1p-116).rounded_long_double() == up);
  CHECK(Bounded2::exact_pair(1.0, 0x1p-64 - 0x1p-117).rounded_long_double() == 1.0L);
  // an error bound that reaches the midpoint is uncertain; one that stops short is not
  CHECK_THROWS_AS(Bounded2::within(1.0, 0x1p-64 + 0x1p-100, 0x1p-99).rounded_long_double(), cdref::uncertain);
  CHECK(Bounded2::within(1.0, 0x1p-64 + 0x1p-100, 0x1p-102).rounded_long_double() == up);
  // below a power of two the gap halves: 1 - 2^-65 is the midpoint between 1 - 2^-64 and 1
  CHECK_THROWS_AS(Bounded2::exact_pair(1.0, -0x1p-65).rounded_long_double(), cdref::uncertain);
  CHECK(Bounded2::exact_pair(1.0, -0x1p-65 + 0x1p-118).rounded_long_double() == 1.0L);
  CHECK(Bounded2::exact_pair(1.0, -0x1p-65 - 0x1p-117).rounded_long_double() == 1.0L - std::ldexp(1.0L, -64));
  // negative values, zero, and the ends of the range it takes
  CHECK(Bounded2::exact_pair(-1.0, -0x1p-64 - 0x1p-116).rounded_long_double() == -up);
  CHECK(std::signbit(Bounded2(0.0).rounded_long_double()) == false);
  CHECK(Bounded2(0x1p-899).rounded_long_double() == std::ldexp(1.0L, -899));
  CHECK_THROWS_AS(Bounded2(0x1p-1000).rounded_long_double(), cdref::uncertain);
  CHECK_THROWS_AS(Bounded2(0x1p1010).rounded_long_double(), cdref::uncertain);
}

TEST_CASE("cdref::Bounded2 certifies square roots that the double filter cannot", "[rounding][oracle]") {
  // sqrt(2): the double filter's bound is an ulp or so, too wide to round; the double word
  // is 2^-100 close and rounds it.
  CHECK_THROWS_AS(cdref::Bounded::root(cdref::Bounded(2.0)).rounded(), cdref::uncertain);
  CHECK(Bounded2::root(Bounded2(2.0)).rounded() == std::sqrt(2.0));
  // a square root exactly between two floats is a tie: uncertain, never guessed
  const double mid = 1.0 + std::ldexp(1.0, -24);  // halfway between 1 and 1 + 2^-23
  CHECK((Bounded2(mid) * Bounded2(mid)).rounded() == mid * mid);  // 49 bits: exact
  CHECK_THROWS_AS(Bounded2::root(Bounded2(mid) * Bounded2(mid)).rounded_float(), cdref::uncertain);
  CHECK(Bounded2::root(Bounded2(mid) * Bounded2(mid)).rounded() == mid);
}

TEST_CASE("GMP's block cache: installed, exact sizes kept, contents moved, threads and their ends", "[rounding][gmp-pool]") {
  namespace gp = cdref::exact::gmp_pool_detail;
  // tests/main.cpp's listener installs it when the run starts, as cdref's main does (and sets
  // MPFR's default precision)
  REQUIRE(mpfr::mpreal::get_default_prec() == 128);
  void* (*a)(std::size_t) = nullptr;
  void* (*r)(void*, std::size_t, std::size_t) = nullptr;
  void (*f)(void*, std::size_t) = nullptr;
  mp_get_memory_functions(&a, &r, &f);
  REQUIRE(a == &gp::allocate);
  REQUIRE(r == &gp::reallocate);
  REQUIRE(f == &gp::release);
  // cached sizes: multiples of 8 up to 256, and only those
  REQUIRE(gp::class_of(8) == 0);
  REQUIRE(gp::class_of(256) == 31);
  REQUIRE(gp::class_of(0) == -1);
  REQUIRE(gp::class_of(12) == -1);
  REQUIRE(gp::class_of(264) == -1);
  // a freed block comes back for a request of its own size, never for another
  void* p = gp::allocate(40);
  gp::release(p, 40);
  void* q = gp::allocate(48);
  REQUIRE(q != p);
  REQUIRE(gp::allocate(40) == p);
  gp::release(q, 48);
  // realloc keeps the contents across sizes, cached or not
  for (std::size_t from : {8u, 24u, 100u, 256u, 1000u})
    for (std::size_t to : {16u, 40u, 256u, 300u, 4096u}) {
      auto* b = static_cast<unsigned char*>(gp::allocate(from));
      for (std::size_t i = 0; i < from; ++i) b[i] = static_cast<unsigned char>(i * 7 + from);
      auto* c = static_cast<unsigned char*>(gp::reallocate(b, from, to));
      for (std::size_t i = 0; i < std::min(from, to); ++i) REQUIRE(c[i] == static_cast<unsigned char>(i * 7 + from));
      gp::release(c, to);
    }
  gp::release(p, 40);
  // threads compute, hand their numbers to this thread and end; this thread frees them
  auto harmonic = [](int n) {
    mpq_class s = 0;
    for (int k = 1; k <= n; ++k) s += mpq_class(1, k);
    return s;
  };
  const mpq_class expected = harmonic(300);
  std::vector<mpq_class> got(4);
  std::vector<std::thread> ts;
  for (int t = 0; t < 4; ++t) ts.emplace_back([&, t] { got[t] = harmonic(300); });
  for (auto& t : ts) t.join();
  for (const auto& g : got) REQUIRE(g == expected);
  got.clear();  // blocks allocated by ended threads, freed here
  REQUIRE(harmonic(300) == expected);
}

}  // namespace cdref_test_rounding
