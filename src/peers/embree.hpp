// src/peers/embree.hpp - Embree 3's ray queries in `cdref peers` (libembree-dev): rtcIntersect1
// on a scene of one triangle (ray-triangle-cast) and on a scene of a fan's triangles
// (ray-fan-cast, the mesh level: on the watertight family, a miss is a leak through a shared
// edge or vertex), each in Embree's default mode and in its robust mode (RTC_SCENE_FLAG_ROBUST).
// Embree is float throughout (vertices RTC_FORMAT_FLOAT3, float rays): the cases' float
// roundings reach it unchanged and its errors are graded in ulps of float.
//
// Embree picks its instruction set when the device is made, and its answers differ between
// them (which shots leak, in the last bit of a distance); the gallery pins SSE2, which every
// x86-64 has, and names it in the library's row. One scene per case, one build thread.
//
// A hit's distance `tfar` is in units of the given direction, as cdref's lambda_enter; `u`, `v`
// are the barycentric weights of the second and third vertices, as cdref's. On a fan, an
// intersect filter sees every triangle the ray crosses and rejects each, so that traversal goes
// on: the hits are counted (each triangle once) and the nearest taken.
#pragma once

#include <embree3/rtcore.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cdref/error.hpp>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "adapter.hpp"

namespace cdref::peers::embree {

/// The process's device: SSE2, one thread for scene builds. Made once.
inline RTCDevice device() {
  static const RTCDevice d = [] {
    const RTCDevice x = rtcNewDevice("isa=sse2,threads=1,set_affinity=0");
    if (!x) throw std::runtime_error("Embree could not make a device (rtcNewDevice)");
    return x;
  }();
  return d;
}

/// What the intersect filter saw on a fan: the triangles hit (one bit each) and the nearest.
struct Seen {
  unsigned mask = 0;
  float nearest = std::numeric_limits<float>::infinity();
};
inline void count(const RTCFilterFunctionNArguments* a) {
  Seen* s = static_cast<Seen*>(a->geometryUserPtr);
  for (unsigned i = 0; i < a->N; ++i) {
    if (a->valid[i] != -1) continue;
    s->mask |= 1u << RTCHitN_primID(a->hit, a->N, i);
    s->nearest = std::min(s->nearest, RTCRayN_tfar(a->ray, a->N, i));
    a->valid[i] = 0;  // rejected: the traversal goes on to the other triangles
  }
}

/// A committed scene of one triangle geometry, released with its scope.
struct Scene {
  RTCScene id;
  Scene(bool robust, const std::vector<float>& v, const std::vector<unsigned>& tri, Seen* seen) {
    id = rtcNewScene(device());
    if (robust) rtcSetSceneFlags(id, RTC_SCENE_FLAG_ROBUST);
    const RTCGeometry g = rtcNewGeometry(device(), RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vb = static_cast<float*>(
        rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), v.size() / 3));
    auto* ib = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), tri.size() / 3));
    if (!vb || !ib) {
      rtcReleaseGeometry(g);
      rtcReleaseScene(id);
      throw std::runtime_error("Embree could not allocate a geometry buffer");
    }
    std::copy(v.begin(), v.end(), vb);
    std::copy(tri.begin(), tri.end(), ib);
    if (seen) {
      rtcSetGeometryUserData(g, seen);
      rtcSetGeometryIntersectFilterFunction(g, count);
    }
    rtcCommitGeometry(g);
    rtcAttachGeometry(id, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(id);
    if (const RTCError e = rtcGetDeviceError(device()); e != RTC_ERROR_NONE)
      throw invalid_input("Embree refused the scene (error " + std::to_string(int(e)) + ")");
  }
  ~Scene() { rtcReleaseScene(id); }
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;
};

/// The ray source + t direction, t in [0, inf) (columns 0 to 5), on the scene.
inline RTCRayHit shoot(const Scene& s, const Inputs& in) {
  RTCRayHit rh{};
  rh.ray.org_x = float(in[0]), rh.ray.org_y = float(in[1]), rh.ray.org_z = float(in[2]);
  rh.ray.dir_x = float(in[3]), rh.ray.dir_y = float(in[4]), rh.ray.dir_z = float(in[5]);
  rh.ray.tnear = 0;
  rh.ray.tfar = std::numeric_limits<float>::infinity();
  rh.ray.mask = ~0u;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  rtcIntersect1(s.id, &ctx, &rh);
  return rh;
}


/// Embree's adapters, default mode and robust mode.
inline std::vector<Adapter> adapters() {
  const std::string lib = "Embree " RTC_VERSION_STRING " (float, SSE2)";
  const Query ray_tri = fuzz::query_by_name("ray-triangle-cast");
  const Query ray_fan = fuzz::query_by_name("ray-fan-cast");
  std::vector<Adapter> out;
  for (const bool robust : {false, true}) {
    const std::string mode = robust ? "robust mode (RTC_SCENE_FLAG_ROBUST)" : "default mode";
    out.push_back(
        {lib, "rtcIntersect1 on one triangle, " + mode, "ray-triangle-cast",
         std::string("a ray in the triangle's plane and a triangle of zero area are never hit (cdref: the closed "
                     "triangle's points); ") +
             (robust ? "a source on the triangle is a hit at 0, as in cdref"
                     : "hits count for t > 0 only, so a source on the triangle's plane is set apart too") +
             "; both faces are hit; lambda_enter is tfar, u and v Embree's barycentric weights",
         {"lambda_enter", "u", "v"},
         [robust](const Inputs& in, const Answer&) {
           return triangle_differs({qv(in, 6), qv(in, 9), qv(in, 12)}, qv(in, 0), qv(in, 3), robust);
         },
         [robust, ray_tri](const Inputs& in) {
           std::vector<float> v;
           for (int k = 6; k < 15; ++k) v.push_back(float(in[std::size_t(k)]));
           const Scene s(robust, v, {0, 1, 2}, nullptr);
           const RTCRayHit rh = shoot(s, in);
           const bool hit = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
           Out o(ray_tri, hit);
           if (hit) o.set("lambda_enter", {rh.ray.tfar}).set("u", {rh.hit.u}).set("v", {rh.hit.v});
           return o.a;
         },
         24});
    out.push_back(
        {lib, "rtcIntersect1 on the fan's triangles, " + mode + ", every hit counted by an intersect filter",
         "ray-fan-cast",
         std::string("a triangle of zero area and a ray in a triangle's plane are never hit there (cdref: the "
                     "closed triangle's points): such fans are set apart") +
             (robust ? "" : ", and in default mode (t > 0) a source in a triangle's plane") +
             "; the point is source + lambda_enter direction in float",
         {"lambda_enter", "point", "hits"},
         [robust](const Inputs& in, const Answer&) { return fan_differs(in, robust); },
         [robust, ray_fan](const Inputs& in) {
           std::vector<float> v;
           std::vector<unsigned> tri;
           fan(in, v, tri);
           Seen seen;
           const Scene s(robust, v, tri, &seen);
           (void)shoot(s, in);
           const bool hit = seen.mask != 0;
           Out o(ray_fan, hit);
           if (hit) {
             const float t = seen.nearest;
             o.set("lambda_enter", {t})
                 .set("point", {float(in[0]) + t * float(in[3]), float(in[1]) + t * float(in[4]),
                                float(in[2]) + t * float(in[5])})
                 .set("hits", {double(std::popcount(seen.mask))});
           }
           return o.a;
         },
         24});
  }
  return out;
}

}  // namespace cdref::peers::embree
