// src/scene/engine.hpp - a scene run over the number type T (float, double, CGAL::Gmpq).
//
// Per frame k = 0 .. frames:
//   1. positions: at float and double p_k = p_{k-1} + v dt (keyframes: t_k = t_{k-1} + dt
//      and linear interpolation, both in T), as an engine integrates; at an exact T,
//      p_k = p_0 + v (k dt) and t_k = k dt exactly;
//   2. the broad phase: sweep and prune on x over the bodies' axis-aligned bounds (grown by
//      the proximity thresholds that concern them, and swept over the step for bodies in a
//      time-of-impact effect); only the pairs it reports reach an effect;
//   3. each effect on its reported pairs, evaluating only what it needs:
//        trigger        the boolean test (book::intersect: no root, no division it can avoid)
//        contact        the boolean test, then book::proximity only where it says overlap
//        proximity      book::proximity (distance against the threshold)
//        time-of-impact the space-time test of Section 3.1.2: the relative motion of the
//                       step cast on the configuration space obstacle (sphere: the sphere of
//                       the summed radii; box and triangle: the shape grown by the radius, cast
//                       part by part, see sweep_box and sweep_triangle), only for pairs whose
//                       swept bounds overlap;
//      and each raycast effect: the sensor's cast against each target whose bounds it hits.
// A mesh is its triangles, each behind a bounds test (the mid-phase). At an exact T the
// oriented boxes go through cdref::solid (the truth for any independent axes); at float and
// double through the book, which takes the axes as orthonormal, as engines do.
#pragma once

#include <algorithm>
#include <cdref/book/box_box.hpp>
#include <cdref/book/obb.hpp>
#include <cdref/book/ray_box.hpp>
#include <cdref/book/ray_sphere.hpp>
#include <cdref/book/ray_triangle.hpp>
#include <cdref/book/sphere_box.hpp>
#include <cdref/book/sphere_sphere.hpp>
#include <cdref/book/sphere_triangle.hpp>
#include <cdref/book/triangle_box.hpp>
#include <cdref/book/triangle_triangle.hpp>
#include <cdref/book/obb_obb.hpp>
#include <cdref/solid/obb.hpp>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <set>

#include "scene.hpp"

namespace cdref::scene::engine {

// The sign of x - y; for values of different quadratic fields (exact square roots) the
// exact types provide compare_fields, found by argument-dependent lookup.
template <class S>
int cmp(const S& x, const S& y) {
  if constexpr (std::is_floating_point_v<S>) {
    return x < y ? -1 : (y < x ? 1 : 0);
  } else {
    return compare_fields(x, y);
  }
}

template <class T>
struct Bounds {
  Vec3<T> lo, hi;
  void add(const Bounds& o) {
    for (int i = 0; i < 3; ++i) {
      if (o.lo[i] < lo[i]) lo[i] = o.lo[i];
      if (hi[i] < o.hi[i]) hi[i] = o.hi[i];
    }
  }
  bool meets(const Bounds& o) const {
    for (int i = 0; i < 3; ++i)
      if (hi[i] < o.lo[i] || o.hi[i] < lo[i]) return false;
    return true;
  }
  Box<T> box() const { return to_center_extent(MinMaxBox<T>{lo, hi}); }
};

template <class T>
Vec3<T> v3(const V3& v) {
  return Vec3<T>(T(v[0]), T(v[1]), T(v[2]));
}
template <class S>
double dbl(const S& x) {
  return number_traits<S>::to_double(x);
}
template <class S>
void push3(std::vector<double>& out, const Vec3<S>& v) {
  for (int i = 0; i < 3; ++i) out.push_back(dbl(v[i]));
}

// The first hit of a segment s + lambda d (lambda in [0, 1]) on the lateral surface of the
// cylinder of radius r around the segment a b, entering from outside the infinite cylinder
// with its foot between a and b. Entries through the caps are the spheres' (see sweep_*).
template <class T>
std::optional<sqrt_t<T>> cylinder_entry(const Vec3<T>& s, const Vec3<T>& d, const Vec3<T>& a, const Vec3<T>& b,
                                        const T& r) {
  using S = sqrt_t<T>;
  const Vec3<T> e = b - a, w = s - a;
  const T ee = e.dot(e);
  if (ee == T(0)) return std::nullopt;
  // perpendicular parts scaled by ee: wp = w ee - (w.e) e, dp = d ee - (d.e) e
  const Vec3<T> wp = w * ee - e * w.dot(e), dp = d * ee - e * d.dot(e);
  const T A = dp.dot(dp), B = wp.dot(dp), C = wp.dot(wp) - r * r * ee * ee;
  if (A == T(0) || !(C > T(0))) return std::nullopt;  // parallel to the axis, or starting inside
  const T disc = B * B - A * C;
  if (disc < T(0)) return std::nullopt;
  const S lambda = (S(-B) - root(disc)) / S(A);
  if (lambda < S(0) || S(1) < lambda) return std::nullopt;
  const S foot = S(w.dot(e)) + lambda * S(d.dot(e));
  if (foot < S(0) || S(ee) < foot) return std::nullopt;
  return lambda;
}

template <class S>
void take(std::optional<S>& best, const S& x) {
  if (!best || cmp(x, *best) < 0) best = x;
}
template <class T, class C>
void take_cast(std::optional<sqrt_t<T>>& best, const C& c) {
  using S = sqrt_t<T>;
  if (c.hit) take(best, S(c.lambda_enter));
}

// A sphere of radius r moving from s to s + d against a box: the first lambda in [0, 1] at
// which they touch, on the box grown by r, i.e. the union of the box grown along one axis
// (three boxes), the cylinders of radius r around its 12 edges and the spheres of radius r
// at its 8 corners: the union's first entry is the earliest entry of its parts. nullopt: no
// touch within the step; 0: touching at the start.
template <class T>
std::optional<sqrt_t<T>> sweep_box(const Vec3<T>& s, const Vec3<T>& d, const Box<T>& b, const T& r,
                                   std::uint64_t& parts) {
  using S = sqrt_t<T>;
  if (book::intersect(Sphere<T>{s, r}, b)) return S(0);
  const Segment<T> seg{s, Vec3<T>(s + d)};
  std::optional<S> best;
  for (int i = 0; i < 3; ++i) {
    Box<T> g = b;
    g.extent[i] += r;
    take_cast<T>(best, book::cast(seg, g, want_lambda_enter));
  }
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    for (int sj : {-1, 1})
      for (int sk : {-1, 1}) {
        Vec3<T> a = b.center, c = b.center;
        a[j] += T(sj) * b.extent[j];
        a[k] += T(sk) * b.extent[k];
        c[j] = a[j];
        c[k] = a[k];
        a[i] -= b.extent[i];
        c[i] += b.extent[i];
        if (auto l = cylinder_entry(s, d, a, c, r)) take(best, *l);
      }
  }
  for (int m = 0; m < 8; ++m) {
    Vec3<T> corner = b.center;
    for (int i = 0; i < 3; ++i) corner[i] += ((m >> i) & 1) ? b.extent[i] : T(-b.extent[i]);
    take_cast<T>(best, book::cast(seg, Sphere<T>{corner, r}, want_lambda_enter));
  }
  parts += 3 + 12 + 8;
  return best;
}

// The same against a triangle: the prism of the triangle thickened by r on both sides
// (clipped by its five planes; the offset r |n| brings the root of n.n), the three edge
// cylinders and the three vertex spheres. A zero-area triangle has no prism: its capsules
// are the whole grown set.
template <class T>
std::optional<sqrt_t<T>> sweep_triangle(const Vec3<T>& s, const Vec3<T>& d, const Triangle<T>& t, const T& r,
                                        std::uint64_t& parts) {
  using S = sqrt_t<T>;
  if (book::intersect(Sphere<T>{s, r}, t)) return S(0);
  const Segment<T> seg{s, Vec3<T>(s + d)};
  std::optional<S> best;
  const Vec3<T> n = (t.vertex[1] - t.vertex[0]).cross(t.vertex[2] - t.vertex[0]);
  const T nn = n.dot(n);
  if (nn != T(0)) {
    // planes m.(x - v0) <= o, clipped over lambda in [0, 1]; relative to v0, so that a
    // triangle far from the origin does not cancel its plane offsets at float
    const Vec3<T> w(s - t.vertex[0]);
    S lo(0), hi(1);
    bool empty = false;
    auto clip = [&](const Vec3<T>& m, const S& o) {
      const T md = m.dot(d);
      const S gap = o - S(m.dot(w));
      if (md == T(0)) {
        if (gap < S(0)) empty = true;
      } else if (md > T(0)) {
        const S l = gap / S(md);
        if (l < hi) hi = l;
      } else {
        const S l = gap / S(md);
        if (lo < l) lo = l;
      }
    };
    const S off = S(r) * root(nn);
    clip(n, off);
    clip(Vec3<T>(-n), off);
    for (int i = 0; i < 3; ++i) {
      const Vec3<T> m = (t.vertex[(i + 1) % 3] - t.vertex[i]).cross(n);  // outward for the winding of n
      clip(m, S(m.dot(Vec3<T>(t.vertex[i] - t.vertex[0]))));
    }
    if (!empty && lo <= hi) take(best, lo);
  }
  for (int i = 0; i < 3; ++i) {
    if (auto l = cylinder_entry(s, d, t.vertex[i], t.vertex[(i + 1) % 3], r)) take(best, *l);
    take_cast<T>(best, book::cast(seg, Sphere<T>{t.vertex[i], r}, want_lambda_enter));
  }
  parts += 1 + 3 + 3;
  return best;
}

template <class T>
class Engine {
 public:
  using S = sqrt_t<T>;
  static constexpr bool exact = is_exact_v<T>;

  Engine(const Scene& sc, Precision p) : s_(sc), n_(int(sc.bodies.size())) {
    run_.precision = p;
    if constexpr (!exact) representable(sc);
    dt_ = T(sc.time_step);
    pos_.resize(n_);
    prev_.resize(n_);
    vel_.resize(n_);
    time_ = T(0);
    for (int i = 0; i < n_; ++i) {
      pos_[i] = v3<T>(sc.bodies[i].position);
      vel_[i] = v3<T>(sc.bodies[i].velocity);
    }
    in_a_.assign(sc.effects.size(), std::vector<char>(n_, 0));
    in_b_ = in_a_;
    margin_.assign(n_, T(0));
    swept_.assign(n_, 0);
    used_.assign(n_, 0);
    for (std::size_t e = 0; e < sc.effects.size(); ++e) {
      const Effect& ef = sc.effects[e];
      for (const auto* side : {&ef.a, &ef.b})
        for (int x : *side) {
          (side == &ef.a ? in_a_ : in_b_)[e][x] = 1;
          if (ef.kind == EffectKind::raycast) continue;  // sensors test their targets' bounds
          used_[x] = 1;
          if (ef.kind == EffectKind::proximity && margin_[x] < T(ef.threshold)) margin_[x] = T(ef.threshold);
          if (ef.kind == EffectKind::time_of_impact) swept_[x] = 1;
        }
    }
    // the naive count: every quantity for every pair of primitives every frame
    std::uint64_t prims = 0, sensors = 0;
    for (const Body& b : sc.bodies) {
      if (b.sensor())
        ++sensors;
      else
        prims += b.shape == Shape::mesh ? b.faces.size() : 1;
    }
    run_.naive = std::uint64_t(sc.frames + 1) * (prims * (prims - 1) / 2 * 4 + sensors * prims);
    for (const char* k : {"broad", "intersect", "proximity", "cast", "sweep"}) run_.counts[k] = 0;
  }

  Run run() {
    const auto t0 = std::chrono::steady_clock::now();
    // A value the run's type cannot hold (a coordinate beyond float's range, a position
    // that overflows after many frames) stops the run where it happens, named with its frame.
    for (int k = 0; k <= s_.frames; ++k) {
      try {
        if (k > 0) advance(k);
        frame(k);
      } catch (const invalid_input& e) {
        throw invalid_input(std::string("the ") + precision_name(run_.precision) + " run stopped at frame " +
                            std::to_string(k) + ": " + e.what());
      }
    }
    run_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return std::move(run_);
  }

 private:
  // ---- motion ----
  Vec3<T> keyframed(const Body& b, const T& t) const {
    const auto& ks = b.keyframes;
    if (!(T(ks.front().time) < t)) return v3<T>(ks.front().position);
    for (std::size_t i = 0; i + 1 < ks.size(); ++i) {
      const T t0(ks[i].time), t1(ks[i + 1].time);
      if (t <= t1) {
        const T f = (t - t0) / (t1 - t0);
        const Vec3<T> p0 = v3<T>(ks[i].position), p1 = v3<T>(ks[i + 1].position);
        return Vec3<T>(p0 + (p1 - p0) * f);
      }
    }
    return v3<T>(ks.back().position);
  }
  // At float (or double) every number of the scene must be a finite value of T: a radius
  // of 1e39 is refused by name rather than run as an infinity.
  static void representable(const Scene& sc) {
    auto check = [](double x, const std::string& what) {
      if (!std::isfinite(T(x)) || (x != 0 && std::fabs(x) < double(std::numeric_limits<T>::denorm_min()) / 2))
        throw invalid_input(what + " (" + detail::show(x) + ") is beyond " + precision_name_of() + "'s range");
    };
    check(sc.time_step, "the time step");
    for (const Body& b : sc.bodies) {
      const std::string n = "body '" + b.name + "' ";
      auto v = [&](const V3& x, const std::string& what) {
        for (int i = 0; i < 3; ++i) check(x[i], n + what);
      };
      check(b.radius, n + "radius");
      v(b.extent, "extent");
      for (const V3& a : b.axes) v(a, "axis");
      for (const V3& x : b.vertices) v(x, "vertex");
      v(b.direction, "direction");
      v(b.position, "position");
      v(b.velocity, "velocity");
      for (const Keyframe& kf : b.keyframes) {
        check(kf.time, n + "keyframe time");
        v(kf.position, "keyframe position");
      }
    }
  }
  static const char* precision_name_of() { return std::is_same_v<T, float> ? "float" : "double"; }
  // An engine's position that overflows is refused where it happens.
  void finite_positions(int k) const {
    for (int i = 0; i < n_; ++i)
      for (int c = 0; c < 3; ++c)
        if (!std::isfinite(pos_[i][c]))
          throw invalid_input("body '" + s_.bodies[i].name + "' has left " + precision_name_of() +
                              "'s range (position " + detail::show(pos_[i][c]) + " at frame " + std::to_string(k) + ")");
  }
  void advance(int k) {
    prev_ = pos_;
    if constexpr (exact) {
      time_ = T(k) * dt_;
    } else {
      time_ = time_ + dt_;
    }
    for (int i = 0; i < n_; ++i) {
      const Body& b = s_.bodies[i];
      if (!b.keyframes.empty()) {
        pos_[i] = keyframed(b, time_);
      } else if (b.moves()) {
        if constexpr (exact) {
          pos_[i] = Vec3<T>(v3<T>(b.position) + vel_[i] * time_);
        } else {
          const Vec3<T> step = vel_[i] * dt_;
          pos_[i] = Vec3<T>(pos_[i] + step);
        }
      }
    }
    if constexpr (!exact) finite_positions(k);
  }
  Vec3<T> origin(int i) const {  // a sensor's source
    const Body& b = s_.bodies[i];
    if (b.attached_to >= 0) return Vec3<T>(pos_[b.attached_to] + v3<T>(b.position));
    return pos_[i];
  }

  // ---- shapes at the current (or previous) positions ----
  Sphere<T> sphere(int i, bool prev = false) const {
    return {prev ? prev_[i] : pos_[i], T(s_.bodies[i].radius)};
  }
  Box<T> box(int i, bool prev = false) const { return {prev ? prev_[i] : pos_[i], v3<T>(s_.bodies[i].extent)}; }
  OrientedBox<T> obb(int i) const {
    const Body& b = s_.bodies[i];
    if (b.shape == Shape::box) {
      return {pos_[i], v3<T>(b.extent), {unit_vec<T>(0), unit_vec<T>(1), unit_vec<T>(2)}};
    }
    return {pos_[i], v3<T>(b.extent), {v3<T>(b.axes[0]), v3<T>(b.axes[1]), v3<T>(b.axes[2])}};
  }
  Triangle<T> triangle(int i, int f) const {
    const Body& b = s_.bodies[i];
    Triangle<T> t;
    for (int c = 0; c < 3; ++c) t.vertex[c] = Vec3<T>(pos_[i] + v3<T>(b.vertices[b.faces[f][c]]));
    return t;
  }
  static Bounds<T> bounds_of(const Triangle<T>& t) {
    Bounds<T> bb{t.vertex[0], t.vertex[0]};
    for (int c = 1; c < 3; ++c) bb.add({t.vertex[c], t.vertex[c]});
    return bb;
  }
  Bounds<T> bounds(int i) const {
    const Body& b = s_.bodies[i];
    switch (b.shape) {
      case Shape::sphere: {
        const Vec3<T> r(T(b.radius), T(b.radius), T(b.radius));
        return {Vec3<T>(pos_[i] - r), Vec3<T>(pos_[i] + r)};
      }
      case Shape::box: {
        const Vec3<T> h = v3<T>(b.extent);
        return {Vec3<T>(pos_[i] - h), Vec3<T>(pos_[i] + h)};
      }
      case Shape::obb: {
        Vec3<T> h = zero_vec<T>();
        for (int a = 0; a < 3; ++a)
          for (int c = 0; c < 3; ++c) {
            const T x = T(b.axes[a][c]) * T(b.extent[a]);
            h[c] += x < T(0) ? T(-x) : x;
          }
        return {Vec3<T>(pos_[i] - h), Vec3<T>(pos_[i] + h)};
      }
      case Shape::mesh: {
        Bounds<T> bb = bounds_of(triangle(i, 0));
        for (std::size_t f = 1; f < b.faces.size(); ++f) bb.add(bounds_of(triangle(i, int(f))));
        return bb;
      }
      default: break;
    }
    return {pos_[i], pos_[i]};
  }

  // ---- the pair queries ----
  template <class Fn>
  bool any_triangle(int m, const Bounds<T>& other, Fn fn) {
    const Body& b = s_.bodies[m];
    for (std::size_t f = 0; f < b.faces.size(); ++f) {
      const Triangle<T> t = triangle(m, int(f));
      if (!bounds_of(t).meets(other)) continue;
      if (fn(t)) return true;
    }
    return false;
  }
  bool obb_pair(const OrientedBox<T>& a, const OrientedBox<T>& b) {
    if constexpr (exact)
      return solid::separate(a, b).intersect;
    else
      return book::intersect(a, b);
  }
  bool tri_obb(const Triangle<T>& t, const OrientedBox<T>& b) {
    if constexpr (exact)
      return solid::separate(t, b).intersect;
    else
      return book::intersect(t, b);
  }
  // The boolean test of a pair (a sphere first when there is one).
  bool intersect(int a, int b) {
    std::uint64_t& c = run_.counts["intersect"];
    const Shape A = s_.bodies[a].shape, B = s_.bodies[b].shape;
    if (A != Shape::sphere && B == Shape::sphere) return intersect(b, a);
    if (A == Shape::mesh && B != Shape::mesh) return intersect(b, a);
    if (A == Shape::sphere) {
      const Sphere<T> sp = sphere(a);
      switch (B) {
        case Shape::sphere: ++c; return book::intersect(sp, sphere(b));
        case Shape::box: ++c; return book::intersect(sp, box(b));
        case Shape::obb:
          ++c;
          if constexpr (exact) return solid::intersect(sp, obb(b));
          else return book::intersect(sp, obb(b));
        case Shape::mesh: return any_triangle(b, bounds(a), [&](const Triangle<T>& t) { ++c; return book::intersect(sp, t); });
        default: break;
      }
    }
    if (B == Shape::mesh) {
      if (A == Shape::mesh) {
        const Bounds<T> bb = bounds(b);
        return any_triangle(a, bb, [&](const Triangle<T>& ta) {
          return any_triangle(b, bounds_of(ta), [&](const Triangle<T>& tb) { ++c; return book::intersect(ta, tb).intersect; });
        });
      }
      if (A == Shape::box) {
        const Box<T> bx = box(a);
        return any_triangle(b, bounds(a), [&](const Triangle<T>& t) { ++c; return book::intersect(t, bx); });
      }
      const OrientedBox<T> o = obb(a);
      return any_triangle(b, bounds(a), [&](const Triangle<T>& t) { ++c; return tri_obb(t, o); });
    }
    ++c;
    if (A == Shape::box && B == Shape::box) return book::intersect(box(a), box(b));
    return obb_pair(obb(a), obb(b));
  }
  // Proximity of a sphere a against b (a mesh: the nearest triangle, or the deepest).
  Proximity<S> proximity(int a, int b, const T& reach) {
    std::uint64_t& c = run_.counts["proximity"];
    const Sphere<T> sp = sphere(a);
    switch (s_.bodies[b].shape) {
      case Shape::sphere: ++c; return book::proximity(sp, sphere(b), want_all);
      case Shape::box: ++c; return book::proximity(sp, box(b), want_all);
      case Shape::obb:
        ++c;
        if constexpr (exact) return solid::proximity(sp, obb(b), want_all);
        else return book::proximity(sp, obb(b), want_all);
      default: break;
    }
    Bounds<T> around = bounds(a);
    for (int i = 0; i < 3; ++i) {
      around.lo[i] -= reach;
      around.hi[i] += reach;
    }
    std::optional<Proximity<S>> best;
    any_triangle(b, around, [&](const Triangle<T>& t) {
      ++c;
      Proximity<S> p = book::proximity(sp, t, want_all);
      if (!best) best = p;
      else if (p.intersect && best->intersect ? cmp(best->depth, p.depth) < 0 : cmp(p.distance, best->distance) < 0)
        best = p;
      return false;
    });
    if (best) return *best;
    Proximity<S> far;  // no triangle within reach
    far.distance = S(reach) + S(1);
    return far;
  }

  // ---- the frame ----
  using Key = std::tuple<int, int, int>;  // effect, a, b
  void event(int k, int e, const char* kind, int a, int b, std::vector<double> v = {}) {
    run_.events.push_back({k, e, kind, a, b, std::move(v)});
  }
  void sample(int k, int e, int a, int b, const std::vector<double>& v) { run_.samples.push_back({k, e, a, b, v}); }
  std::vector<double> prox_values(const Proximity<S>& p, bool distance) {
    std::vector<double> v;
    if (distance) {
      v.push_back(dbl(p.distance));
    } else {
      v.push_back(dbl(p.depth));
      const Vec3<S> pv(p.on_b - p.on_a);
      if (p.depth == S(0))
        push3(v, zero_vec<S>());
      else
        push3(v, Vec3<S>(pv / p.depth));
    }
    push3(v, p.on_a);
    push3(v, p.on_b);
    return v;
  }

  // The pairs whose (swept, margin-grown) bounds meet, handed to `each(i, j)` (i < j) as the
  // sweep finds them: none is stored, so a frame's memory does not grow with its overlaps.
  template <class Each>
  void broad_phase(Each&& each) {
    struct Item {
      Bounds<T> b;
      int i;
    };
    std::vector<Item> items;
    for (int i = 0; i < n_; ++i) {
      if (!used_[i] || s_.bodies[i].sensor()) continue;
      Bounds<T> bb = bounds(i);
      if (swept_[i] && have_prev_) {
        std::swap(pos_, prev_);
        bb.add(bounds(i));
        std::swap(pos_, prev_);
      }
      for (int c = 0; c < 3; ++c) {
        bb.lo[c] -= margin_[i];
        bb.hi[c] += margin_[i];
      }
      items.push_back({bb, i});
    }
    std::sort(items.begin(), items.end(), [](const Item& x, const Item& y) { return x.b.lo[0] < y.b.lo[0]; });
    std::uint64_t found = 0;
    for (std::size_t x = 0; x < items.size(); ++x)
      for (std::size_t y = x + 1; y < items.size() && !(items[x].b.hi[0] < items[y].b.lo[0]); ++y)
        if (items[x].b.meets(items[y].b)) {
          ++found;
          each(std::min(items[x].i, items[y].i), std::max(items[x].i, items[y].i));
        }
    run_.counts["broad"] += found;
  }

  void frame(int k) {
    run_.path.emplace_back();
    for (int i = 0; i < n_; ++i) {
      const Vec3<T> p = s_.bodies[i].sensor() ? origin(i) : pos_[i];
      run_.path.back().push_back({dbl(p[0]), dbl(p[1]), dbl(p[2])});
    }
    // the states that hold this frame, 12 bytes each (a sorted vector, not a tree of nodes):
    // a pair's state begins when it holds and held not in the frame before
    std::vector<Key> now;
    broad_phase([&](int i, int j) {
      for (int e = 0; e < int(s_.effects.size()); ++e) {
        const Effect& ef = s_.effects[e];
        if (ef.kind == EffectKind::raycast) continue;
        int a = -1, b = -1;
        if (in_a_[e][i] && in_b_[e][j]) a = i, b = j;
        if (in_a_[e][j] && in_b_[e][i]) a = j, b = i;
        if (a < 0) continue;
        if (s_.bodies[b].shape == Shape::sphere && s_.bodies[a].shape != Shape::sphere) std::swap(a, b);
        pair(k, e, a, b, now);
      }
    });
    std::sort(now.begin(), now.end());
    // states that held and were not reported again end here (in the order of their keys)
    for (const Key& key : active_)
      if (!std::binary_search(now.begin(), now.end(), key))
        event(k, std::get<0>(key), "end", std::get<1>(key), std::get<2>(key));
    active_ = std::move(now);
    for (int e = 0; e < int(s_.effects.size()); ++e)
      if (s_.effects[e].kind == EffectKind::raycast) raycast(k, e);
    have_prev_ = true;
  }

  void pair(int k, int e, int a, int b, std::vector<Key>& now) {
    const Effect& ef = s_.effects[e];
    const Key key{e, a, b};
    auto hold = [&](bool on, std::vector<double> v) {
      if (!on) return;
      now.push_back(key);  // (a pair and an effect are met once a frame)
      if (!std::binary_search(active_.begin(), active_.end(), key)) event(k, e, "begin", a, b, std::move(v));
    };
    switch (ef.kind) {
      case EffectKind::trigger: hold(intersect(a, b), {}); break;
      case EffectKind::contact: {
        if (!intersect(a, b)) break;
        const Proximity<S> p = proximity(a, b, T(0));
        if (!p.intersect) break;  // a mesh's triangles all apart
        const auto v = prox_values(p, false);
        sample(k, e, a, b, v);
        hold(true, v);
        break;
      }
      case EffectKind::proximity: {
        const Proximity<S> p = proximity(a, b, T(ef.threshold));
        if (p.intersect || p.distance <= S(T(ef.threshold))) {
          const auto v = prox_values(p, true);
          sample(k, e, a, b, v);
          hold(true, v);
        }
        break;
      }
      case EffectKind::time_of_impact:
        if (k > 0) impact(k, e, a, b);
        break;
      default: break;
    }
  }

  void impact(int k, int e, int a, int b) {
    std::uint64_t& c = run_.counts["sweep"];
    const Vec3<T> da(pos_[a] - prev_[a]), db(pos_[b] - prev_[b]);
    const Vec3<T> d(da - db);
    const T r(s_.bodies[a].radius);
    std::optional<S> l;
    std::uint64_t parts = 0;
    switch (s_.bodies[b].shape) {
      case Shape::sphere: {
        ++c;
        const Vec3<T> s0(prev_[a] - prev_[b]);
        const Sphere<T> cso{zero_vec<T>(), T(r + T(s_.bodies[b].radius))};
        if (book::intersect(Sphere<T>{s0, T(0)}, cso)) {
          l = S(0);
        } else {
          const auto cs = book::cast(Segment<T>{s0, Vec3<T>(s0 + d)}, cso, want_lambda_enter);
          if (cs.hit) l = cs.lambda_enter;
        }
        break;
      }
      case Shape::box:
        ++c;
        l = sweep_box(prev_[a], d, box(b, true), r, parts);
        break;
      case Shape::mesh: {
        Bounds<T> sw{Vec3<T>(prev_[a]), Vec3<T>(prev_[a])};
        sw.add({pos_[a], pos_[a]});
        for (int i = 0; i < 3; ++i) {
          sw.lo[i] -= r;
          sw.hi[i] += r;
        }
        std::optional<S> best;
        any_triangle(b, sw, [&](const Triangle<T>& t) {
          ++c;
          if (auto x = sweep_triangle(prev_[a], d, t, r, parts)) take(best, *x);
          return false;
        });
        l = best;
        break;
      }
      default: break;
    }
    if (!l || *l == S(0)) return;  // no touch in the step, or touching already at its start
    std::vector<double> v;
    const S t = S(T(T(k - 1) * dt_)) + *l * S(dt_);
    v.push_back(dbl(t));
    push3(v, Vec3<S>(affine(prev_[a], *l, da)));
    sample(k, e, a, b, v);
    event(k, e, "impact", a, b, v);
  }

  void raycast(int k, int e) {
    const Effect& ef = s_.effects[e];
    for (int a : ef.a) {
      const Body& sb = s_.bodies[a];
      const Vec3<T> o = origin(a), dir = v3<T>(sb.direction);
      const bool seg = sb.shape == Shape::segment;
      std::optional<Cast<S>> best;
      int best_b = -1;
      auto consider = [&](const Cast<S>& c, int b) {
        if (c.hit && (!best || cmp(S(c.lambda_enter), best->lambda_enter) < 0)) {
          best = c;
          best_b = b;
        }
      };
      for (int b : ef.b) {
        const Bounds<T> bb = bounds(b);
        ++run_.counts["broad"];
        const bool near = seg ? book::hit(Segment<T>{o, Vec3<T>(o + dir)}, bb.box())
                              : book::hit(Ray<T>{o, dir}, bb.box());
        if (!near) continue;
        std::uint64_t& c = run_.counts["cast"];
        auto shot = [&](const auto& shape) -> Cast<S> {
          ++c;
          if (seg) return to_cast(cast_any(Segment<T>{o, Vec3<T>(o + dir)}, shape));
          return to_cast(cast_any(Ray<T>{o, dir}, shape));
        };
        switch (s_.bodies[b].shape) {
          case Shape::sphere: consider(shot(sphere(b)), b); break;
          case Shape::box: consider(shot(box(b)), b); break;
          case Shape::obb: consider(shot(obb(b)), b); break;
          case Shape::mesh:
            for (std::size_t f = 0; f < s_.bodies[b].faces.size(); ++f) {
              const Triangle<T> t = triangle(b, int(f));
              const Bounds<T> tb = bounds_of(t);
              const bool hitbox = seg ? book::hit(Segment<T>{o, Vec3<T>(o + dir)}, tb.box())
                                      : book::hit(Ray<T>{o, dir}, tb.box());
              if (hitbox) consider(shot(t), b);
            }
            break;
          default: break;
        }
      }
      const int was = sensor_hit_.count({e, a}) ? sensor_hit_[{e, a}] : -1;
      std::vector<double> v;
      if (best) {
        v.push_back(dbl(best->lambda_enter));
        push3(v, best->point);
        push3(v, best->normal);
        sample(k, e, a, best_b, v);
      }
      if (best_b != was || k == 0) {
        if (best_b != was) event(k, e, "hit", a, best_b, v);
        sensor_hit_[{e, a}] = best_b;
      }
    }
  }
  template <class C>
  static Cast<S> to_cast(const C& c) {
    Cast<S> r;
    r.hit = c.hit;
    r.lambda_enter = S(c.lambda_enter);
    r.lambda_exit = S(c.lambda_exit);
    for (int i = 0; i < 3; ++i) {
      r.point[i] = S(c.point[i]);
      r.normal[i] = S(c.normal[i]);
    }
    return r;
  }
  template <class Shot, class Shape_>
  static auto cast_any(const Shot& shot, const Shape_& shape) {
    if constexpr (exact && std::is_same_v<Shape_, OrientedBox<T>>)
      return solid::cast(shot, shape, want_cast);  // the truth for any independent axes
    else
      return book::cast(shot, shape, want_cast);
  }

  const Scene& s_;
  int n_;
  Run run_;
  T dt_, time_;
  std::vector<Vec3<T>> pos_, prev_, vel_;
  std::vector<std::vector<char>> in_a_, in_b_;
  std::vector<T> margin_;
  std::vector<char> swept_, used_;
  bool have_prev_ = false;
  std::vector<Key> active_;  // the states holding after the last frame, sorted
  std::map<std::pair<int, int>, int> sensor_hit_;
};

}  // namespace cdref::scene::engine
