// cdref/robust/ray_triangle.hpp - the robust ray and segment casts on a triangle (Section 3.4)
// at float, double and long double: watertight, with a certificate.
//
// Two pieces: the classification (below, "Classification and certificate": exact where the
// double words decide, never a false miss where they do not), and the values where the double
// words cannot give them, from Woop, Benthin and Wald, "Watertight Ray/Triangle Intersection"
// (JCGT 2013), the test pbrt-v4 ships, run in F (watertight() below). With the vertices moved to the source (P_k = v_k - s), the axes permuted so
// that z is the direction's largest coordinate (kz), and the shear Sx = -d_x/d_z, Sy = -d_y/d_z
// applied (p_k = (P_kx + Sx P_kz, P_ky + Sy P_kz)), the ray is the origin of the sheared plane
// looking down z, and the edge functions
//   e0 = p1 x p2,  e1 = p2 x p0,  e2 = p0 x p1   (2D cross products, one rounding per product
//                                                and one for the difference)
// are det(d, B, C), det(d, C, A), det(d, A, B) of book/ray_triangle.hpp divided by d_z, as rounded.
// The ray meets the triangle iff they do not have opposite signs; det = e0 + e1 + e2, and
// lambda = (e0 z0 + e1 z1 + e2 z2) / det with z_k = P_kz / d_z, tested against [0, 1] or
// [0, inf) by sign (closed: lambda = 0 and lambda = 1 are hits).
//
// Why no ray leaks between two triangles that share an edge: every vertex is translated and
// sheared the same way in every triangle that holds it (the same rounded sheared coordinates),
// so the triangles' projections form a mesh again; a shared edge's function is computed from
// the same two products in both triangles, with its operands swapped, and fl(a b) - fl(c d) is
// exactly -(fl(c d) - fl(a b)); and its sign is never the wrong one for the sheared coordinates
// (rounding is monotonic: a b > c d implies fl(a b) >= fl(c d)), only possibly 0, which a
// closed test counts as inside. So the origin, which lies in the sheared mesh, lies in some
// triangle's closed projection as computed. (pbrt-v4 recomputes in double where a float edge
// function is 0 to avoid a double hit; with closed triangles a double hit is allowed, and cdref
// does not.) Where det = 0 as computed the shot is parallel to the plane as rounded: if all
// three edge functions are 0 the line lies in the plane and the book's coplanar clip runs in F,
// else a miss.
//
// Every length is first scaled by a power of two (robust/words.hpp), so that the shear's products
// neither overflow nor underflow early. Two triangles of a mesh may get different scales; away
// from underflow a power of two commutes with every rounding, so their shared edge's function
// still has the same sign in both. Values: lambda = t/det, the
// barycentric weights b_k = e_k/det, point = b0 v0 + b1 v1 + b2 v2 (pbrt's), the normal
// (v1 - v0) x (v2 - v0) normalised and turned to face the source.
//
// Classification and certificate. WBW's signs are exact only for the rounded sheared
// coordinates, not for the inputs: on a shot in the triangle's plane it reports a miss (the
// sheared triangle is not exactly flat), and near an edge it may differ from the exact answer.
// So the classification is taken from the inputs themselves: the book's cast run on double
// words (robust/words.hpp: exact inputs, rigorous bounds) is exact when it completes (certain,
// values from the double words rounded to F, not claimed correctly rounded). Otherwise the
// signs of the orientation form (w_k = d . (B x C), ..., Ns, Nt of oracle/ray_triangle.hpp) are
// taken on double words one by one, and a sign too close to call counts as met: two certain
// opposite signs (or lambda certainly out of range) prove a miss (certain), and anything else
// is reported as a hit, uncertain, with WBW's values in F. A false miss is therefore
// impossible: a ray that meets the union of a mesh's closed triangles hits one of them, on
// every mesh, whatever each triangle's scale (this is stronger than WBW's own argument, which
// holds only while every triangle is evaluated by WBW). A false hit is possible only where the
// answer is uncertain: that is what campaigns count.
#pragma once

#include <cdref/book/ray_triangle.hpp>

#include "words.hpp"

namespace cdref::robust {

namespace detail {

// WBW on a scaled shot (lambda in [0, 1] when bounded). d = 0 (a zero-length segment) is a
// point test, the book's in F.
// With `values`, a miss still carries the values at the plane's crossing (or at the source):
// the caller reports an uncertain hit there.
template <class F>
TriangleCast<F> watertight(const Vec3<F>& s, const Vec3<F>& d, const Triangle<F>& tri, bool bounded,
                           bool values = false) {
  if (d[0] == F(0) && d[1] == F(0) && d[2] == F(0)) return book::detail::cast_triangle(s, d, tri, bounded, want_all);
  int kz = 0;
  for (int i = 1; i < 3; ++i)
    if (std::fabs(d[i]) > std::fabs(d[kz])) kz = i;
  const int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
  const F Sx = -d[kx] / d[kz], Sy = -d[ky] / d[kz], Sz = F(1) / d[kz];
  F px[3], py[3], pz[3];
  for (int k = 0; k < 3; ++k) {
    const Vec3<F> P = tri.vertex[k] - s;
    px[k] = P[kx] + Sx * P[kz];
    py[k] = P[ky] + Sy * P[kz];
    pz[k] = P[kz];
  }
  const F e[3] = {px[1] * py[2] - py[1] * px[2], px[2] * py[0] - py[2] * px[0], px[0] * py[1] - py[0] * px[1]};
  TriangleCast<F> r;
  const F det = e[0] + e[1] + e[2];
  if (det == F(0)) {
    if (e[0] == F(0) && e[1] == F(0) && e[2] == F(0)) return book::detail::cast_flat(s, d, tri, bounded, want_all);
    if (values) r.point = s;
    return r;
  }
  const F t = e[0] * (Sz * pz[0]) + e[1] * (Sz * pz[1]) + e[2] * (Sz * pz[2]);
  const bool out = ((e[0] < F(0) || e[1] < F(0) || e[2] < F(0)) && (e[0] > F(0) || e[1] > F(0) || e[2] > F(0))) ||
                   (det > F(0) ? (t < F(0) || (bounded && t > det)) : (t > F(0) || (bounded && t < det)));
  if (out && !values) return r;
  r.hit = !out;
  const F lambda = t / det;
  const F b0 = e[0] / det, b1 = e[1] / det, b2 = e[2] / det;
  r.lambda_enter = r.lambda_exit = lambda;
  r.enters = lambda != F(0);
  r.u = b1, r.v = b2;
  r.point = tri.vertex[0] * b0 + tri.vertex[1] * b1 + tri.vertex[2] * b2;
  const Vec3<F> n = Vec3<F>(tri.vertex[1] - tri.vertex[0]).cross(Vec3<F>(tri.vertex[2] - tri.vertex[0]));
  const F side = Vec3<F>(s - tri.vertex[0]).dot(n), nn = n.norm();
  if (side != F(0) && nn > F(0) && std::isfinite(nn)) r.normal = (side > F(0) ? n : Vec3<F>(-n)) / nn;
  return r;
}

template <class F>
TriangleCast<F> triangle_cast_value(const TriangleCast<W>& c) {
  TriangleCast<F> r;
  static_cast<Cast<F>&>(r) = cast_value<F>(c);
  r.u = value<F>(c.u);
  r.v = value<F>(c.v);
  return r;
}

// A sign on double words, or 2 when it is too close to call.
inline int sign_or_unknown(const W& x) {
  try {
    return x > W(0.0) ? 1 : (x < W(0.0) ? -1 : 0);
  } catch (const oracle::uncertain&) {
    return 2;
  }
}

// The orientation form on exact double words: 0 a proven miss, 1 a proven hit, 2 a sign too
// close to call (then no miss is proven).
template <class ShotW>
int orientation_hit(const ShotW& shot, const Triangle<W>& tri, bool bounded) {
  const Vec3<W> s = shot.source;
  const Vec3<W> d = [&] {
    if constexpr (std::is_same_v<ShotW, Ray<W>>)
      return shot.direction;
    else
      return Vec3<W>(shot.target - shot.source);
  }();
  const Vec3<W> A = tri.vertex[0] - s, B = tri.vertex[1] - s, C = tri.vertex[2] - s;
  const int w[3] = {sign_or_unknown(d.dot(Vec3<W>(B.cross(C)))), sign_or_unknown(d.dot(Vec3<W>(C.cross(A)))),
                    sign_or_unknown(d.dot(Vec3<W>(A.cross(B))))};
  bool pos = false, neg = false, unknown = false;
  for (int k : w) pos |= k == 1, neg |= k == -1, unknown |= k == 2;
  if (pos && neg) return 0;
  if (unknown || (!pos && !neg)) return 2;  // a sign too close to call, or the flat cases
  const int sD = pos ? 1 : -1;
  const Vec3<W> n = Vec3<W>(tri.vertex[1] - tri.vertex[0]).cross(Vec3<W>(tri.vertex[2] - tri.vertex[0]));
  const int ns = sign_or_unknown(A.dot(n));
  if (ns == -sD) return 0;  // lambda < 0
  int nt = -sD;
  if constexpr (!std::is_same_v<ShotW, Ray<W>>) {
    if (bounded) {
      nt = sign_or_unknown(Vec3<W>(tri.vertex[0] - shot.target).dot(n));
      if (nt == sD) return 0;  // lambda > 1
    }
  }
  return ns != 2 && nt != 2 ? 1 : 2;
}

template <class Shot, class F>
std::pair<TriangleCast<F>, Decision> triangle_cast_eval(const Shot& shot, const Triangle<F>& tri, bool bounded) {
  Scale used;
  const auto words = on_words(shot, tri, [](const auto& a, const auto& b) { return book::cast(a, b, want_all); }, &used);
  if (words) {
    TriangleCast<F> r = triangle_cast_value<F>(*words);
    r.point = Scale{-used.k}.len(r.point);
    return {r, {r.hit, true}};
  }
  const auto o = on_words(shot, tri, [bounded](const auto& a, const auto& b) { return orientation_hit(a, b, bounded); });
  if (o && *o == 0) return {TriangleCast<F>{}, {false, true}};
  // WBW's values in F, the shot and the triangle scaled
  const Scale sc = scale_of(shot, tri);
  const Shot ss = scaled(shot, sc);
  const Vec3<F> d = [&] {
    if constexpr (std::is_same_v<Shot, Ray<F>>)
      return ss.direction;
    else
      return Vec3<F>(ss.target - ss.source);
  }();
  TriangleCast<F> r = watertight(ss.source, d, scaled(tri, sc), bounded, true);
  r.hit = true;
  r.point = Scale{-sc.k}.len(r.point);
  return {r, {true, o && *o == 1}};
}

}  // namespace detail

template <class F>
TriangleCast<F> cast(const Segment<F>& seg, const Triangle<F>& tri) {
  check(seg, "segment");
  check(tri, "triangle");
  return detail::triangle_cast_eval(seg, tri, true).first;
}
template <class F>
TriangleCast<F> cast(const Ray<F>& ray, const Triangle<F>& tri) {
  check(ray, "ray");
  check(tri, "triangle");
  return detail::triangle_cast_eval(ray, tri, false).first;
}
template <class F>
Decision decide(const Segment<F>& seg, const Triangle<F>& tri) {
  check(seg, "segment");
  check(tri, "triangle");
  return detail::triangle_cast_eval(seg, tri, true).second;
}
template <class F>
Decision decide(const Ray<F>& ray, const Triangle<F>& tri) {
  check(ray, "ray");
  check(tri, "triangle");
  return detail::triangle_cast_eval(ray, tri, false).second;
}
template <class F>
bool hit(const Segment<F>& seg, const Triangle<F>& tri) {
  return decide(seg, tri).value;
}
template <class F>
bool hit(const Ray<F>& ray, const Triangle<F>& tri) {
  return decide(ray, tri).value;
}

}  // namespace cdref::robust
