// fuzz/families_sat.cpp - the case families of the Section 3.3 queries: triangles against
// boxes, oriented boxes against oriented boxes, and every Section 3.1-3.3 family against an
// axis-aligned box turned into one against an oriented box.
//
// Oriented boxes get random rotations (from a uniform random unit quaternion, its matrix
// rounded to doubles: orthonormal only to rounding, as every rotated box that reaches cdref).
// Where the axis-aligned families place a primitive relative to a box (touching a face, an
// edge, a corner, grazing, parallel to a face), the oriented family places it the same way
// in the box's frame and moves the whole case with the box's rotation, so "2^-k from a face"
// survives (up to the rotation's rounding).
//
// As in families.cpp, no expression takes two draws where C++ leaves their order open; the named
// locals are drawn in the order the g++ builds took them, so seeds keep their cases.
#include <cdref/fuzz/families.hpp>
#include <cmath>

#include "family_tools.hpp"

namespace cdref::fuzz {

namespace {

using namespace family;

// ---- rotations ----
struct Rot {
  V col[3];  // the axes
  V apply(V p) const { return p.x * col[0] + (p.y * col[1] + p.z * col[2]); }
};
Rot rotation(Next& next) {
  double w, x, y, z, n;
  do {
    w = uni(next, -1, 1), x = uni(next, -1, 1), y = uni(next, -1, 1), z = uni(next, -1, 1);
    n = w * w + x * x + y * y + z * z;
  } while (n < 1e-2 || n > 1);
  const double s = 1 / std::sqrt(n);
  w *= s, x *= s, y *= s, z *= s;
  Rot r;
  r.col[0] = {1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)};
  r.col[1] = {2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)};
  r.col[2] = {2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)};
  return r;
}
// A rotation by the angle t about a random axis (Rodrigues), for near-parallel frames.
Rot small_rotation(Next& next, double t) {
  const V k = unit(next);
  const double c = std::cos(t), s = std::sin(t), C = 1 - c;
  Rot r;
  r.col[0] = {c + k.x * k.x * C, k.y * k.x * C + k.z * s, k.z * k.x * C - k.y * s};
  r.col[1] = {k.x * k.y * C - k.z * s, c + k.y * k.y * C, k.z * k.y * C + k.x * s};
  r.col[2] = {k.x * k.z * C + k.y * s, k.y * k.z * C - k.x * s, c + k.z * k.z * C};
  return r;
}
Rot compose(const Rot& a, const Rot& b) {  // a after b
  Rot r;
  for (int i = 0; i < 3; ++i) r.col[i] = a.apply(b.col[i]);
  return r;
}
// A signed permutation: exactly orthonormal in floats.
Rot signed_permutation(Next& next) {
  static const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  const int* p = perms[pick(next, 6)];
  Rot r;
  for (int i = 0; i < 3; ++i) r.col[i] = axis(p[i], sign(next));
  return r;
}

struct Obb {
  V c, h;
  Rot r;
  // the projection radius on the direction L
  double radius(V L) const {
    return h.x * std::fabs(dot(r.col[0], L)) + h.y * std::fabs(dot(r.col[1], L)) + h.z * std::fabs(dot(r.col[2], L));
  }
};
void put_obb(Inputs& in, int k, const Obb& b) {
  put(in, k, b.c);
  put(in, k + 3, b.h);
  for (int i = 0; i < 3; ++i) put(in, k + 6 + 3 * i, b.r.col[i]);
}
V comp(V v, int i) { return i == 0 ? V{v.x, 0, 0} : (i == 1 ? V{0, v.y, 0} : V{0, 0, v.z}); }
double at(V v, int i) { return i == 0 ? v.x : (i == 1 ? v.y : v.z); }

// ---- a triangle and an axis-aligned box: v0, v1, v2, box centre, box extent ----
void tri_box(Inputs& in, V a, V b, V c, V bc, V bh) {
  put(in, 0, a);
  put(in, 3, b);
  put(in, 6, c);
  put(in, 9, bc);
  put(in, 12, bh);
}
void tri_box_uniform(Inputs& in, Next& next) {
  const V bc = uvec(next, -1, 1), bh = uvec(next, 0.1, 2);
  const V c = uvec(next, -3, 3), b = uvec(next, -3, 3);
  return tri_box(in, uvec(next, -3, 3), b, c, bc, bh);
}
// A triangle touching the box to within `rel` (of the box's size): a vertex near a face, the
// triangle's plane near a corner, or an edge near an edge (the grazing case).
void tri_box_touching(Inputs& in, Next& next, double rel, V offset, int kind) {
  const V bc = offset + uvec(next, -1, 1), bh = uvec(next, 0.1, 2);
  const double size = std::sqrt(dot(bh, bh));
  V s{sign(next), sign(next), sign(next)};  // the corner or the edge's side
  const V corner = bc + V{s.x * bh.x, s.y * bh.y, s.z * bh.z};
  switch (kind) {
    case 0: {  // a vertex near face i, the others farther out
      const int i = pick(next, 3);
      V p = bc;
      for (int j = 0; j < 3; ++j)
        p = p + (j == i ? axis(j, at(s, j) * at(bh, j)) : axis(j, uni(next, -at(bh, j), at(bh, j))));
      const V n = axis(i, at(s, i));
      const V v0 = p + (rel * size) * n;
      const V t = perp(next, n);
      const double d1 = uni(next, 0.2, 2), d2 = uni(next, 0.2, 2);
      return tri_box(in, v0, v0 + d1 * (n + t), v0 + d2 * (n - t), bc, bh);
    }
    case 1: {  // the plane through a corner, its normal pointing out of the box
      V n = {s.x * uni(next, 0.2, 1), s.y * uni(next, 0.2, 1), s.z * uni(next, 0.2, 1)};
      n = normalized(n);
      const V p = corner + (rel * size) * n;
      const V t1 = perp(next, n), t2 = cross(n, t1);
      const double c2 = uni(next, 0.5, 3), c1 = uni(next, 0.5, 3);  // the third vertex's
      const double b2 = uni(next, 0.5, 3), b1 = uni(next, 0.5, 3);  // the second's
      const double a1 = uni(next, 0.5, 3);
      return tri_box(in, p + a1 * t1, p - b1 * t1 + b2 * t2, p - c1 * t1 - c2 * t2, bc, bh);
    }
    default: {  // an edge passing a box edge (along axis i) at rel * size
      const int i = pick(next, 3);
      V p = corner - axis(i, at(s, i) * at(bh, i)) + axis(i, uni(next, -at(bh, i), at(bh, i)));  // on the box edge
      // the outward bisector of the two faces at that edge
      V out = V{s.x, s.y, s.z} - axis(i, at(s, i));
      out = normalized(out);
      const V e_dir = normalized(axis(i, 1) + uni(next, -2, 2) * cross(axis(i, 1), out));  // skew to the box edge
      const V q = p + (rel * size) * out;
      const double l0 = uni(next, 0.5, 3), l1 = uni(next, 0.5, 3);
      const double along = uni(next, -1, 1), away = uni(next, 0.5, 3);
      return tri_box(in, q - l0 * e_dir, q + l1 * e_dir, q + away * out + along * e_dir, bc, bh);
    }
  }
}

// v turned by the angle t about the unit axis k.
V turned(V v, V k, double t) {
  const double c = std::cos(t), sn = std::sin(t);
  return c * v + (sn * cross(k, v) + ((1 - c) * dot(k, v)) * k);
}

// A triangle in a face's plane turned by 2^-k radians about an axis in that plane, its nearest
// point within 1e-9 box sizes of the face (out or in).
void tri_box_near_parallel(Inputs& in, Next& next, int k) {
  const V bc = uvec(next, -1, 1), bh = uvec(next, 0.1, 2);
  const double size = std::sqrt(dot(bh, bh));
  const int i = pick(next, 3);
  const double sg = sign(next);
  const V n = axis(i, sg);
  const V in_plane = normalized(cross(n, unit(next)));
  const V m = turned(n, in_plane, std::ldexp(1.0, -k));  // the triangle's normal
  const V t1 = normalized(cross(m, in_plane)), t2 = cross(m, t1);
  const V p = bc + axis(i, sg * at(bh, i)) + uni(next, -1e-9, 1e-9) * size * n;  // on the face plane
  V v[3];
  for (V& x : v) {
    const double b = uni(next, -2, 2);
    x = p + uni(next, -2, 2) * t1 + b * t2;
  }
  // lift the triangle so that its lowest vertex (towards the box) sits at p's height along n
  double low = dot(v[0] - p, n);
  for (const V& x : v) low = std::min(low, dot(x - p, n));
  for (V& x : v) x = x - low * n;
  return tri_box(in, v[0], v[1], v[2], bc, bh);
}

// A segment (or ray) along a box edge's direction turned by 2^-k radians, passing the edge
// within 1e-9 box sizes outside or inside (layout of the box-shot families).
void shot_near_parallel(Inputs& in, Next& next, int k, bool ray) {
  const V bc = uvec(next, -1, 1), bh = uvec(next, 0.1, 2);
  const double size = std::sqrt(dot(bh, bh));
  const int i = pick(next, 3);
  const V s{sign(next), sign(next), sign(next)};
  const V corner = bc + V{s.x * bh.x, s.y * bh.y, s.z * bh.z} - axis(i, at(s, i) * at(bh, i));
  V out = V{s.x, s.y, s.z} - axis(i, at(s, i));
  out = normalized(out);
  const V d = turned(axis(i, 1), normalized(cross(axis(i, 1), unit(next))), std::ldexp(1.0, -k));
  const V along = axis(i, uni(next, -at(bh, i), at(bh, i)));
  const V mid = corner + uni(next, -1e-9, 1e-9) * size * out + along;
  const double l = uni(next, 1, 4) * size;
  put(in, 0, mid - l * d);
  put(in, 3, ray ? d : mid + l * d);
  put(in, 6, bc);
  put(in, 9, bh);
}

}  // namespace

std::vector<Family> segment_box_family_list(bool ray) {
  std::vector<Family> f = box_shot_family_list(ray);
  f.push_back({"near-parallel", "along a box edge turned by 2^-k radians, passing it within 1e-9 box sizes",
               range(4, 52, 4), [ray](Next& next, int k, Inputs& in) { return shot_near_parallel(in, next, k, ray); }});
  return f;
}

std::vector<Family> triangle_box_family_list() {
  std::vector<Family> f;
  f.push_back({"uniform", "box centre in [-1,1]^3, extent in [0.1,2]^3; vertices in [-3,3]^3", {0},
               [](Next& next, int, Inputs& in) { return tri_box_uniform(in, next); }});
  f.push_back({"near-touching", "a vertex near a face or the plane near a corner, 2^-k box sizes apart or in",
               tangency_scales(), [](Next& next, int k, Inputs& in) {
                 const int kind = pick(next, 2);
                 return tri_box_touching(in, next, sign(next) * std::ldexp(1.0, -k), V{0, 0, 0}, kind);
               }});
  f.push_back({"grazing", "an edge passing a box edge 2^-k box sizes outside or inside", tangency_scales(),
               [](Next& next, int k, Inputs& in) { return tri_box_touching(in, next, sign(next) * std::ldexp(1.0, -k), V{0, 0, 0}, 2); }});
  f.push_back({"near-parallel", "in a face's plane turned by 2^-k radians, within 1e-9 box sizes of the face",
               range(4, 52, 4), [](Next& next, int k, Inputs& in) { return tri_box_near_parallel(in, next, k); }});
  f.push_back({"long-range", "touching to within 1e-9 box sizes, 10^k from the origin", decades(), [](Next& next, int k, Inputs& in) {
                 const int kind = pick(next, 3);
                 const V offset = std::pow(10.0, k) * unit(next);
                 return tri_box_touching(in, next, uni(next, -1e-9, 1e-9), offset, kind);
               }});
  f.push_back({"degenerate", "zero-area triangles (a segment, a point), flat boxes, coplanar with a face", {0},
               [](Next& next, int, Inputs& in) {
                 const V bc = uvec(next, -1, 1), bh = uvec(next, 0.1, 2);
                 const V a = uvec(next, -3, 3), b = uvec(next, -3, 3);
                 switch (pick(next, 4)) {
                   case 0: return tri_box(in, a, b, a + uni(next, -1, 2) * (b - a), bc, bh);  // collinear
                   case 1: return tri_box(in, a, a, a, bc, bh);                             // a point
                   case 2: {  // a flat box, a triangle in its plane
                     V h = bh;
                     const int i = pick(next, 3);
                     h = h - comp(h, i);
                     V p = a - comp(a, i) + comp(bc, i), q = b - comp(b, i) + comp(bc, i);
                     V r = uvec(next, -3, 3);
                     r = r - comp(r, i) + comp(bc, i);
                     return tri_box(in, p, q, r, bc, h);
                   }
                   default: {  // in a face's plane
                     const int i = pick(next, 3);
                     const V face = comp(bc, i) + axis(i, sign(next) * at(bh, i));
                     V p = a - comp(a, i) + face, q = b - comp(b, i) + face, r = uvec(next, -3, 3);
                     r = r - comp(r, i) + face;
                     return tri_box(in, p, q, r, bc, bh);
                   }
                 }
               }});
  f.push_back({"magnitude", "the uniform family scaled by 10^k", magnitudes(),
               [](Next& next, int k, Inputs& in) { tri_box_uniform(in, next); scaled(in, 15, k); }});
  return f;
}

// ---- one oriented box against another: two of centre, extent, axis0, axis1, axis2 ----
namespace {

void two_obbs(Inputs& in, const Obb& a, const Obb& b) {
  put_obb(in, 0, a);
  put_obb(in, 15, b);
}
Obb random_obb(Next& next, V c) { return {c, uvec(next, 0.1, 2), rotation(next)}; }

// B placed against A along a candidate axis (a face of A or B, or an edge cross) at the
// sum of their radii times 1 + rel, shifted at random across the axis by less than both.
void obbs_touching(Inputs& in, Next& next, double rel, V offset, int kind, const Rot* rb = nullptr) {
  const Obb A = random_obb(next, offset + uvec(next, -1, 1));
  const Obb B0{V{0, 0, 0}, uvec(next, 0.1, 2), rb ? compose(*rb, A.r) : rotation(next)};
  Obb B = B0;
  V L;
  if (kind == 0)
    L = pick(next, 2) ? A.r.col[pick(next, 3)] : B.r.col[pick(next, 3)];
  else {
    const int j = pick(next, 3);
    L = cross(A.r.col[pick(next, 3)], B.r.col[j]);
    if (dot(L, L) < 1e-20) L = A.r.col[0];
  }
  L = sign(next) * normalized(L);
  const double d = (A.radius(L) + B.radius(L)) * (1 + rel);
  B.c = A.c + d * L;
  return two_obbs(in, A, B);
}

void obbs_uniform(Inputs& in, Next& next) {
  const Obb A = random_obb(next, uvec(next, -2, 2));
  const Obb B = random_obb(next, uvec(next, -2, 2));
  return two_obbs(in, A, B);
}

void scaled_obbs(Inputs& in, int k) {
  const double f = std::pow(10.0, k);
  for (int base : {0, 15})
    for (int i = 0; i < 6; ++i) in[base + i] *= f;  // centres and extents; the axes stay
}

}  // namespace

std::vector<Family> obb_obb_family_list() {
  std::vector<Family> f;
  f.push_back({"uniform", "centres in [-2,2]^3, extents in [0.1,2]^3, random rotations", {0},
               [](Next& next, int, Inputs& in) { return obbs_uniform(in, next); }});
  f.push_back({"near-touching", "placed along a face normal at the sum of the radii times 1 +- 2^-k",
               tangency_scales(), [](Next& next, int k, Inputs& in) { return obbs_touching(in, next, sign(next) * std::ldexp(1.0, -k), V{0, 0, 0}, 0); }});
  f.push_back({"grazing", "placed along an edge cross a_i x b_j at the sum of the radii times 1 +- 2^-k (edge-edge)",
               tangency_scales(), [](Next& next, int k, Inputs& in) { return obbs_touching(in, next, sign(next) * std::ldexp(1.0, -k), V{0, 0, 0}, 1); }});
  f.push_back({"near-parallel", "B's frame A's turned by 2^-k radians, placed face or edge to face 1e-9 apart or in",
               range(4, 52, 4), [](Next& next, int k, Inputs& in) {
                 const Rot t = small_rotation(next, std::ldexp(1.0, -k));
                 const int kind = pick(next, 2);
                 return obbs_touching(in, next, uni(next, -1e-9, 1e-9), V{0, 0, 0}, kind, &t);
               }});
  f.push_back({"long-range", "placed face or edge to face within 1e-9 of touching, 10^k from the origin", decades(),
               [](Next& next, int k, Inputs& in) {
                 const int kind = pick(next, 2);
                 const V offset = std::pow(10.0, k) * unit(next);
                 return obbs_touching(in, next, uni(next, -1e-9, 1e-9), offset, kind);
               }});
  f.push_back({"degenerate", "zero extents, identical boxes, signed-permutation frames touching exactly", {0},
               [](Next& next, int, Inputs& in) {
                 Obb A = random_obb(next, uvec(next, -1, 1));
                 switch (pick(next, 4)) {
                   case 0: {  // zero extents along some axes
                     Obb B = random_obb(next, uvec(next, -2, 2));
                     if (pick(next, 2)) A.h = comp(A.h, pick(next, 3));
                     if (pick(next, 2)) B.h = V{0, 0, 0};
                     return two_obbs(in, A, B);
                   }
                   case 1: return two_obbs(in, A, A);
                   case 2: {  // exactly orthonormal frames, faces touching exactly (dyadic values)
                     Obb a{V{double(pick(next, 5)), double(pick(next, 5)), 0}, V{1, 2, 0.5}, signed_permutation(next)};
                     Obb b{a.c, V{0.5, 1, 2}, signed_permutation(next)};
                     const int i = pick(next, 3);
                     const V L = axis(i, sign(next));
                     b.c = a.c + (a.radius(L) + b.radius(L)) * L;
                     return two_obbs(in, a, b);
                   }
                   default: {  // B inside A
                     Obb B{A.c, 0.25 * A.h, rotation(next)};
                     return two_obbs(in, A, B);
                   }
                 }
               }});
  f.push_back({"magnitude", "the uniform family's centres and extents scaled by 10^k", magnitudes(),
               [](Next& next, int k, Inputs& in) { obbs_uniform(in, next); scaled_obbs(in, k); }});
  return f;
}

// ---- an axis-aligned family turned into one against an oriented box ----
// `points` are the input offsets of the case's points, `vectors` those of its directions,
// `scalars` those copied as they are (a radius), `center` and `extent` the box's; the oriented
// case keeps the primitive's offsets and writes centre, extent and the three axes at
// `box_at`. One case in eight gets a signed permutation (an exactly orthonormal frame, where
// the book's frame transform is exact) instead of a random rotation.
std::vector<Family> rotated_family_list(std::vector<Family> base, std::vector<int> points, std::vector<int> vectors,
                                        std::vector<int> scalars, int center, int extent, int box_at) {
  std::vector<Family> out;
  for (Family& f : base) {
    auto make = f.make;
    out.push_back({f.name, f.describe + "; the box turned by a random rotation", f.scales,
                   [make, points, vectors, scalars, center, extent, box_at](Next& next, int k, Inputs& o) {
                     Inputs in{};
                     make(next, k, in);
                     const Rot r = pick(next, 8) == 0 ? signed_permutation(next) : rotation(next);
                     const V c{in[center], in[center + 1], in[center + 2]};
                     for (int p : points) put(o, p, c + r.apply(V{in[p], in[p + 1], in[p + 2]} - c));
                     for (int v : vectors) put(o, v, r.apply(V{in[v], in[v + 1], in[v + 2]}));
                     for (int x : scalars) o[x] = in[x];
                     put_obb(o, box_at, Obb{c, V{in[extent], in[extent + 1], in[extent + 2]}, r});
                   }});
  }
  return out;
}

}  // namespace cdref::fuzz
