// fuzz/families_polygons.cpp - the case families of the Section 3.4 polygon queries: convex
// planar polygons of 3 to 8 vertices in random planes (rounded to double, so planar to rounding:
// the fan of the vertex list is what the query answers), shots aimed at their edges and at the
// fan's diagonals, spheres and boxes touching them, two polygons touching; degenerate vertex
// lists (repeated, collinear, not convex, not planar) on the integer lattice.
//
// As in families.cpp, no expression takes two draws where C++ leaves their order open; the named
// locals are drawn in the order the g++ builds took them, so seeds keep their cases.
#include <cdref/fuzz/families.hpp>
#include <cmath>

#include "family_tools.hpp"

namespace cdref::fuzz {

namespace {

using namespace family;

struct Poly {
  std::vector<V> v;
  V n;  // unit normal of the plane it was made in
};
// A convex polygon of 3..8 vertices around c, radius r, in a random plane.
Poly convex_polygon(Next& next, V c, double r) {
  Poly p;
  p.n = unit(next);
  const V u = perp(next, p.n), w = cross(p.n, u);
  const int n = 3 + pick(next, 6);
  for (int i = 0; i < n; ++i) {
    const double a = 6.283185307179586 * (i + uni(next, 0.15, 0.85)) / n, rr = r * uni(next, 0.6, 1);
    p.v.push_back(c + (rr * std::cos(a)) * u + (rr * std::sin(a)) * w);
  }
  return p;
}
void put_polygon(Inputs& in, int k, const std::vector<V>& v) {
  in[k] = double(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) put(in, k + 1 + 3 * int(i), v[i]);
}
// A degenerate vertex list on the integer lattice: a repeated vertex, three collinear, a reflex
// vertex (not convex), a vertex off the plane (not planar), or all collinear.
std::vector<V> degenerate_polygon(Next& next) {
  auto ivec = [&] { return V{double(pick(next, 7)) - 3, double(pick(next, 7)) - 3, double(pick(next, 7)) - 3}; };
  const V a = ivec(), b = ivec(), c = ivec();
  switch (pick(next, 5)) {
    case 0: return {a, b, b, c};                                  // repeated
    case 1: return {a, a + 0.5 * (b - a), b, c};                  // collinear
    case 2: return {a, b, a + 0.25 * (b - a) + 0.25 * (c - a), c};  // reflex at the third vertex
    case 3: return {a, b, c, a + (c - b) + V{0, 0, 1}};           // not planar
    default: return {a, a + (b - a), a + 2.0 * (b - a)};          // all collinear
  }
}

// ---- a shot and a polygon: source, target (or direction), n, p0..p7 ----
void shot_poly(Inputs& in, V s, V t, const std::vector<V>& v) {
  put(in, 0, s);
  put(in, 3, t);
  put_polygon(in, 6, v);
}
// A convex polygon of radius 0.5 to 2 around a centre in [-w, w]^3.
Poly random_polygon(Next& next, double w) {
  const double r = uni(next, 0.5, 2);
  return convex_polygon(next, uvec(next, -w, w), r);
}
void shot_poly_uniform(Inputs& in, Next& next, bool ray) {
  const Poly p = random_polygon(next, 1);
  const V s = uvec(next, -3, 3);
  return shot_poly(in, s, ray ? unit(next) : uvec(next, -3, 3), p.v);
}
// Aimed at a point of an edge or of a fan diagonal v0 - v_i (kind 0, 1), or at a vertex (2),
// moved rel * size across it in the plane, from a source 1 to 4 sizes away.
void shot_poly_edge(Inputs& in, Next& next, bool ray, double rel, V offset, int kind) {
  const double size = uni(next, 0.5, 2);
  const Poly p = convex_polygon(next, offset, size);
  const int n = int(p.v.size());
  V a, b;
  if (kind == 1 && n > 3) {
    a = p.v[0], b = p.v[2 + pick(next, n - 3)];
  } else {
    const int i = pick(next, n);
    a = p.v[i], b = p.v[(i + 1) % n];
  }
  V x = kind == 2 ? a : a + uni(next, 0.05, 0.95) * (b - a);
  x = x + (rel * size) * normalized(cross(b - a, p.n));
  const V tilt = unit(next);
  const double amount = uni(next, -0.8, 0.8);
  const double side = sign(next);
  const V s = x + uni(next, 1, 4) * size * normalized(side * p.n + amount * tilt);
  const V d = x - s;
  return shot_poly(in, s, ray ? d : s + uni(next, 1.1, 3) * d, p.v);
}

// ---- two polygons: a_n, a_p0..a_p7, b_n, b_p0..b_p7 ----
void poly_poly(Inputs& in, const std::vector<V>& a, const std::vector<V>& b) {
  put_polygon(in, 0, a);
  put_polygon(in, 25, b);
}
void poly_poly_uniform(Inputs& in, Next& next) {
  const Poly b = random_polygon(next, 1);
  return poly_poly(in, random_polygon(next, 1).v, b.v);
}
// B's vertex 0 at a point of A (inside, or on a fan diagonal) moved rel * size along A's normal,
// B's other vertices on that side.
void poly_poly_touching(Inputs& in, Next& next, double rel, V offset) {
  const double size = uni(next, 0.5, 2);
  const Poly a = convex_polygon(next, offset, size);
  const int n = int(a.v.size());
  const V toward = a.v[1 + pick(next, n - 1)];
  const V x = a.v[0] + uni(next, 0.1, 0.9) * (toward - a.v[0]);
  const double side = sign(next);
  Poly b = convex_polygon(next, x, size);
  // turn B so that it leaves x on one side of A: put x first, lift the others
  std::vector<V> bv{x + (side * rel * size) * a.n};
  for (std::size_t i = 1; i < b.v.size(); ++i) {
    V y = b.v[i];
    const double h = dot(y - x, a.n) * side;
    if (h < 0.2 * size) y = y + (side * (0.2 * size - h)) * a.n;
    bv.push_back(y);
  }
  return poly_poly(in, a.v, bv);
}

// ---- a polygon and a box: n, p0..p7, box_center, box_extent ----
void poly_box(Inputs& in, const std::vector<V>& v, V c, V h) {
  put_polygon(in, 0, v);
  put(in, 25, c);
  put(in, 28, h);
}
void poly_box_uniform(Inputs& in, Next& next) {
  const V h = uvec(next, 0.1, 1.5), c = uvec(next, -1, 1);
  return poly_box(in, random_polygon(next, 2).v, c, h);
}
// A polygon in a plane that touches the box at a corner (or along an edge, for a plane that
// holds an edge direction), moved rel * size along its normal.
void poly_box_touching(Inputs& in, Next& next, double rel, V offset) {
  const V c = offset + uvec(next, -1, 1), h = uvec(next, 0.2, 1.5);
  const double size = uni(next, 0.5, 2);
  Poly p = convex_polygon(next, V{0, 0, 0}, size);
  // the corner of the box furthest along -n (its support point), and the plane through it
  const V n = p.n;
  const V corner{c.x - (n.x > 0 ? h.x : -h.x), c.y - (n.y > 0 ? h.y : -h.y), c.z - (n.z > 0 ? h.z : -h.z)};
  const V at = corner - (rel * size) * n;  // rel > 0: off the box
  std::vector<V> v;
  const V across = perp(next, n);
  const V shift = uni(next, -0.5, 0.5) * size * across;
  for (const V& q : p.v) v.push_back(at + q + shift);
  return poly_box(in, v, c, h);
}

// ---- a polygon and a sphere: n, p0..p7, center, radius ----
void poly_sphere(Inputs& in, const std::vector<V>& v, V c, double rho) {
  put_polygon(in, 0, v);
  put(in, 25, c);
  in[28] = rho;
}
void poly_sphere_uniform(Inputs& in, Next& next) {
  const double rho = uni(next, 0.1, 2);
  const V c = uvec(next, -3, 3);
  return poly_sphere(in, random_polygon(next, 1).v, c, rho);
}
// The sphere touching the polygon at an interior point (along the normal) or at a vertex (along
// a direction away from the polygon), at rho (1 + rel).
void poly_sphere_touching(Inputs& in, Next& next, double rel, V offset) {
  const double size = uni(next, 0.5, 2);
  const Poly p = convex_polygon(next, offset, size);
  const double rho = uni(next, 0.25, 2);
  V x, dir;
  if (pick(next, 2) == 0) {
    const int n = int(p.v.size());
    const V toward = p.v[1 + pick(next, n - 2)];
    x = p.v[0] + uni(next, 0.1, 0.8) * (toward - p.v[0]) + 0.1 * (p.v[2] - p.v[1]);
    dir = sign(next) * p.n;
  } else {
    const int i = pick(next, int(p.v.size()));
    x = p.v[i];
    const V centroid = (1.0 / 3) * (p.v[0] + p.v[1] + p.v[2]);
    dir = normalized(x - centroid);
  }
  return poly_sphere(in, p.v, x + (rho * (1 + rel)) * dir, rho);
}

}  // namespace

std::vector<Family> polygon_shot_family_list(bool ray) {
  std::vector<Family> f;
  f.push_back({"uniform", "a convex polygon of 3 to 8 vertices (radius 0.5 to 2, centre in [-1,1]^3), the shot in [-3,3]^3",
               {0}, [ray](Next& next, int, Inputs& in) { return shot_poly_uniform(in, next, ray); }});
  f.push_back({"near-edge",
               "aimed at a point of an edge or of a fan diagonal v0 - v_i, or at a vertex, moved 2^-k of the size "
               "across it",
               tangency_scales(), [ray](Next& next, int k, Inputs& in) {
                 const int kind = pick(next, 3);
                 return shot_poly_edge(in, next, ray, sign(next) * std::ldexp(1.0, -k), V{0, 0, 0}, kind);
               }});
  f.push_back({"long-range", "aimed at an edge, a diagonal or a vertex to within 1e-9, 10^k from the origin", decades(),
               [ray](Next& next, int k, Inputs& in) {
                 const int kind = pick(next, 3);
                 const V offset = std::pow(10.0, k) * unit(next);
                 return shot_poly_edge(in, next, ray, uni(next, -1e-9, 1e-9), offset, kind);
               }});
  f.push_back({"degenerate", "vertex lists on the integer lattice: repeated, collinear, not convex, not planar", {0},
               [ray](Next& next, int, Inputs& in) {
                 const std::vector<V> v = degenerate_polygon(next);
                 const V s{double(pick(next, 9)) - 4, double(pick(next, 9)) - 4, 5};
                 const V x = v[pick(next, int(v.size()))];
                 const V d = dot(x - s, x - s) == 0 ? V{0, 0, -1} : x - s;
                 return shot_poly(in, s, ray ? d : s + 2.0 * d, v);
               }});
  f.push_back({"magnitude", "the uniform family scaled by 10^k", magnitudes(),
               [ray](Next& next, int k, Inputs& in) {
                 shot_poly_uniform(in, next, ray);
                 const double n = in[6];
                 scaled(in, 31, k);
                 in[6] = n;
               }});
  return f;
}

std::vector<Family> polygon_polygon_family_list() {
  std::vector<Family> f;
  f.push_back({"uniform", "two convex polygons of 3 to 8 vertices, radius 0.5 to 2, centres in [-1,1]^3", {0},
               [](Next& next, int, Inputs& in) { return poly_poly_uniform(in, next); }});
  f.push_back({"near-touching", "B's first vertex 2^-k of the size from a point of A (off it or through it)",
               tangency_scales(), [](Next& next, int k, Inputs& in) {
                 return poly_poly_touching(in, next, sign(next) * std::ldexp(1.0, -k), V{0, 0, 0});
               }});
  f.push_back({"long-range", "touching to within 1e-9 of the size, 10^k from the origin", decades(),
               [](Next& next, int k, Inputs& in) {
                 const V offset = std::pow(10.0, k) * unit(next);
                 return poly_poly_touching(in, next, uni(next, -1e-9, 1e-9), offset);
               }});
  f.push_back({"degenerate", "degenerate vertex lists on the integer lattice, against each other", {0},
               [](Next& next, int, Inputs& in) {
                 const std::vector<V> b = degenerate_polygon(next);
                 return poly_poly(in, degenerate_polygon(next), b);
               }});
  f.push_back({"magnitude", "the uniform family scaled by 10^k", magnitudes(), [](Next& next, int k, Inputs& in) {
                 poly_poly_uniform(in, next);
                 const double na = in[0], nb = in[25];
                 scaled(in, 50, k);
                 in[0] = na, in[25] = nb;
               }});
  return f;
}

std::vector<Family> polygon_box_family_list() {
  std::vector<Family> f;
  f.push_back({"uniform", "a convex polygon (radius 0.5 to 2, centre in [-2,2]^3), a box in [-1,1]^3 with extents 0.1 to 1.5",
               {0}, [](Next& next, int, Inputs& in) { return poly_box_uniform(in, next); }});
  f.push_back({"near-touching", "the polygon's plane 2^-k of its size from the box's support corner (off or through)",
               tangency_scales(), [](Next& next, int k, Inputs& in) {
                 return poly_box_touching(in, next, sign(next) * std::ldexp(1.0, -k), V{0, 0, 0});
               }});
  f.push_back({"long-range", "touching to within 1e-9 of the size, 10^k from the origin", decades(),
               [](Next& next, int k, Inputs& in) {
                 const V offset = std::pow(10.0, k) * unit(next);
                 return poly_box_touching(in, next, uni(next, -1e-9, 1e-9), offset);
               }});
  f.push_back({"degenerate", "degenerate vertex lists on the integer lattice, boxes with integer corners", {0},
               [](Next& next, int, Inputs& in) {
                 const V h{double(pick(next, 3)), double(1 + pick(next, 2)), double(pick(next, 3))};
                 const V c{double(pick(next, 5)) - 2, double(pick(next, 5)) - 2, double(pick(next, 5)) - 2};
                 return poly_box(in, degenerate_polygon(next), c, h);
               }});
  f.push_back({"magnitude", "the uniform family scaled by 10^k", magnitudes(), [](Next& next, int k, Inputs& in) {
                 poly_box_uniform(in, next);
                 const double n = in[0];
                 scaled(in, 31, k);
                 in[0] = n;
               }});
  return f;
}

std::vector<Family> polygon_sphere_family_list() {
  std::vector<Family> f;
  f.push_back({"uniform", "a convex polygon (radius 0.5 to 2, centre in [-1,1]^3), centre in [-3,3]^3, radius 0.1 to 2",
               {0}, [](Next& next, int, Inputs& in) { return poly_sphere_uniform(in, next); }});
  f.push_back({"near-touching", "touching the polygon's face or a vertex at rho (1 +- 2^-k)", tangency_scales(),
               [](Next& next, int k, Inputs& in) {
                 return poly_sphere_touching(in, next, sign(next) * std::ldexp(1.0, -k), V{0, 0, 0});
               }});
  f.push_back({"long-range", "touching to within 1e-9 radii, 10^k from the origin", decades(), [](Next& next, int k, Inputs& in) {
                 const V offset = std::pow(10.0, k) * unit(next);
                 return poly_sphere_touching(in, next, uni(next, -1e-9, 1e-9), offset);
               }});
  f.push_back({"degenerate", "degenerate vertex lists on the integer lattice; the centre on a vertex, radius 0 or 1",
               {0}, [](Next& next, int, Inputs& in) {
                 const std::vector<V> v = degenerate_polygon(next);
                 const V c = pick(next, 2) == 0 ? v[pick(next, int(v.size()))]
                                                : V{double(pick(next, 7)) - 3, double(pick(next, 7)) - 3, 1};
                 return poly_sphere(in, v, c, double(pick(next, 2)));
               }});
  f.push_back({"magnitude", "the uniform family scaled by 10^k", magnitudes(), [](Next& next, int k, Inputs& in) {
                 poly_sphere_uniform(in, next);
                 const double n = in[0];
                 scaled(in, 29, k);
                 in[0] = n;
               }});
  return f;
}

}  // namespace cdref::fuzz
