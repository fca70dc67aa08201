// src/peers/fcl.cpp - FCL's functions in `cdref peers` (libfcl-dev: FCL 0.7 at double, so the
// cases reach it unrounded and its errors are graded in ulps of double).
//
// What is graded, as FCL's users call it:
//   obb-obb            OBB<double>::overlap (the bounding-volume test of its BVH traversals);
//   triangle-box       fcl::collide of a one-triangle BVHModel<OBBRSS> against a Box, once with
//                      each narrow-phase solver (GST_LIBCCD, the default, and GST_INDEP);
//   triangle-triangle  fcl::collide of two one-triangle BVHModels;
//   sphere-triangle,   fcl::collide (a contact asked for: its penetration_depth is the depth)
//   sphere-box,        and fcl::distance (unsigned: -1 where FCL finds them in contact, read as
//   sphere-sphere      distance 0) on a Sphere against the other shape.
// A Box takes full side lengths: twice the extents, exact in double unless they overflow (then
// the case is refused). FCL's signed distance (DistanceRequest::enable_signed_distance) is not
// graded: on two concentric spheres it does not return (Debian's 0.7.0, seen with a centre
// distance of 0 and 1e-300), and a row cannot time a call out.
//
// Two of FCL's conventions are decided exactly and set apart:
//   OBB<double>::overlap adds 1e-6 to every |R_ij| (a fixed margin against parallel edges) and
//   assumes orthonormal axes: its 15 tests are evaluated on the case's rationals with the margin,
//   and a case where that differs from the exact answer is FCL's meaning, not its rounding;
//   sphere-triangle grows the radius by machine epsilon (r + 2^-52, rounded) and tests it
//   strictly, and calls a zero-area triangle a contact with any sphere: likewise evaluated
//   exactly.
#include "fcl.hpp"

#include <fcl/fcl.h>

#include <cdref/book/point_triangle.hpp>
#include <cdref/error.hpp>
#include <cdref/exact/rationals.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <string>

#ifndef CDREF_FCL_VERSION
#define CDREF_FCL_VERSION "0.7"
#endif

namespace cdref::peers {

namespace {

using S = double;
using V = ::fcl::Vector3<S>;

V vec(const Inputs& in, int k) { return V(in[k], in[k + 1], in[k + 2]); }
::fcl::Transform3<S> at(const Inputs& in, int k) {
  ::fcl::Transform3<S> t = ::fcl::Transform3<S>::Identity();
  t.translation() = vec(in, k);
  return t;
}
/// A Box of the case's extents (column k): FCL's side lengths, twice the extents.
std::shared_ptr<::fcl::Box<S>> box(const Inputs& in, int k) {
  const V side = 2 * vec(in, k);
  if (!side.allFinite()) throw invalid_input("the box's side lengths (twice its extents) overflow double");
  return std::make_shared<::fcl::Box<S>>(side);
}
/// A one-triangle mesh (vertices at columns k, k + 3, k + 6).
std::shared_ptr<::fcl::BVHModel<::fcl::OBBRSS<S>>> triangle(const Inputs& in, int k) {
  auto m = std::make_shared<::fcl::BVHModel<::fcl::OBBRSS<S>>>();
  m->beginModel(1, 3);
  m->addTriangle(vec(in, k), vec(in, k + 3), vec(in, k + 6));
  m->endModel();
  return m;
}
::fcl::CollisionObject<S> object(std::shared_ptr<::fcl::CollisionGeometry<S>> g, const ::fcl::Transform3<S>& t) {
  return ::fcl::CollisionObject<S>(std::move(g), t);
}
/// fcl::collide on two objects with the solver given; *depth (when asked) is the first contact's
/// penetration depth as FCL reports it.
bool collide(const ::fcl::CollisionObject<S>& a, const ::fcl::CollisionObject<S>& b, ::fcl::GJKSolverType solver,
             double* depth = nullptr) {
  ::fcl::CollisionRequest<S> rq;
  rq.gjk_solver_type = solver;
  rq.enable_contact = depth != nullptr;
  ::fcl::CollisionResult<S> rs;
  ::fcl::collide(&a, &b, rq, rs);
  if (depth) *depth = rs.numContacts() ? rs.getContact(0).penetration_depth : 0;
  return rs.isCollision();
}
/// fcl::distance (unsigned): -1 where FCL finds the objects in contact, read as 0.
double distance(const ::fcl::CollisionObject<S>& a, const ::fcl::CollisionObject<S>& b) {
  ::fcl::DistanceRequest<S> rq;
  ::fcl::DistanceResult<S> rs;
  const double d = ::fcl::distance(&a, &b, rq, rs);
  return d < 0 ? 0 : d;
}

/// fcl::collide with a contact asked for, then fcl::distance where FCL finds none: intersect,
/// depth (the contact's penetration depth, negated where FCL reports it negative) and distance.
Answer proximity(Query q, const ::fcl::CollisionObject<S>& a, const ::fcl::CollisionObject<S>& b, bool negated_depth) {
  double depth = 0;
  const bool hit = collide(a, b, ::fcl::GST_LIBCCD, &depth);
  Out o(q, hit);
  o.set("depth", {hit ? (negated_depth ? -depth : depth) : 0.0});
  return o.set("distance", {hit ? 0.0 : distance(a, b)}).a;
}

// ---- FCL's conventions evaluated exactly ----

/// OBB<double>::overlap's 15 tests (obbDisjoint) on the case's rationals, with its margin: R =
/// A^T B and T = A^T (c_b - c_a) from the axes as given, |R_ij| + 1e-6 in the bounds.
bool obb_overlap_exact(const Inputs& in) {
  const QV ca = qv(in, 0), cb = qv(in, 15);
  const Q ea[3] = {Q(in[3]), Q(in[4]), Q(in[5])}, eb[3] = {Q(in[18]), Q(in[19]), Q(in[20])};
  const QV A[3] = {qv(in, 6), qv(in, 9), qv(in, 12)}, B[3] = {qv(in, 21), qv(in, 24), qv(in, 27)};
  const QV t = sub(cb, ca);
  const Q reps(1e-6);  // the double FCL adds (S reps = 1e-6)
  Q R[3][3], F[3][3], T[3];
  auto abs = [](const Q& x) { return x < 0 ? Q(-x) : x; };
  for (int i = 0; i < 3; ++i) {
    T[i] = dot(A[i], t);
    for (int j = 0; j < 3; ++j) R[i][j] = dot(A[i], B[j]), F[i][j] = abs(R[i][j]) + reps;
  }
  for (int i = 0; i < 3; ++i) {  // A's axes
    const Q bound = ea[i] + F[i][0] * eb[0] + F[i][1] * eb[1] + F[i][2] * eb[2];
    if (abs(T[i]) > bound) return false;
  }
  for (int j = 0; j < 3; ++j) {  // B's axes
    const Q s = R[0][j] * T[0] + R[1][j] * T[1] + R[2][j] * T[2];
    if (abs(s) > eb[j] + F[0][j] * ea[0] + F[1][j] * ea[1] + F[2][j] * ea[2]) return false;
  }
  for (int i = 0; i < 3; ++i)  // A_i x B_j, with (i, i1, i2) and (j, j1, j2) cyclic
    for (int j = 0; j < 3; ++j) {
      const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      const Q s = T[i2] * R[i1][j] - T[i1] * R[i2][j];
      const Q bound = ea[i1] * F[i2][j] + ea[i2] * F[i1][j] + eb[j1] * F[i][j2] + eb[j2] * F[i][j1];
      if (abs(s) > bound) return false;
    }
  return true;
}

/// sphereTriangleIntersect on the case's rationals: a zero-area triangle is a contact; otherwise
/// the centre's squared distance to the triangle below (r + 2^-52)^2, the sum rounded as FCL
/// rounds it.
bool sphere_triangle_exact(const Inputs& in) {
  const QV c = qv(in, 0), v0 = qv(in, 4), v1 = qv(in, 7), v2 = qv(in, 10);
  const QV n = cross(sub(v1, v0), sub(v2, v0));
  if (n.x == 0 && n.y == 0 && n.z == 0) return true;
  using Vq = Vec3<Q>;
  auto vq = [](const QV& p) { return Vq(p.x, p.y, p.z); };
  const Triangle<Q> tri{{vq(v0), vq(v1), vq(v2)}};
  const Q grown(in[3] + std::numeric_limits<double>::epsilon());
  return book::squared_distance(vq(c), tri) < grown * grown;
}

}  // namespace

std::vector<Adapter> fcl_adapters() {
  const std::string lib = "FCL " CDREF_FCL_VERSION " (double)";
  const Query obb_obb = fuzz::query_by_name("obb-obb");
  const Query tri_box = fuzz::query_by_name("triangle-box");
  const Query tri_tri = fuzz::query_by_name("triangle-triangle");
  const Query sphere_tri = fuzz::query_by_name("sphere-triangle");
  const Query sphere_box = fuzz::query_by_name("sphere-box");
  const Query sphere_sphere = fuzz::query_by_name("sphere-sphere");
  auto none = [](const Inputs&, const Answer&) { return false; };
  std::vector<Adapter> out;
  out.push_back({lib, "OBB<double>::overlap", "obb-obb",
                 "a margin: 1e-6 is added to every |R_ij| of the relative rotation (FCL's guard for parallel edges), "
                 "and the axes are taken as orthonormal; the cases where its 15 tests, evaluated exactly with that "
                 "margin, answer otherwise than the exact solid are set apart",
                 {},
                 [](const Inputs& in, const Answer& t) { return obb_overlap_exact(in) != t.cls; },
                 [obb_obb](const Inputs& in) {
                   auto obb = [&](int k) {
                     ::fcl::Matrix3<S> axis;
                     for (int i = 0; i < 3; ++i) axis.col(i) = vec(in, k + 6 + 3 * i);
                     return ::fcl::OBB<S>(axis, vec(in, k), vec(in, k + 3));
                   };
                   return Out(obb_obb, obb(0).overlap(obb(15))).a;
                 },
                 53});
  for (const auto& [solver, name] : {std::pair{::fcl::GST_LIBCCD, "GST_LIBCCD (libccd's GJK, the default)"},
                                     std::pair{::fcl::GST_INDEP, "GST_INDEP (FCL's own GJK)"}}) {
    out.push_back({lib, std::string("fcl::collide (one-triangle BVHModel<OBBRSS>, Box; ") + name + ")", "triangle-box",
                   "none: GJK's tolerance is its numerics, graded; the adapter gives the box's side lengths as "
                   "twice its extents",
                   {},
                   none,
                   [tri_box, solver = solver](const Inputs& in) {
                     const auto a = object(triangle(in, 0), ::fcl::Transform3<S>::Identity());
                     const auto b = object(box(in, 12), at(in, 9));
                     return Out(tri_box, collide(a, b, solver)).a;
                   },
                   53});
  }
  out.push_back({lib, "fcl::collide (two one-triangle BVHModel<OBBRSS>)", "triangle-triangle",
                 "none (intersect only: FCL's contacts are not cdref's segment)",
                 {},
                 none,
                 [tri_tri](const Inputs& in) {
                   const auto a = object(triangle(in, 0), ::fcl::Transform3<S>::Identity());
                   const auto b = object(triangle(in, 9), ::fcl::Transform3<S>::Identity());
                   return Out(tri_tri, collide(a, b, ::fcl::GST_LIBCCD)).a;
                 },
                 53});
  out.push_back({lib, "fcl::collide and fcl::distance (Sphere, one-triangle BVHModel<OBBRSS>)", "sphere-triangle",
                 "the radius grown by machine epsilon (r + 2^-52) and tested strictly, and a zero-area triangle in "
                 "contact with every sphere: the cases where that, evaluated exactly, differs from the closed "
                 "solids are set apart; FCL reports the depth negated, which the adapter turns back",
                 {"distance", "depth"},
                 [](const Inputs& in, const Answer& t) { return sphere_triangle_exact(in) != t.cls; },
                 [sphere_tri](const Inputs& in) {
                   const auto a = object(std::make_shared<::fcl::Sphere<S>>(in[3]), at(in, 0));
                   const auto b = object(triangle(in, 4), ::fcl::Transform3<S>::Identity());
                   return proximity(sphere_tri, a, b, true);
                 },
                 53});
  out.push_back({lib, "fcl::collide and fcl::distance (Sphere, Box)", "sphere-box",
                 "none: touching is a contact of depth 0; the adapter gives the box's side lengths as twice its "
                 "extents",
                 {"distance", "depth"},
                 none,
                 [sphere_box](const Inputs& in) {
                   const auto a = object(std::make_shared<::fcl::Sphere<S>>(in[3]), at(in, 0));
                   const auto b = object(box(in, 7), at(in, 4));
                   return proximity(sphere_box, a, b, false);
                 },
                 53});
  out.push_back({lib, "fcl::collide and fcl::distance (Sphere, Sphere)", "sphere-sphere",
                 "none: touching is a contact of depth 0",
                 {"distance", "depth"},
                 none,
                 [sphere_sphere](const Inputs& in) {
                   const auto a = object(std::make_shared<::fcl::Sphere<S>>(in[3]), at(in, 0));
                   const auto b = object(std::make_shared<::fcl::Sphere<S>>(in[7]), at(in, 4));
                   return proximity(sphere_sphere, a, b, false);
                 },
                 53});
  return out;
}

}  // namespace cdref::peers
