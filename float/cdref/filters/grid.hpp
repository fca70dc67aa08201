// cdref/filters/grid.hpp - double inputs as integers on a grid, one grid a coordinate axis, and
// exact signs of polynomials in them: the exact looks of the oracles' first stages
// (triangle_filter.hpp for the casts on a triangle, sat_grid.hpp for a triangle and a box).
//
// A finite double is m 2^e with m an odd integer (or 0); 2^e is the coarsest grid it lies on.
// The values one axis carries (the x coordinates of every point, and every length measured
// along x) lie on the coarsest grid 2^G they share, G the smallest of their e: x_j = n_j 2^G
// with n_j an integer, read off the bits, so that nothing rounds and subnormals are no
// exception. A polynomial whose every monomial takes one factor from each of the axes it
// involves (a cross product's component takes one from each of the other two axes, a triple
// product one from each of the three) is the same polynomial in the n's scaled by a positive
// constant, 2^-(G_0 + G_1 + G_2) or the part of it its axes name: its sign is the integer
// polynomial's. Each n_j is kept below 2^62 (an axis whose values span more, 1e12 beside 0.1,
// is on no grid narrow enough), so a difference of two fits in an int64, a product of two
// differences in 127 bits, and a product of three in 190: the sums of those are taken in
// 256-bit two's complement (Sum256).
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>

#include <cdref/vec.hpp>

namespace cdref::filters::grid {

using Wide = __int128;
using UWide = unsigned __int128;

struct Dyadic {
  std::int64_t m = 0;
  int e = 0;
};
// A finite double as m 2^e with m odd, or m = 0.
inline Dyadic dyadic(double x) {
  const std::uint64_t b = std::bit_cast<std::uint64_t>(x);
  const int biased = int((b >> 52) & 0x7ff);
  std::uint64_t mant = b & ((std::uint64_t(1) << 52) - 1);
  if (biased != 0) mant |= std::uint64_t(1) << 52;  // a subnormal has no implicit bit
  if (mant == 0) return {};
  const int tz = std::countr_zero(mant);
  mant >>= tz;
  const int e = (biased == 0 ? -1074 : biased - 1075) + tz;
  return {(b >> 63) ? -std::int64_t(mant) : std::int64_t(mant), e};
}

// One axis's values as integers on the coarsest grid 2^G they share: n_j = x_j 2^-G exactly.
// false where one is not finite or where an n_j needs more than `bits` bits (the axis's values
// span more, from the largest's top bit to the finest's lowest): 62 for an int64, so that a
// difference of two fits in one; up to 125 for a 128-bit integer, whose differences the caller
// checks (a box 10^12 from the origin with extents near 1: the coordinates span about 96 bits
// on the extents' grid, their differences far fewer). `grid` is G, or no_grid where every value
// is 0 (any grid does).
inline constexpr int no_grid = 1 << 20;
template <int N, class I = std::int64_t>
bool axis_on_grid(const double (&x)[N], I (&n)[N], int& grid, int bits = 62) {
  Dyadic d[N];
  grid = no_grid;
  for (int j = 0; j < N; ++j) {
    if (!(std::fabs(x[j]) <= std::numeric_limits<double>::max())) return false;  // NaN, infinities
    d[j] = dyadic(x[j]);
    if (d[j].m != 0) grid = std::min(grid, d[j].e);
  }
  for (int j = 0; j < N; ++j) {
    n[j] = 0;
    if (d[j].m == 0) continue;
    const int shift = d[j].e - grid;  // >= 0
    if (int(std::bit_width(std::uint64_t(std::llabs(d[j].m)))) + shift > bits) return false;
    n[j] = I(d[j].m) * (I(1) << shift);
  }
  return true;
}
// x as an int64 where |x| < 2^62 (a difference of two such then fits in 63 bits)
inline bool narrow(Wide x, std::int64_t& out) {
  if (x <= -(Wide(1) << 62) || x >= (Wide(1) << 62)) return false;
  out = std::int64_t(x);
  return true;
}

// A ray's direction on grids of its own, 2^(G_i + delta) on axis i with one delta for the three:
// every monomial of d . (A x B) takes d from one axis and A, B from the other two, so each is
// scaled by 2^-(delta + G_0 + G_1 + G_2), the same positive factor. delta is the largest that
// keeps every d_i an integer (a unit direction beside coordinates 10^6 from the origin has bits
// far below their grid). false where a d_i would need more than 62 bits (its axes' grids too far
// apart for the direction's spread), where it is not finite, or where it is zero. An axis whose
// positions are all 0 (no grid) takes d_i's own.
inline bool direction_on_grid(const Vec3<double>& dir, int (&grid)[3], std::int64_t (&d)[3]) {
  Dyadic q[3];
  int delta = no_grid;
  for (int i = 0; i < 3; ++i) {
    if (!(std::fabs(dir[i]) <= std::numeric_limits<double>::max())) return false;
    q[i] = dyadic(dir[i]);
    if (q[i].m == 0) continue;
    if (grid[i] == no_grid) grid[i] = q[i].e;
    delta = std::min(delta, q[i].e - grid[i]);
  }
  if (delta == no_grid) return false;
  for (int i = 0; i < 3; ++i) {
    d[i] = 0;
    if (q[i].m == 0) continue;
    const int shift = q[i].e - grid[i] - delta;  // >= 0
    if (std::bit_width(std::uint64_t(std::llabs(q[i].m))) + shift > 62) return false;
    d[i] = q[i].m * (std::int64_t(1) << shift);
  }
  return true;
}

// A sum of products, each x a (x a signed 128-bit integer below 2^127 in magnitude, a an int64:
// below 2^190, a 192-bit magnitude from two 64 x 64 -> 128-bit products) or x y (both 128-bit:
// below 2^254, from four), added to or subtracted from a 256-bit two's-complement sum, exact
// while the sum stays below 2^255. add, add_product and the accumulation beneath them are always
// inlined: in a unit where many grid evaluations call them, g++ kept them out of line, and the
// triangle casts' grid decision (ray_triangle's exact_eval::settle) took 1.2 times as long.
struct Sum256 {
  std::uint64_t acc[4] = {0, 0, 0, 0};
  // + x a
  [[gnu::always_inline]] void add(Wide x, std::int64_t a) {
    if (x == 0 || a == 0) return;
    const UWide mx = x < 0 ? UWide(-x) : UWide(x);  // |x| < 2^127: -x does not overflow
    const std::uint64_t ma = a < 0 ? -std::uint64_t(a) : std::uint64_t(a);
    const UWide lo = UWide(std::uint64_t(mx)) * ma, hi = UWide(std::uint64_t(mx >> 64)) * ma;
    const UWide mid = (lo >> 64) + std::uint64_t(hi);
    const std::uint64_t m[4] = {std::uint64_t(lo), std::uint64_t(mid), std::uint64_t(mid >> 64) + std::uint64_t(hi >> 64),
                                0};
    accumulate(m, (x < 0) != (a < 0));
  }
  // + x y, both below 2^127 in magnitude (the product below 2^254: a few of them stay below 2^255)
  [[gnu::always_inline]] void add_product(Wide x, Wide y) {
    if (x == 0 || y == 0) return;
    const UWide mx = x < 0 ? UWide(-x) : UWide(x), my = y < 0 ? UWide(-y) : UWide(y);
    const std::uint64_t x0 = std::uint64_t(mx), x1 = std::uint64_t(mx >> 64);
    const std::uint64_t y0 = std::uint64_t(my), y1 = std::uint64_t(my >> 64);
    const UWide p00 = UWide(x0) * y0, p01 = UWide(x0) * y1, p10 = UWide(x1) * y0, p11 = UWide(x1) * y1;
    std::uint64_t m[4];
    m[0] = std::uint64_t(p00);
    UWide t = (p00 >> 64) + std::uint64_t(p01) + std::uint64_t(p10);  // below 3 2^64
    m[1] = std::uint64_t(t);
    t = (t >> 64) + (p01 >> 64) + (p10 >> 64) + std::uint64_t(p11);
    m[2] = std::uint64_t(t);
    m[3] = std::uint64_t((t >> 64) + (p11 >> 64));
    accumulate(m, (x < 0) != (y < 0));
  }
  int sign() const {
    if (std::int64_t(acc[3]) < 0) return -1;
    return (acc[0] | acc[1] | acc[2] | acc[3]) != 0 ? 1 : 0;
  }

 private:
  // acc +- m, limb by limb with the carry or borrow
  [[gnu::always_inline]] void accumulate(const std::uint64_t (&m)[4], bool neg) {
    UWide carry = 0;
    for (int l = 0; l < 4; ++l) {
      if (!neg) {
        const UWide t = UWide(acc[l]) + m[l] + carry;
        acc[l] = std::uint64_t(t);
        carry = t >> 64;
      } else {
        const UWide t = UWide(acc[l]) - m[l] - carry;
        acc[l] = std::uint64_t(t);
        carry = (t >> 64) != 0;  // a borrow wraps the high half
      }
    }
  }
};

}  // namespace cdref::filters::grid
