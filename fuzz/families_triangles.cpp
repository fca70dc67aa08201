// fuzz/families_triangles.cpp - the case families of the Section 3.4 queries: a sphere and a
// triangle (touching the triangle's face, an edge or a vertex, zero-area triangles).
#include <cdref/fuzz/families.hpp>
#include <cmath>

#include "family_tools.hpp"

namespace cdref::fuzz {

namespace {

using namespace family;

// ---- a sphere and a triangle: centre, radius, v0, v1, v2 ----
Inputs sphere_tri(V c, double rho, V a, V b, V d) {
  Inputs in{};
  put(in, 0, c);
  in[3] = rho;
  put(in, 4, a);
  put(in, 7, b);
  put(in, 10, d);
  return in;
}
Inputs sphere_tri_uniform(Next& next) {
  const V c = uvec(next, -3, 3);
  const double rho = uni(next, 0.1, 2);
  return sphere_tri(c, rho, uvec(next, -2, 2), uvec(next, -2, 2), uvec(next, -2, 2));
}

// A triangle and a sphere whose closest point x is an interior point of the triangle, of an
// edge, or a vertex (kind 0, 1, 2), the centre at rho (1 + rel) from x along a direction of
// x's normal cone.
Inputs sphere_tri_touching(Next& next, double rel, V offset, int kind) {
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
      dir = normalized(uni(next, 0.1, 1) * out + uni(next, -1, 1) * n);
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
  return sphere_tri(x + (rho * (1 + rel)) * dir, rho, a, b, d);
}

}  // namespace

std::vector<Family> sphere_triangle_family_list() {
  std::vector<Family> f;
  f.push_back({"uniform", "centre in [-3,3]^3, radius in [0.1,2], vertices in [-2,2]^3", {0},
               [](Next& next, int) { return sphere_tri_uniform(next); }});
  f.push_back({"near-touching", "touching the face, an edge or a vertex, at rho (1 +- 2^-k) from it", tangency_scales,
               [](Next& next, int k) {
                 return sphere_tri_touching(next, sign(next) * std::ldexp(1.0, -k), V{0, 0, 0}, pick(next, 3));
               }});
  f.push_back({"long-range", "touching to within 1e-9 radii, 10^k from the origin", decades, [](Next& next, int k) {
                 return sphere_tri_touching(next, uni(next, -1e-9, 1e-9), std::pow(10.0, k) * unit(next), pick(next, 3));
               }});
  f.push_back({"degenerate", "zero-area triangles (a segment, a point), the centre on the triangle, radius 0, slivers",
               {0}, [](Next& next, int) {
                 const V a = uvec(next, -2, 2), b = uvec(next, -2, 2), d = uvec(next, -2, 2);
                 const double rho = uni(next, 0.25, 2);
                 switch (pick(next, 5)) {
                   case 0: return sphere_tri(uvec(next, -3, 3), rho, a, b, a + uni(next, -1, 2) * (b - a));  // collinear
                   case 1: return sphere_tri(uvec(next, -3, 3), rho, a, a, a);                              // a point
                   case 2: return sphere_tri(a + 0.3 * (b - a) + 0.3 * (d - a), rho, a, b, d);             // centre on it
                   case 3: return sphere_tri(uvec(next, -3, 3), 0.0, a, b, d);                              // radius 0
                   default: return sphere_tri(uvec(next, -3, 3), rho, a, b, b + std::ldexp(1.0, -40) * (d - b));  // a sliver
                 }
               }});
  f.push_back({"magnitude", "the uniform family scaled by 10^k", magnitudes,
               [](Next& next, int k) { return scaled(sphere_tri_uniform(next), 13, k); }});
  return f;
}

}  // namespace cdref::fuzz
