/// \file
/// cdref/truth/basics.hpp - what <cdref/truth.hpp>'s functions share, without their
/// declarations: the Path of an answer, the result type of a classification alone, and the tools
/// that compare an answer with the truth (Deviation, ulp_distance, scale_of, compare,
/// first_difference). The library's units that define the functions include this header, not
/// truth.hpp: adding a query's declarations to truth.hpp recompiles what calls them, not every
/// query group.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "../error.hpp"
#include "../fan.hpp"
#include "../fields.hpp"
#include "../primitives.hpp"
#include "../results.hpp"

namespace cdref::truth {

/// How the answer is computed: both give the same, correctly rounded answer.
enum class Path {
  oracle,  ///< the fast exact oracle: filters with proven bounds, exact arithmetic where they cannot decide
  exact,   ///< the book's algorithm at CGAL::Gmpq on every input (slower; for cross-checking the oracle)
};

namespace detail {
/// The result type of the queries whose answer is a classification alone.
template <class>
using Bool = bool;
/// A proximity result with its witnesses exchanged (the other argument order).
template <class S>
Proximity<S> swapped(Proximity<S> p) {
  std::swap(p.on_a, p.on_b);
  return p;
}
}  // namespace detail

/// ---- comparing an answer with the truth ----
/// How far a value is from the truth, three ways.
struct Deviation {
  /// Representable values of the caller's type between the value and the truth (0: equal;
  /// saturates at 2^64 - 1; the maximum when either is not finite and they differ).
  std::uint64_t ulps = 0;
  /// |value - truth|, rounded to double.
  double abs = 0;
  /// abs / scale: the error relative to the inputs' scale (see scale_of), so that 1e-15 against
  /// an exact 0 reads as what it is and not as 10^18 ulps.
  double rel = 0;
};

/// The ulps between two values of F (float or double): how many representable values lie
/// between them, counting one of the ends. 0 and -0 are equal.
template <class F>
std::uint64_t ulp_distance(F a, F b) {
  static_assert(std::is_same_v<F, float> || std::is_same_v<F, double>, "ulps of float or double");
  if (a == b) return 0;
  if (!(std::isfinite(a) && std::isfinite(b))) return std::numeric_limits<std::uint64_t>::max();
  using I = std::conditional_t<std::is_same_v<F, float>, std::int32_t, std::int64_t>;
  using U = std::conditional_t<std::is_same_v<F, float>, std::uint32_t, std::uint64_t>;
  // the bit patterns mapped to a line: negative values below 0, in order
  const auto line = [](F x) {
    I i;
    std::memcpy(&i, &x, sizeof i);
    return i < 0 ? I(std::numeric_limits<I>::min() - i) : i;
  };
  const I x = line(a), y = line(b);
  return x > y ? std::uint64_t(U(x) - U(y)) : std::uint64_t(U(y) - U(x));
}

/// The deviation of `value` from `truth` (both of the caller's type F), `scale` the magnitude
/// the relative error is taken against (a positive number; scale_of gives the inputs').
template <class F>
Deviation deviation(F value, F truth, double scale) {
  Deviation d;
  d.ulps = ulp_distance(value, truth);
  d.abs = double(std::fabs(static_cast<long double>(value) - static_cast<long double>(truth)));
  d.rel = scale > 0 ? d.abs / scale : d.abs;
  return d;
}

/// The inputs' scale: the largest magnitude among the primitives' coordinates and lengths
/// (radius, extents), at least the smallest normal number. A coordinate's error relative to it
/// is the error as a fraction of the scene's size.
template <class A, class B>
double scale_of(const A& a, const B& b) {
  double s = std::numeric_limits<double>::min();
  const auto take = [&s](const auto& m) {
    using M = std::remove_cvref_t<decltype(m)>;
    if constexpr (std::is_same_v<M, int> || std::is_same_v<M, bool>) {
    } else if constexpr (requires { m.rows(); }) {
      for (int i = 0; i < 3; ++i) s = std::fmax(s, std::fabs(double(m[i])));
    } else if constexpr (requires { m.size(); m[0]; }) {
      for (const auto& v : m)
        for (int i = 0; i < 3; ++i) s = std::fmax(s, std::fabs(double(v[i])));
    } else {
      s = std::fmax(s, std::fabs(double(m)));
    }
  };
  // (through a copy at double: a polygon's or a fan's unused vertices are zero there)
  const auto da = rebind<double>(a);
  const auto db = rebind<double>(b);
  std::apply([&](const auto&... m) { (take(m), ...); }, members(da));
  std::apply([&](const auto&... m) { (take(m), ...); }, members(db));
  return s;
}

/// One field's comparison (compare's rows).
struct FieldDeviation {
  std::string field;   ///< the answer column's name ("lambda_enter", "point", ...)
  int component = 0;   ///< 0, 1, 2 for a vector's x, y, z; 0 otherwise
  double value = 0;    ///< the answer's value
  double truth = 0;    ///< the truth's value
  Deviation error;     ///< how far apart (a flag or an index: ulps 0 or 1, abs the same)
};

/// Every field of `mine` against `truth` (results of one kind at the caller's type, from the
/// same inputs a and b), each with its error in ulps, absolute and relative to its natural
/// scale: the inputs' scale (scale_of) for points, distances and depths; 1 for lambda on a
/// segment, a normal, u and v; the inputs' scale over the largest direction component for
/// lambda on a ray. Only fields where the truth's classification gives them meaning are listed
/// (a cast's values on a hit, a separating axis when apart), and for those only where both
/// classifications agree; the classification itself is the first row.
template <class R, class A, class B>
std::vector<FieldDeviation> compare(const R& mine, const R& truth, const A& a, const B& b) {
  std::vector<FieldDeviation> out;
  if constexpr (std::is_same_v<R, bool>) {
    const double d = mine == truth ? 0 : 1;
    out.push_back({"intersect", 0, double(mine), double(truth), {std::uint64_t(d), d, d}});
    return out;
  }
  const double scene = scale_of(a, b);
  double lambda_scale = 1;
  if constexpr (std::is_same_v<A, Ray<float>> || std::is_same_v<A, Ray<double>>) {
    const double dmax = std::fmax(std::fabs(double(a.direction[0])),
                                  std::fmax(std::fabs(double(a.direction[1])), std::fabs(double(a.direction[2]))));
    lambda_scale = scene / dmax;
  }
  const bool agree = classification_of(mine) == classification_of(truth);
  const bool positive = classification_of(truth);
  if constexpr (!std::is_same_v<R, bool>) zip_fields(mine, truth, [&](const char* name, const auto& x, const auto& y) {
    using M = std::remove_cvref_t<decltype(x)>;
    const std::string f = name;
    const bool is_class = f == "hit" || f == "intersect";
    if (!is_class) {
      if (!agree) return;
      const bool on_hit_only = f == "lambda_enter" || f == "lambda_exit" || f == "point" || f == "normal" ||
                               f == "u" || f == "v" || f == "enters" || f == "unbounded_exit";
      if (on_hit_only && !positive) return;
      if ((f == "axis" || f == "direction") && positive) return;
    }
    if constexpr (std::is_same_v<M, bool> || std::is_same_v<M, int>) {
      const double d = x == y ? 0 : 1;
      out.push_back({f, 0, double(x), double(y), {std::uint64_t(d), d, d}});
    } else if constexpr (requires { x.rows(); }) {
      double s = scene;
      if (f == "normal") s = 1;
      if (f == "direction") {
        s = std::numeric_limits<double>::min();
        for (int i = 0; i < 3; ++i) s = std::fmax(s, std::fabs(double(y[i])));
      }
      for (int i = 0; i < 3; ++i) out.push_back({f, i, double(x[i]), double(y[i]), deviation(x[i], y[i], s)});
    } else {
      double s = scene;
      if (f == "lambda_enter" || f == "lambda_exit") s = lambda_scale;
      if (f == "u" || f == "v") s = 1;
      out.push_back({f, 0, double(x), double(y), deviation(x, y, s)});
    }
  });
  return out;
}

/// The first field in which two results of one kind differ, as "name: value, value" (vectors
/// as "point_y: ..."; values in hex-float); "" when every field is equal bit for bit (so 0 and
/// -0 differ).
template <class R>
std::string first_difference(const R& x, const R& y) {
  const auto show = [](double v) {
    char b[40];
    std::snprintf(b, sizeof b, "%a", v);
    return std::string(b);
  };
  const auto same = [](const auto& u, const auto& v) {
    if constexpr (std::is_floating_point_v<std::remove_cvref_t<decltype(u)>>)
      return std::memcmp(&u, &v, sizeof u) == 0;
    else
      return u == v;
  };
  std::string diff;
  if constexpr (std::is_same_v<R, bool>) {
    if (x != y) diff = std::string("intersect: ") + (x ? "1" : "0") + ", " + (y ? "1" : "0");
  } else {
    zip_fields(x, y, [&](const char* name, const auto& u, const auto& v) {
      if (!diff.empty()) return;
      using M = std::remove_cvref_t<decltype(u)>;
      if constexpr (requires { u.rows(); }) {
        for (int i = 0; i < 3 && diff.empty(); ++i)
          if (!same(u[i], v[i]))
            diff = std::string(name) + "_" + "xyz"[i] + ": " + show(double(u[i])) + ", " + show(double(v[i]));
      } else if constexpr (std::is_same_v<M, bool> || std::is_same_v<M, int>) {
        if (u != v) diff = std::string(name) + ": " + std::to_string(u) + ", " + std::to_string(v);
      } else if (!same(u, v)) {
        diff = std::string(name) + ": " + show(double(u)) + ", " + show(double(v));
      }
    });
  }
  return diff;
}

}  // namespace cdref::truth
