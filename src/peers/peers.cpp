// src/peers/peers.cpp - `cdref peers`: widely used libraries' functions on cdref's families
// against the exact answer.
//
// Each adapter maps a query's case onto one library function in the library's own
// conventions and states where those conventions give another meaning than cdref's (a ray
// starting inside a sphere reported at its exit, a line that also hits behind its source, a
// triangle test that is its bounds' test). Cases where the meanings differ are decided from
// the exact answer and set apart as "convention" cases: they are not counted as drift. What
// remains is the function's numerical drift, graded like any implementation of a campaign.
//
// The adapters and their exact helpers: adapter.hpp; a library with its own header keeps its
// adapters there (ode.hpp, embree.hpp). Each adapter runs once a case through the campaign engine, which
// sets its convention's cases apart (fuzz::Implementation::set_apart) on the exact answer it
// computed for the grading.
//
// Built when GLM (libglm-dev), Bullet (libbullet-dev), ODE (libode-dev), Embree (libembree-dev),
// FCL (libfcl-dev, its own unit: fcl.cpp), Open3D (libopen3d-dev, its own unit: open3d.cpp), Rapier (npm's WebAssembly package run by node, in
// scripts/rapier) and Eigen are present. ODE and FCL run at double
// (Debian's builds; precision 53). GLM, Eigen, Embree and Bullet's float build run at float (precision 24: the inputs are the cases' float roundings);
// Bullet's float64 build runs at double in its own executable, cdref_peers_bullet64 (this file
// compiled with CDREF_BULLET64 and BT_USE_DOUBLE_PRECISION), because its inline functions carry
// the same names as the float build's.
#include <Eigen/Geometry>
#include <cdref/error.hpp>
#include <cdref/exact/gmp_pool.hpp>
#include <cdref/fuzz/campaign.hpp>
#include <cdref/validate.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <memory>
#include <mutex>
#include <optional>

#include "../options.hpp"
#include "../output.hpp"
#include "adapter.hpp"
#include "command.hpp"
#if defined(CDREF_HAVE_ODE) && !defined(CDREF_BULLET64)
#include "ode.hpp"
#endif
#if defined(CDREF_HAVE_EMBREE) && !defined(CDREF_BULLET64)
#include "embree.hpp"
#endif
#if defined(CDREF_HAVE_FCL) && !defined(CDREF_BULLET64)
#include "fcl.hpp"
#endif
#if defined(CDREF_HAVE_RAPIER) && !defined(CDREF_BULLET64)
#include "rapier.hpp"
#endif
#if defined(CDREF_HAVE_OPEN3D) && !defined(CDREF_BULLET64)
#include "open3d.hpp"
#endif

#ifdef CDREF_HAVE_GLM
#define GLM_ENABLE_EXPERIMENTAL
#include <glm/glm.hpp>
#include <glm/gtx/intersect.hpp>
#endif
#ifdef CDREF_HAVE_BULLET
#include <BulletCollision/CollisionDispatch/btCollisionObject.h>
#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>
#include <BulletCollision/CollisionDispatch/btSphereBoxCollisionAlgorithm.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <BulletCollision/NarrowPhaseCollision/btRaycastCallback.h>
#include <LinearMath/btAabbUtil2.h>
#include <LinearMath/btVector3.h>
#endif

namespace cdref::peers {

namespace {

#ifdef CDREF_BULLET64
using real = double;  // Bullet's float64 build: btScalar is double
constexpr int kPrecision = 53;
#define CDREF_BULLET_NAME "Bullet 3.24 (float64)"
#else
using real = float;
constexpr int kPrecision = 24;
#define CDREF_BULLET_NAME "Bullet 3.24 (float)"
#endif
real f(double x) { return real(x); }
[[maybe_unused]] bool behind(Query q, const Inputs& in) { return reversed_hits(q, in, kPrecision); }

std::vector<Adapter> adapters() {
  std::vector<Adapter> out;
  const Query ray_sphere = fuzz::query_by_name("ray-sphere-cast");
  const Query ray_tri = fuzz::query_by_name("ray-triangle-cast");
  (void)ray_sphere, (void)ray_tri;  // GLM's and Eigen's rows only: not in the float64 helper
  const Query seg_box = fuzz::query_by_name("segment-box-cast");
  const Query box_box = fuzz::query_by_name("box-box");
  const Query tri_box = fuzz::query_by_name("triangle-box");
  const Query sphere_box = fuzz::query_by_name("sphere-box");
#ifdef CDREF_HAVE_GLM
  out.push_back(
      {"GLM 0.9.9.8", "glm::intersectRaySphere (vec3, radius squared, unit direction)", "ray-sphere-cast",
       "a source inside or on the sphere: GLM reports the exit point (or no hit when the distance is below "
       "epsilon); the adapter normalizes the direction and squares the radius in float",
       {"point"},
       [](const Inputs& in, const Answer&) { return source_inside(in); },
       [ray_sphere](const Inputs& in) {
         const glm::vec3 s(f(in[0]), f(in[1]), f(in[2])), d = glm::normalize(glm::vec3(f(in[3]), f(in[4]), f(in[5])));
         const glm::vec3 c(f(in[6]), f(in[7]), f(in[8]));
         const float r = f(in[9]);
         float dist = 0;
         const bool hit = glm::intersectRaySphere(s, d, c, r * r, dist);
         Out o(ray_sphere, hit);
         const glm::vec3 p = s + d * dist;
         return o.set("point", {p.x, p.y, p.z}).a;
       }});
  out.push_back(
      {"GLM 0.9.9.8", "glm::intersectLineSphere (vec3, through source and source + direction)", "ray-sphere-cast",
       "a line, not a ray: it also meets spheres behind the source; a source inside reports the line's first point; "
       "the adapter passes source + direction rounded to float as the second point",
       {"point"},
       [ray_sphere](const Inputs& in, const Answer& t) { return source_inside(in) || (!t.cls && behind(ray_sphere, in)); },
       [ray_sphere](const Inputs& in) {
         const glm::vec3 s(f(in[0]), f(in[1]), f(in[2])), d(f(in[3]), f(in[4]), f(in[5]));
         const glm::vec3 c(f(in[6]), f(in[7]), f(in[8]));
         glm::vec3 p1(0), n1(0), p2(0), n2(0);  // left unset on a miss
         const bool hit = glm::intersectLineSphere(s, glm::vec3(s + d), c, f(in[9]), p1, n1, p2, n2);
         Out o(ray_sphere, hit);
         return o.set("point", {p1.x, p1.y, p1.z}).a;
       }});
  out.push_back(
      {"GLM 0.9.9.8", "glm::intersectRayTriangle (vec3)", "ray-triangle-cast",
       "no test of the distance's sign: a triangle behind the source is hit (a line test); a ray in the "
       "triangle's plane is never a hit",
       {"lambda_enter", "u", "v"},
       [ray_tri](const Inputs& in, const Answer& t) { return in_plane(in) || (!t.cls && behind(ray_tri, in)); },
       [ray_tri](const Inputs& in) {
         const glm::vec3 s(f(in[0]), f(in[1]), f(in[2])), d(f(in[3]), f(in[4]), f(in[5]));
         const glm::vec3 a(f(in[6]), f(in[7]), f(in[8])), b(f(in[9]), f(in[10]), f(in[11])), c(f(in[12]), f(in[13]), f(in[14]));
         glm::vec2 bary(0);
         float dist = 0;
         const bool hit = glm::intersectRayTriangle(s, d, a, b, c, bary, dist);
         Out o(ray_tri, hit);
         return o.set("lambda_enter", {dist}).set("u", {bary.x}).set("v", {bary.y}).a;
       }});
#endif
#ifdef CDREF_HAVE_BULLET
  auto bt = [](const Inputs& in, int k) { return btVector3(f(in[k]), f(in[k + 1]), f(in[k + 2])); };
  out.push_back({CDREF_BULLET_NAME, "btRayAabb (segment against min-max box)", "segment-box-cast",
                 "Bullet's normal is the entry face's inward normal (cdref's: outward), which the adapter "
                 "negates; a source inside hits at 0 with a zero normal, as in cdref; the adapter gives the box as "
                 "min = centre - extent and max = centre + extent in the function's type",
                 {"lambda_enter", "normal"},
                 [](const Inputs&, const Answer&) { return false; },
                 [seg_box, bt](const Inputs& in) {
                   const btVector3 s = bt(in, 0), t = bt(in, 3), c = bt(in, 6), h = bt(in, 9);
                   btScalar param = 1;
                   btVector3 n(0, 0, 0);
                   const bool hit = btRayAabb(s, t, c - h, c + h, param, n);
                   Out o(seg_box, hit);
                   return o.set("lambda_enter", {param}).set("normal", {-n.x(), -n.y(), -n.z()}).a;
                 }});
  out.push_back({CDREF_BULLET_NAME, "btRayAabb2 (slabs with the inverse direction, lambda in [0, 1])",
                 "segment-box-cast",
                 "a source inside the box gives the slabs' entry, which is negative (cdref: 0), so those cases are "
                 "set apart; the adapter computes the inverse direction as Bullet's callers do (BT_LARGE_FLOAT for "
                 "a zero component) and the box as min and max in the function's type",
                 {"lambda_enter"},
                 [](const Inputs& in, const Answer&) { return source_in_box(in); },
                 [seg_box, bt](const Inputs& in) {
                   const btVector3 s = bt(in, 0), t = bt(in, 3), c = bt(in, 6), h = bt(in, 9);
                   const btVector3 dir = t - s;
                   btVector3 inv;
                   unsigned sign[3];
                   for (int i = 0; i < 3; ++i) {
                     inv[i] = dir[i] == btScalar(0) ? btScalar(BT_LARGE_FLOAT) : btScalar(1) / dir[i];
                     sign[i] = inv[i] < btScalar(0);
                   }
                   const btVector3 bounds[2] = {c - h, c + h};
                   btScalar tmin = 0;
                   const bool hit = btRayAabb2(s, inv, sign, bounds, tmin, 0, 1);
                   return Out(seg_box, hit).set("lambda_enter", {tmin}).a;
                 }});
  out.push_back(
      {CDREF_BULLET_NAME, "btTriangleRaycastCallback::processTriangle (segment, both faces)", "segment-triangle-cast",
       "the segment must cross the triangle's plane strictly (an end on the plane, or a segment in it, is no hit), "
       "and the triangle is grown by a tolerance of 1e-4 |n|^2 on its edge functions: the cases where either "
       "decides otherwise than the closed triangle, decided exactly, are set apart",
       {"lambda_enter", "normal"},
       [](const Inputs& in, const Answer& t) {
         const QV a = qv(in, 0), b = qv(in, 3), v0 = qv(in, 6), v1 = qv(in, 9), v2 = qv(in, 12);
         const QV n = cross(sub(v1, v0), sub(v2, v0));
         const Q da = dot(n, sub(a, v0)), db = dot(n, sub(b, v0));
         if (da * db >= 0) return t.cls;  // no strict crossing: Bullet never hits; set apart where the truth does
         // the crossing point and the edge functions with Bullet's tolerance, exactly
         const Q s = da / (da - db);
         const QV p{a.x + s * (b.x - a.x), a.y + s * (b.y - a.y), a.z + s * (b.z - a.z)};
         const Q tol = Q(double(btScalar(-0.0001))) * dot(n, n);
         const QV q0 = sub(v0, p), q1 = sub(v1, p), q2 = sub(v2, p);
         const bool grown = dot(cross(q0, q1), n) >= tol && dot(cross(q1, q2), n) >= tol && dot(cross(q2, q0), n) >= tol;
         return grown != t.cls;
       },
       [](const Inputs& in) {
         struct Catch : btTriangleRaycastCallback {
           bool hit = false;
           btScalar fraction = 0;
           btVector3 normal{0, 0, 0};
           Catch(const btVector3& from, const btVector3& to) : btTriangleRaycastCallback(from, to, 0) {}
           btScalar reportHit(const btVector3& n, btScalar f, int, int) override {
             hit = true;
             fraction = f;
             normal = n;
             return f;
           }
         };
         auto v = [&](int k) { return btVector3(f(in[k]), f(in[k + 1]), f(in[k + 2])); };
         btVector3 tri[3] = {v(6), v(9), v(12)};
         Catch c(v(0), v(3));
         c.processTriangle(tri, 0, 0);
         return Out(fuzz::query_by_name("segment-triangle-cast"), c.hit)
             .set("lambda_enter", {c.fraction})
             .set("normal", {c.normal.x(), c.normal.y(), c.normal.z()})
             .a;
       }});
  out.push_back(
      {CDREF_BULLET_NAME, "btSphereBoxCollisionAlgorithm::getSphereDistance (box margin 0)", "sphere-box",
       "none with the box's collision margin set to 0 (Bullet's default 0.04 rounds the box's corners by it); "
       "Bullet's signed distance d (negative inside) gives intersect = d <= 0, distance = max(d, 0), depth = "
       "max(-d, 0); a contact distance of 1e18 makes it answer every case",
       {"distance", "depth"},
       [](const Inputs&, const Answer&) { return false; },
       [sphere_box, bt](const Inputs& in) {
         btBoxShape box(bt(in, 7));
         box.setMargin(0);
         btSphereShape ball(f(in[3]));
         btTransform at;
         at.setIdentity();
         at.setOrigin(bt(in, 4));
         btTransform sat;
         sat.setIdentity();
         sat.setOrigin(bt(in, 0));
         btCollisionObject box_obj, ball_obj;
         box_obj.setCollisionShape(&box);
         box_obj.setWorldTransform(at);
         ball_obj.setCollisionShape(&ball);
         ball_obj.setWorldTransform(sat);
         const btCollisionObjectWrapper bw(nullptr, &box, &box_obj, at, -1, -1);
         const btCollisionObjectWrapper sw(nullptr, &ball, &ball_obj, sat, -1, -1);
         btCollisionAlgorithmConstructionInfo ci;
         btPersistentManifold manifold;
         btSphereBoxCollisionAlgorithm alg(&manifold, ci, &sw, &bw, false);
         btVector3 on_box, normal;
         btScalar d = 0;
         if (!alg.getSphereDistance(&bw, on_box, normal, d, bt(in, 0), f(in[3]), btScalar(1e18)))
           throw invalid_input("getSphereDistance answered no distance");
         return Out(sphere_box, d <= 0).set("distance", {std::max<btScalar>(d, 0)}).set("depth", {std::max<btScalar>(-d, 0)}).a;
       }});
  out.push_back({CDREF_BULLET_NAME, "TestAabbAgainstAabb2", "box-box",
                 "none; the adapter gives each box as min and max in the function's type", {},
                 [](const Inputs&, const Answer&) { return false; },
                 [box_box, bt](const Inputs& in) {
                   const btVector3 ca = bt(in, 0), ha = bt(in, 3), cb = bt(in, 6), hb = bt(in, 9);
                   return Out(box_box, TestAabbAgainstAabb2(ca - ha, ca + ha, cb - hb, cb + hb)).a;
                 }});
  out.push_back(
      {CDREF_BULLET_NAME, "TestTriangleAgainstAabb2", "triangle-box",
       "a conservative test: the triangle's bounds against the box, so a triangle apart from the box whose "
       "bounds meet it is reported as overlapping",
       {},
       [](const Inputs& in, const Answer& t) {
         if (t.cls) return false;
         for (int i = 0; i < 3; ++i) {  // the triangle's exact bounds meet the box's
           Q lo = Q(in[i]), hi = lo;
           for (int v = 1; v < 3; ++v) {
             const Q x(in[3 * v + i]);
             if (x < lo) lo = x;
             if (hi < x) hi = x;
           }
           if (hi < Q(in[9 + i]) - Q(in[12 + i]) || Q(in[9 + i]) + Q(in[12 + i]) < lo) return false;
         }
         return true;
       },
       [tri_box, bt](const Inputs& in) {
         const btVector3 v[3] = {bt(in, 0), bt(in, 3), bt(in, 6)};
         const btVector3 c = bt(in, 9), h = bt(in, 12);
         return Out(tri_box, TestTriangleAgainstAabb2(v, c - h, c + h)).a;
       }});
#endif
#ifndef CDREF_BULLET64
  out.push_back({"Eigen 3.4", "AlignedBox3f::intersects", "box-box",
                 "none; the adapter gives each box as min and max rounded to float", {},
                 [](const Inputs&, const Answer&) { return false; },
                 [box_box](const Inputs& in) {
                   auto box = [&](int k) {
                     const Eigen::Vector3f c(f(in[k]), f(in[k + 1]), f(in[k + 2])), h(f(in[k + 3]), f(in[k + 4]), f(in[k + 5]));
                     return Eigen::AlignedBox3f(c - h, c + h);
                   };
                   return Out(box_box, box(0).intersects(box(6))).a;
                 }});
  out.push_back({"Eigen 3.4", "AlignedBox3f::exteriorDistance (point to box, minus the radius)", "sphere-box",
                 "none (intersect: the centre's distance <= radius; distance: max(that - radius, 0)); the adapter "
                 "gives the box as min and max rounded to float",
                 {"distance"},
                 [](const Inputs&, const Answer&) { return false; },
                 [sphere_box](const Inputs& in) {
                   const Eigen::Vector3f p(f(in[0]), f(in[1]), f(in[2])), c(f(in[4]), f(in[5]), f(in[6])),
                       h(f(in[7]), f(in[8]), f(in[9]));
                   const float r = f(in[3]);
                   const float e = Eigen::AlignedBox3f(c - h, c + h).exteriorDistance(p);
                   Out o(sphere_box, e <= r);
                   return o.set("distance", {std::max(e - r, 0.0f)}).a;
                 }});
  out.push_back({"Eigen 3.4", "ParametrizedLine3f::intersectionParameter with Hyperplane3f::Through(v0, v1, v2)",
                 "ray-triangle-cast",
                 "a plane, not a triangle: the cases the exact answer calls a miss, and rays in the plane, are set "
                 "apart; a hit is a finite parameter >= 0",
                 {"lambda_enter"},
                 [](const Inputs& in, const Answer& t) { return !t.cls || in_plane(in); },
                 [ray_tri](const Inputs& in) {
                   auto v = [&](int k) { return Eigen::Vector3f(f(in[k]), f(in[k + 1]), f(in[k + 2])); };
                   const Eigen::ParametrizedLine<float, 3> line(v(0), v(3));
                   const auto plane = Eigen::Hyperplane<float, 3>::Through(v(6), v(9), v(12));
                   const float t = line.intersectionParameter(plane);
                   return Out(ray_tri, std::isfinite(t) && t >= 0).set("lambda_enter", {t}).a;
                 }});
#endif
#if defined(CDREF_HAVE_ODE) && !defined(CDREF_BULLET64)
  for (Adapter& ad : ode::adapters()) out.push_back(std::move(ad));
#endif
#if defined(CDREF_HAVE_EMBREE) && !defined(CDREF_BULLET64)
  for (Adapter& ad : embree::adapters()) out.push_back(std::move(ad));
#endif
#if defined(CDREF_HAVE_FCL) && !defined(CDREF_BULLET64)
  for (Adapter& ad : fcl_adapters()) out.push_back(std::move(ad));
#endif
#if defined(CDREF_HAVE_RAPIER) && !defined(CDREF_BULLET64)
  for (Adapter& ad : rapier::adapters()) out.push_back(std::move(ad));
#endif
#if defined(CDREF_HAVE_OPEN3D) && !defined(CDREF_BULLET64)
  for (Adapter& ad : open3d_adapters()) out.push_back(std::move(ad));
#endif
  for (Adapter& ad : out)
    if (!ad.precision) ad.precision = kPrecision;  // this executable's own type
  return out;
}

// Drift against scale: one panel per query and family with more than one scale, one curve per
// library function (the share of its graded cases it misclassifies).
[[maybe_unused]] std::string svg(const nlohmann::json& results, std::uint64_t n, std::uint64_t seed) {
  // a panel per query and family: "query: family" -> function -> (scale, misclassified %); a
  // function's legend says the type it runs at, and a double build's curve is dashed
  std::map<std::string, std::map<std::string, std::vector<std::pair<int, double>>>> curves;
  std::map<std::string, bool> at_double;  // function -> runs at double
  for (const auto& r : results) {
    const bool dbl = r["precision"].get<int>() == 53;
    const std::string fn = r["library"].get<std::string>() + ": " + r["function"].get<std::string>() +
                           (dbl ? "  [double]" : "  [float]");
    at_double[fn] = dbl;
    for (const auto& [fam, pts] : r["curves"].items())
      for (const auto& p : pts)
        curves[r["query"].get<std::string>() + ": " + fam][fn].push_back({p[0].get<int>(), p[1].get<double>()});
  }
  std::vector<std::string> fams;
  for (const auto& [fam, fns] : curves) {
    bool several = false;
    for (const auto& [fn, pts] : fns) several = several || pts.size() > 1;
    if (several) fams.push_back(fam);
  }
  const double pw = 420, ph = 250, legend = 18;
  const int cols = 2, rows = int((fams.size() + cols - 1) / cols);
  std::size_t most = 0;
  for (const auto& fam : fams) most = std::max(most, curves.at(fam).size());
  const double cell_h = ph + 60 + legend * double(most);
  std::ostringstream o;
  o.precision(5);
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << cols * (pw + 200) << "\" height=\"" << rows * cell_h + 40
    << "\" font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    << "<text x=\"10\" y=\"20\" font-size=\"14\">Library functions (at float, or at double where dashed): "
       "misclassified share of the graded cases against the family's scale, a panel per query and family ("
    << n << " cases per scale, seed " << seed << ")</text>\n";
  const char* colour[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf", "#7f7f7f", "#bcbd22"};
  for (std::size_t p = 0; p < fams.size(); ++p) {
    const double x0 = 60 + double(p % cols) * (pw + 200), y0 = 50 + double(p / cols) * cell_h;
    const auto& fns = curves.at(fams[p]);
    int lo = 1 << 30, hi = -(1 << 30);
    double top = 1;
    for (const auto& [fn, pts] : fns)
      for (const auto& [sc, v] : pts) lo = std::min(lo, sc), hi = std::max(hi, sc), top = std::max(top, v);
    top = std::ceil(top / 10) * 10;
    if (hi == lo) hi = lo + 1;
    auto X = [&](double sc) { return x0 + (sc - lo) / double(hi - lo) * pw; };
    auto Y = [&](double v) { return y0 + ph - v / top * ph; };
    o << "<text x=\"" << x0 << "\" y=\"" << y0 - 6 << "\" font-size=\"13\">" << fams[p] << "</text>\n"
      << "<rect x=\"" << x0 << "\" y=\"" << y0 << "\" width=\"" << pw << "\" height=\"" << ph
      << "\" fill=\"none\" stroke=\"#999\"/>\n";
    for (int t = 0; t <= 4; ++t)
      o << "<text x=\"" << x0 - 6 << "\" y=\"" << Y(top * t / 4) + 4 << "\" text-anchor=\"end\">" << top * t / 4 << "%</text>\n";
    o << "<text x=\"" << x0 << "\" y=\"" << y0 + ph + 14 << "\">scale " << lo << "</text><text x=\"" << x0 + pw
      << "\" y=\"" << y0 + ph + 14 << "\" text-anchor=\"end\">" << hi << "</text>\n";
    int c = 0;
    for (const auto& [fn, pts0] : fns) {
      auto pts = pts0;
      std::sort(pts.begin(), pts.end());
      const char* col = colour[c % 10];
      const bool dashed = at_double.at(fn);
      o << "<polyline fill=\"none\" stroke=\"" << col << "\" stroke-width=\"1.5\""
        << (dashed ? " stroke-dasharray=\"6 3\"" : "") << " points=\"";
      for (const auto& [sc, v] : pts) o << X(sc) << "," << Y(v) << " ";
      o << "\"/>\n";
      for (const auto& [sc, v] : pts)
        o << "<circle cx=\"" << X(sc) << "\" cy=\"" << Y(v) << "\" r=\"2.5\" fill=\"" << col << "\"/>\n";
      o << "<text x=\"" << x0 << "\" y=\"" << y0 + ph + 32 + legend * c << "\" fill=\"" << col << "\">" << fn << "</text>\n";
      ++c;
    }
  }
  o << "</svg>\n";
  return o.str();
}

// What a library writes to standard error while its row runs (FCL's "eigen: too many iterations
// in Jacobi transform." when it fits a bounding box to a degenerate triangle, an assertion's
// message from a library's C code): kept from the terminal, counted by line, the first line kept,
// and both given with the row. std::cerr goes to this buffer, file descriptor 2 to a temporary
// file read back at the end (the row's engine threads are the only writers meanwhile).
class Captured : public std::streambuf {
 public:
  Captured() : old_(std::cerr.rdbuf(this)) {
    std::fflush(stderr);
    file_ = std::tmpfile();
    saved_ = file_ ? ::dup(2) : -1;
    if (saved_ >= 0) ::dup2(::fileno(file_), 2);
  }
  ~Captured() override { finish(); }
  Captured(const Captured&) = delete;
  Captured& operator=(const Captured&) = delete;
  /// Standard error given back; what went to file descriptor 2 counted.
  void finish() {
    if (old_) std::cerr.rdbuf(old_), old_ = nullptr;
    if (saved_ >= 0) {
      std::fflush(stderr);
      ::dup2(saved_, 2);
      ::close(saved_);
      saved_ = -1;
      std::rewind(file_);
      char buf[4096];
      std::size_t k;
      while ((k = std::fread(buf, 1, sizeof buf, file_)) > 0) put(buf, std::streamsize(k));
    }
    if (file_) std::fclose(file_), file_ = nullptr;
  }
  std::uint64_t lines() const { return lines_; }
  const std::string& first() const { return first_; }

 protected:
  int_type overflow(int_type c) override {
    if (c != traits_type::eof()) {
      const char one = char(c);
      put(&one, 1);
    }
    return traits_type::not_eof(c);
  }
  std::streamsize xsputn(const char* p, std::streamsize n) override {
    put(p, n);
    return n;
  }

 private:
  // one write at a time (the engine's threads share the stream): a message written in one piece
  // stays whole
  void put(const char* p, std::streamsize n) {
    const std::lock_guard<std::mutex> one(m_);
    for (std::streamsize i = 0; i < n; ++i) {
      if (p[i] == '\n') {
        ++lines_;
        line_done_ = true;
      } else if (!line_done_ && first_.size() < 200) {
        first_ += p[i];
      }
    }
  }
  std::streambuf* old_;
  std::FILE* file_ = nullptr;
  int saved_ = -1;
  std::mutex m_;
  std::uint64_t lines_ = 0;
  std::string first_;
  bool line_done_ = false;
};

// Runs one adapter's campaign: its rows per family (cases, convention cases, misclassified,
// p99 and max ulps of each graded output over the family) and its misclassified share per
// scale, as JSON.
nlohmann::json collect(const Adapter& ad, std::uint64_t n, std::uint64_t seed, int threads) {
  const Query q = fuzz::query_by_name(ad.query);
  // the library's function through the validate API, as a user's own function runs: once a
  // case, the cases its convention gives another meaning set apart by the engine
  // (Options::convention, CellStats::set_apart), decided on the exact answer it computed
  validate::Options o;
  o.query = ad.query;
  o.n = n;
  o.seed = seed;
  o.precision = ad.precision;
  o.threads = threads;
  o.name = "peer";
  o.convention = [&ad](const validate::Case& c) { return ad.differs(c.inputs(), c.exact_answer()); };
  if (ad.prefetch) o.prefetch = ad.prefetch;
  std::optional<Captured> said(std::in_place);
  const validate::Report rep = validate::run_engine(o, [&ad](const validate::Case& c) { return ad.run(c.inputs()); });
  const fuzz::Results& res = rep.results;
  said->finish();
  const std::uint64_t said_lines = said->lines();
  const std::string said_first = said->first();
  said.reset();
  struct Fam {
    std::uint64_t cases = 0, refused = 0, apart = 0, fp = 0, fn = 0;
    std::map<std::string, std::pair<fuzz::Histogram, std::uint64_t>> ulps;  // histogram, max
    std::map<std::string, std::pair<double, double>> err;                     // max abs, max rel
    // the worst value per graded group, and a misclassified case from the scale with the most,
    // each with the scale of its cell
    std::map<std::string, std::pair<fuzz::Exemplar, int>> worst;
    std::pair<fuzz::Exemplar, int> missed;
    std::uint64_t missed_most = 0;
    // the smallest scale with a misclassified case, and the counts at the largest scale
    std::optional<int> first_wrong;
    int last_scale = 0;
    std::uint64_t last_fp = 0, last_fn = 0;
  };
  // an exemplar as JSON: the case's inputs by column name, the function's answer and the truth
  const std::vector<std::string>& columns = fuzz::info(q).inputs;
  auto example = [&columns](const std::pair<fuzz::Exemplar, int>& e) {
    nlohmann::json in = nlohmann::json::object();
    for (std::size_t c = 0; c < columns.size(); ++c) in[columns[c]] = e.first.inputs[c];
    return nlohmann::json{{"scale", e.second}, {"inputs", in}, {"got", double(e.first.got)}, {"want", double(e.first.want)}};
  };
  std::map<std::string, Fam> fams;
  nlohmann::json out = {{"library", ad.library}, {"function", ad.function}, {"query", ad.query},
                        {"convention", ad.convention}, {"graded", ad.graded}, {"precision", ad.precision}};
  out["curves"] = nlohmann::json::object();
  if (said_lines) out["library_messages"] = {{"lines", said_lines}, {"first", said_first}};
  for (const auto& [k, st] : res.cells) {
    Fam& f = fams[k.family];
    const std::uint64_t graded = st.n - st.refused - st.set_apart;
    out["curves"][k.family].push_back({k.scale, graded ? 100.0 * double(st.cls_fp + st.cls_fn) / double(graded) : 0.0});
    f.cases += st.n;
    f.refused += st.refused;
    f.apart += st.set_apart;
    f.fp += st.cls_fp;
    f.fn += st.cls_fn;
    if (st.cls_fp + st.cls_fn && !f.first_wrong) f.first_wrong = k.scale;  // (cells in increasing scale)
    f.last_scale = k.scale, f.last_fp = st.cls_fp, f.last_fn = st.cls_fn;
    if (st.cls_example.set && st.cls_fp + st.cls_fn > f.missed_most) {
      f.missed = {st.cls_example, k.scale};
      f.missed_most = st.cls_fp + st.cls_fn;
    }
    for (const std::string& g : ad.graded) {
      int first = 0;
      const int gi = group(q, g, &first);
      auto& [h, mx] = f.ulps[g];
      for (int b = 0; b < fuzz::Histogram::bins; ++b) h.count[b] += st.out[gi].hist.count[b];
      if (st.out[gi].worst.set) mx = std::max(mx, st.out[gi].worst.metric);
      auto& [w, at] = f.worst[g];
      if (st.out[gi].worst.set && (!w.set || st.out[gi].worst.metric > w.metric)) w = st.out[gi].worst, at = k.scale;
      auto& [ab, re] = f.err[g];
      ab = std::max(ab, st.out[gi].max_abs);
      re = std::max(re, st.out[gi].max_rel);
    }
  }
  out["families"] = nlohmann::json::array();
  for (auto& [fam, f] : fams) {
    nlohmann::json jr = {{"family", fam},
                         {"cases", f.cases},
                         {"convention", f.apart},
                         {"refused", f.refused},
                         {"false_positives", f.fp},
                         {"false_negatives", f.fn},
                         {"largest_scale", {{"scale", f.last_scale}, {"false_positives", f.last_fp}, {"false_negatives", f.last_fn}}}};
    if (f.first_wrong) jr["first_misclassified_scale"] = *f.first_wrong;
    jr["ulps"] = nlohmann::json::object();
    for (const auto& g : ad.graded) {
      const auto& [h, mx] = f.ulps[g];
      const auto& [ab, re] = f.err[g];
      jr["ulps"][g] = {{"p99", h.total() ? h.quantile(0.99) : 0}, {"max", mx}, {"max_abs", ab}, {"max_rel", re}};
      if (f.worst[g].first.set) jr["ulps"][g]["worst"] = example(f.worst[g]);
    }
    if (f.missed.first.set) jr["misclassified_example"] = example(f.missed);
    out["families"].push_back(jr);
  }
  return out;
}

[[maybe_unused]] void print(std::ostream& o, const nlohmann::json& r) {
  o << "\n" << r["library"].get<std::string>() << ": " << r["function"].get<std::string>() << " as "
    << r["query"].get<std::string>() << "\n  convention: " << r["convention"].get<std::string>() << "\n";
  if (r.contains("library_messages"))
    o << "  the library wrote " << r["library_messages"]["lines"].get<std::uint64_t>()
      << " lines to standard error while it ran (kept from the terminal), the first: "
      << r["library_messages"]["first"].get<std::string>() << "\n";
  char line[256];
  std::snprintf(line, sizeof line, "  %-18s %8s %10s %8s %16s %12s", "family", "cases", "convention", "refused", "misclassified",
                "first wrong");
  o << line;
  for (const auto& g : r["graded"]) o << "  " << g.get<std::string>() << " p99/max ulps, max rel";
  o << "\n";
  for (const auto& f : r["families"]) {
    std::snprintf(line, sizeof line, "  %-18s %8llu %10llu %8llu %7llu/%-8llu", f["family"].get<std::string>().c_str(),
                  f["cases"].get<unsigned long long>(), f["convention"].get<unsigned long long>(),
                  f["refused"].get<unsigned long long>(),
                  f["false_positives"].get<unsigned long long>(), f["false_negatives"].get<unsigned long long>());
    o << line;
    if (f.contains("first_misclassified_scale"))
      std::snprintf(line, sizeof line, " %12d", f["first_misclassified_scale"].get<int>());
    else
      std::snprintf(line, sizeof line, " %12s", "-");
    o << line;
    for (const auto& g : r["graded"]) {
      const auto& u = f["ulps"][g.get<std::string>()];
      std::snprintf(line, sizeof line, "  %10llu/%-10llu %9.2g", u["p99"].get<unsigned long long>(),
                    u["max"].get<unsigned long long>(), u.contains("max_rel") ? u["max_rel"].get<double>() : 0.0);
      o << line;
    }
    o << "\n";
  }
}

struct Args {
  std::uint64_t n = 2000, seed = 1;
  std::string json_out, svg_out, rows_out;
  int threads = 2;
  std::vector<std::string> libraries;  // --library: only these (empty: every library built in)
  // the library is one of those asked for (its row's library name begins with it)
  bool wants(const std::string& library) const {
    if (libraries.empty()) return true;
    for (const std::string& l : libraries)
      if (library.rfind(l + " ", 0) == 0) return true;
    return false;
  }
};

// The options of `cdref peers` (and of its float64 helper, which adds --rows).
void add_options(cli::Command& c, Args& a) {
  c.whole("--n", a.n, 1, 10000000, "cases per family and scale (default 2000)")
      .whole("--seed", a.seed, 0, UINT64_MAX, "the seed (default 1)")
      .whole("--threads", a.threads, 1, 4096, "worker threads (default 2)");
}

}  // namespace

#ifdef CDREF_BULLET64
// cdref_peers_bullet64: Bullet's float64 build in its own process (its inline functions carry
// the float build's names), run by `cdref peers`, which prints its rows with the others.
int helper_main(int argc, char** argv) {
  cli::Program program("cdref_peers_bullet64", "Bullet's float64 build for cdref peers");
  Args a;
  cli::Command root = program.root();
  add_options(root, a);
  root.text("--rows", a.rows_out, "the file to write the rows to").required();
  return program.run(argc, argv, [&] {
    cli::io::Output rows(a.rows_out, "--rows");
    nlohmann::json all = nlohmann::json::array();
    for (const Adapter& ad : adapters()) all.push_back(collect(ad, a.n, a.seed, a.threads));
    rows.stream() << all.dump() << "\n";
    rows.commit();
    return 0;
  });
}
#else
// Runs the helper with these arguments, no shell; true when it exits 0.
bool run_helper(const std::string& exe, const std::vector<std::string>& args) {
  std::vector<char*> argv;
  std::vector<std::string> all = {exe};
  all.insert(all.end(), args.begin(), args.end());
  for (std::string& s : all) argv.push_back(s.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, exe.c_str(), nullptr, nullptr, argv.data(), environ) != 0) return false;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

int peers_run(const Args& a) {
  // the outputs first: a path that cannot be written is refused before the work
  std::optional<cli::io::Output> svg_file, json_file;
  if (!a.svg_out.empty()) svg_file.emplace(a.svg_out, "--svg");
  if (!a.json_out.empty()) json_file.emplace(a.json_out, "--json");
  // (with --json - or --svg -, standard output is the data's: the table goes to standard error)
  std::ostream& human = a.json_out == "-" || a.svg_out == "-" ? std::cerr : std::cout;

  human << "Library functions on cdref's families, against the exact answer (" << a.n
            << " cases per family and scale, seed " << a.seed << ").\n"
            << "convention: cases where the library's meaning differs from cdref's (set apart, not drift);\n"
            << "refused: cases the function cannot take (beyond its type's range, or refused for the reason its row states);\n"
            << "misclassified: false positives / false negatives among the others (first wrong: the smallest of the family's\n"
               "scales where it misclassifies; the JSON gives the counts at its largest); errors in ulps of the function's\n"
               "type (float; double for ODE, FCL and Bullet's float64 build): p99 / max, and the largest error relative to the\n"
               "inputs' scale.\n";
#ifndef CDREF_HAVE_GLM
  human << "(GLM not found at build time: apt-get install libglm-dev and rebuild)\n";
#endif
#ifndef CDREF_HAVE_BULLET
  human << "(Bullet not found at build time: apt-get install libbullet-dev and rebuild)\n";
#endif
#ifndef CDREF_HAVE_ODE
  human << "(ODE not found at build time: apt-get install libode-dev and rebuild)\n";
#endif
#ifndef CDREF_HAVE_EMBREE
  human << "(Embree not found at build time: apt-get install libembree-dev and rebuild)\n";
#endif
#ifndef CDREF_HAVE_FCL
  human << "(FCL not found at build time: apt-get install libfcl-dev and rebuild)\n";
#endif
#ifndef CDREF_HAVE_OPEN3D
  human << "(Open3D not found at build time: apt-get install libopen3d-dev and rebuild)\n";
#endif
#ifndef CDREF_HAVE_RAPIER
  human << "(Rapier not found at build time: scripts/deps.sh installs it with npm into scripts/rapier; rebuild)\n";
#endif
  nlohmann::json all = nlohmann::json::array();
  // a row that cannot run (a library's process that cannot start, say) is named and the others
  // go on: what they computed is written, and the command then fails
  std::vector<std::string> failed;
  for (const Adapter& ad : adapters()) {
    if (!a.wants(ad.library)) continue;
    try {
      all.push_back(collect(ad, a.n, a.seed, a.threads));
      print(human, all.back());
    } catch (const std::exception& e) {
      failed.push_back(ad.library + ": " + ad.function + ": " + e.what());
      human << "\n" << ad.library << ": " << ad.function << " could not run: " << e.what() << "\n";
    }
  }
  // Bullet's float64 build, from its helper beside this executable
  const std::string helper = beside_this_program("cdref_peers_bullet64");
  const bool bullet64 = a.wants("Bullet ");
  if (bullet64 && std::filesystem::exists(helper)) {
    const std::string rows = std::filesystem::temp_directory_path() / ("cdref-peers-" + std::to_string(::getpid()) + ".json");
    if (run_helper(helper, {"--n", std::to_string(a.n), "--seed", std::to_string(a.seed), "--threads",
                            std::to_string(a.threads), "--rows", rows})) {
      std::ifstream in(rows);
      const nlohmann::json more = nlohmann::json::parse(in);
      std::filesystem::remove(rows);
      for (const auto& r : more) {
        all.push_back(r);
        print(human, r);
      }
    } else {
      std::filesystem::remove(rows);
      failed.push_back("the float64 helper " + helper + " failed");
      human << "\n(Bullet's float64 build: the helper " << helper << " failed)\n";
    }
  } else if (bullet64) {
    human << "\n(Bullet's float64 build: no helper " << helper << ")\n";
  }
  cli::io::Outputs outs;
  if (svg_file) outs.attempt([&] {
      svg_file->stream() << svg(all, a.n, a.seed);
      svg_file->commit();
    });
  if (json_file) outs.attempt([&] {
      json_file->stream() << all.dump(1) << "\n";
      json_file->commit();
    });
  outs.finish();
  if (!failed.empty())
    throw std::runtime_error(std::to_string(failed.size()) + " gallery row(s) could not run (the others are written): " +
                             failed.front());
  return 0;
}

void add_peers_command(cli::Program& program) {
  auto a = std::make_shared<Args>();
  cli::Command c = program.add(
      "peers",
      description,
      [a] { return peers_run(*a); });
  add_options(c, *a);
  c.choices("--library", a->libraries, {"GLM", "Bullet", "Eigen", "Embree", "ODE", "FCL", "Open3D", "Rapier"},
            "only this library's functions (repeatable; default: every library built in)")
      .text("--json", a->json_out, "write the rows as JSON to this file (- for standard output)")
      .text("--svg", a->svg_out, "draw the gallery to this SVG");
}
#endif

}  // namespace cdref::peers

#ifdef CDREF_BULLET64
int main(int argc, char** argv) {
  cdref::cli::io::init();
  return cdref::peers::helper_main(argc, argv);
}
#elif defined(CDREF_PEERS_PROGRAM)
// cdref_peers, the gallery's program: `cdref peers ARGS` runs it in its own place as
// `cdref peers ARGS`, so that it parses, prints and exits as cdref's command did.
int main(int argc, char** argv) {
  cdref::exact::use_gmp_pool();  // GMP's small blocks cached per thread (gmp_pool.hpp), as in cdref
  cdref::cli::io::init();
  cdref::cli::Program program("cdref", "cdref's gallery: run it as cdref peers [OPTIONS]");
  cdref::peers::add_peers_command(program);
  return program.run(argc, argv, []() -> int { throw std::runtime_error("the gallery runs as: cdref peers [OPTIONS]"); });
}
#endif
