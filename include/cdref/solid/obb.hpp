/// \file
/// cdref/solid/obb.hpp - the oriented box as the solid its inputs define: queries on the
/// parallelepiped P = {c + sum_i u_i a_i : |u_i| <= h_i}, whatever the axes (linearly
/// independent, not necessarily orthonormal). At an exact type these are the truth that the
/// book's frame-transform formulations (cdref/book/obb.hpp, obb_obb.hpp) approximate; when
/// the axes are exactly orthonormal both agree exactly.
///
/// Coordinates. With n_i = a_{i+1} x a_{i+2} (the face normals) and delta = det[a_0 a_1 a_2]
/// = a_i . n_i != 0, the coordinates of a point p are u_i = n_i . (p - c) / delta (Cramer's
/// rule: n_i . a_j = delta [i = j]). cdref uses U_i = sign(delta) n_i . (p - c) = |delta| u_i
/// and the box [-H, H], H_i = |delta| h_i: a uniform scaling of the u coordinates, so no
/// division, and ray parameters are unchanged.
///
///   separate(A, B)        Theorem 3.1 on the two polytopes (book/separating_axes.hpp):
///                         faces n_i, edges a_i; the same axis order as the book's.
///   cast / hit(Segment | Ray, OrientedBox)
///                         Algorithm 3.3 in U coordinates (P is exactly the box [-H, H]
///                         there); the entry point s + lambda r in world coordinates; the
///                         normal of the entering face U_i = -+H_i is -+sign(delta) n_i / |n_i|
///                         (outward, unit: one square root).
///   proximity / intersect(Sphere, OrientedBox)
///                         centre q in P (|U_i| <= H_i for all i): distance 0; the nearest
///                         face is the i minimising delta_i = (H_i - |U_i|) / |n_i| (its
///                         squared value (H_i - |U_i|)^2 / |n_i|^2 is compared, first on
///                         ties; the side is that of U_i, + for U_i = 0 as in the chapter);
///                         witness on the box y = q + s (H_i - |U_i|) sign(delta) n_i / |n_i|^2
///                         (rational), on the sphere q - rho s sign(delta) n_i / |n_i|, depth
///                         delta_i + rho.
///                         q outside: the closest point x of P (unique: P is convex) is the
///                         nearest among the 8 vertices, the feet of q on the 12 edge lines
///                         strictly inside their edge and the feet on the 6 face planes strictly
///                         inside their face: it lies on the boundary, in the relative interior
///                         of a face, of an edge, or at a vertex, and there it is that foot. With
///                         v = x - q: distance max(|v| - rho, 0), depth max(rho - |v|, 0),
///                         witnesses q + rho v/|v| (sphere) and x (box); intersect iff
///                         |v|^2 <= rho^2.
/// Every value is rational except where a length |n_i| or |v| is taken: one square root per
/// value, so Quad<T> holds them exactly at a rational T.
#pragma once

#include "../book/ray_box.hpp"
#include "../book/separating_axes.hpp"

namespace cdref::solid {

namespace detail {

using book::detail::abs_of;
using book::detail::min_of;

template <class T>
struct Frame {
  std::array<Vec3<T>, 3> n;  ///< face normals, times sign(delta): U_i = n_i . (p - c)
  Vec3<T> H;                 ///< |delta| h
  T delta_abs;
  int delta_sign;
};

template <class T>
Frame<T> frame(const OrientedBox<T>& b) {
  Frame<T> f;
  for (int i = 0; i < 3; ++i) f.n[i] = b.axis[(i + 1) % 3].cross(b.axis[(i + 2) % 3]);
  const T delta = b.axis[0].dot(f.n[0]);
  f.delta_sign = delta < T(0) ? -1 : 1;
  f.delta_abs = abs_of(delta);
  if (f.delta_sign < 0)
    for (auto& n : f.n) n = -n;
  for (int i = 0; i < 3; ++i) f.H[i] = f.delta_abs * b.extent[i];
  return f;
}
template <class T>
Vec3<T> coords(const Frame<T>& f, const Vec3<T>& p, const Vec3<T>& c) {
  const Vec3<T> d = p - c;
  return Vec3<T>(f.n[0].dot(d), f.n[1].dot(d), f.n[2].dot(d));
}
template <class T>
Vec3<T> coords_of_vector(const Frame<T>& f, const Vec3<T>& v) {
  return Vec3<T>(f.n[0].dot(v), f.n[1].dot(v), f.n[2].dot(v));
}

template <class T>
Cast<sqrt_t<T>> cast_solid(const Vec3<T>& s_world, const Vec3<T>& r_world, const OrientedBox<T>& b, bool bounded,
                           unsigned w) {
  using S = sqrt_t<T>;
  const Frame<T> f = frame(b);
  const Vec3<T> s = coords(f, s_world, b.center);
  const Vec3<T> r = coords_of_vector(f, r_world);
  const Box<T> box{zero_vec<T>(), f.H};
  const unsigned bt = bounded ? book::detail::outcode(Vec3<T>(s + r), f.H) : book::detail::outcode_at_infinity(s, r, f.H);
  const Cast<T> c = book::detail::cast_box_local(s, r, box, book::detail::outcode(s, f.H), bt, bounded, want_normal);
  Cast<S> out;
  out.hit = c.hit;
  if (!c.hit) return out;
  out.enters = c.enters;
  out.unbounded_exit = c.unbounded_exit;
  out.lambda_enter = S(c.lambda_enter);
  out.lambda_exit = S(c.lambda_exit);
  if (w & want_point) out.point = lift<S>(affine(s_world, c.lambda_enter, r_world));
  if (c.enters && (w & want_normal)) {
    int axis = 0;
    while (c.normal[axis] == T(0)) ++axis;
    const T sg = c.normal[axis];  // -1 or +1
    const Vec3<T>& n = f.n[axis];
    const S len = root(T(n.squaredNorm()));
    for (int k = 0; k < 3; ++k) out.normal[k] = S(T(sg * n[k])) / len;
  }
  return out;
}

template <class T>
bool hit_solid(const Vec3<T>& s_world, const Vec3<T>& r_world, const OrientedBox<T>& b, bool bounded) {
  const Frame<T> f = frame(b);
  const Vec3<T> s = coords(f, s_world, b.center);
  const Vec3<T> r = coords_of_vector(f, r_world);
  const unsigned bt = bounded ? book::detail::outcode(Vec3<T>(s + r), f.H) : book::detail::outcode_at_infinity(s, r, f.H);
  return book::detail::hit_box_local(s, r, f.H, book::detail::outcode(s, f.H), bt, bounded);
}

/// The closest point of the parallelepiped to q (outside it) where q's side of each pair of faces
/// designates it, certainly (book::detail::surely_positive): with o_m = +-1 where U_m > H_m or
/// U_m < -H_m and 0 where |U_m| < H_m, one nonzero o_i designates the foot of q on face i, two the
/// foot on the edge parallel to the third axis a_i between faces (j, o_j) and (k, o_k), three the
/// vertex c + sum_m o_m h_m a_m. A point x of P is the closest to q iff q - x lies in P's normal
/// cone there: with w = q - x, max over P of w.y = w.c + sum_m h_m |w.a_m| equals w.x = w.c +
/// sum_m u_m(x) w.a_m, i.e. for each m, w.a_m = 0 or u_m(x) = h_m sign(w.a_m). For the face's
/// foot w is a multiple of n_i (orthogonal to a_m, m != i) of the sign o_i, so the foot is the
/// closest point iff it lies in the face: |U_m(foot)| <= H_m (tested strictly); for the edge's,
/// w.a_i = 0 and the foot must lie on the edge (|t| < h_i) with o_j w.a_j > 0 and o_k w.a_k > 0;
/// for the vertex, o_m w.a_m > 0 for every m. Where each of those is certain the point is the
/// unique closest point, so the enumeration below returns it too; otherwise (a test too close to
/// call, or a designated feature that is not the closest: axes far from orthogonal) false. At an
/// exact type the answer is the enumeration's; on double words (robust/words.hpp) it takes a few
/// dozen operations where the enumeration takes some six hundred.
template <class T>
bool closest_by_outcode(const OrientedBox<T>& b, const Frame<T>& f, const Vec3<T>& q, const Vec3<T>& U, T& d2,
                        Vec3<T>* point) {
  using book::detail::surely_positive;
  int o[3], out = 0, inside_axis = 0;
  for (int m = 0; m < 3; ++m) {
    if (surely_positive(T(U[m] - f.H[m])))
      o[m] = 1;
    else if (surely_positive(T(-f.H[m] - U[m])))
      o[m] = -1;
    else if (surely_positive(T(f.H[m] - U[m])) && surely_positive(T(U[m] + f.H[m])))
      o[m] = 0, inside_axis = m;
    else
      return false;
    out += o[m] != 0;
  }
  Vec3<T> x;
  if (out == 1) {
    const int i = o[0] != 0 ? 0 : o[1] != 0 ? 1 : 2;
    const Vec3<T>& n = f.n[i];
    const T nn = n.squaredNorm();
    const T excess = U[i] - T(o[i]) * f.H[i];
    for (int m = 0; m < 3; ++m) {
      if (m == i) continue;
      const T Um = U[m] - excess * f.n[m].dot(n) / nn;
      if (!surely_positive(T(f.H[m] - Um)) || !surely_positive(T(Um + f.H[m]))) return false;
    }
    x = q - (excess / nn) * n;
  } else if (out == 2) {
    const int i = inside_axis, j = (i + 1) % 3, k = (i + 2) % 3;
    const Vec3<T> p0 = b.center + (T(o[j]) * b.extent[j]) * b.axis[j] + (T(o[k]) * b.extent[k]) * b.axis[k];
    const Vec3<T>& a = b.axis[i];
    const T t = a.dot(Vec3<T>(q - p0)) / a.squaredNorm();
    if (!surely_positive(T(b.extent[i] - t)) || !surely_positive(T(t + b.extent[i]))) return false;
    x = p0 + t * a;
    const Vec3<T> w = q - x;
    if (!surely_positive(T(T(o[j]) * b.axis[j].dot(w))) || !surely_positive(T(T(o[k]) * b.axis[k].dot(w)))) return false;
  } else {
    x = b.center;
    for (int m = 0; m < 3; ++m) x += (T(o[m]) * b.extent[m]) * b.axis[m];
    const Vec3<T> w = q - x;
    for (int m = 0; m < 3; ++m)
      if (!surely_positive(T(T(o[m]) * b.axis[m].dot(w)))) return false;
  }
  d2 = Vec3<T>(x - q).squaredNorm();
  if (point) *point = x;
  return true;
}

/// The closest point of the parallelepiped to q (outside it): its squared distance, and with
/// `point` the point itself. The candidates are the 8 vertices, the feet of q on the 12 edges
/// that fall strictly inside their edge and the feet on the 6 face planes that fall strictly
/// inside their face: each point of the boundary is offered at most once (a foot on a face's
/// border is an edge's foot or a vertex), so equal candidates never compete. The smallest
/// squared distance needs no decision (min); the point is the first candidate reaching it.
template <class T>
T closest_enumerated(const OrientedBox<T>& b, const Frame<T>& f, const Vec3<T>& q, const Vec3<T>& U, Vec3<T>* point) {
  T best(0);
  bool have = false;
  auto offer = [&](const Vec3<T>& x) {
    const T d2 = Vec3<T>(x - q).squaredNorm();
    if (point) {
      if (!have || d2 < best) best = d2, *point = x;
    } else {
      best = have ? min_of(best, d2) : d2;
    }
    have = true;
  };
  // vertices
  for (int s0 : {-1, 1})
    for (int s1 : {-1, 1})
      for (int s2 : {-1, 1}) {
        Vec3<T> x = b.center;
        const int sg[3] = {s0, s1, s2};
        for (int i = 0; i < 3; ++i) x += (T(sg[i]) * b.extent[i]) * b.axis[i];
        offer(x);
      }
  // edges parallel to a_i: c + sj h_j a_j + sk h_k a_k + t a_i, |t| < h_i
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    for (int sj : {-1, 1})
      for (int sk : {-1, 1}) {
        const Vec3<T> p0 = b.center + (T(sj) * b.extent[j]) * b.axis[j] + (T(sk) * b.extent[k]) * b.axis[k];
        const Vec3<T>& a = b.axis[i];
        const T t = a.dot(Vec3<T>(q - p0)) / a.squaredNorm();
        if (T(-b.extent[i]) < t && t < b.extent[i]) offer(Vec3<T>(p0 + t * a));
      }
  }
  // faces: the foot of q on the plane U_i = sg H_i, if strictly inside the face
  for (int i = 0; i < 3; ++i)
    for (int sg : {-1, 1}) {
      const Vec3<T>& n = f.n[i];
      const T nn = n.squaredNorm();
      const T excess = U[i] - T(sg) * f.H[i];  // n . (q - c) - offset
      // foot = q - (excess / |n|^2) n; its coordinates U_m - excess (n_m . n) / |n|^2
      bool inside = true;
      for (int m = 0; m < 3 && inside; ++m) {
        if (m == i) continue;
        const T Um = U[m] - excess * f.n[m].dot(n) / nn;
        inside = abs_of(Um) < f.H[m];
      }
      if (inside) offer(Vec3<T>(q - (excess / nn) * n));
    }
  return best;
}
/// The two together: the designated feature where that is certain, else the enumeration.
template <class T>
T closest_outside(const OrientedBox<T>& b, const Frame<T>& f, const Vec3<T>& q, const Vec3<T>& U, Vec3<T>* point) {
  if (T d2; closest_by_outcode(b, f, q, U, d2, point)) return d2;
  return closest_enumerated(b, f, q, U, point);
}

}  // namespace detail

/// ---- separating axes ----
template <class T>
Separation<T> separate(const OrientedBox<T>& a, const OrientedBox<T>& b) {
  return book::separate_polytopes(a, b, "oriented box A", "oriented box B");
}
/// Theorem 3.1 on the segment and the oriented box taken as the solid its axes define (a
/// parallelepiped): whether they intersect, else the first separating axis in this file's order and
/// its direction (a cdref::Separation). Throws cdref::invalid_input naming a bad argument.
template <class T>
Separation<T> separate(const Segment<T>& s, const OrientedBox<T>& b) {
  return book::separate_polytopes(s, b, "segment", "oriented box");
}
/// Theorem 3.1 on the ray and the oriented box taken as the solid its axes define (a
/// parallelepiped): whether they intersect, else the first separating axis in this file's order and
/// its direction (a cdref::Separation). Throws cdref::invalid_input naming a bad argument.
template <class T>
Separation<T> separate(const Ray<T>& r, const OrientedBox<T>& b) {
  return book::separate_polytopes(r, b, "ray", "oriented box");
}
/// Theorem 3.1 on the triangle and the oriented box taken as the solid its axes define (a
/// parallelepiped): whether they intersect, else the first separating axis in this file's order and
/// its direction (a cdref::Separation). Throws cdref::invalid_input naming a bad argument.
template <class T>
Separation<T> separate(const Triangle<T>& t, const OrientedBox<T>& b) {
  return book::separate_polytopes(t, b, "triangle", "oriented box");
}

/// ---- casts ----
template <class T>
Cast<sqrt_t<T>> cast(const Segment<T>& seg, const OrientedBox<T>& b, unsigned w = want_cast) {
  check(seg, "segment");
  check(b, "oriented box");
  return detail::cast_solid(seg.source, Vec3<T>(seg.target - seg.source), b, true, w);
}
/// The ray (lambda >= 0 in units of |direction|) cast on the closed oriented box taken as the solid
/// its axes define (a parallelepiped): hit, entry and exit parameters, entry point and normal (only
/// what the mask `w` asks for is computed). Throws cdref::invalid_input naming a bad argument.
template <class T>
Cast<sqrt_t<T>> cast(const Ray<T>& ray, const OrientedBox<T>& b, unsigned w = want_cast) {
  check(ray, "ray");
  check(b, "oriented box");
  return detail::cast_solid(ray.source, ray.direction, b, false, w);
}
/// Whether the segment meets the closed oriented box taken as the solid its axes define (a
/// parallelepiped): the cast's classification alone. Throws cdref::invalid_input naming a bad
/// argument.
template <class T>
bool hit(const Segment<T>& seg, const OrientedBox<T>& b) {
  check(seg, "segment");
  check(b, "oriented box");
  return detail::hit_solid(seg.source, Vec3<T>(seg.target - seg.source), b, true);
}
/// Whether the ray meets the closed oriented box taken as the solid its axes define (a
/// parallelepiped): the cast's classification alone. Throws cdref::invalid_input naming a bad
/// argument.
template <class T>
bool hit(const Ray<T>& ray, const OrientedBox<T>& b) {
  check(ray, "ray");
  check(b, "oriented box");
  return detail::hit_solid(ray.source, ray.direction, b, false);
}

/// ---- sphere ----
template <class T>
bool intersect(const Sphere<T>& sp, const OrientedBox<T>& b) {
  check(sp, "sphere");
  check(b, "oriented box");
  const detail::Frame<T> f = detail::frame(b);
  const Vec3<T> U = detail::coords(f, sp.center, b.center);
  bool inside = true;
  for (int i = 0; i < 3; ++i) inside = inside && detail::abs_of(U[i]) <= f.H[i];
  if (inside) return true;
  return detail::closest_outside(b, f, sp.center, U, static_cast<Vec3<T>*>(nullptr)) <= sp.radius * sp.radius;
}

/// Distance, penetration depth and witness points of the sphere and the oriented box taken as the
/// solid its axes define (a parallelepiped) (a cdref::Proximity; only what the mask `w` asks for is
/// computed, the rest stays 0). Throws cdref::invalid_input naming a bad argument.
template <class T>
Proximity<sqrt_t<T>> proximity(const Sphere<T>& sp, const OrientedBox<T>& b, unsigned w = want_proximity) {
  using S = sqrt_t<T>;
  check(sp, "sphere");
  check(b, "oriented box");
  Proximity<S> res;
  const detail::Frame<T> f = detail::frame(b);
  const Vec3<T>& q = sp.center;
  const T& rho = sp.radius;
  const Vec3<T> U = detail::coords(f, q, b.center);
  bool inside = true;
  for (int i = 0; i < 3; ++i) inside = inside && detail::abs_of(U[i]) <= f.H[i];
  if (!inside) {
    Vec3<T> x;
    const T vv = detail::closest_outside(b, f, q, U, &x);
    const Vec3<T> v = x - q;
    res.intersect = vv <= rho * rho;
    if (w & want_closest) res.closest = lift<S>(x);
    if (!(w & (want_distance | want_depth | want_witnesses))) return res;
    const S len = root(vv);
    if (w & want_distance) res.distance = book::detail::max_of(S(len - S(rho)), S(0));
    if (w & want_depth) res.depth = book::detail::max_of(S(S(rho) - len), S(0));
    if (w & want_witnesses) {
      res.on_a = offset(q, S(rho), book::detail::divided(v, len));
      res.on_b = lift<S>(x);
    }
    return res;
  }
  res.intersect = true;
  if (w & want_closest) res.closest = lift<S>(q);
  if (!(w & (want_depth | want_witnesses))) return res;
  // the nearest face: smallest (H_i - |U_i|)^2 / |n_i|^2, first on ties
  int axis = 0;
  T best(0);
  for (int i = 0; i < 3; ++i) {
    const T gap = f.H[i] - detail::abs_of(U[i]);
    const T d2 = gap * gap / f.n[i].squaredNorm();
    if (i == 0 || d2 < best) axis = i, best = d2;
  }
  const T sg = U[axis] < T(0) ? T(-1) : T(1);
  const Vec3<T>& n = f.n[axis];
  const T nn = n.squaredNorm();
  const T gap = f.H[axis] - detail::abs_of(U[axis]);
  const S len = root(nn);  // |n|
  if (w & want_depth) res.depth = S(gap) / len + S(rho);
  if (w & want_witnesses) {
    res.on_b = lift<S>(Vec3<T>(q + (sg * gap / nn) * n));
    for (int k = 0; k < 3; ++k) res.on_a[k] = S(q[k]) - S(T(rho * sg * n[k])) / len;
  }
  return res;
}

}  // namespace cdref::solid
