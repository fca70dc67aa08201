// src/peers/ode.hpp - ODE's collision functions in `cdref peers` (libode-dev; Debian builds ODE
// in double precision, dReal = double, so the cases reach it unrounded and its errors are
// graded in ulps of double). dCollide answers every pair here: a ray geom (dCreateRay with
// length dInfinity: the infinite ray; ODE normalizes its direction) against a sphere, a box
// (dCreateBox takes full side lengths: twice the extents, exact in double unless they
// overflow, which is refused) or a one-triangle mesh (OPCODE's trimesh, two-sided by default);
// a sphere against a box; a box against a box. A contact is a hit (touching counts as one for
// every pair here); its `pos` is the point, `normal` the normal, `depth` the depth.
#pragma once

#include <ode/ode.h>

#include <cdref/error.hpp>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "adapter.hpp"

#ifndef CDREF_ODE_VERSION
#define CDREF_ODE_VERSION "0.16"
#endif

namespace cdref::peers::ode {

static_assert(sizeof(dReal) == sizeof(double), "cdref grades ODE's double build (Debian's libode-dev)");

/// ODE's internal errors and failed assertions (a direction or a triangle's normal it cannot
/// normalize, say) end in abort() once their handler returns: the handler throws instead, so the
/// case is refused, named by ODE's message, and the process goes on.
[[noreturn]] inline void refuse(int, const char* msg, va_list ap) {
  char text[512];
  std::vsnprintf(text, sizeof text, msg, ap);
  throw invalid_input(std::string("ODE refused the case: ") + text);
}

/// One ODE call at a time: Debian's ODE, trimeshes through OPCODE, crashed (a segmentation fault
/// in OPCODE's MeshInterface::FetchTriangleFromDoubles) when two threads collided rays with
/// meshes of their own; the engine's other work (the exact answers) still runs in parallel.
inline std::mutex& lock() {
  static std::mutex m;
  return m;
}

/// ODE initialised once in the process, its error and assertion handlers refusing the case, and
/// its collision data allocated in each thread that collides (OPCODE's trimesh keeps per-thread
/// caches): called before every collision.
inline void ready() {
  static std::once_flag once;
  std::call_once(once, [] {
    dSetErrorHandler(refuse);
    dSetDebugHandler(refuse);
    if (!dInitODE2(0)) throw std::runtime_error("ODE could not be initialised (dInitODE2)");
  });
  thread_local const bool data = dAllocateODEDataForThread(dAllocateMaskAll) != 0;
  if (!data) throw std::runtime_error("ODE could not allocate its collision data for this thread");
}

/// A geom destroyed with its scope.
struct Geom {
  dGeomID id;
  explicit Geom(dGeomID g) : id(g) {}
  ~Geom() { dGeomDestroy(id); }
  Geom(const Geom&) = delete;
  Geom& operator=(const Geom&) = delete;
};

/// The infinite ray source + lambda direction (columns 0 to 5).
inline dGeomID ray(const Inputs& in) {
  const dGeomID r = dCreateRay(nullptr, dInfinity);
  dGeomRaySet(r, in[0], in[1], in[2], in[3], in[4], in[5]);
  return r;
}
/// A box at centre c (column k) with extents (column k + 3): ODE's full side lengths.
inline dGeomID box(const Inputs& in, int k) {
  const double lx = 2 * in[k + 3], ly = 2 * in[k + 4], lz = 2 * in[k + 5];
  if (!std::isfinite(lx) || !std::isfinite(ly) || !std::isfinite(lz))
    throw invalid_input("the box's side lengths (twice its extents) overflow double");
  const dGeomID b = dCreateBox(nullptr, lx, ly, lz);
  dGeomSetPosition(b, in[k], in[k + 1], in[k + 2]);
  return b;
}
inline dGeomID sphere(double x, double y, double z, double r) {
  const dGeomID s = dCreateSphere(nullptr, r);
  dGeomSetPosition(s, x, y, z);
  return s;
}
/// One contact at most: its count (0 or 1) and the contact.
inline int collide(dGeomID a, dGeomID b, dContactGeom& c) { return dCollide(a, b, 1, &c, sizeof(dContactGeom)); }

/// A one-triangle trimesh (vertices at columns k, k + 3, k + 6), destroyed with its scope.
struct Triangle {
  double v[9];
  dTriIndex idx[3] = {0, 1, 2};
  dTriMeshDataID data;
  dGeomID id;
  Triangle(const Inputs& in, int k) {
    for (int i = 0; i < 9; ++i) v[i] = in[k + i];
    data = dGeomTriMeshDataCreate();
    dGeomTriMeshDataBuildDouble(data, v, 3 * sizeof(double), 3, idx, 3, 3 * sizeof(dTriIndex));
    id = dCreateTriMesh(nullptr, data, nullptr, nullptr, nullptr);
  }
  ~Triangle() {
    dGeomDestroy(id);
    dGeomTriMeshDataDestroy(data);
  }
  Triangle(const Triangle&) = delete;
  Triangle& operator=(const Triangle&) = delete;
};

/// The infinite ray of the case against the shape `make` builds from it (a Geom or a Triangle),
/// as a cast's answer: the contact's point and, where asked, its normal.
template <class Make>
Answer cast(Query q, const Inputs& in, const Make& make, bool normal) {
  ready();
  const std::lock_guard<std::mutex> one(lock());
  const Geom r(ray(in));
  const auto shape = make(in);
  dContactGeom c;
  const bool hit = collide(r.id, shape.id, c) > 0;
  Out o(q, hit);
  if (hit) o.set("point", {c.pos[0], c.pos[1], c.pos[2]});
  if (hit && normal) o.set("normal", {c.normal[0], c.normal[1], c.normal[2]});
  return o.a;
}

/// ODE's adapters.
inline std::vector<Adapter> adapters() {
  const std::string lib = "ODE " CDREF_ODE_VERSION " (double)";
  const Query ray_sphere = fuzz::query_by_name("ray-sphere-cast");
  const Query ray_box = fuzz::query_by_name("ray-box-cast");
  const Query ray_tri = fuzz::query_by_name("ray-triangle-cast");
  const Query sphere_box = fuzz::query_by_name("sphere-box");
  const Query box_box = fuzz::query_by_name("box-box");
  std::vector<Adapter> out;
  out.push_back({lib, "dCollide (dCreateRay of length dInfinity, dCreateSphere)", "ray-sphere-cast",
                 "a source inside or on the sphere: ODE reports where the ray leaves it, its normal turned inward "
                 "(cdref: the source, at lambda 0): those cases are set apart",
                 {"point", "normal"},
                 [](const Inputs& in, const Answer&) { return source_inside(in); },
                 [ray_sphere](const Inputs& in) {
                   return cast(ray_sphere, in, [](const Inputs& x) { return Geom(sphere(x[6], x[7], x[8], x[9])); }, true);
                 },
                 53});
  out.push_back({lib, "dCollide (dCreateRay of length dInfinity, dCreateBox)", "ray-box-cast",
                 "a source inside or on the box: ODE reports where the ray leaves it (cdref: the source, at lambda "
                 "0): those cases are set apart; the adapter gives the box's side lengths as twice its extents",
                 {"point", "normal"},
                 [](const Inputs& in, const Answer&) { return source_in_box(in); },
                 [ray_box](const Inputs& in) { return cast(ray_box, in, [](const Inputs& x) { return Geom(box(x, 6)); }, true); },
                 53});
  out.push_back({lib, "dCollide (dCreateRay of length dInfinity, one-triangle dCreateTriMesh)", "ray-triangle-cast",
                 "a ray in the triangle's plane is never a hit (cdref: the closed triangle's points on it): those "
                 "cases are set apart; both faces are hit (ODE's default), as in cdref",
                 {"point"},
                 [](const Inputs& in, const Answer&) { return in_plane(in); },
                 [ray_tri](const Inputs& in) { return cast(ray_tri, in, [](const Inputs& x) { return Triangle(x, 6); }, false); },
                 53});
  out.push_back({lib, "dCollide (dCreateSphere, dCreateBox)", "sphere-box",
                 "none: touching is a contact of depth 0, a centre inside the box gives the radius plus the distance "
                 "to the nearest face, as in cdref; apart, ODE gives no distance (only intersect and depth graded)",
                 {"depth"},
                 [](const Inputs&, const Answer&) { return false; },
                 [sphere_box](const Inputs& in) {
                   ready();
                   const std::lock_guard<std::mutex> one(lock());
                   const Geom s(sphere(in[0], in[1], in[2], in[3])), b(box(in, 4));
                   dContactGeom c;
                   const bool hit = collide(s.id, b.id, c) > 0;
                   Out o(sphere_box, hit);
                   if (hit) o.set("depth", {c.depth});
                   return o.a;
                 },
                 53});
  out.push_back({lib, "dCollide (dCreateBox, dCreateBox)", "box-box",
                 "none: touching boxes are in contact; the adapter gives each box's side lengths as twice its extents",
                 {},
                 [](const Inputs&, const Answer&) { return false; },
                 [box_box](const Inputs& in) {
                   ready();
                   const std::lock_guard<std::mutex> one(lock());
                   const Geom a(box(in, 0)), b(box(in, 6));
                   dContactGeom c;
                   return Out(box_box, collide(a.id, b.id, c) > 0).a;
                 },
                 53});
  return out;
}

}  // namespace cdref::peers::ode
