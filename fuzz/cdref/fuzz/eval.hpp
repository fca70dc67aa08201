// cdref/fuzz/eval.hpp - one query of the campaign engine evaluated by the book at number
// type T, with the values reported as the IEEE type F would hold them (exact types round
// correctly to F). Used for the implementations under test, the truth, and the fuzz
// targets' cross-checks.
#pragma once

#include <cdref/exact.hpp>
#include <cdref/exact/long_double.hpp>
#include <cdref/oracle/bounded.hpp>
#include <cdref/oracle/bounded2.hpp>
#include <cdref/fuzz/campaign.hpp>

namespace cdref::fuzz {

namespace detail {

template <class T>
Vec3<T> v3(const Inputs& in, int k) {
  return Vec3<T>(T(in[k]), T(in[k + 1]), T(in[k + 2]));
}

// A value of the sqrt type S as the implementation of type F reports it (exact values
// rounded correctly to F).
template <class F, class S>
long double value(const S& x) {
  if constexpr (std::is_same_v<S, oracle::Bounded> || std::is_same_v<S, oracle::Bounded2>) {
    // the filters: certain, or they throw
    if constexpr (std::is_same_v<F, float>)
      return x.rounded_float();
    else if constexpr (std::is_same_v<F, double>)
      return x.rounded();
    else
      throw oracle::uncertain();  // a double filter cannot certify a long double
  } else if constexpr (!number_traits<S>::is_exact)
    return static_cast<long double>(x);
  else if constexpr (std::is_same_v<F, long double>)
    return exact::round_long_double(x);
  else
    return static_cast<long double>(round_to<F>(x));
}

template <class F, class S>
void put_cast(Answer& a, const Cast<S>& c, bool values = true) {
  a.cls = c.hit;
  if (!values) return;
  a.v[0] = value<F>(c.lambda_enter);
  a.v[1] = value<F>(c.lambda_exit);
  for (int i = 0; i < 3; ++i) {
    a.v[2 + i] = value<F>(c.point[i]);
    a.v[5 + i] = value<F>(c.normal[i]);
  }
}

template <class F, class S>
void put_prox(Answer& a, const Proximity<S>& p, bool values = true) {
  a.cls = p.intersect;
  if (!values) return;
  a.v[0] = value<F>(p.distance);
  a.v[1] = value<F>(p.depth);
  for (int i = 0; i < 3; ++i) {
    a.v[2 + i] = value<F>(p.on_a[i]);
    a.v[5 + i] = value<F>(p.on_b[i]);
  }
}

}  // namespace detail

// The book at number type T on the inputs (converted to T), values reported as F.
// With values = false only the two classifications are computed (no root, no rounding).
template <class T, class F>
Answer eval(Query q, const Inputs& in, bool values = true) {
  const unsigned wc = values ? want_cast : 0u, wp = values ? want_proximity : 0u;
  Answer a;
  switch (q) {
    case Query::sphere_sphere: {
      const Sphere<T> A{detail::v3<T>(in, 0), T(in[3])}, B{detail::v3<T>(in, 4), T(in[7])};
      detail::put_prox<F>(a, book::proximity(A, B, wp), values);
      a.pred = book::intersect(A, B);
      break;
    }
    case Query::segment_sphere_cast: {
      const Segment<T> s{detail::v3<T>(in, 0), detail::v3<T>(in, 3)};
      const Sphere<T> sp{detail::v3<T>(in, 6), T(in[9])};
      detail::put_cast<F>(a, book::cast(s, sp, wc), values);
      a.pred = book::hit(s, sp);
      break;
    }
    case Query::ray_sphere_cast: {
      const Ray<T> r{detail::v3<T>(in, 0), detail::v3<T>(in, 3)};
      const Sphere<T> sp{detail::v3<T>(in, 6), T(in[9])};
      detail::put_cast<F>(a, book::cast(r, sp, wc), values);
      a.pred = book::hit(r, sp);
      break;
    }
    case Query::segment_sphere: {
      const Segment<T> s{detail::v3<T>(in, 0), detail::v3<T>(in, 3)};
      const Sphere<T> sp{detail::v3<T>(in, 6), T(in[9])};
      detail::put_prox<F>(a, book::proximity(s, sp, wp), values);
      a.pred = book::intersect(s, sp);
      break;
    }
    case Query::box_box: {
      const Box<T> A{detail::v3<T>(in, 0), detail::v3<T>(in, 3)}, B{detail::v3<T>(in, 6), detail::v3<T>(in, 9)};
      a.cls = book::intersect(A, B);
      a.pred = book::intersect(to_min_max(A), to_min_max(B));
      break;
    }
    case Query::segment_box_cast: {
      const Segment<T> s{detail::v3<T>(in, 0), detail::v3<T>(in, 3)};
      const Box<T> b{detail::v3<T>(in, 6), detail::v3<T>(in, 9)};
      detail::put_cast<F>(a, book::cast(s, b, wc), values);
      a.pred = book::hit(s, b);
      break;
    }
    case Query::ray_box_cast: {
      const Ray<T> r{detail::v3<T>(in, 0), detail::v3<T>(in, 3)};
      const Box<T> b{detail::v3<T>(in, 6), detail::v3<T>(in, 9)};
      detail::put_cast<F>(a, book::cast(r, b, wc), values);
      a.pred = book::hit(r, b);
      break;
    }
    case Query::sphere_box: {
      const Sphere<T> sp{detail::v3<T>(in, 0), T(in[3])};
      const Box<T> b{detail::v3<T>(in, 4), detail::v3<T>(in, 7)};
      detail::put_prox<F>(a, book::proximity(sp, b, wp), values);
      a.pred = book::intersect(sp, b);
      break;
    }
  }
  return a;
}

}  // namespace cdref::fuzz
