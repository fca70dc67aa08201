// cdref/robust/separating_axes.hpp - robust versions of the Section 3.3 queries: segment,
// ray and triangle against axis-aligned and oriented boxes, oriented box against oriented
// box (separate / intersect / decide), and the casts and the sphere query on an oriented box
// (cast / hit / proximity / intersect / decide), at float, double and long double.
//
// Formulation: the solid's own answer (cdref::solid and Theorem 3.1 on the true face normals,
// book/separating_axes.hpp), evaluated on double words (robust/words.hpp: exact inputs, every
// length scaled by a power of two, a rigorous running error bound). Products
// of two inputs are exact in a double word, so a cross product of parallel axes is exactly
// zero and drops out; every other quantity carries an error of order u^2 times its operands.
// Each decisive comparison (a separating axis's intervals, an outcode, the order of two
// crossing parameters, a squared distance against rho^2) is certain when the double word's
// sign is certain; |x|, min and max need no decision (they are 1-Lipschitz).
//
// First look: at double, separate() takes the whole answer from the oracle's first stage where
// it certifies the classification and the first separating axis, with that axis's direction
// proven within 3/4 of an ulp (sat_first_look.hpp), before the grids and the double words below.
// Certificate: at double every entry point first runs the oracle's first stage
// (filters/sat_filter.hpp: static bounds derived there), whose answer where it decides is the
// solid's at an exact type; decide_separation(), the predicate and the full query all take it.
// (For a segment or a ray and an oriented box that stage is Algorithm 3.3 in the box's face
// coordinates, and after it the solid's cast decision on double words comes before the axes:
// has_cast_decision below; for two oriented boxes and for a triangle and a box, Theorem 3.1 in
// B's face coordinates first.) Where the first stage leaves a few axes open (every other axis
// certainly not separating), those axes alone on double words with rigorous bounds come next
// (filters/sat_words.hpp): where they decide, the classification is the solid's at an exact type
// too. The order of these stages is stages_before_whole below, shared with the oracle.
// A triangle, a segment or a ray and an axis-aligned box at float and double are first evaluated
// exactly, the inputs read as integers on a grid per coordinate axis (filters/sat_grid.hpp):
// where the inputs fit the grids (sat_grid.hpp: all but a triangle's vertex far from a small
// box, or a ray's direction whose components' grids lie far apart), the full query's classification, first separating axis and direction are the
// book's at an exact type (the direction rounded once), zero-area triangles and flat boxes
// included: triangle-box in about 150 ns a case where the whole formulation on double words took
// 3,000-4,300 (standalone loop over 4,000 cases of each family, 2026-11-29). decide() takes it
// after the filters (or Algorithm 3.3's certificate).
// A segment or a ray and an axis-aligned box take Algorithm 3.3's certificate instead
// (ray_box.hpp; has_slab_certificate below): where it is certain the classification is exact,
// and where neither it nor the double words are, its value is the answer of every entry point.
// Otherwise decide_separation() (decide(), where the pair has no other; decide_cast() for
// the casts, which classify as cast() does) is certain when the double-word evaluation completed, every
// decision certain: then the classification (and the first separating axis, the entering
// face) equals the solid's at an exact type. When a comparison is too close to call: for the
// separating-axis queries (separate, decide_separation, intersect) Theorem 3.1 on exact
// rationals (sat_exact.hpp: tens of microseconds, where every faster stage left the answer
// open), so that their classification and first separating axis are always the book's at an
// exact type and decide_separation() always certain; for the casts and the sphere, the same
// formulation runs in F and the answer is marked uncertain. Values come from the double word
// rounded to F; they are not claimed correctly rounded (that is the oracle's job). Where their
// enclosure is wider than u/16 of the value they come from exact rationals instead: a sphere's
// distance or depth far below its radius (obb_xx, rational.hpp's sharpen_gap), a cast's
// parameters and point at a grazing angle or through an edge (exact_obb_cast). The casts at
// double take a first look before all this (obb_cast.hpp: the cast filter's classification, the
// faces entered and left from its certain signs, each face's parameter alone, the point and the
// normal from it, every value proven within 3/4 of an ulp; about 270 ns a hit where this path
// took 1.2-1.4 us; where it proves every value asked it answers alone). The sphere's full
// query at double takes a first look before all this (sphere_obb.hpp: the closest point's
// feature certified by its normal cone and every value proven within 3/4 of an ulp, in about
// 200 ns where this path takes 1.3 us); where it proves every value asked it answers alone, and
// where it certified the feature but not the distance (near touching), sharpen_gap takes
// |x - q|^2 from that feature instead of obb_xx's enumeration. Where the nearest face of
// a centre inside cannot be called (two faces at nearly equal distance) the values come from
// the double words with lenient signs (words.hpp; the sphere's query relative to its centre:
// about_centre), and the sphere's witness is 4 ulps off at worst on sphere-obb's degenerate
// family (`cdref campaign --query sphere-obb --impl robust-double --n 500`). The full query and decide() always classify
// alike: when the classification is certain but a later step of the double-word evaluation is
// not (two faces entered at nearly the same parameter, a closest point on a face's border),
// the full query's values come from F and its classification is the certain one.
#pragma once

#include <cdref/filters/sat_filter.hpp>
#include <cdref/filters/sat_grid.hpp>
#include <cdref/filters/sat_words.hpp>
#include <cdref/filters/box_cast_words.hpp>
#include <cdref/solid/obb.hpp>
#include <bit>
#include <type_traits>

#include "rational.hpp"
#include "ray_box.hpp"
#include "sphere_box.hpp"
#include "obb_cast.hpp"
#include "length_scale.hpp"
#include "sat_exact.hpp"
#include "sat_first_look.hpp"
#include "sphere_obb.hpp"
#include "words.hpp"

namespace cdref::robust {

namespace detail {

// The degree in lengths of a polytope's face normals and edge directions (book/separating_axes.hpp,
// polytope()): the double words scale every length by 2^k (words.hpp, Scale: positions, extents,
// a ray's direction; not an oriented box's axes), so a separating axis comes back multiplied by
// 2^(k deg): a segment's or a ray's edge 1, a triangle's normal 2 and its edges 1, a box's faces
// and edges 0 (unit vectors, or an oriented box's axes and their cross products).
struct PolytopeDegrees {
  int faces, face, edge;  // the face count, and the degrees
};
template <class F> constexpr PolytopeDegrees degrees_of(const Segment<F>*) { return {0, 0, 1}; }
template <class F> constexpr PolytopeDegrees degrees_of(const Ray<F>*) { return {0, 0, 1}; }
template <class F> constexpr PolytopeDegrees degrees_of(const Triangle<F>*) { return {1, 2, 1}; }
template <class F> constexpr PolytopeDegrees degrees_of(const Box<F>*) { return {3, 0, 0}; }
template <class F> constexpr PolytopeDegrees degrees_of(const OrientedBox<F>*) { return {3, 0, 0}; }
template <class A, class B>
int axis_degree(int axis) {
  constexpr PolytopeDegrees da = degrees_of(static_cast<const A*>(nullptr)), db = degrees_of(static_cast<const B*>(nullptr));
  if (axis < da.faces) return da.face;
  if (axis < da.faces + db.faces) return db.face;
  return da.edge + db.edge;
}

template <class F, class A, class B>
std::pair<Separation<F>, bool> separation(const A& a, const B& b) {
  Scale sc;
  const auto r =
      on_words(a, b, [](const auto& x, const auto& y) { return book::separate(book::polytope(x), book::polytope(y)); }, &sc);
  if (r) {
    Separation<F> s;
    s.intersect = r->intersect;
    s.axis = r->axis;
    // the axis at the inputs' own scale: the word's, taken back by 2^(-k deg)
    if (r->axis >= 0) s.direction = Scale{-sc.k * axis_degree<A, B>(r->axis)}.len(value<F>(r->direction));
    return {s, true};
  }
  return {book::separate(book::polytope(a), book::polytope(b)), false};
}

}  // namespace detail

namespace detail {
// At double, the oracle's first stage (filters/sat_filter.hpp: every candidate axis in double
// against one static bound; for a sphere, two certificates from a point of the box) before the
// double words: 1 (they meet), 0 (disjoint) or 2 (undecided; always at float and long double).
// Where it decides, its answer is the solid's at an exact type, so every entry point takes it
// (decide(), the predicate and the full query's classification stay alike).
// `open` (at double): the axes it left open (filters/sat_filter.hpp). The certified decisions take
// stages_before_whole below instead, which puts the double words of what the cheapest filter
// leaves open before the rest of the filters.
template <class F, class A, class B>
int first_stage(const A& a, const B& b, unsigned* open = nullptr) {
  if (open) *open = 0;
  if constexpr (std::is_same_v<F, double>) return filters::sat::filter(a, b, nullptr, open);
  else return filters::sat::unknown;
}
// (For a sphere, where the filter cannot decide: on an oriented box whose axes are signed
// coordinate axes, the axis-aligned box it is, by sphere-box's certified decision (sphere_box.hpp),
// as the oracle's second stage takes it; on any other, the two certificates on double words. Both
// decide cases 2^-52 from tangency where the whole formulation on double words takes microseconds:
// on the near-touching family at 2^-52, whose rotations include the signed permutations, the
// aligned boxes' decision took 838-851 ns a case before sphere-box's decision came first, 199 ns
// after: standalone loop, min of 15, 2026-11-29, README.)
inline int sphere_obb_certificates(const Sphere<double>& s, const OrientedBox<double>& b) {
  if (const int f = filters::sphere_obb::filter(s, b); f != filters::sat::unknown) return f;
  if (Box<double> box; filters::sphere_obb::as_axis_aligned(b, box))
    if (const Decision d = decide(s, box); d.certain) return int(d.value);
  return filters::sat_words::decide(s, b);
}
// Last, the first look's classification (sphere_obb.hpp: the centre certainly inside, or g =
// |x - q| - rho of certain sign), so that decide() and proximity() classify alike where the
// double words cannot tell and it can.
template <class F>
int first_stage(const Sphere<F>& s, const OrientedBox<F>& b) {
  if constexpr (std::is_same_v<F, double>) {
    if (const int f = sphere_obb_certificates(s, b); f != filters::sat::unknown) return f;
    return with_products([&](auto mul) {
      int cls = filters::sat::unknown;
      Proximity<double> r;
      sphere_obb_fast<decltype(mul)>(s, b, cls, filters::sat::unknown, 0u, r, [] { return filters::sat::unknown; });
      return cls;
    });
  } else {
    return filters::sat::unknown;
  }
}
// A segment or a ray and an axis-aligned box meet exactly when Algorithm 3.3 hits, and its
// robust certificate (ray_box.hpp: exact outcodes, the slab parameters as accurate pairs, exact
// ties) decides them at every F: on uniform cases for less than the static bounds, and where
// those cannot decide (a shot touching the box 10^12 from the origin) in tens of nanoseconds
// where the separating axes on double words take a microsecond. For those two pairs it takes
// the first stage's place; the double words come second.
template <class A, class B, class F>
inline constexpr bool has_slab_certificate =
    (std::is_same_v<A, Segment<F>> || std::is_same_v<A, Ray<F>>) && std::is_same_v<B, Box<F>>;
// A segment or a ray and an oriented box meet exactly when the solid's cast hits (Algorithm
// 3.3 in the box's face coordinates, solid/obb.hpp): on double words that decision costs a
// fraction of the separating axes' (a few hundred nanoseconds against 1.5 us where the first
// stage cannot decide, 10^12 from the origin), so it comes before them.
template <class A, class B, class F>
inline constexpr bool has_cast_decision =
    (std::is_same_v<A, Segment<F>> || std::is_same_v<A, Ray<F>>) && std::is_same_v<B, OrientedBox<F>>;
// At double, Algorithm 3.3 in the box's face coordinates on bounded double words first
// (filters/box_cast_words.hpp: tens of nanoseconds where the solid's cast on Bounded2 takes two
// microseconds), then the solid's cast on double words where those leave the case open.
template <class A, class B>
std::optional<bool> cast_decision_on_words(const A& a, const B& b) {
  if constexpr (std::is_same_v<B, OrientedBox<double>>)
    if (const int r = filters::box_cast_words::obb_cast_words(a, b); r != filters::staged::unknown) return r != 0;
  return on_words(a, b, [](const auto& x, const auto& y) { return solid::hit(x, y); });
}

// Two oriented boxes, a triangle and a box (axis-aligned or oriented): Theorem 3.1 in B's face
// coordinates first (filters/sat_filter.hpp, filter_face_coordinates).
template <class A, class B>
inline constexpr bool has_face_coordinates =
    (std::is_same_v<B, OrientedBox<double>> && (std::is_same_v<A, OrientedBox<double>> || std::is_same_v<A, Triangle<double>>)) ||
    (std::is_same_v<A, Triangle<double>> && std::is_same_v<B, Box<double>>);

// Every stage before the whole formulation on double words, in the order that decides soonest
// near the boundary: 1 (they meet), 0 (disjoint) or 2 (undecided). Where it decides, the answer
// is the solid's at an exact type. The oracle's stages 1 and 2 (exact/cdref/oracle/
// separating_axes.hpp) and the robust tier's certified decisions both run it. *words (when given):
// whether the answer came from double words rather than the static bounds.
//   - a segment or a ray and an oriented box: Algorithm 3.3 in the box's face coordinates, then
//     the cast's decision on double words (in segment-obb's grazing family at 2^-52, 4,000 cases,
//     seed 1, the world axes decided none of the 2,509 cases the face coordinates left, and the
//     cast's words decided all of them), then the world axes and their open axes on words;
//   - two oriented boxes, a triangle and a box: Theorem 3.1 in B's face coordinates, the axes it
//     leaves open straight on double words (near touching the world axes' filter decides none of
//     what the face coordinates leave: 0 of 1,906 for two oriented boxes at 2^-52, seed 1), the
//     world axes where those words do not decide (they recognise exact zeros: parallel edges),
//     then their open axes on words;
//   - otherwise the world axes, then their open axes on words.
// After the first filter of each (so that inputs near 1 pay nothing more), where the inputs'
// lengths lie beyond 2^+-100 (length_scale.hpp), the same filters the first looks take
// (obb_cast.hpp, sat_first_look.hpp) on the inputs scaled exactly by a power of two: the cast
// filter (a segment or a ray and an oriented box), then the world axes.
// Whatever the first looks classify is then classified here too, so that the full queries and
// the certified decisions (which both run these stages where they are uncertain) always agree.
// At float and long double only the cast's decision on double words (the filters are double's).
template <class A, class B>
int scaled_filters(const A& a, const B& b) {
  LengthScale s;
  A as;
  B bs;
  if (scale_lengths(a, b, s, as, bs) != Scaling::scaled) return filters::sat::unknown;
  if constexpr (has_cast_decision<A, B, double>)
    if (const int f = filters::staged::filter(as, bs); f != filters::sat::unknown) return f;
  return filters::sat::filter<A, B>(as, bs);
}
template <class F, class A, class B>
int stages_before_whole(const A& a, const B& b, bool* words = nullptr) {
  constexpr int unknown = filters::sat::unknown;
  if (words) *words = false;
  if constexpr (!std::is_same_v<F, double>) {
    if constexpr (has_cast_decision<A, B, F>)
      if (const auto h = cast_decision_on_words(a, b)) {
        if (words) *words = true;
        return int(*h);
      }
    return unknown;
  } else {
    unsigned open = 0;
    int r;
    if constexpr (has_cast_decision<A, B, F>) {
      if (const int f = filters::staged::filter(a, b); f != unknown) return f;
      if (const int f = scaled_filters(a, b); f != unknown) return f;
      if (const auto h = cast_decision_on_words(a, b)) {
        if (words) *words = true;
        return int(*h);
      }
      r = filters::sat::filter<A, B>(a, b, nullptr, &open);  // the world axes
    } else if constexpr (has_face_coordinates<A, B>) {
      if constexpr (std::is_same_v<B, Box<double>>)
        if (filters::sat::apart_on_box_faces(a, b)) return 0;  // the outcodes' relative bounds
      if (const int f = filters::sat::filter_face_coordinates(a, b, &open); f != unknown) return f;
      if (const int f = scaled_filters(a, b); f != unknown) return f;
      // (a triangle and a box) more than one axis open, or none named (a degenerate triangle
      // ties several): the exact evaluation on a grid (filters/sat_grid.hpp), about 145 ns, where
      // the double words of each open axis took 1,000 ns a case on the degenerate family and
      // left 78% of it open (standalone loop, 2026-11-29); one open axis (a vertex near a face)
      // costs less on words
      if constexpr (std::is_same_v<A, Triangle<double>> && std::is_same_v<B, Box<double>>)
        if (std::popcount(open) != 1)
          if (const filters::sat_grid::TriangleBox g(a, b); g.ok) {
            if (words) *words = true;
            return int(g.axis < 0);
          }
      if (open != 0)
        if (const int w = filters::sat_words::decide(a, b, open); w != unknown) {
          if (words) *words = true;
          return w;
        }
      r = filters::sat::filter<A, B>(a, b, nullptr, &open);  // the world axes
    } else {
      r = filters::sat::filter(a, b, nullptr, &open);
      if (r == unknown) r = scaled_filters(a, b);
    }
    if (r != unknown) return r;
    if (words) *words = true;
    return filters::sat_words::decide(a, b, open);
  }
}

// A triangle, a segment or a ray and a box at float or double: the book's 13 or 6 axes exactly
// on the inputs read as integers on a grid per coordinate axis (filters/sat_grid.hpp): whether
// they meet, the first separating axis and its direction rounded once, as the book gives them at
// an exact type.
// false where the inputs lie on no grid narrow enough (sat_grid.hpp), where a direction
// component overflows F, and for every other pair.
// Zero-area triangles, flat boxes and triangles in a face's plane tie exactly on some axis,
// which neither the filters nor the double words can call; here ties are decided as ties.
template <class F, class A, class B>
bool separation_on_grid(const A& a, const B& b, Separation<F>& s) {
  if constexpr (std::is_same_v<A, Triangle<F>> && std::is_same_v<B, Box<F>> &&
                (std::is_same_v<F, double> || std::is_same_v<F, float>)) {
    const auto dv = [](const Vec3<F>& v) { return Vec3<double>(double(v[0]), double(v[1]), double(v[2])); };  // exact
    const Triangle<double> t{{dv(a.vertex[0]), dv(a.vertex[1]), dv(a.vertex[2])}};
    const filters::sat_grid::TriangleBox g(t, Box<double>{dv(b.center), dv(b.extent)});
    if (!g.ok) return false;
    Separation<F> out;
    out.intersect = g.axis < 0;
    out.axis = g.axis;
    if (g.axis >= 0 && !g.direction(out.direction)) return false;
    s = out;
    return true;
  } else if constexpr ((std::is_same_v<A, Segment<F>> || std::is_same_v<A, Ray<F>>) && std::is_same_v<B, Box<F>> &&
                       (std::is_same_v<F, double> || std::is_same_v<F, float>)) {
    const auto dv = [](const Vec3<F>& v) { return Vec3<double>(double(v[0]), double(v[1]), double(v[2])); };  // exact
    constexpr bool seg = std::is_same_v<A, Segment<F>>;
    const Vec3<F>& to = [&]() -> const Vec3<F>& {
      if constexpr (seg) return a.target; else return a.direction;
    }();
    const filters::sat_grid::ShotBox g(dv(a.source), dv(to), Box<double>{dv(b.center), dv(b.extent)}, seg);
    if (!g.ok) return false;
    Separation<F> out;
    out.intersect = g.axis < 0;
    out.axis = g.axis;
    if (g.axis >= 0 && !g.direction(to, out.direction)) return false;
    s = out;
    return true;
  } else {
    (void)a, (void)b, (void)s;
    return false;
  }
}

}  // namespace detail

// ---- separating axes ----
#define CDREF_ROBUST_SEPARATE(A, B, NA, NB)                                                 \
  template <class F>                                                                        \
  Separation<F> separate(const A<F>& a, const B<F>& b) {                                    \
    check(a, NA);                                                                           \
    check(b, NB);                                                                           \
    if constexpr (std::is_same_v<F, double>) { /* the first look (sat_first_look.hpp) */   \
      Separation<double> first;                                                             \
      if (with_products([&](auto mul) { return detail::sat_first_look<decltype(mul), false>(a, b, first); })) \
        return first;                                                                       \
    }                                                                                       \
    if (Separation<F> g; detail::separation_on_grid(a, b, g)) return g; /* exact */       \
    const auto [s, certain] = detail::separation<F>(a, b);                                  \
    /* where the double words are certain they are exact already; else on rationals */     \
    return certain ? s : detail::separation_exact<F>(a, b);                                 \
  }                                                                                         \
  template <class F>                                                                        \
  Decision decide_separation(const A<F>& a, const B<F>& b) {                                \
    check(a, NA);                                                                           \
    check(b, NB);                                                                           \
    if constexpr (detail::has_slab_certificate<A<F>, B<F>, F>) {                               \
      const Decision slab = decide(a, b); /* before the first stage: it costs less */       \
      if (slab.certain) return slab;                                                        \
    }                                                                                       \
    if (const int f = detail::stages_before_whole<F>(a, b); f != filters::sat::unknown) return {f != 0, true}; \
    if (Separation<F> g; detail::separation_on_grid(a, b, g)) return {g.intersect, true};      \
    const auto [s, certain] = detail::separation<F>(a, b);                                  \
    return {certain ? s.intersect : detail::separation_exact<F>(a, b).intersect, true};     \
  }                                                                                         \
  template <class F>                                                                        \
  bool intersect(const A<F>& a, const B<F>& b) {                                            \
    return decide_separation(a, b).value; /* the first stage first, as separate() */        \
  }                                                                                         \
  /* the oracle's every-output path at double first (fuzz/cdref/fuzz/spec.hpp): the first */ \
  /* look's answer where it proves the direction the truth rounded (sat_first_look.hpp) */  \
  inline bool separate_rounded(const A<double>& a, const B<double>& b, Separation<double>& res) { \
    check(a, NA);                                                                           \
    check(b, NB);                                                                           \
    return with_products([&](auto mul) { return detail::sat_first_look<decltype(mul), true>(a, b, res); }); \
  }
CDREF_ROBUST_SEPARATE(Segment, Box, "segment", "box")
CDREF_ROBUST_SEPARATE(Ray, Box, "ray", "box")
CDREF_ROBUST_SEPARATE(Triangle, Box, "triangle", "box")
CDREF_ROBUST_SEPARATE(Segment, OrientedBox, "segment", "oriented box")
CDREF_ROBUST_SEPARATE(Ray, OrientedBox, "ray", "oriented box")
CDREF_ROBUST_SEPARATE(Triangle, OrientedBox, "triangle", "oriented box")
CDREF_ROBUST_SEPARATE(OrientedBox, OrientedBox, "oriented box A", "oriented box B")
#undef CDREF_ROBUST_SEPARATE
// decide() where no other robust query on the same pair has one (a segment or a ray and an
// axis-aligned box: ray_box.hpp's certificate of Algorithm 3.3 decides the same thing).
template <class F> Decision decide(const Triangle<F>& a, const Box<F>& b) { return decide_separation(a, b); }
template <class F> Decision decide(const Segment<F>& a, const OrientedBox<F>& b) { return decide_separation(a, b); }
template <class F> Decision decide(const Ray<F>& a, const OrientedBox<F>& b) { return decide_separation(a, b); }
template <class F> Decision decide(const Triangle<F>& a, const OrientedBox<F>& b) { return decide_separation(a, b); }
template <class F> Decision decide(const OrientedBox<F>& a, const OrientedBox<F>& b) { return decide_separation(a, b); }

// ---- casts on an oriented box, a sphere and an oriented box ----
namespace detail {

// A hit's parameters and entry point exactly, each rounded once (rational.hpp), where the
// double words leave them loose: Algorithm 3.3 in the solid's U coordinates (cdref/solid/obb.hpp:
// U_i = n_i . (p - c) with n_i signed so that n_i . a_i = |delta|, the slab |U_i| <= H_i =
// |delta| h_i) on GMP rationals. Each slab with U_i(r) != 0 is crossed at (-+H_i - U_i(s)) /
// U_i(r); lambda_enter is the largest entry and 0, lambda_exit the smallest exit (and 1 for a
// segment); the point s + lambda_enter r. Nothing where the exact slabs give no hit (a hit the
// classification could not certify). The double words' parameter is a quotient of two
// cancelling sums where the shot crosses a face at a grazing angle or meets an edge, and their
// bound there reached 2^-51 of the value: the ray-obb cast's point was 141 ulps off on the
// planes family, the segment's lambda_exit 21 (`cdref campaign --impl robust-double`).
template <class F>
bool exact_obb_cast(Cast<F>& out, const Vec3<F>& src, const Vec3<F>& dt, bool segment, const OrientedBox<F>& b,
                    unsigned w) {
  RVec S, R, C, a[3], n[3], d;
  set_vec(S, src);
  set_vec(R, dt);
  if (segment) sub_vec(R, R, S);
  set_vec(C, b.center);
  sub_vec(d, S, C);
  for (int i = 0; i < 3; ++i) set_vec(a[i], b.axis[i]);
  for (int i = 0; i < 3; ++i) cross_vec(n[i], a[(i + 1) % 3], a[(i + 2) % 3]);
  Rational delta, lo, hi, H, us, ur, t0, t1;
  dot_vec(delta, a[0], n[0]);
  const bool flip = mpq_sgn(delta.q) < 0;
  if (flip) mpq_neg(delta.q, delta.q);
  bool bounded_hi = segment;  // hi = 1 for a segment; +inf until a slab bounds it for a ray
  mpq_set_si(hi.q, 1, 1);
  for (int i = 0; i < 3; ++i) {
    set_rational(H, b.extent[i]);
    mpq_mul(H.q, H.q, delta.q);
    dot_vec(us, n[i], d);
    dot_vec(ur, n[i], R);
    if (flip) mpq_neg(us.q, us.q), mpq_neg(ur.q, ur.q);
    if (mpq_sgn(ur.q) == 0) {  // parallel to the slab: inside it or no hit
      mpq_abs(t0.q, us.q);
      if (mpq_cmp(t0.q, H.q) > 0) return false;
      continue;
    }
    mpq_neg(t0.q, H.q);
    mpq_sub(t0.q, t0.q, us.q);
    mpq_div(t0.q, t0.q, ur.q);
    mpq_sub(t1.q, H.q, us.q);
    mpq_div(t1.q, t1.q, ur.q);
    if (mpq_sgn(ur.q) < 0) mpq_swap(t0.q, t1.q);
    if (mpq_cmp(t0.q, lo.q) > 0) mpq_set(lo.q, t0.q);
    if (!bounded_hi || mpq_cmp(t1.q, hi.q) < 0) mpq_set(hi.q, t1.q), bounded_hi = true;
  }
  if (!bounded_hi || mpq_cmp(lo.q, hi.q) > 0) return false;
  if (w & want_lambda_enter) out.lambda_enter = rounded<F>(lo);
  if (w & want_lambda_exit) out.lambda_exit = rounded<F>(hi);
  Rational x;
  for (int k = 0; k < 3 && (w & want_point); ++k) {
    mpq_mul(x.q, lo.q, R[k].q);
    mpq_add(x.q, x.q, S[k].q);
    out.point[k] = rounded<F>(x);
  }
  return true;
}
template <class F, class A>
void sharpen_obb_cast(Cast<F>& c, const Cast<W>& cw, const A& a, const OrientedBox<F>& b, unsigned w) {
  // (words.hpp, sharp: an enclosure wider than u/16 of the value, or holding 0)
  bool any = ((w & want_lambda_enter) && !sharp<F>(cw.lambda_enter)) ||
             ((w & want_lambda_exit) && !cw.unbounded_exit && !sharp<F>(cw.lambda_exit));
  for (int i = 0; i < 3 && !any && (w & want_point); ++i) any = !sharp<F>(cw.point[i]);
  if (!any) return;
  if constexpr (std::is_same_v<A, Segment<F>>)
    exact_obb_cast(c, a.source, a.target, true, b, w);
  else
    exact_obb_cast(c, a.source, a.direction, false, b, w);
}

// The full query and its certificate from one evaluation, so that they always classify alike:
// the double-word query; else the double-word classification with the query's values from the
// double words with lenient signs (or in F where those miss or do not complete); else the
// classification in F too, uncertain.
template <class F, class A>
std::pair<Cast<F>, Decision> cast_eval(const A& a, const OrientedBox<F>& b, unsigned w) {
  Scale sc;
  if (const auto r = on_words(a, b, [w](const auto& x, const auto& y) { return solid::cast(x, y, w); }, &sc)) {
    Cast<F> c = cast_value<F>(*r);
    c.point = Scale{-sc.k}.len(c.point);  // parameters and unit normals do not scale
    if (c.hit && (w & (want_lambda_enter | want_lambda_exit | want_point))) sharpen_obb_cast(c, *r, a, b, w);
    return {c, {r->hit, true}};
  }
  // the values from the double words with lenient signs where they complete with a hit, F's
  // own value kept where it lies within their enclosure (words.hpp); else from F
  Cast<F> c = solid::cast(a, b, w);
  const auto lw = on_words_lenient(a, b, [w](const auto& x, const auto& y) { return solid::cast(x, y, w); }, &sc);
  if (lw && lw->hit) take_lenient_values<F>(c, *lw, sc.k);
  const auto h = cast_decision_on_words(a, b);
  const Decision d = h ? Decision{*h, true} : Decision{solid::hit(a, b), false};
  if (d.value && lw && lw->hit && (w & (want_lambda_enter | want_lambda_exit | want_point))) sharpen_obb_cast(c, *lw, a, b, w);
  c.hit = d.value;
  return {c, d};
}

// |x - q|^2 exactly, x the point of the solid P closest to a centre q outside it (false for q
// in the closed P, whose depth does not cancel): with the face normals n_i (signed so that
// n_i . a_i = |delta|) and U_i = n_i . (q - c), q is in P iff |U_i| <= H_i = |delta| h_i for
// every i. Otherwise x is the nearest of the feet of q on the six face planes that lie in
// their face (the foot on U_i = s H_i moves U_j by -(U_i - s H_i) n_i . n_j / |n_i|^2, and
// |x - q|^2 = (U_i - s H_i)^2 / |n_i|^2) and the twelve edges' closest points (segment_xx):
// every candidate is a point of P, and the closest point, in a face's relative interior or on
// an edge, is among them.
template <class F>
bool obb_xx(Rational& xx, const Vec3<F>& q, const OrientedBox<F>& b) {
  RVec a[3], n[3], c, p, d;
  set_vec(c, b.center);
  set_vec(p, q);
  sub_vec(d, p, c);
  Rational h[3], H[3], U[3], nn[3], delta, t;
  for (int i = 0; i < 3; ++i) set_vec(a[i], b.axis[i]), set_rational(h[i], b.extent[i]);
  for (int i = 0; i < 3; ++i) cross_vec(n[i], a[(i + 1) % 3], a[(i + 2) % 3]);
  dot_vec(delta, a[0], n[0]);
  if (mpq_sgn(delta.q) < 0) {
    mpq_neg(delta.q, delta.q);
    for (auto& ni : n)
      for (auto& x : ni) mpq_neg(x.q, x.q);
  }
  bool inside = true;
  for (int i = 0; i < 3; ++i) {
    mpq_mul(H[i].q, delta.q, h[i].q);
    dot_vec(U[i], n[i], d);
    dot_vec(nn[i], n[i], n[i]);
    mpq_abs(t.q, U[i].q);
    inside = inside && mpq_cmp(t.q, H[i].q) <= 0;
  }
  if (inside) return false;
  bool have = false;
  const auto offer = [&](const Rational& v) {
    if (!have || mpq_cmp(v.q, xx.q) < 0) mpq_set(xx.q, v.q);
    have = true;
  };
  Rational g, nij, uj, v;
  for (int i = 0; i < 3; ++i)
    for (const int sg : {-1, 1}) {
      // g = (U_i - s H_i) / |n_i|^2
      if (sg > 0) mpq_sub(g.q, U[i].q, H[i].q);
      else mpq_add(g.q, U[i].q, H[i].q);
      mpq_div(g.q, g.q, nn[i].q);
      bool in_face = true;
      for (int j = 0; j < 3 && in_face; ++j) {
        if (j == i) continue;
        dot_vec(nij, n[i], n[j]);
        mpq_mul(uj.q, g.q, nij.q);
        mpq_sub(uj.q, U[j].q, uj.q);
        mpq_abs(uj.q, uj.q);
        in_face = mpq_cmp(uj.q, H[j].q) <= 0;
      }
      if (!in_face) continue;
      mpq_mul(v.q, g.q, g.q);
      mpq_mul(v.q, v.q, nn[i].q);
      offer(v);
    }
  // the edges: along a_i, at s_j h_j a_j + s_k h_k a_k, from -h_i a_i to +h_i a_i
  RVec ha[3];
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) mpq_mul(ha[i][k].q, a[i][k].q, h[i].q);
  for (int i = 0; i < 3; ++i)
    for (const int sj : {-1, 1})
      for (const int sk : {-1, 1}) {
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        RVec m, e0, e1;
        for (int x = 0; x < 3; ++x) {
          mpq_set(m[x].q, c[x].q);
          if (sj > 0) mpq_add(m[x].q, m[x].q, ha[j][x].q);
          else mpq_sub(m[x].q, m[x].q, ha[j][x].q);
          if (sk > 0) mpq_add(m[x].q, m[x].q, ha[k][x].q);
          else mpq_sub(m[x].q, m[x].q, ha[k][x].q);
          mpq_sub(e0[x].q, m[x].q, ha[i][x].q);
          mpq_add(e1[x].q, m[x].q, ha[i][x].q);
        }
        segment_xx(v, p, e0, e1);
        offer(v);
      }
  return true;
}

// The proximity on double words relative to the sphere's centre (words.hpp, about_centre), one
// type for every F (words.hpp, HotWords).
struct SphereObbWords : HotWords {
  unsigned w;
  template <class S, class B>
  auto operator()(const S& x, const B& y) const {
    const unsigned want = w;
    return about_centre(x, y, want, [want](const auto& a, const auto& c) { return solid::proximity(a, c, want); },
                        [](auto box, const auto& c) {
                          box.center = std::decay_t<decltype(c)>(box.center - c);
                          return box;
                        });
  }
};

template <class F>
std::pair<Proximity<F>, Decision> proximity_eval(const Sphere<F>& s, const OrientedBox<F>& b, unsigned w,
                                                 WordValues* kept = nullptr) {
  return proximity_on_words(
      s, b, SphereObbWords{{}, w},
      [](const auto& x, const auto& y) { return solid::intersect(x, y); }, kept);
}

}  // namespace detail

#define CDREF_ROBUST_OBB_CAST(A, NA)                                          \
  template <class F>                                                          \
  Cast<F> cast(const A<F>& a, const OrientedBox<F>& b, unsigned w = want_cast) { \
    check(a, NA);                                                             \
    [[maybe_unused]] const int det = checked_orientation(b, "oriented box");  \
    if constexpr (std::is_same_v<F, double>) { /* the first look (obb_cast.hpp) */ \
      Cast<double> first;                                                     \
      if (with_products([&](auto mul) {                                       \
            return detail::obb_cast_first_look<decltype(mul), false>(a, b, det, w, first); \
          }))                                                                 \
        return first;                                                         \
    }                                                                         \
    auto [c, d] = detail::cast_eval(a, b, w);                                 \
    /* the cast hits exactly when the segment or ray meets the solid; where */ \
    /* the double words are certain they are exact already */                 \
    if (!d.certain) /* the stages decide_cast() takes, so that both classify alike */ \
      if (const int f = detail::stages_before_whole<F>(a, b); f != filters::sat::unknown) c.hit = f != 0; \
    return c;                                                                 \
  }                                                                           \
  template <class F>                                                          \
  Decision decide_cast(const A<F>& a, const OrientedBox<F>& b) {              \
    check(a, NA);                                                             \
    check(b, "oriented box");                                                 \
    /* cast_eval(a, b, want_cast)'s classification without its values (the lenient ones): */ \
    /* the stages before the whole formulation (the decision on double words among them), */ \
    /* the cast's on double words, else the solid's in F */                   \
    if (const int f = detail::stages_before_whole<F>(a, b); f != filters::sat::unknown) return {f != 0, true}; \
    if (const auto c = detail::on_words(a, b, [](const auto& x, const auto& y) { return solid::cast(x, y, want_cast).hit; })) \
      return {*c, true};                                                      \
    return {solid::hit(a, b), false};                                         \
  }                                                                           \
  template <class F>                                                          \
  bool hit(const A<F>& a, const OrientedBox<F>& b) {                          \
    return decide_cast(a, b).value;                                           \
  }
CDREF_ROBUST_OBB_CAST(Segment, "segment")
CDREF_ROBUST_OBB_CAST(Ray, "ray")
#undef CDREF_ROBUST_OBB_CAST
// The oracle's every-output path at double first (fuzz/cdref/fuzz/spec.hpp, oracle_truth_of):
// every value of the truth correctly rounded where the first look proves it (obb_cast.hpp), else
// false. The inputs checked as cast() checks them.
template <class Shot>
bool cast_rounded(const Shot& a, const OrientedBox<double>& b, Cast<double>& res) {
  check(a, std::is_same_v<Shot, Segment<double>> ? "segment" : "ray");
  const int det = checked_orientation(b, "oriented box");
  return with_products(
      [&](auto mul) { return detail::obb_cast_first_look<decltype(mul), true>(a, b, det, want_cast, res); });
}

namespace detail {
// proximity() at double, every value asked: the first look (sphere_obb.hpp), its classification
// from g or the first stage; true where it proved every value asked.
// (feature, certified: as sphere_obb_fast's)
template <class Mul, bool Correct = false>
bool sphere_obb_first_look(const Sphere<double>& s, const OrientedBox<double>& b, unsigned w, Proximity<double>& res,
                           ObbFeature* feature = nullptr, bool* certified = nullptr) {
  const unsigned asked = w & (want_distance | want_depth | want_witnesses | want_closest);
  if (!asked) return false;
  int cls = filters::sat::unknown;
  const unsigned done = sphere_obb_fast<Mul, Correct>(s, b, cls, filters::sat::unknown, w, res,
                                                      [&] { return sphere_obb_certificates(s, b); }, feature, certified);
  if (cls == filters::sat::unknown || (done & asked) != asked) return false;
  res.intersect = cls != 0;
  return true;
}
}  // namespace detail

template <class F>
Proximity<F> proximity(const Sphere<F>& s, const OrientedBox<F>& b, unsigned w = want_proximity) {
  check(s, "sphere");
  check(b, "oriented box");
  detail::ObbFeature feature;
  bool certified = false;  // (the first look's feature, q outside)
  if constexpr (std::is_same_v<F, double>) {
    Proximity<double> res;
    if (with_products([&](auto mul) {
          return detail::sphere_obb_first_look<decltype(mul)>(s, b, w, res, &feature, &certified);
        }))
      return res;
  }
  detail::WordValues kv;
  auto [p, d] = with_fma([&] { return detail::proximity_eval(s, b, w, &kv); });
  if (!d.certain)  // (where the double words are certain they are exact already)
    if (const int f = detail::first_stage(s, b); f != filters::sat::unknown) p.intersect = f != 0;
  // the distance and the depth sharpened where the double words leave them loose (rational.hpp),
  // from the first look's certified feature where it has one, else from every feature (obb_xx:
  // at 2^-52 of the radius from touching 75.7 us a case, 6.1 us from the feature; README)
  detail::sharpen_gap(p, kv, s.radius, w, [&](detail::Rational& xx) {
    if constexpr (std::is_same_v<F, double>)
      if (certified) return detail::sphere_obb_xx(s, b, feature, xx);
    return detail::obb_xx(xx, s.center, b);
  });
  return p;
}
// The oracle's every-output path at double first (fuzz/cdref/fuzz/spec.hpp, oracle_truth_of):
// every value the truth correctly rounded where the first look proves it (sphere_obb.hpp),
// else false. The inputs checked as proximity() checks them.
inline bool proximity_rounded(const Sphere<double>& s, const OrientedBox<double>& b, Proximity<double>& res) {
  check(s, "sphere");
  check(b, "oriented box");
  return with_products(
      [&](auto mul) { return detail::sphere_obb_first_look<decltype(mul), true>(s, b, want_proximity, res); });
}
template <class F>
Decision decide(const Sphere<F>& s, const OrientedBox<F>& b) {
  check(s, "sphere");
  check(b, "oriented box");
  if (const int f = detail::first_stage(s, b); f != filters::sat::unknown) return {f != 0, true};
  return detail::proximity_eval(s, b, want_proximity).second;
}
template <class F>
bool intersect(const Sphere<F>& s, const OrientedBox<F>& b) {
  return decide(s, b).value;
}

}  // namespace cdref::robust
