// fuzz/families_triangles.cpp - the case families of the Section 3.4 queries: a sphere and a
// triangle (touching the triangle's face, an edge or a vertex, zero-area triangles); ray and
// segment casts on a triangle (aimed at an edge or a vertex, grazing the plane, in the plane,
// zero-area triangles); fans of triangles around a shared vertex or edge of a closed mesh (the
// watertight family).
//
// As in families.cpp, no expression takes two draws where C++ leaves their order open; the named
// locals are drawn in the order the g++ builds took them, so seeds keep their cases.
#include <cdref/fuzz/families.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "family_tools.hpp"

namespace cdref::fuzz {

namespace {

using namespace family;

// ---- a sphere and a triangle: centre, radius, v0, v1, v2 ----
void sphere_tri(Inputs& in, V c, double rho, V a, V b, V d) {
  put(in, 0, c);
  in[3] = rho;
  put(in, 4, a);
  put(in, 7, b);
  put(in, 10, d);
}
void sphere_tri_uniform(Inputs& in, Next& next) {
  const V c = uvec(next, -3, 3);
  const double rho = uni(next, 0.1, 2);
  const V d = uvec(next, -2, 2), b = uvec(next, -2, 2);
  return sphere_tri(in, c, rho, uvec(next, -2, 2), b, d);
}

// A triangle and a sphere whose closest point x is an interior point of the triangle, of an
// edge, or a vertex (kind 0, 1, 2), the centre at rho (1 + rel) from x along a direction of
// x's normal cone.
void sphere_tri_touching(Inputs& in, Next& next, double rel, V offset, int kind) {
  V a, b, d, n;
  do {
    a = offset + uvec(next, -2, 2), b = offset + uvec(next, -2, 2), d = offset + uvec(next, -2, 2);
    n = cross(b - a, d - a);
  } while (dot(n, n) < 1e-2);
  n = normalized(n);
  const double rho = uni(next, 0.25, 2);
  V x, dir;
  switch (kind) {
    case 0: {  // the face: x inside, along +-n
      double s = uni(next, 0.05, 0.9), t = uni(next, 0.05, 0.9);
      if (s + t > 0.95) s *= 0.5, t *= 0.5;
      x = a + s * (b - a) + t * (d - a);
      dir = sign(next) * n;
      break;
    }
    case 1: {  // the edge ab: x inside it, along a mix of +-n and the outward edge normal
      x = a + uni(next, 0.05, 0.95) * (b - a);
      V out = normalized(cross(b - a, n));
      if (dot(out, d - a) > 0) out = -1.0 * out;
      const double up = uni(next, -1, 1);
      dir = normalized(uni(next, 0.1, 1) * out + up * n);
      break;
    }
    default: {  // the vertex a: along a direction with (b - a) . dir <= 0 and (d - a) . dir <= 0
      x = a;
      for (;;) {
        dir = unit(next);
        if (dot(b - a, dir) < 0 && dot(d - a, dir) < 0) break;
      }
      break;
    }
  }
  return sphere_tri(in, x + (rho * (1 + rel)) * dir, rho, a, b, d);
}

// ---- a shot and a triangle: source, target (or direction), v0, v1, v2 ----
void shot_tri(Inputs& in, V s, V t, V a, V b, V d) {
  put(in, 0, s);
  put(in, 3, t);
  put(in, 6, a);
  put(in, 9, b);
  put(in, 12, d);
}
// The shot from s aimed at x, passing it by `over` (a segment's target lies beyond x by a factor
// in [1.1, 3] of |x - s|, or before it when `short_of`); a ray's direction is x - s.
void aimed(Inputs& in, Next& next, bool ray, V s, V x, V a, V b, V d) {
  const V dir = x - s;
  return shot_tri(in, s, ray ? dir : s + uni(next, 1.1, 3) * dir, a, b, d);
}
V random_triangle(Next& next, V offset, V& a, V& b, V& d) {
  V n;
  do {
    a = offset + uvec(next, -2, 2), b = offset + uvec(next, -2, 2), d = offset + uvec(next, -2, 2);
    n = cross(b - a, d - a);
  } while (dot(n, n) < 1e-2);
  return normalized(n);
}
void shot_tri_uniform(Inputs& in, Next& next, bool ray) {
  const V s = uvec(next, -3, 3);
  const V d = uvec(next, -2, 2), b = uvec(next, -2, 2), a = uvec(next, -2, 2);
  return shot_tri(in, s, ray ? unit(next) : uvec(next, -3, 3), a, b, d);
}
// Aimed at a point of an edge (kind 0) or at a vertex (kind 1), moved by rel (relative to the
// triangle's size) across the edge in the plane (outward for rel > 0), from a source on either
// side at distance 1 to 4.
void shot_tri_edge(Inputs& in, Next& next, bool ray, double rel, V offset, int kind) {
  V a, b, d;
  const V n = random_triangle(next, offset, a, b, d);
  V x, out;
  if (kind == 0) {
    x = a + uni(next, 0.05, 0.95) * (b - a);
    out = normalized(cross(b - a, n));
    if (dot(out, d - a) > 0) out = -1.0 * out;
  } else {
    x = a;
    out = normalized((a - b) + (a - d));
  }
  x = x + (rel * std::sqrt(dot(b - a, b - a))) * out;
  const V tilt = unit(next);
  const double amount = uni(next, -0.8, 0.8);
  const double side = sign(next);
  const V s = x + uni(next, 1, 4) * normalized(side * n + amount * tilt);
  return aimed(in, next, ray, s, x, a, b, d);
}
// Aimed at an interior point, the direction 2^-k radians from the triangle's plane.
void shot_tri_grazing(Inputs& in, Next& next, bool ray, int k) {
  V a, b, d;
  const V n = random_triangle(next, V{0, 0, 0}, a, b, d);
  double s1 = uni(next, 0.05, 0.9), s2 = uni(next, 0.05, 0.9);
  if (s1 + s2 > 0.95) s1 *= 0.5, s2 *= 0.5;
  const V x = a + s1 * (b - a) + s2 * (d - a);
  const V along = normalized(cross(n, unit(next)));
  const V dir = along + (sign(next) * std::ldexp(1.0, -k)) * n;
  return aimed(in, next, ray, x - uni(next, 1, 4) * dir, x, a, b, d);
}
// A triangle with small integer coordinates (in [-8, 8], of nonzero area), and points exactly in
// its plane: v0 + alpha e1 + beta e2 with alpha, beta = (j - low) / 4, j < count (exact in double).
struct LatticePlane {
  V a, b, d;
  explicit LatticePlane(Next& next) {
    auto ivec = [&] { return V{double(pick(next, 17)) - 8, double(pick(next, 17)) - 8, double(pick(next, 17)) - 8}; };
    V n;
    do {
      a = ivec(), b = ivec(), d = ivec();
      n = cross(b - a, d - a);
    } while (dot(n, n) == 0);
  }
  V point(Next& next, int count, int low) const {
    const double al = (double(pick(next, count)) - low) / 4, be = (double(pick(next, count)) - low) / 4;
    return a + al * (b - a) + be * (d - a);
  }
};
// A shot exactly in the plane of a lattice triangle.
void shot_tri_coplanar(Inputs& in, Next& next, bool ray) {
  const LatticePlane pl(next);
  const V a = pl.a, b = pl.b, d = pl.d;
  auto in_plane = [&] { return pl.point(next, 17, 6); };
  const V s = in_plane();
  V t = in_plane();
  if (ray && dot(t - s, t - s) == 0) t = s + (b - a);
  return shot_tri(in, s, ray ? t - s : t, a, b, d);
}

// ---- a shot and a fan of triangles around a shared vertex: source, target (or direction),
// n, closed, centre, ring r0..r7 ----
struct FanShape {
  V center;
  std::vector<V> ring;
  bool closed = false;
};
void shot_fan(Inputs& in, V s, V t, const FanShape& f) {
  put(in, 0, s);
  put(in, 3, t);
  in[6] = double(f.ring.size());
  in[7] = f.closed ? 1 : 0;
  put(in, 8, f.center);
  for (std::size_t i = 0; i < f.ring.size(); ++i) put(in, 11 + 3 * int(i), f.ring[i]);
}

// The unit sphere as an icosahedron subdivided twice (162 vertices, 320 faces, counter-
// clockwise seen from outside), and each vertex's one-ring in order.
struct Sphere320 {
  std::vector<V> v;
  std::vector<std::array<int, 3>> f;
  std::vector<std::vector<int>> ring;
};
const Sphere320& sphere320() {
  static const Sphere320 m = [] {
    Sphere320 r;
    const double g = (1 + std::sqrt(5.0)) / 2;
    r.v = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
           {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
    for (V& x : r.v) x = normalized(x);
    r.f = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
           {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
           {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
    for (int level = 0; level < 2; ++level) {
      std::map<std::pair<int, int>, int> mid;
      auto midpoint = [&](int a, int b) {
        const auto key = std::minmax(a, b);
        const auto it = mid.find(key);
        if (it != mid.end()) return it->second;
        r.v.push_back(normalized(0.5 * (r.v[a] + r.v[b])));
        return mid[key] = int(r.v.size()) - 1;
      };
      std::vector<std::array<int, 3>> next;
      for (const auto& t : r.f) {
        const int a = midpoint(t[0], t[1]), b = midpoint(t[1], t[2]), c = midpoint(t[2], t[0]);
        next.push_back({t[0], a, c});
        next.push_back({t[1], b, a});
        next.push_back({t[2], c, b});
        next.push_back({a, b, c});
      }
      r.f = next;
    }
    // one-rings: the faces (v, a, b) around v give the edges a -> b of a cycle
    r.ring.resize(r.v.size());
    std::vector<std::map<int, int>> succ(r.v.size());
    for (const auto& t : r.f)
      for (int k = 0; k < 3; ++k) succ[t[k]][t[(k + 1) % 3]] = t[(k + 2) % 3];
    for (std::size_t i = 0; i < r.v.size(); ++i) {
      int a = succ[i].begin()->first;
      for (std::size_t k = 0; k < succ[i].size(); ++k) {
        r.ring[i].push_back(a);
        a = succ[i][a];
      }
    }
    return r;
  }();
  return m;
}

// A random rotation (the matrix of a random unit quaternion), applied in double.
struct Rotation {
  V c0, c1, c2;
  V operator()(V x) const { return x.x * c0 + x.y * c1 + x.z * c2; }
};
Rotation random_rotation(Next& next) {
  double w, x, y, z, n;
  do {
    w = uni(next, -1, 1), x = uni(next, -1, 1), y = uni(next, -1, 1), z = uni(next, -1, 1);
    n = w * w + x * x + y * y + z * z;
  } while (n < 1e-2 || n > 1);
  n = std::sqrt(n);
  w /= n, x /= n, y /= n, z /= n;
  return {{1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)},
          {2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)},
          {2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)}};
}

// The watertight family: a fan of a closed mesh (the subdivided icosahedron, or a perturbed
// height grid), sized 10^[-3, 3], placed 10^k from the origin and turned at random, each vertex
// computed once in double (so the triangles share it exactly); the shot aimed at the shared
// vertex or at a point of an edge shared by two triangles (that point rounded), from a source
// near the surface (1 to 4 edge lengths) or far (10^3 to 10^4 sizes).
void shot_fan_watertight(Inputs& in, Next& next, bool ray, int k) {
  const double size = std::pow(10.0, uni(next, -3, 3));
  const V offset = std::pow(10.0, k) * unit(next);
  const Rotation rot = random_rotation(next);
  auto place = [&](V x) { return offset + rot(size * x); };
  FanShape f;
  V normal;
  if (pick(next, 2) == 0) {  // a vertex of the sphere and its one-ring (5 or 6 triangles)
    const Sphere320& m = sphere320();
    const int c = pick(next, int(m.v.size()));
    f.center = place(m.v[c]);
    for (int j : m.ring[c]) f.ring.push_back(place(m.v[j]));
    normal = rot(m.v[c]);
  } else {  // an interior vertex of a height grid: six triangles (one diagonal per cell)
    auto h = [&] { return uni(next, -0.3, 0.3); };
    auto jit = [&] { return uni(next, -0.2, 0.2); };
    f.center = place(V{jit(), jit(), h()});
    for (const V& q : {V{1, 0, 0}, V{1, 1, 0}, V{0, 1, 0}, V{-1, 0, 0}, V{-1, -1, 0}, V{0, -1, 0}})
      f.ring.push_back(place(V{q.x + jit(), q.y + jit(), h()}));
    normal = rot(V{0, 0, 1});
  }
  f.closed = true;
  V x = f.center;
  if (pick(next, 2) == 1) {  // a point of a shared edge: keep the two triangles that hold it
    const int j = pick(next, int(f.ring.size()));
    const int n = int(f.ring.size());
    x = f.center + uni(next, 0.05, 0.95) * (f.ring[j] - f.center);
    f.ring = {f.ring[(j + n - 1) % n], f.ring[j], f.ring[(j + 1) % n]};
    f.closed = false;
  }
  const double edge = size * 0.3;
  const double dist = pick(next, 2) == 0 ? uni(next, 1, 4) * edge : std::pow(10.0, uni(next, 3, 4)) * size;
  const V tilt = unit(next);
  const double amount = uni(next, -0.7, 0.7);
  const V dir = normalized(sign(next) * normal + amount * tilt);
  const V s = x + dist * dir;
  const V d = x - s;
  return shot_fan(in, s, ray ? d : x + uni(next, 0.1, 2) * d, f);
}
void shot_fan_uniform(Inputs& in, Next& next, bool ray) {
  FanShape f;
  f.center = uvec(next, -1, 1);
  const int n = 3 + pick(next, 6);
  const V axis_ = unit(next), u = perp(next, axis_), w = cross(axis_, u);
  for (int i = 0; i < n; ++i) {
    const double a = 6.283185307179586 * (i + uni(next, 0.1, 0.9)) / n, r = uni(next, 0.5, 2);
    f.ring.push_back(f.center + r * std::cos(a) * u + r * std::sin(a) * w + uni(next, -0.5, 0.5) * axis_);
  }
  f.closed = pick(next, 2) == 0;
  const V s = uvec(next, -3, 3);
  return shot_fan(in, s, ray ? unit(next) : uvec(next, -3, 3), f);
}

// ---- two triangles: a_v0, a_v1, a_v2, b_v0, b_v1, b_v2 ----
void tri_tri(Inputs& in, V a0, V a1, V a2, V b0, V b1, V b2) {
  put(in, 0, a0);
  put(in, 3, a1);
  put(in, 6, a2);
  put(in, 9, b0);
  put(in, 12, b1);
  put(in, 15, b2);
}
void tri_tri_uniform(Inputs& in, Next& next) {
  const V b2 = uvec(next, -2, 2), b1 = uvec(next, -2, 2), b0 = uvec(next, -2, 2);
  const V a2 = uvec(next, -2, 2), a1 = uvec(next, -2, 2);
  return tri_tri(in, uvec(next, -2, 2), a1, a2, b0, b1, b2);
}
// B's tip at a point x of A (interior, an edge or a vertex: kind 0, 1, 2) moved rel * size
// along A's normal (rel > 0: off A, on the side where B lies), B's other vertices on that side.
void tri_tri_touching(Inputs& in, Next& next, double rel, V offset, int kind) {
  V a, b, d;
  const V n = random_triangle(next, offset, a, b, d);
  V x;
  if (kind == 0) {
    double s1 = uni(next, 0.05, 0.9), s2 = uni(next, 0.05, 0.9);
    if (s1 + s2 > 0.95) s1 *= 0.5, s2 *= 0.5;
    x = a + s1 * (b - a) + s2 * (d - a);
  } else if (kind == 1) {
    x = a + uni(next, 0.05, 0.95) * (b - a);
  } else {
    x = a;
  }
  const double side = sign(next), size = std::sqrt(dot(b - a, b - a));
  auto up = [&] {
    const V tilt = unit(next);
    const double amount = uni(next, 0.5, 2);
    return x + (side * uni(next, 0.3, 2)) * n + amount * tilt;
  };
  V y1 = up(), y2 = up();
  // keep B's other vertices strictly on its side of A's plane
  if (side * dot(y1 - x, n) < 0.1) y1 = y1 + (side * (0.1 - side * dot(y1 - x, n))) * n;
  if (side * dot(y2 - x, n) < 0.1) y2 = y2 + (side * (0.1 - side * dot(y2 - x, n))) * n;
  return tri_tri(in, a, b, d, x + (side * rel * size) * n, y1, y2);
}
// B nearly parallel to A (tilted 2^-k) and overlapping it in projection, at a height near 0.
void tri_tri_parallel(Inputs& in, Next& next, int k) {
  V a, b, d;
  const V n = random_triangle(next, V{0, 0, 0}, a, b, d);
  const V c = (1.0 / 3) * (a + b + d);
  const V tilt = std::ldexp(1.0, -k) * perp(next, n);
  auto lift = [&](V p) { return p + (dot(p - c, tilt) + uni(next, -1, 1) * std::ldexp(1.0, -k)) * n; };
  const double off2 = uni(next, -1, 1);
  const V off = uni(next, -1, 1) * (b - a) + off2 * (d - a);
  const V b2 = lift(d + off + uvec(next, -0.5, 0.5));
  const V b1 = lift(b + off + uvec(next, -0.5, 0.5));
  return tri_tri(in, a, b, d, lift(a + off + uvec(next, -0.5, 0.5)), b1, b2);
}
// Two triangles exactly in one plane: a lattice triangle and one of points in its plane.
void tri_tri_coplanar(Inputs& in, Next& next) {
  const LatticePlane pl(next);
  auto in_plane = [&] { return pl.point(next, 13, 4); };
  const V b2 = in_plane(), b1 = in_plane();
  return tri_tri(in, pl.a, pl.b, pl.d, in_plane(), b1, b2);
}

}  // namespace

std::vector<Family> triangle_triangle_family_list() {
  std::vector<Family> f;
  f.push_back({"uniform", "all six vertices in [-2,2]^3", {0}, [](Next& next, int, Inputs& in) { return tri_tri_uniform(in, next); }});
  f.push_back({"near-touching",
               "B's tip 2^-k of A's size from A's face, an edge or a vertex (off it or through it), B's other "
               "vertices on one side",
               tangency_scales(), [](Next& next, int k, Inputs& in) {
                 const int kind = pick(next, 3);
                 return tri_tri_touching(in, next, sign(next) * std::ldexp(1.0, -k), V{0, 0, 0}, kind);
               }});
  f.push_back({"long-range", "touching to within 1e-9 of A's size, 10^k from the origin", decades(),
               [](Next& next, int k, Inputs& in) {
                 const int kind = pick(next, 3);
                 const V offset = std::pow(10.0, k) * unit(next);
                 return tri_tri_touching(in, next, uni(next, -1e-9, 1e-9), offset, kind);
               }});
  f.push_back({"near-parallel", "B tilted 2^-k from A's plane, within 2^-k of it, overlapping it in projection",
               tangency_scales(), [](Next& next, int k, Inputs& in) { return tri_tri_parallel(in, next, k); }});
  f.push_back({"coplanar", "two triangles exactly in one plane (integer vertices)", {0},
               [](Next& next, int, Inputs& in) { return tri_tri_coplanar(in, next); }});
  f.push_back({"degenerate",
               "zero-area triangles (collinear vertices, a point), triangles sharing a vertex or an edge, on the "
               "integer lattice",
               {0}, [](Next& next, int, Inputs& in) {
                 auto ivec = [&] {
                   return V{double(pick(next, 7)) - 3, double(pick(next, 7)) - 3, double(pick(next, 7)) - 3};
                 };
                 const V a = ivec(), b = ivec(), c = ivec(), d = ivec(), e = ivec(), g = ivec();
                 switch (pick(next, 5)) {
                   case 0: return tri_tri(in, a, b, a + 0.5 * (b - a), d, e, g);      // A collinear
                   case 1: return tri_tri(in, a, b, c, d, d, d);                      // B a point
                   case 2: return tri_tri(in, a, b, c, a, e, g);                      // a shared vertex
                   case 3: return tri_tri(in, a, b, c, b, a, g);                      // a shared edge
                   default: return tri_tri(in, a, b, a + 2.0 * (b - a), d, e, d + 0.5 * (e - d));  // two segments
                 }
               }});
  f.push_back({"magnitude", "the uniform family scaled by 10^k", magnitudes(),
               [](Next& next, int k, Inputs& in) { tri_tri_uniform(in, next); scaled(in, 18, k); }});
  return f;
}

std::vector<Family> fan_shot_family_list(bool ray) {
  std::vector<Family> f;
  f.push_back({"uniform",
               "a fan of 3 to 8 triangles around a centre in [-1,1]^3 (closed or open), the source (and target) in "
               "[-3,3]^3",
               {0}, [ray](Next& next, int, Inputs& in) { return shot_fan_uniform(in, next, ray); }});
  f.push_back({"degenerate",
               "fans on the integer lattice with zero-area triangles (a repeated or collinear ring vertex, the centre "
               "on the ring), shots through lattice points (a vertex, an edge), sources on the fan",
               {0}, [ray](Next& next, int, Inputs& in) {
                 auto ivec = [&] {
                   return V{double(pick(next, 7)) - 3, double(pick(next, 7)) - 3, double(pick(next, 7)) - 3};
                 };
                 FanShape f;
                 f.center = ivec();
                 const int n = 3 + pick(next, 4);
                 for (int i = 0; i < n; ++i) f.ring.push_back(ivec());
                 switch (pick(next, 3)) {
                   case 0: f.ring[1] = f.ring[0]; break;                                   // a repeated vertex
                   case 1: f.ring[1] = f.center + 2.0 * (f.ring[0] - f.center); break;     // collinear
                   default: f.center = f.ring[n - 1]; break;                               // the centre on the ring
                 }
                 f.closed = pick(next, 2) == 0;
                 const V x = pick(next, 2) == 0 ? f.ring[pick(next, n)] : 0.5 * (f.center + f.ring[pick(next, n)]);
                 V s = pick(next, 4) == 0 ? f.center : ivec();
                 if (dot(x - s, x - s) == 0) s = s + V{1, 2, 3};
                 return shot_fan(in, s, ray ? x - s : s + 2.0 * (x - s), f);
               }});
  f.push_back({"watertight",
               "a closed mesh's fan (a vertex's one-ring of the subdivided icosahedron or a height grid, or the two "
               "triangles of an edge), sized 10^[-3,3], 10^k from the origin; the shot aimed exactly at the shared "
               "vertex or at a point of the shared edge, from near or far",
               range(0, 6), [ray](Next& next, int k, Inputs& in) { return shot_fan_watertight(in, next, ray, k); }});
  return f;
}

std::vector<Family> triangle_shot_family_list(bool ray) {
  std::vector<Family> f;
  f.push_back({"uniform", ray ? "source in [-3,3]^3, a unit direction, vertices in [-2,2]^3"
                              : "source and target in [-3,3]^3, vertices in [-2,2]^3",
               {0}, [ray](Next& next, int, Inputs& in) { return shot_tri_uniform(in, next, ray); }});
  f.push_back({"near-edge", "aimed at a point of an edge or at a vertex, moved 2^-k of the edge's length across it",
               tangency_scales(), [ray](Next& next, int k, Inputs& in) {
                 const int kind = pick(next, 2);
                 return shot_tri_edge(in, next, ray, sign(next) * std::ldexp(1.0, -k), V{0, 0, 0}, kind);
               }});
  f.push_back({"long-range", "aimed at an edge or a vertex to within 1e-9, the triangle 10^k from the origin", decades(),
               [ray](Next& next, int k, Inputs& in) {
                 const int kind = pick(next, 2);
                 const V offset = std::pow(10.0, k) * unit(next);
                 return shot_tri_edge(in, next, ray, uni(next, -1e-9, 1e-9), offset, kind);
               }});
  f.push_back({"grazing", "aimed at an interior point, 2^-k radians from the triangle's plane", tangency_scales(),
               [ray](Next& next, int k, Inputs& in) { return shot_tri_grazing(in, next, ray, k); }});
  f.push_back({"coplanar", "a shot exactly in the plane of a triangle with integer vertices", {0},
               [ray](Next& next, int, Inputs& in) { return shot_tri_coplanar(in, next, ray); }});
  f.push_back({"degenerate",
               ray ? "zero-area triangles (collinear vertices, a point), the source on the triangle, slivers"
                   : "zero-area triangles (collinear vertices, a point), the source on the triangle, zero-length "
                     "segments, slivers",
               {0}, [ray](Next& next, int, Inputs& in) {
                 auto ivec = [&] {
                   return V{double(pick(next, 9)) - 4, double(pick(next, 9)) - 4, double(pick(next, 9)) - 4};
                 };
                 const V a = ivec(), b = ivec(), d = ivec();
                 // shots through points of the integer lattice, so that they meet edges exactly
                 const V s = ivec(), x = ivec();
                 const V dir = dot(x - s, x - s) == 0 ? V{1, 0, 0} : x - s;
                 auto shot = [&](V src, V dr, V p, V q, V r) { return shot_tri(in, src, ray ? dr : src + dr, p, q, r); };
                 switch (pick(next, ray ? 5 : 6)) {
                   case 0: return shot(s, dir, a, b, a + 0.5 * (b - a));                  // collinear
                   case 1: return shot(s, dir, x, x, x);                                  // a point on the shot
                   case 2: return shot(a + 0.25 * (b - a) + 0.25 * (d - a), dir, a, b, d);  // source on it
                   case 3: return shot(s, dir, a, b, b + std::ldexp(1.0, -40) * (d - b));   // a sliver
                   case 4: return shot(s, 2.0 * (x - s), x, b, d);                        // through a vertex
                   default: return shot(a + 0.5 * (b - a), V{0, 0, 0}, a, b, d);           // zero length, on an edge
                 }
               }});
  f.push_back({"magnitude", "the uniform family scaled by 10^k", magnitudes(),
               [ray](Next& next, int k, Inputs& in) { shot_tri_uniform(in, next, ray); scaled(in, 15, k); }});
  return f;
}

std::vector<Family> sphere_triangle_family_list() {
  std::vector<Family> f;
  f.push_back({"uniform", "centre in [-3,3]^3, radius in [0.1,2], vertices in [-2,2]^3", {0},
               [](Next& next, int, Inputs& in) { return sphere_tri_uniform(in, next); }});
  f.push_back({"near-touching", "touching the face, an edge or a vertex, at rho (1 +- 2^-k) from it", tangency_scales(),
               [](Next& next, int k, Inputs& in) {
                 const int kind = pick(next, 3);
                 return sphere_tri_touching(in, next, sign(next) * std::ldexp(1.0, -k), V{0, 0, 0}, kind);
               }});
  f.push_back({"long-range", "touching to within 1e-9 radii, 10^k from the origin", decades(), [](Next& next, int k, Inputs& in) {
                 const int kind = pick(next, 3);
                 const V offset = std::pow(10.0, k) * unit(next);
                 return sphere_tri_touching(in, next, uni(next, -1e-9, 1e-9), offset, kind);
               }});
  f.push_back({"degenerate", "zero-area triangles (a segment, a point), the centre on the triangle, radius 0, slivers",
               {0}, [](Next& next, int, Inputs& in) {
                 const V a = uvec(next, -2, 2), b = uvec(next, -2, 2), d = uvec(next, -2, 2);
                 const double rho = uni(next, 0.25, 2);
                 switch (pick(next, 5)) {
                   case 0: {  // collinear
                     const V e = a + uni(next, -1, 2) * (b - a);
                     return sphere_tri(in, uvec(next, -3, 3), rho, a, b, e);
                   }
                   case 1: return sphere_tri(in, uvec(next, -3, 3), rho, a, a, a);                              // a point
                   case 2: return sphere_tri(in, a + 0.3 * (b - a) + 0.3 * (d - a), rho, a, b, d);             // centre on it
                   case 3: return sphere_tri(in, uvec(next, -3, 3), 0.0, a, b, d);                              // radius 0
                   default: return sphere_tri(in, uvec(next, -3, 3), rho, a, b, b + std::ldexp(1.0, -40) * (d - b));  // a sliver
                 }
               }});
  f.push_back({"magnitude", "the uniform family scaled by 10^k", magnitudes(),
               [](Next& next, int k, Inputs& in) { sphere_tri_uniform(in, next); scaled(in, 13, k); }});
  return f;
}

}  // namespace cdref::fuzz
