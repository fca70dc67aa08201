// fuzz/families.cpp - the case families of every query.
//
// Each family makes cases from a stream of random words and an integer scale k. The
// families aim at where float code goes wrong: long range (10^k radii away), near
// tangency and near touching (2^-k), grazing box edges and corners, rays parallel to or
// lying in face planes, degenerate placements, and magnitudes from 1e-300 to 1e300 (10^k
// applied to a uniform case, k = -320..300: squares overflow past 1e154 and underflow below
// 1e-154, and at k = -310 and -320 the coordinates themselves are subnormal).
//
// No expression takes two draws from the stream where C++ leaves their order open (the
// arguments of one call, the operands of an overloaded operator): a seed gives the same cases
// from every compiler. Where a case once took several draws in one call, the named locals are
// drawn in the order the g++ builds took them, so seeds keep the cases they always had.
#include <cdref/fuzz/families.hpp>

#include "family_tools.hpp"
#include <cmath>
#include <stdexcept>

namespace cdref::fuzz {

namespace {

using namespace family;

// ---- a segment or ray against a sphere: inputs s, t (or d), c, rho ----
struct SphereShot {
  bool ray;
  void make(Inputs& in, V s, V t, V c, double rho) const {
    put(in, 0, s);
    put(in, 3, ray ? t - s : t);
    put(in, 6, c);
    in[9] = rho;
  }
  // From R radii away, passing at b radii from the centre, ending `over` past the aim point.
  void aimed(Inputs& in, Next& next, double R, double b) const {
    const V c = uvec(next, -1, 1);
    const double rho = uni(next, 0.5, 2);
    const V u = unit(next), w = perp(next, u);
    const V p = c + (b * rho) * w;
    const V s = p - (R * rho) * u;
    const V t = p + uni(next, 0.01, 1.0) * (p - s);
    return make(in, s, t, c, rho);
  }
};

std::vector<Family> sphere_shot_families(bool ray) {
  const SphereShot S{ray};
  std::vector<Family> f;
  f.push_back({"uniform", "centre in [-1,1]^3, radius in [0.25,2], endpoints in [-4,4]^3", {0},
               [S](Next& next, int, Inputs& in) {
                 const V c = uvec(next, -1, 1);
                 const double rho = uni(next, 0.25, 2);
                 const V t = uvec(next, -4, 4), s = uvec(next, -4, 4);
                 return S.make(in, s, t, c, rho);
               }});
  f.push_back({"long-range", "source 10^k radii away, passing 0 to 1.25 radii from the centre", decades(),
               [S](Next& next, int k, Inputs& in) { return S.aimed(in, next, std::pow(10.0, k), uni(next, 0, 1.25)); }});
  f.push_back({"near-tangent", "from 4 radii, passing at rho (1 +- 2^-k) from the centre", tangency_scales(),
               [S](Next& next, int k, Inputs& in) { return S.aimed(in, next, 4, 1 + sign(next) * std::ldexp(1.0, -k)); }});
  f.push_back({"tangent-at-range", "from 10^k radii, passing within 1e-9 radii of tangency", decades(),
               [S](Next& next, int k, Inputs& in) { return S.aimed(in, next, std::pow(10.0, k), 1 + uni(next, -1e-9, 1e-9)); }});
  f.push_back({"degenerate",
               "through the centre, zero length, source inside, source on the sphere, radius 0",
               {0},
               [S, ray](Next& next, int, Inputs& in) {
                 const V c = uvec(next, -1, 1);
                 const double rho = uni(next, 0.5, 2);
                 const int i = pick(next, 3);
                 const double sg = sign(next);
                 switch (pick(next, ray ? 4 : 5)) {
                   case 0: return S.aimed(in, next, uni(next, 1.5, 10), 0);  // through the centre
                   case 1: {  // source inside
                     const V s = c + uvec(next, -0.5, 0.5);
                     return S.make(in, s, s + uvec(next, -4, 4), c, rho);
                   }
                   case 2: {  // source exactly on the sphere, along an axis, in or out
                     const V s = c + axis(i, sg * rho);
                     const double out = pick(next, 2) ? 1 : -1;
                     const V t = s + axis(i, out * uni(next, 0.5, 4));
                     return S.make(in, s, t, c, rho);
                   }
                   case 3: {  // radius 0, line through the point or not
                     const V s = uvec(next, -4, 4);
                     const V t = pick(next, 2) ? c + (c - s) : uvec(next, -4, 4);
                     return S.make(in, s, t, c, 0.0);
                   }
                   default: {  // zero-length segment, inside, on or outside
                     const V u = unit(next);
                     const V s = c + (uni(next, 0, 2) * rho) * u;
                     return S.make(in, s, s, c, rho);
                   }
                 }
               }});
  f.push_back({"magnitude", "the uniform family scaled by 10^k", magnitudes(), [S](Next& next, int k, Inputs& in) {
                 const V c = uvec(next, -1, 1);
                 const double rho = uni(next, 0.25, 2);
                 const V t = uvec(next, -4, 4), s = uvec(next, -4, 4);
                 S.make(in, s, t, c, rho); scaled(in, 10, k);
               }});
  return f;
}

// ---- two spheres: cA, rhoA, cB, rhoB ----
void two_spheres(Inputs& in, V a, double ra, V b, double rb) {
  put(in, 0, a);
  in[3] = ra;
  put(in, 4, b);
  in[7] = rb;
}
void touching_spheres(Inputs& in, Next& next, double rel, V offset) {
  const double ra = uni(next, 0.5, 2), rb = uni(next, 0.5, 2);
  const V a = offset + uvec(next, -1, 1);
  return two_spheres(in, a, ra, a + ((ra + rb) * (1 + rel)) * unit(next), rb);
}
std::vector<Family> sphere_sphere_families() {
  std::vector<Family> f;
  f.push_back({"uniform", "centres in [-2,2]^3, radii in [0.1,2]", {0}, [](Next& next, int, Inputs& in) {
                 const double rb = uni(next, 0.1, 2);
                 const V b = uvec(next, -2, 2);
                 const double ra = uni(next, 0.1, 2);
                 return two_spheres(in, uvec(next, -2, 2), ra, b, rb);
               }});
  f.push_back({"near-touching", "centres (rhoA + rhoB)(1 +- 2^-k) apart", tangency_scales(), [](Next& next, int k, Inputs& in) {
                 return touching_spheres(in, next, sign(next) * std::ldexp(1.0, -k), V{0, 0, 0});
               }});
  f.push_back({"long-range", "touching to within 1e-9 relative, 10^k from the origin", decades(),
               [](Next& next, int k, Inputs& in) {
                 const V offset = std::pow(10.0, k) * unit(next);
                 return touching_spheres(in, next, uni(next, -1e-9, 1e-9), offset);
               }});
  f.push_back({"degenerate", "concentric, internally tangent along an axis, radius 0", {0}, [](Next& next, int, Inputs& in) {
                 const V a = uvec(next, -1, 1);
                 const double ra = uni(next, 0.5, 2), rb = uni(next, 0.5, 2);
                 switch (pick(next, 3)) {
                   case 0: return two_spheres(in, a, ra, a, rb);
                   case 1: {
                     const double d = sign(next) * std::fabs(ra - rb);
                     return two_spheres(in, a, ra, a + axis(pick(next, 3), d), rb);
                   }
                   default: {
                     const double r = pick(next, 2) ? 0.0 : rb;
                     return two_spheres(in, a, 0.0, uvec(next, -2, 2), r);
                   }
                 }
               }});
  f.push_back({"magnitude", "the uniform family scaled by 10^k", magnitudes(), [](Next& next, int k, Inputs& in) {
                 const double rb = uni(next, 0.1, 2);
                 const V b = uvec(next, -2, 2);
                 const double ra = uni(next, 0.1, 2);
                 two_spheres(in, uvec(next, -2, 2), ra, b, rb); scaled(in, 8, k);
               }});
  return f;
}

// ---- sphere and box: c, rho, box centre, box extent ----
void sphere_box(Inputs& in, V c, double rho, V bc, V bh) {
  put(in, 0, c);
  in[3] = rho;
  put(in, 4, bc);
  put(in, 7, bh);
}
// A sphere touching a face, edge or corner of the box to within `rel` of its radius.
void touching_sphere_box(Inputs& in, Next& next, double rel, V offset) {
  const V bc = offset + uvec(next, -1, 1), bh = uvec(next, 0.1, 2);
  const double rho = uni(next, 0.25, 2);
  const int dims = 1 + pick(next, 3);  // 1 face, 2 edge, 3 corner
  V p = bc, n{0, 0, 0};
  const int first = pick(next, 3);
  for (int j = 0; j < 3; ++j) {
    const int i = (first + j) % 3;
    const double h = i == 0 ? bh.x : (i == 1 ? bh.y : bh.z);
    if (j < dims) {
      const double sg = sign(next);
      p = p + axis(i, sg * h);
      n = n + axis(i, sg * uni(next, 0.2, 1));
    } else {
      p = p + axis(i, uni(next, -h, h));
    }
  }
  return sphere_box(in, p + (rho * (1 + rel)) * normalized(n), rho, bc, bh);
}
std::vector<Family> sphere_box_families() {
  std::vector<Family> f;
  f.push_back({"uniform", "box centre in [-1,1]^3, extent in [0.1,2]^3; sphere centre in [-4,4]^3", {0},
               [](Next& next, int, Inputs& in) {
                 const V bh = uvec(next, 0.1, 2), bc = uvec(next, -1, 1);
                 const double rho = uni(next, 0.1, 2);
                 return sphere_box(in, uvec(next, -4, 4), rho, bc, bh);
               }});
  f.push_back({"near-touching", "touching a face, edge or corner to within 2^-k radii", tangency_scales(),
               [](Next& next, int k, Inputs& in) {
                 return touching_sphere_box(in, next, sign(next) * std::ldexp(1.0, -k), V{0, 0, 0});
               }});
  f.push_back({"long-range", "touching to within 1e-9 radii, 10^k from the origin", decades(), [](Next& next, int k, Inputs& in) {
                 const V offset = std::pow(10.0, k) * unit(next);
                 return touching_sphere_box(in, next, uni(next, -1e-9, 1e-9), offset);
               }});
  f.push_back({"degenerate", "centre inside, on a face, at the box centre; zero extent; radius 0", {0},
               [](Next& next, int, Inputs& in) {
                 const V bc = uvec(next, -1, 1), bh = uvec(next, 0.1, 2);
                 const double rho = uni(next, 0.25, 2);
                 switch (pick(next, 5)) {
                   case 0: return sphere_box(in, bc + V{uni(next, -bh.x, bh.x), uni(next, -bh.y, bh.y), uni(next, -bh.z, bh.z)}, rho, bc, bh);
                   case 1: {
                     const int i = pick(next, 3);
                     const double h = i == 0 ? bh.x : (i == 1 ? bh.y : bh.z);
                     return sphere_box(in, bc + axis(i, sign(next) * h), rho, bc, bh);
                   }
                   case 2: return sphere_box(in, bc, rho, bc, bh);
                   case 3: return sphere_box(in, uvec(next, -3, 3), rho, bc, V{0, 0, 0});
                   default: return sphere_box(in, uvec(next, -4, 4), 0.0, bc, bh);
                 }
               }});
  f.push_back({"magnitude", "the uniform family scaled by 10^k", magnitudes(), [](Next& next, int k, Inputs& in) {
                 const V bh = uvec(next, 0.1, 2), bc = uvec(next, -1, 1);
                 const double rho = uni(next, 0.1, 2);
                 sphere_box(in, uvec(next, -4, 4), rho, bc, bh); scaled(in, 10, k);
               }});
  return f;
}

// ---- two boxes: c1, h1, c2, h2 ----
void two_boxes(Inputs& in, V c1, V h1, V c2, V h2) {
  put(in, 0, c1);
  put(in, 3, h1);
  put(in, 6, c2);
  put(in, 9, h2);
}
// Box 2 touches box 1 along 1 to 3 axes (face, edge, corner), off by `gap` of the extents.
void touching_boxes(Inputs& in, Next& next, double gap, V offset) {
  const V c1 = offset + uvec(next, -1, 1), h1 = uvec(next, 0.1, 2), h2 = uvec(next, 0.1, 2);
  V d{0, 0, 0};
  const int dims = 1 + pick(next, 3);
  const double hs[3] = {h1.x + h2.x, h1.y + h2.y, h1.z + h2.z};
  for (int i = 0; i < 3; ++i)
    d = d + axis(i, i < dims ? sign(next) * hs[i] * (1 + gap) : uni(next, -hs[i], hs[i]));
  return two_boxes(in, c1, h1, c1 + d, h2);
}
std::vector<Family> box_box_families() {
  std::vector<Family> f;
  f.push_back({"uniform", "centres in [-2,2]^3, extents in [0.1,2]^3", {0}, [](Next& next, int, Inputs& in) {
                 const V h2 = uvec(next, 0.1, 2), c2 = uvec(next, -2, 2), h1 = uvec(next, 0.1, 2);
                 return two_boxes(in, uvec(next, -2, 2), h1, c2, h2);
               }});
  f.push_back({"near-touching", "faces, edges or corners 2^-k (relative) apart or overlapping", tangency_scales(),
               [](Next& next, int k, Inputs& in) { return touching_boxes(in, next, sign(next) * std::ldexp(1.0, -k), V{0, 0, 0}); }});
  f.push_back({"long-range", "touching to within 1e-9 relative, 10^k from the origin", decades(), [](Next& next, int k, Inputs& in) {
                 const V offset = std::pow(10.0, k) * unit(next);
                 return touching_boxes(in, next, uni(next, -1e-9, 1e-9), offset);
               }});
  f.push_back({"degenerate", "zero extents, identical boxes, exactly touching", {0}, [](Next& next, int, Inputs& in) {
                 const V c = uvec(next, -1, 1), h = uvec(next, 0.1, 2);
                 switch (pick(next, 3)) {
                   case 0: {
                     const V h2 = pick(next, 2) ? V{0, 0, 0} : h;
                     return two_boxes(in, c, V{0, 0, 0}, uvec(next, -2, 2), h2);
                   }
                   case 1: return two_boxes(in, c, h, c, h);
                   default: return touching_boxes(in, next, 0, V{0, 0, 0});
                 }
               }});
  f.push_back({"magnitude", "the uniform family scaled by 10^k", magnitudes(), [](Next& next, int k, Inputs& in) {
                 const V h2 = uvec(next, 0.1, 2), c2 = uvec(next, -2, 2), h1 = uvec(next, 0.1, 2);
                 two_boxes(in, uvec(next, -2, 2), h1, c2, h2); scaled(in, 12, k);
               }});
  return f;
}

// ---- a segment or ray against a box: s, t (or d), c, h ----
struct BoxShot {
  bool ray;
  void make(Inputs& in, V s, V t, V c, V h) const {
    put(in, 0, s);
    put(in, 3, ray ? t - s : t);
    put(in, 6, c);
    put(in, 9, h);
  }
  // From R box sizes away, aimed at `aim`, ending past it.
  void aimed(Inputs& in, Next& next, V c, V h, V aim, double R) const {
    const double size = std::sqrt(dot(h, h));
    const V s = aim - (R * size) * unit(next);
    const V t = aim + uni(next, 0.01, 1.0) * (aim - s);
    return make(in, s, t, c, h);
  }
};
std::vector<Family> box_shot_families(bool ray) {
  const BoxShot B{ray};
  std::vector<Family> f;
  f.push_back({"uniform", "box centre in [-1,1]^3, extent in [0.1,2]^3, endpoints in [-4,4]^3", {0},
               [B](Next& next, int, Inputs& in) {
                 const V c = uvec(next, -1, 1), h = uvec(next, 0.1, 2);
                 const V t = uvec(next, -4, 4), s = uvec(next, -4, 4);
                 return B.make(in, s, t, c, h);
               }});
  f.push_back({"long-range", "from 10^k box sizes away, aimed within 1.2 extents of the centre", decades(),
               [B](Next& next, int k, Inputs& in) {
                 const V c = uvec(next, -1, 1), h = uvec(next, 0.1, 2);
                 const V a = uvec(next, -1.2, 1.2);
                 return B.aimed(in, next, c, h, c + V{a.x * h.x, a.y * h.y, a.z * h.z}, std::pow(10.0, k));
               }});
  f.push_back({"grazing", "aimed at an edge or corner, off by 2^-k of the extent", tangency_scales(),
               [B](Next& next, int k, Inputs& in) {
                 const V c = uvec(next, -1, 1), h = uvec(next, 0.1, 2);
                 const int dims = 2 + pick(next, 2);
                 const int first = pick(next, 3);
                 V aim = c;
                 for (int j = 0; j < 3; ++j) {
                   const int i = (first + j) % 3;
                   const double hi = i == 0 ? h.x : (i == 1 ? h.y : h.z);
                   double x;
                   if (j < dims) {
                     const double side = sign(next);
                     x = side * hi * (1 + sign(next) * std::ldexp(1.0, -k));
                   } else {
                     x = uni(next, -hi, hi);
                   }
                   aim = aim + axis(i, x);
                 }
                 return B.aimed(in, next, c, h, aim, 4);
               }});
  f.push_back({"planes", "parallel to a face just outside or inside it, lying in a face plane, ending on a plane",
               {0}, [B](Next& next, int, Inputs& in) {
                 const V c = uvec(next, -1, 1), h = uvec(next, 0.1, 2);
                 const int i = pick(next, 3);
                 const double hi = i == 0 ? h.x : (i == 1 ? h.y : h.z);
                 const double sg = sign(next);
                 V s = c + uvec(next, -4, 4), t = c + uvec(next, -4, 4);
                 switch (pick(next, 3)) {
                   case 0: {  // parallel to face i: both endpoints share coordinate i
                     const double sg_off = sign(next);
                     const double off = hi * (1 + sg_off * std::ldexp(1.0, -pick(next, 40)));
                     const double ci = (i == 0 ? c.x : (i == 1 ? c.y : c.z)) + sg * off;
                     s = s - axis(i, dot(s, axis(i)) - ci);
                     t = t - axis(i, dot(t, axis(i)) - ci);
                     break;
                   }
                   case 1: {  // in a face plane, exactly
                     const double ci = (i == 0 ? c.x : (i == 1 ? c.y : c.z)) + sg * hi;
                     s = s - axis(i, dot(s, axis(i)) - ci);
                     t = t - axis(i, dot(t, axis(i)) - ci);
                     break;
                   }
                   default: {  // the target exactly on a face plane
                     const double ci = (i == 0 ? c.x : (i == 1 ? c.y : c.z)) + sg * hi;
                     t = t - axis(i, dot(t, axis(i)) - ci);
                     break;
                   }
                 }
                 return B.make(in, s, t, c, h);
               }});
  f.push_back({"degenerate", "zero-length segments, zero-extent boxes, sources inside", {0}, [B, ray](Next& next, int, Inputs& in) {
                 const V c = uvec(next, -1, 1), h = uvec(next, 0.1, 2);
                 switch (pick(next, ray ? 2 : 3)) {
                   case 0: {
                     V hz = h;
                     if (pick(next, 2)) hz.x = 0; else hz.z = 0;
                     const V t = uvec(next, -4, 4), s = uvec(next, -4, 4);
                     return B.make(in, s, t, c, hz);
                   }
                   case 1: {
                     const V s = c + V{uni(next, -h.x, h.x), uni(next, -h.y, h.y), uni(next, -h.z, h.z)};
                     return B.make(in, s, s + uvec(next, -4, 4), c, h);
                   }
                   default: {
                     const V s = c + uvec(next, -3, 3);
                     return B.make(in, s, s, c, h);
                   }
                 }
               }});
  f.push_back({"magnitude", "the uniform family scaled by 10^k", magnitudes(), [B](Next& next, int k, Inputs& in) {
                 const V c = uvec(next, -1, 1), h = uvec(next, 0.1, 2);
                 const V t = uvec(next, -4, 4), s = uvec(next, -4, 4);
                 B.make(in, s, t, c, h); scaled(in, 12, k);
               }});
  return f;
}

}  // namespace

std::vector<Family> sphere_sphere_family_list() { return sphere_sphere_families(); }
std::vector<Family> sphere_shot_family_list(bool ray) { return sphere_shot_families(ray); }
std::vector<Family> sphere_box_family_list() { return sphere_box_families(); }
std::vector<Family> box_box_family_list() { return box_box_families(); }
std::vector<Family> box_shot_family_list(bool ray) { return box_shot_families(ray); }

const std::vector<Family>& families(Query q) { return info(q).families; }

const Family& family_by_name(Query q, const std::string& name) {
  std::string names;
  for (const Family& f : families(q)) {
    if (f.name == name) return f;
    names += (names.empty() ? "" : ", ") + f.name;
  }
  throw std::invalid_argument("no family '" + name + "' for query " + info(q).name + " (families: " + names + ")");
}

std::uint64_t cell_key(std::uint64_t seed, Query q, const Family& f, int scale) {
  using M = CaseStream;
  std::uint64_t key = M::mix(seed);
  key = M::mix(key ^ std::uint64_t(q.id));
  for (char ch : f.name) key = M::mix(key ^ std::uint64_t(static_cast<unsigned char>(ch)));
  return M::mix(key ^ std::uint64_t(std::int64_t(scale)));
}

void make_case_into(std::uint64_t key, const Family& f, int scale, std::uint64_t i, Inputs& out) {
  CaseStream next{CaseStream::mix(key ^ i)};
  f.make(next, scale, out);
}

Inputs make_case_of(std::uint64_t key, const Family& f, int scale, std::uint64_t i) {
  Inputs in{};
  make_case_into(key, f, scale, i, in);
  return in;
}

Inputs make_case(std::uint64_t seed, Query q, const Family& f, int scale, std::uint64_t i) {
  return make_case_of(cell_key(seed, q, f, scale), f, scale, i);
}

}  // namespace cdref::fuzz
