// src/peers/open3d.cpp - Open3D's RaycastingScene in `cdref peers` (libopen3d-dev: Open3D 0.16 at
// float, its tensors float32, so the cases reach it as their float roundings and its errors are
// graded in ulps of float).
//
// RaycastingScene is Open3D's ray-casting front end on Embree: a scene per case (its own Embree
// device), one triangle added with AddTriangles, then
//   CastRays        a ray (origin, direction) against the triangle: t_hit, primitive_uvs (Embree's
//                   u and v: the barycentric weights of v1 and v2), in Embree's robust mode
//                   (Open3D sets RTC_SCENE_FLAG_ROBUST) from tnear = 0; on a fan's triangles
//                   (ray-fan-cast, the mesh level), with CountIntersections' count of hits;
//   ComputeClosestPoints and ComputeDistance  a point's closest point on the triangle and its
//                   distance (Embree's point query with the closest-point routine of Embree's
//                   tutorials, in float).
// Open3D's closest-point routine aborts the process on some cases (closest_point_aborts(), below):
// those are refused, named, before the call.
// What it adds to Embree and hides: Open3D 0.16 sets every ray's mask to 0, and Debian's Embree
// is built with ray masks, so on Debian every ray misses (CastRays answers t_hit = inf): the row
// shows it as false negatives. The point queries do not use the mask.
#include "open3d.hpp"

#include <open3d/t/geometry/RaycastingScene.h>

#include <algorithm>
#include <array>
#include <cdref/error.hpp>
#include <cmath>
#include <limits>
#include <string>

#ifndef CDREF_OPEN3D_VERSION
#define CDREF_OPEN3D_VERSION "0.16"
#endif

namespace cdref::peers {

namespace {

namespace o3 = ::open3d;

// ---- the cases Open3D's closest-point routine aborts on ----
// RaycastingScene's closest point is Ericson's region walk in float on Eigen::AlignedVector3 (four
// lanes, the fourth 0): a + v ab with a scalar v that is not finite (an overflowed product of
// coordinates, seen near 4e9, or 0/0 on a triangle with two equal vertices) makes the fourth lane
// NaN, and the assertion in squaredNorm, compiled into Debian's libOpen3D, aborts the process
// (an abort cannot be caught: it fires inside TBB's task machinery). The walk is repeated here in
// float, its dot products summed in Eigen's lane order (a region test can hinge on a cancelling
// difference, so the order decides the region), and a case on which it meets such a scalar, or an
// intermediate within 16 times of float's overflow, is refused, named.
bool closest_point_aborts(const Inputs& in) {
  auto v = [&](int k) { return std::array<float, 3>{float(in[k]), float(in[k + 1]), float(in[k + 2])}; };
  const auto p = v(0), a = v(3), b = v(6), c = v(9);
  auto sub = [](const std::array<float, 3>& x, const std::array<float, 3>& y) {
    return std::array<float, 3>{x[0] - y[0], x[1] - y[1], x[2] - y[2]};
  };
  // AlignedVector3's dot, as Eigen's SSE reduction sums the four lanes: (x + z) + (y + w), w = 0
  auto dot = [](const std::array<float, 3>& x, const std::array<float, 3>& y) {
    return (x[0] * y[0] + x[2] * y[2]) + x[1] * y[1];
  };
  bool near = false;  // an intermediate near or past overflow
  auto seen = [&near](float x) {
    near = near || !(std::fabs(x) <= std::numeric_limits<float>::max() / 16);
    return x;
  };
  const auto ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
  const float d1 = seen(dot(ab, ap)), d2 = seen(dot(ac, ap));
  if (d1 <= 0.f && d2 <= 0.f) return near;
  const auto bp = sub(p, b);
  const float d3 = seen(dot(ab, bp)), d4 = seen(dot(ac, bp));
  if (d3 >= 0.f && d4 <= d3) return near;
  const auto cp = sub(p, c);
  const float d5 = seen(dot(ab, cp)), d6 = seen(dot(ac, cp));
  if (d6 >= 0.f && d5 <= d6) return near;
  const float vc = seen(d1 * d4 - d3 * d2);
  if (vc <= 0.f && d1 >= 0.f && d3 <= 0.f) return near || !std::isfinite(d1 / (d1 - d3));
  const float vb = seen(d5 * d2 - d1 * d6);
  if (vb <= 0.f && d2 >= 0.f && d6 <= 0.f) return near || !std::isfinite(d2 / (d2 - d6));
  const float va = seen(d3 * d6 - d5 * d4);
  if (va <= 0.f && (d4 - d3) >= 0.f && (d5 - d6) >= 0.f)
    return near || !std::isfinite((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const float denom = 1.f / seen(va + vb + vc);
  return near || !std::isfinite(vb * denom) || !std::isfinite(vc * denom);
}

/// A scene holding the triangle whose vertices start at column k (rounded to float).
struct Scene {
  o3::t::geometry::RaycastingScene scene;
  Scene(const Inputs& in, int k) {
    o3::core::Tensor v({3, 3}, o3::core::Float32);
    float* p = v.GetDataPtr<float>();
    for (int i = 0; i < 9; ++i) p[i] = float(in[std::size_t(k + i)]);
    const o3::core::Tensor t = o3::core::Tensor::Init<std::uint32_t>({{0, 1, 2}});
    scene.AddTriangles(v, t);
  }
};
/// A float32 tensor of shape {1, n} from the case's columns [k, k + n).
o3::core::Tensor row(const Inputs& in, int k, int n) {
  o3::core::Tensor r({1, n}, o3::core::Float32);
  float* p = r.GetDataPtr<float>();
  for (int i = 0; i < n; ++i) p[i] = float(in[std::size_t(k + i)]);
  return r;
}

}  // namespace

std::vector<Adapter> open3d_adapters() {
  const std::string lib = "Open3D " CDREF_OPEN3D_VERSION " (float)";
  const Query ray_tri = fuzz::query_by_name("ray-triangle-cast");
  const Query point_tri = fuzz::query_by_name("point-triangle");
  const Query ray_fan = fuzz::query_by_name("ray-fan-cast");
  std::vector<Adapter> out;
  out.push_back(
      {lib, "RaycastingScene::CastRays (one triangle)", "ray-triangle-cast",
       "Embree's robust mode from tnear = 0: a ray in the triangle's plane and a triangle of zero area are never hit "
       "(cdref: the closed triangle's points), those cases are set apart; a hit is a finite t_hit, u and v Embree's "
       "barycentric weights (on Debian no ray hits: Open3D sets each ray's mask to 0 and Debian's Embree tests masks)",
       {"lambda_enter", "u", "v"},
       [](const Inputs& in, const Answer&) {
         return triangle_differs({qv(in, 6), qv(in, 9), qv(in, 12)}, qv(in, 0), qv(in, 3), true);
       },
       [ray_tri](const Inputs& in) {
         Scene s(in, 6);
         auto r = s.scene.CastRays(row(in, 0, 6));
         const float t = r["t_hit"].GetDataPtr<float>()[0];
         const float* uv = r["primitive_uvs"].GetDataPtr<float>();
         const bool hit = std::isfinite(t);
         Out o(ray_tri, hit);
         if (hit) o.set("lambda_enter", {t}).set("u", {uv[0]}).set("v", {uv[1]});
         return o.a;
       },
       24});
  out.push_back(
      {lib, "RaycastingScene::CastRays and CountIntersections (the fan's triangles)", "ray-fan-cast",
       "Embree's robust mode from tnear = 0 on the mesh: a fan with a triangle of zero area or a ray in a triangle's "
       "plane is set apart; hits is CountIntersections' count (on Debian no ray hits: every shot of the watertight "
       "family leaks)",
       {"lambda_enter", "hits"},
       [](const Inputs& in, const Answer&) { return fan_differs(in, true); },
       [ray_fan](const Inputs& in) {
         std::vector<float> v;
         std::vector<unsigned> tri;
         fan(in, v, tri);
         o3::t::geometry::RaycastingScene scene;
         o3::core::Tensor vt({std::int64_t(v.size() / 3), 3}, o3::core::Float32);
         std::copy(v.begin(), v.end(), vt.GetDataPtr<float>());
         o3::core::Tensor tt({std::int64_t(tri.size() / 3), 3}, o3::core::UInt32);
         std::copy(tri.begin(), tri.end(), tt.GetDataPtr<std::uint32_t>());
         scene.AddTriangles(vt, tt);
         const o3::core::Tensor ray = row(in, 0, 6);
         auto r = scene.CastRays(ray);
         const float t = r["t_hit"].GetDataPtr<float>()[0];
         const int hits = scene.CountIntersections(ray).GetDataPtr<int>()[0];
         const bool hit = std::isfinite(t);
         Out o(ray_fan, hit);
         if (hit) o.set("lambda_enter", {t}).set("hits", {double(hits)});
         return o.a;
       },
       24});
  out.push_back(
      {lib, "RaycastingScene::ComputeClosestPoints and ComputeDistance (one triangle)", "point-triangle",
       "none: the closest point is witness_b and its distance the distance; intersect is read as the closest point "
       "equal to the point; the cases its float routine aborts the process on are refused",
       {"distance", "witness_b"},
       [](const Inputs&, const Answer&) { return false; },
       [point_tri](const Inputs& in) {
         if (closest_point_aborts(in))
           throw invalid_input("Open3D's closest-point routine would abort on this case (a scalar of its float "
                               "walk overflows or is 0/0, and an Eigen assertion then ends the process)");
         Scene s(in, 3);
         const o3::core::Tensor q = row(in, 0, 3);
         auto cp = s.scene.ComputeClosestPoints(q);
         const float* x = cp["points"].GetDataPtr<float>();
         const float d = s.scene.ComputeDistance(q).GetDataPtr<float>()[0];
         const bool on = x[0] == float(in[0]) && x[1] == float(in[1]) && x[2] == float(in[2]);
         return Out(point_tri, on).set("distance", {d}).set("witness_b", {x[0], x[1], x[2]}).a;
       },
       24});
  return out;
}

}  // namespace cdref::peers
