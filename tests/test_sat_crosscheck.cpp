// tests/test_sat_crosscheck.cpp - an independent check of the Section 3.3 and 3.4 answers
// against CGAL in its exact kernel (CGAL::Epeck), on every family of the campaign (at least
// 10^4 inputs per pair, hard families included):
//   segment-box, ray-box   CGAL::do_intersect(Segment_3 | Ray_3, Iso_cuboid_3): closed
//                          segment or ray against the closed box, as in cdref;
//   triangle-box           CGAL::do_intersect(Triangle_3, Iso_cuboid_3) (a triangle of zero
//                          area as the segment or point it spans, which CGAL's Triangle_3 does
//                          not take);
//   oriented boxes         CGAL has no such pair. Each box is built as the closed triangle mesh
//                          of its parallelepiped (vertices c +- h_0 a_0 +- h_1 a_1 +- h_2 a_2 in
//                          Epeck, exact) and Polygon_mesh_processing::do_intersect decides:
//                          two boxes with do_overlap_test_of_bounded_sides (volumes included);
//                          a segment: it crosses the surface or its source lies in the box
//                          (Side_of_triangle_mesh); a triangle: the surfaces meet or a vertex
//                          lies in the box. Boxes of zero extent have no closed mesh and are
//                          left to the other tests.
//   sphere-triangle        CGAL::squared_distance(Point_3, Triangle_3) (or Segment_3, Point_3
//                          for zero-area triangles) equals |x - c|^2 for the book's closest
//                          point x, and decides the closed ball against rho^2;
//   ray/segment-triangle   CGAL::do_intersect(Ray_3 | Segment_3, Triangle_3) decides, and
//                          CGAL::intersection's point (or segment, for a shot in the plane)
//                          is the book's entry point (and exit point);
//   triangle-triangle      CGAL::do_intersect(Triangle_3, Triangle_3) (zero-area triangles as
//                          their spans) decides, and CGAL::intersection's point or segment is
//                          the book's [p, q] where the triangles are not coplanar;
//   polygons               the union of CGAL's answers on the fan triangles (Ray_3, Segment_3,
//                          Triangle_3, Iso_cuboid_3; squared_distance for the sphere).
// cdref's answers are the book at Gmpq for the axis-aligned pairs (there it is the truth) and
// the solid (cdref::solid, Theorem 3.1 on the true normals) at Gmpq for oriented boxes, on the
// campaign's rounded rotations and on exactly orthonormal rational frames (from integer
// quaternions), where the book's frame transform must give the same answer.
#include <cdref/exact/cgal_kernels.hpp>

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <CGAL/Polygon_mesh_processing/intersection.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/intersections.h>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

#include <cdref/book/polygon_obb.hpp>
#include <cdref/fuzz/campaign.hpp>
#include <random>

#include "support.hpp"

using namespace cdref;
using namespace cdref::test;
namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

using K = CGAL::Epeck;
using FT = K::FT;
using P3 = K::Point_3;
using Mesh = CGAL::Surface_mesh<P3>;

FT ft(const Q& x) { return FT(mpq_class(x.mpq())); }
P3 pt(const Vec3<Q>& v) { return P3(ft(v[0]), ft(v[1]), ft(v[2])); }
Vec3<Q> qv(const fuzz::Inputs& in, int k) { return Vec3<Q>(Q(in[k]), Q(in[k + 1]), Q(in[k + 2])); }
OrientedBox<Q> qobb(const fuzz::Inputs& in, int k) {
  return {qv(in, k), qv(in, k + 3), {qv(in, k + 6), qv(in, k + 9), qv(in, k + 12)}};
}
bool finite(const fuzz::Inputs& in, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(in[i])) return false;
  return true;
}
bool flat(const OrientedBox<Q>& b) { return b.extent[0] == 0 || b.extent[1] == 0 || b.extent[2] == 0; }

// The closed triangle mesh of the parallelepiped, faces oriented outward.
Mesh box_mesh(const OrientedBox<Q>& b) {
  Mesh m;
  Mesh::Vertex_index v[8];
  for (int k = 0; k < 8; ++k) {
    Vec3<Q> p = b.center;
    for (int i = 0; i < 3; ++i) p += (((k >> i) & 1) ? Q(1) : Q(-1)) * b.extent[i] * b.axis[i];
    v[k] = m.add_vertex(pt(p));
  }
  // quads of the unit cube (bit i of the index = sign along axis i), outward for a
  // right-handed frame; a left-handed one flips every face
  const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  const bool flip = b.axis[0].dot(b.axis[1].cross(b.axis[2])) < 0;
  for (const auto& q : quads) {
    int a = q[0], c = q[2];
    if (flip) std::swap(a, c);
    m.add_face(v[a], v[q[1]], v[c]);
    m.add_face(v[a], v[c], v[q[3]]);
  }
  return m;
}
bool inside(const Mesh& m, const Vec3<Q>& p) {
  CGAL::Side_of_triangle_mesh<Mesh, K> side(m);
  return side(pt(p)) != CGAL::ON_UNBOUNDED_SIDE;
}
bool pmp_boxes(const OrientedBox<Q>& a, const OrientedBox<Q>& b) {
  return PMP::do_intersect(box_mesh(a), box_mesh(b), CGAL::parameters::do_overlap_test_of_bounded_sides(true),
                           CGAL::parameters::do_overlap_test_of_bounded_sides(true));
}
bool pmp_segment(const Segment<Q>& s, const OrientedBox<Q>& b) {
  const Mesh m = box_mesh(b);
  if (inside(m, s.source)) return true;
  if (s.source == s.target) return false;
  const std::vector<P3> line = {pt(s.source), pt(s.target)};
  return PMP::do_intersect(m, line);
}
bool pmp_triangle(const Triangle<Q>& t, const OrientedBox<Q>& b) {
  const Mesh m = box_mesh(b);
  if (inside(m, t.vertex[0])) return true;
  Mesh tm;
  tm.add_face(tm.add_vertex(pt(t.vertex[0])), tm.add_vertex(pt(t.vertex[1])), tm.add_vertex(pt(t.vertex[2])));
  return PMP::do_intersect(m, tm);
}
// a zero-area triangle: the segment between its two farthest vertices (or a point)
std::optional<Segment<Q>> degenerate_span(const Triangle<Q>& t) {
  const Vec3<Q> n = Vec3<Q>(t.vertex[1] - t.vertex[0]).cross(Vec3<Q>(t.vertex[2] - t.vertex[0]));
  if (!book::detail::is_zero(n)) return std::nullopt;
  Segment<Q> best{t.vertex[0], t.vertex[0]};
  Q far = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) {
      const Q d = Vec3<Q>(t.vertex[i] - t.vertex[j]).squaredNorm();
      if (d > far) far = d, best = {t.vertex[i], t.vertex[j]};
    }
  return best;
}
K::Iso_cuboid_3 cuboid(const Box<Q>& b) { return K::Iso_cuboid_3(pt(Vec3<Q>(b.center - b.extent)), pt(Vec3<Q>(b.center + b.extent))); }

// Every case of every family and scale of query `name`, n per cell: f(inputs) -> (cdref, CGAL)
// or nothing (a case left out); counts agreements and both outcomes.
struct Tally {
  std::uint64_t n = 0, yes = 0, no = 0, skipped = 0;
};
template <class Fn>
Tally over_families(const char* name, std::uint64_t per_cell, Fn f) {
  const fuzz::Query q = fuzz::query_by_name(name);
  Tally t;
  for (const fuzz::Family& fam : fuzz::families(q))
    for (int k : fam.scales)
      for (std::uint64_t i = 0; i < per_cell; ++i) {
        const fuzz::Inputs in = fuzz::make_case(17, q, fam, k, i);
        INFO(name << " " << fam.name << "/" << k << " case " << i);
        if (!finite(in, fuzz::info(q).inputs.size())) {
          ++t.skipped;
          continue;
        }
        const std::optional<std::pair<bool, bool>> r = f(in);
        if (!r) {
          ++t.skipped;
          continue;
        }
        REQUIRE(r->first == r->second);
        ++t.n;
        (r->first ? t.yes : t.no)++;
      }
  return t;
}

}  // namespace

TEST_CASE("segment-box, ray-box and triangle-box agree with CGAL's exact kernel on every family", "[sat][cgal]") {
  const Tally seg = over_families("segment-box", 220, [](const fuzz::Inputs& in) {
    const Segment<Q> s{qv(in, 0), qv(in, 3)};
    const Box<Q> b{qv(in, 6), qv(in, 9)};
    return std::optional{std::pair{book::separate(s, b).intersect,
                                   CGAL::do_intersect(K::Segment_3(pt(s.source), pt(s.target)), cuboid(b))}};
  });
  const Tally ray = over_families("ray-box", 220, [](const fuzz::Inputs& in) {
    const Ray<Q> r{qv(in, 0), qv(in, 3)};
    const Box<Q> b{qv(in, 6), qv(in, 9)};
    if (book::detail::is_zero(r.direction)) return std::optional<std::pair<bool, bool>>{};
    return std::optional{std::pair{book::separate(r, b).intersect,
                                   CGAL::do_intersect(K::Ray_3(pt(r.source), K::Vector_3(ft(r.direction[0]), ft(r.direction[1]), ft(r.direction[2]))), cuboid(b))}};
  });
  const Tally tri = over_families("triangle-box", 180, [](const fuzz::Inputs& in) {
    const Triangle<Q> t{{qv(in, 0), qv(in, 3), qv(in, 6)}};
    const Box<Q> b{qv(in, 9), qv(in, 12)};
    bool cgal;
    if (const auto s = degenerate_span(t))
      cgal = CGAL::do_intersect(K::Segment_3(pt(s->source), pt(s->target)), cuboid(b));
    else
      cgal = CGAL::do_intersect(K::Triangle_3(pt(t.vertex[0]), pt(t.vertex[1]), pt(t.vertex[2])), cuboid(b));
    return std::optional{std::pair{book::separate(t, b).intersect, cgal}};
  });
  for (const Tally* t : {&seg, &ray, &tri}) {
    CHECK(t->n >= 10000);
    CHECK(t->yes > 1000);
    CHECK(t->no > 1000);
  }
}

TEST_CASE("oriented boxes agree with CGAL's mesh intersection on every family", "[sat][cgal][obb]") {
  const Tally boxes = over_families("obb-obb", 140, [](const fuzz::Inputs& in) {
    const OrientedBox<Q> a = qobb(in, 0), b = qobb(in, 15);
    if (flat(a) || flat(b)) return std::optional<std::pair<bool, bool>>{};
    return std::optional{std::pair{solid::separate(a, b).intersect, pmp_boxes(a, b)}};
  });
  const Tally seg = over_families("segment-obb", 175, [](const fuzz::Inputs& in) {
    const Segment<Q> s{qv(in, 0), qv(in, 3)};
    const OrientedBox<Q> b = qobb(in, 6);
    if (flat(b)) return std::optional<std::pair<bool, bool>>{};
    return std::optional{std::pair{solid::separate(s, b).intersect, pmp_segment(s, b)}};
  });
  const Tally tri = over_families("triangle-obb", 160, [](const fuzz::Inputs& in) {
    const Triangle<Q> t{{qv(in, 0), qv(in, 3), qv(in, 6)}};
    const OrientedBox<Q> b = qobb(in, 9);
    if (flat(b)) return std::optional<std::pair<bool, bool>>{};
    const auto span = degenerate_span(t);
    const bool cgal = span ? pmp_segment(*span, b) : pmp_triangle(t, b);
    return std::optional{std::pair{solid::separate(t, b).intersect, cgal}};
  });
  for (const Tally* t : {&boxes, &seg, &tri}) {
    CHECK(t->n >= 10000);
    CHECK(t->yes > 500);
    CHECK(t->no > 500);
  }
}

TEST_CASE("polygon-obb agrees with CGAL's mesh intersection on the fan triangles on every family",
          "[sat][cgal][obb][polygon]") {
  // The polygon is the union of its fan triangles; each meets the box's closed mesh (PMP) or has
  // a vertex inside it, a zero-area triangle as the segment or point it spans.
  const Tally t = over_families("polygon-obb", 60, [](const fuzz::Inputs& in) {
    const OrientedBox<Q> b = qobb(in, 25);
    if (flat(b)) return std::optional<std::pair<bool, bool>>{};
    Polygon<Q> p;
    p.n = int(in[0]);
    for (int i = 0; i < p.n; ++i) p.vertex[i] = qv(in, 1 + 3 * i);
    const Mesh m = box_mesh(b);
    bool cgal = false;
    for (int k = 0; k < p.triangles() && !cgal; ++k) {
      const Triangle<Q> tr = p.triangle(k);
      if (inside(m, tr.vertex[0])) {
        cgal = true;
      } else if (const auto span = degenerate_span(tr)) {
        if (span->source != span->target) {
          const std::vector<P3> line = {pt(span->source), pt(span->target)};
          cgal = inside(m, span->source) || inside(m, span->target) || PMP::do_intersect(m, line);
        }
      } else {
        Mesh tm;
        tm.add_face(tm.add_vertex(pt(tr.vertex[0])), tm.add_vertex(pt(tr.vertex[1])), tm.add_vertex(pt(tr.vertex[2])));
        cgal = PMP::do_intersect(m, tm);
      }
    }
    return std::optional{std::pair{solid::intersect(p, b), cgal}};
  });
  CHECK(t.n >= 2000);
  CHECK(t.yes > 300);
  CHECK(t.no > 300);
}

TEST_CASE("exactly orthonormal oriented boxes: the book, the solid and CGAL's meshes agree", "[sat][cgal][obb]") {
  // Rational rotations from integer quaternions, placed near touching along a random axis
  // (face or edge cross) on a 1/64 grid: the book's 15-axis test is exact here.
  std::mt19937_64 rng(5);
  auto i_in = [&](int lo, int hi) { return lo + int(rng() % std::uint64_t(hi - lo + 1)); };
  std::uint64_t yes = 0, no = 0;
  for (int n = 0; n < 1500; ++n) {
    auto frame = [&] { return rational_rotation(i_in(-3, 3), i_in(-3, 3), i_in(-3, 3), i_in(1, 3)); };
    const OrientedBox<Q> A{Vec3<Q>(Q(i_in(-64, 64)) / 64, Q(i_in(-64, 64)) / 64, Q(i_in(-64, 64)) / 64),
                           Vec3<Q>(Q(i_in(4, 64)) / 32, Q(i_in(4, 64)) / 32, Q(i_in(4, 64)) / 32), frame()};
    OrientedBox<Q> B{Vec3<Q>(0, 0, 0), Vec3<Q>(Q(i_in(4, 64)) / 32, Q(i_in(4, 64)) / 32, Q(i_in(4, 64)) / 32), frame()};
    // along an axis L: the centres (rA(L) + rB(L)) |L|^-2 L (1 + j/64) apart (|L|^2 rational)
    Vec3<Q> L = i_in(0, 1) ? A.axis[i_in(0, 2)] : Vec3<Q>(A.axis[i_in(0, 2)].cross(B.axis[i_in(0, 2)]));
    if (book::detail::is_zero(L)) L = A.axis[0];
    auto radius = [&](const OrientedBox<Q>& b) {
      Q r = 0;
      for (int k = 0; k < 3; ++k) r += b.extent[k] * CGAL::abs(b.axis[k].dot(L));
      return r;
    };
    const Q t = (radius(A) + radius(B)) / L.squaredNorm() * (Q(1) + Q(i_in(-2, 2)) / 64);
    B.center = A.center + t * L;
    INFO("case " << n);
    const Separation<Q> s = solid::separate(A, B), b = book::separate(A, B);
    REQUIRE(s.intersect == b.intersect);
    REQUIRE(s.axis == b.axis);
    REQUIRE(s.intersect == pmp_boxes(A, B));
    (s.intersect ? yes : no)++;
  }
  CHECK(yes > 300);
  CHECK(no > 300);
}

TEST_CASE("sphere-triangle: the closest point's squared distance equals CGAL's on every family",
          "[sphere-triangle][cgal]") {
  // The book at Gmpq is the truth for this pair: its closest point x must lie at exactly CGAL's
  // squared_distance(Point_3, Triangle_3) from the centre (CGAL's own projection and region
  // code in Epeck), and proximity().intersect must be that distance against rho^2. CGAL's
  // Triangle_3 must not be degenerate: a zero-area triangle is the segment or point it spans.
  std::uint64_t regions[3] = {0, 0, 0};  // x at a vertex, on an edge, inside the face
  const Tally t = over_families("sphere-triangle", 400, [&](const fuzz::Inputs& in) {
    const Vec3<Q> c = qv(in, 0);
    const Q rho(in[3]);
    const Triangle<Q> tri{{qv(in, 4), qv(in, 7), qv(in, 10)}};
    const Vec3<Q> x = book::detail::closest_on_triangle(tri, c);
    FT cgal;
    if (const auto s = degenerate_span(tri))
      cgal = s->source == s->target ? CGAL::squared_distance(pt(c), pt(s->source))
                                    : CGAL::squared_distance(pt(c), K::Segment_3(pt(s->source), pt(s->target)));
    else
      cgal = CGAL::squared_distance(pt(c), K::Triangle_3(pt(tri.vertex[0]), pt(tri.vertex[1]), pt(tri.vertex[2])));
    REQUIRE(ft(Vec3<Q>(x - c).squaredNorm()) == cgal);
    int at_vertex = 0;
    for (const auto& v : tri.vertex) at_vertex += x == v;
    const Vec3<Q> n = Vec3<Q>(tri.vertex[1] - tri.vertex[0]).cross(Vec3<Q>(tri.vertex[2] - tri.vertex[0]));
    const bool on_edge = [&] {
      for (int i = 0; i < 3; ++i) {
        const Vec3<Q> e = tri.vertex[(i + 1) % 3] - tri.vertex[i];
        if (book::detail::is_zero(Vec3<Q>(e.cross(Vec3<Q>(x - tri.vertex[i]))))) return true;
      }
      return false;
    }();
    ++regions[at_vertex ? 0 : on_edge || book::detail::is_zero(n) ? 1 : 2];
    const Sphere<Q> s{c, rho};
    return std::optional{std::pair{book::proximity(s, tri, want_all).intersect, cgal <= ft(rho * rho)}};
  });
  CHECK(t.n >= 10000);
  CHECK(t.yes > 1000);
  CHECK(t.no > 1000);
  // every region was visited, many times
  INFO("regions: vertex " << regions[0] << ", edge " << regions[1] << ", face " << regions[2]);
  for (const std::uint64_t r : regions) CHECK(r > 500);
}

namespace {

// ray-triangle-cast and segment-triangle-cast: the classification and the intersection itself
// (CGAL::intersection gives a point, or a segment for a shot in the triangle's plane) against
// the book at Gmpq, the truth for this pair.
template <bool IsRay>
Tally triangle_cast_against_cgal(std::uint64_t per_cell, std::uint64_t& points, std::uint64_t& segments) {
  return over_families(IsRay ? "ray-triangle-cast" : "segment-triangle-cast", per_cell, [&](const fuzz::Inputs& in) {
    const Vec3<Q> s = qv(in, 0), t = qv(in, 3);
    const Triangle<Q> tri{{qv(in, 6), qv(in, 9), qv(in, 12)}};
    if (IsRay && book::detail::is_zero(t)) return std::optional<std::pair<bool, bool>>{};  // refused: zero direction
    const TriangleCast<Quad<Q>> c = IsRay ? book::cast(Ray<Q>{s, t}, tri) : book::cast(Segment<Q>{s, t}, tri);
    const Vec3<Q> d = IsRay ? t : Vec3<Q>(t - s);
    auto shot_meets = [&](const auto& obj) {
      if constexpr (IsRay)
        return CGAL::do_intersect(K::Ray_3(pt(s), K::Vector_3(ft(t[0]), ft(t[1]), ft(t[2]))), obj);
      else
        return CGAL::do_intersect(K::Segment_3(pt(s), pt(t)), obj);
    };
    bool cgal;
    if (const auto span = degenerate_span(tri)) {
      if (span->source == span->target)
        cgal = IsRay ? K::Ray_3(pt(s), K::Vector_3(ft(t[0]), ft(t[1]), ft(t[2]))).has_on(pt(span->source))
                     : (s == t ? s == span->source : K::Segment_3(pt(s), pt(t)).has_on(pt(span->source)));
      else if (!IsRay && s == t)
        cgal = K::Segment_3(pt(span->source), pt(span->target)).has_on(pt(s));
      else
        cgal = shot_meets(K::Segment_3(pt(span->source), pt(span->target)));
    } else {
      const K::Triangle_3 T3(pt(tri.vertex[0]), pt(tri.vertex[1]), pt(tri.vertex[2]));
      if (!IsRay && s == t) {
        cgal = T3.has_on(pt(s));
      } else {
        cgal = shot_meets(T3);
        if (cgal && c.hit) {
          const auto x = IsRay ? CGAL::intersection(K::Ray_3(pt(s), K::Vector_3(ft(t[0]), ft(t[1]), ft(t[2]))), T3)
                               : CGAL::intersection(K::Segment_3(pt(s), pt(t)), T3);
          REQUIRE(bool(x));
          REQUIRE((c.lambda_enter.is_rational() && c.lambda_exit.is_rational()));
          const Q le = c.lambda_enter.a(), lx = c.lambda_exit.a();
          const P3 enter = pt(Vec3<Q>(s + d * le)), leave = pt(Vec3<Q>(s + d * lx));
          REQUIRE(pt(Vec3<Q>(c.point[0].a(), c.point[1].a(), c.point[2].a())) == enter);
          if (const P3* p = boost::get<P3>(&*x)) {
            REQUIRE(le == lx);
            REQUIRE(*p == enter);
            ++points;
          } else {
            const K::Segment_3* g = boost::get<K::Segment_3>(&*x);
            REQUIRE(g);
            REQUIRE(((g->source() == enter && g->target() == leave) || (g->source() == leave && g->target() == enter)));
            ++segments;
          }
        }
      }
    }
    return std::optional{std::pair{c.hit, cgal}};
  });
}

}  // namespace

TEST_CASE("ray and segment casts on a triangle agree with CGAL's Ray_3 / Segment_3 and Triangle_3 on every family",
          "[triangle-cast][cgal]") {
  std::uint64_t points = 0, segments = 0;
  const Tally ray = triangle_cast_against_cgal<true>(180, points, segments);
  const Tally seg = triangle_cast_against_cgal<false>(180, points, segments);
  INFO("intersections compared: " << points << " points, " << segments << " segments");
  for (const Tally& t : {ray, seg}) {
    CHECK(t.n >= 10000);
    CHECK(t.yes > 1000);
    CHECK(t.no > 1000);
  }
  CHECK(points > 2000);
  CHECK(segments > 20);
}

TEST_CASE("triangle-triangle agrees with CGAL's Triangle_3 pair (classification and segment) on every family",
          "[triangle-triangle][cgal]") {
  std::uint64_t points = 0, segments = 0, coplanar = 0;
  const Tally t = over_families("triangle-triangle", 180, [&](const fuzz::Inputs& in) {
    const Triangle<Q> a{{qv(in, 0), qv(in, 3), qv(in, 6)}}, b{{qv(in, 9), qv(in, 12), qv(in, 15)}};
    const TriangleIntersection<Q> r = book::intersect(a, b);
    const auto sa = degenerate_span(a), sb = degenerate_span(b);
    auto seg = [](const Segment<Q>& s) { return K::Segment_3(pt(s.source), pt(s.target)); };
    auto t3 = [](const Triangle<Q>& x) { return K::Triangle_3(pt(x.vertex[0]), pt(x.vertex[1]), pt(x.vertex[2])); };
    bool cgal;
    if (sa && sb) {
      if (sa->source == sa->target)
        cgal = sb->source == sb->target ? sa->source == sb->source : seg(*sb).has_on(pt(sa->source));
      else if (sb->source == sb->target)
        cgal = seg(*sa).has_on(pt(sb->source));
      else
        cgal = CGAL::do_intersect(seg(*sa), seg(*sb));
    } else if (sa || sb) {
      const Segment<Q>& s = sa ? *sa : *sb;
      const K::Triangle_3 other = t3(sa ? b : a);
      cgal = s.source == s.target ? other.has_on(pt(s.source)) : CGAL::do_intersect(seg(s), other);
    } else {
      cgal = CGAL::do_intersect(t3(a), t3(b));
      if (cgal && r.intersect) {
        if (r.coplanar) {
          ++coplanar;
        } else {
          const auto x = CGAL::intersection(t3(a), t3(b));
          REQUIRE(bool(x));
          if (const P3* p = boost::get<P3>(&*x)) {
            REQUIRE(*p == pt(r.p));
            REQUIRE(r.p == r.q);
            ++points;
          } else {
            const K::Segment_3* g = boost::get<K::Segment_3>(&*x);
            REQUIRE(g);
            REQUIRE(((g->source() == pt(r.p) && g->target() == pt(r.q)) ||
                     (g->source() == pt(r.q) && g->target() == pt(r.p))));
            ++segments;
          }
        }
      }
    }
    return std::optional{std::pair{r.intersect, cgal}};
  });
  INFO("segments " << segments << ", points " << points << ", coplanar " << coplanar);
  CHECK(t.n >= 10000);
  CHECK(t.yes > 1000);
  CHECK(t.no > 1000);
  CHECK(segments > 1000);
  CHECK(coplanar > 20);
}

TEST_CASE("polygon queries agree with CGAL on the fan triangles on every family", "[polygon][cgal]") {
  // A polygon is the union of its fan triangles (v0, v_i, v_i+1): CGAL decides each triangle
  // (Ray_3, Segment_3, Triangle_3 and Iso_cuboid_3 pairs; squared_distance for the sphere), a
  // zero-area triangle as the segment or point it spans, and the polygon's answer is the union.
  auto fan = [](const fuzz::Inputs& in, int k) {
    std::vector<Triangle<Q>> out;
    const int n = int(in[k]);
    for (int i = 1; i + 1 < n; ++i) out.push_back({{qv(in, k + 1), qv(in, k + 1 + 3 * i), qv(in, k + 4 + 3 * i)}});
    return out;
  };
  auto t3 = [](const Triangle<Q>& x) { return K::Triangle_3(pt(x.vertex[0]), pt(x.vertex[1]), pt(x.vertex[2])); };
  auto seg3 = [](const Segment<Q>& s) { return K::Segment_3(pt(s.source), pt(s.target)); };
  auto poly_of = [](const fuzz::Inputs& in, int k) {
    Polygon<Q> p;
    p.n = int(in[k]);
    for (int i = 0; i < p.n; ++i) p.vertex[i] = qv(in, k + 1 + 3 * i);
    return p;
  };
  for (const bool is_ray : {true, false}) {
    const Tally t = over_families(is_ray ? "ray-polygon-cast" : "segment-polygon-cast", 230, [&](const fuzz::Inputs& in) {
      const Vec3<Q> s = qv(in, 0), e = qv(in, 3);
      if (is_ray && book::detail::is_zero(e)) return std::optional<std::pair<bool, bool>>{};
      bool cgal = false;
      for (const Triangle<Q>& tr : fan(in, 6)) {
        const auto span = degenerate_span(tr);
        if (!is_ray && s == e) {
          cgal = cgal || (span ? (span->source == span->target ? s == span->source : seg3(*span).has_on(pt(s)))
                               : t3(tr).has_on(pt(s)));
          continue;
        }
        const K::Ray_3 r(pt(s), K::Vector_3(ft(e[0]), ft(e[1]), ft(e[2])));
        const K::Segment_3 g(pt(s), pt(e));
        if (span && span->source == span->target)
          cgal = cgal || (is_ray ? r.has_on(pt(span->source)) : g.has_on(pt(span->source)));
        else if (span)
          cgal = cgal || (is_ray ? CGAL::do_intersect(r, seg3(*span)) : CGAL::do_intersect(g, seg3(*span)));
        else
          cgal = cgal || (is_ray ? CGAL::do_intersect(r, t3(tr)) : CGAL::do_intersect(g, t3(tr)));
      }
      const Polygon<Q> p = poly_of(in, 6);
      const bool mine = is_ray ? book::cast(Ray<Q>{s, e}, p).hit : book::cast(Segment<Q>{s, e}, p).hit;
      return std::optional{std::pair{mine, cgal}};
    });
    CHECK(t.n >= 10000);
    CHECK(t.yes > 1000);
    CHECK(t.no > 1000);
  }
  const Tally sph = over_families("polygon-sphere", 230, [&](const fuzz::Inputs& in) {
    const Vec3<Q> c = qv(in, 25);
    const Q rho(in[28]);
    bool cgal = false;
    for (const Triangle<Q>& tr : fan(in, 0)) {
      FT d2;
      if (const auto span = degenerate_span(tr))
        d2 = span->source == span->target ? CGAL::squared_distance(pt(c), pt(span->source))
                                          : CGAL::squared_distance(pt(c), seg3(*span));
      else
        d2 = CGAL::squared_distance(pt(c), t3(tr));
      cgal = cgal || d2 <= ft(rho * rho);
    }
    return std::optional{std::pair{book::proximity(Sphere<Q>{c, rho}, poly_of(in, 0), want_all).intersect, cgal}};
  });
  const Tally box = over_families("polygon-box", 230, [&](const fuzz::Inputs& in) {
    const Box<Q> b{qv(in, 25), qv(in, 28)};
    bool cgal = false;
    for (const Triangle<Q>& tr : fan(in, 0)) {
      if (const auto span = degenerate_span(tr)) {
        if (span->source == span->target) {
          const Vec3<Q> x = span->source;
          bool inside = true;
          for (int i = 0; i < 3; ++i) inside = inside && x[i] >= b.center[i] - b.extent[i] && x[i] <= b.center[i] + b.extent[i];
          cgal = cgal || inside;
        } else {
          cgal = cgal || CGAL::do_intersect(seg3(*span), cuboid(b));
        }
      } else {
        cgal = cgal || CGAL::do_intersect(t3(tr), cuboid(b));
      }
    }
    return std::optional{std::pair{book::intersect(poly_of(in, 0), b), cgal}};
  });
  const Tally pp = over_families("polygon-polygon", 230, [&](const fuzz::Inputs& in) {
    bool cgal = false;
    for (const Triangle<Q>& x : fan(in, 0))
      for (const Triangle<Q>& y : fan(in, 25)) {
        if (cgal) break;
        const auto sx = degenerate_span(x), sy = degenerate_span(y);
        if (sx && sy) {
          if (sx->source == sx->target)
            cgal = sy->source == sy->target ? sx->source == sy->source : seg3(*sy).has_on(pt(sx->source));
          else if (sy->source == sy->target)
            cgal = seg3(*sx).has_on(pt(sy->source));
          else
            cgal = CGAL::do_intersect(seg3(*sx), seg3(*sy));
        } else if (sx || sy) {
          const Segment<Q>& g = sx ? *sx : *sy;
          const K::Triangle_3 o = t3(sx ? y : x);
          cgal = g.source == g.target ? o.has_on(pt(g.source)) : CGAL::do_intersect(seg3(g), o);
        } else {
          cgal = CGAL::do_intersect(t3(x), t3(y));
        }
      }
    return std::optional{std::pair{book::intersect(poly_of(in, 0), poly_of(in, 25)), cgal}};
  });
  for (const Tally& t : {sph, box, pp}) {
    CHECK(t.n >= 10000);
    CHECK(t.yes > 1000);
    CHECK(t.no > 1000);
  }
}
