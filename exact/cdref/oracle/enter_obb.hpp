// cdref/oracle/enter_obb.hpp - oracle::enter on an oriented box (the solid's cast, solid/obb.hpp):
// a segment's or a ray's lambda_enter correctly rounded to double (what every cast shares, and
// the exact path: enter.hpp).
//
// ---- An oriented box: the solid's faces, each a plane as the triangle's ---------------------
// The truth is the solid's cast (solid/obb.hpp): with the face normals n_i = a_{i+1} x a_{i+2},
// turned by sign(delta), delta = a_i . n_i (the same determinant for every i), the box is
// [-H, H] in U_i = n_i . (p - c), H_i = |delta| h_i, and Algorithm 3.3 runs there: lambda_enter
// is the largest lambda over the faces the source lies outside of (U_i(s) < -H_i or > H_i), the
// parameter where U_i(s + lambda d) = -+H_i. Face by face (face_entry): n_i a cross product of
// exact doubles (cross_term, its cross terms 0), delta a dot_words of a_i and n_i whose sign
// must be certain, H_i = delta h_i a double word (scale_word, word_bounds.hpp). The outcode bits
// are the certain signs of U_i(s) + H_i and U_i(s) - H_i (add_words and sign_of: never an exact
// 0, so a source on a face is uncertain); undecided: the exact path. A face's plane is g(l) = n_i . (s - c + l d) -+ H_i,
// linear in l: plane_parameter with the offset -+H_i. Rounding is monotone, so the largest of
// the rounded parameters is the rounded largest. Range: robust::in_certified_range, every input
// at most 2^200 (H_i is of degree 4).
// First, though, the entering face alone (filters/obb_face.hpp: the classification's filter,
// kept, picks it from its certain signs, and that face's parameter alone on double words, about
// 18 exact products instead of some 60 for three faces). Where the filter cannot tell (two
// faces entered at nearly the same parameter, an outcode near 0) or the face's rounding is
// uncertain, every face as above.
#pragma once

#include <cdref/filters/obb_face.hpp>
#include <cdref/oracle/enter.hpp>
#include <cdref/oracle/separating_axes.hpp>

namespace cdref::oracle {

namespace enter_detail {

// Face i's entry on double words (header, "An oriented box"): n_i = a_{i+1} x a_{i+2}, delta =
// a_i . n_i (the same determinant for every i) turned so that delta > 0, H_i = delta h_i, the
// source's coordinate U_i and its certain outcode, then the plane's parameter; 0 where the
// source lies between the face's two planes (no entry through them), nothing where a sign or
// the rounding is uncertain.
template <class Mul>
std::optional<double> face_entry(const Pair<double> (&sc)[3], const Pair<double> (&d)[3],
                                 const Pair<double> (&a)[3][3], double h, int i) {
  Word n[3];
  cross_words<Mul>(a[(i + 1) % 3], a[(i + 2) % 3], n);
  const double zero[3] = {0, 0, 0};
  Word delta = dot_words<Mul>(a[i], zero, n);
  if (!(magnitude_lo(delta) > 0)) return std::nullopt;
  if (delta.v.hi < 0) {
    delta = negated(delta);
    for (auto& c : n) c = negated(c);
  }
  const Word H = scale_word<Mul>(delta, h);
  const Word U = dot_words<Mul>(sc, zero, n);
  // U + H < 0: outside the lower plane; U - H > 0: outside the upper one (sign_of is never 0)
  const int lower = sign_of(add_words(U, H, 1)), upper = sign_of(add_words(U, H, -1));
  if (lower == word_bounds::unknown || upper == word_bounds::unknown) return std::nullopt;
  if (lower > 0 && upper < 0) return 0.0;
  return plane_parameter<Mul>(sc, d, n, U, lower < 0 ? H : negated(H));
}

// The entering face's parameter alone (filters/obb_face.hpp), rounded; nothing where D's sign or
// the rounding is uncertain.
template <class Mul>
std::optional<double> one_face_entry(const Pair<double> (&sc)[3], const Pair<double> (&d)[3],
                                     const OrientedBox<double>& b, const ObbFace& e) {
  const std::optional<FaceParameter> p = face_parameter<Mul>(sc, d, b, e);
  double v;
  if (!p || !Bounded2::within(p->z.hi, p->z.lo, p->err).try_rounded(v)) return std::nullopt;
  return v;
}

// The oriented box's double path on a hit (header, "An oriented box"): the value, or nothing.
template <class Mul, class Shot>
std::optional<double> obb_double(const Shot& x, const OrientedBox<double>& b, const std::optional<ObbFace>& face) {
  using std::fabs;
  if (face && face->plane < 0) return 0.0;  // the source in the box (the filter's certain outcodes)
  Pair<double> sc[3], d[3], a[3][3];
  shot_pairs(x, b.center, sc, d);
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i) a[k][i] = {b.axis[k][i], 0.0};
  if (!in_face_range(sc, d, b)) return std::nullopt;
  // most hits: the entering face picked in double, its parameter alone
  if (face)
    if (const auto v = one_face_entry<Mul>(sc, d, b, *face)) return v;
  // the others: every face, the largest entry (rounding is monotone)
  if (!robust::in_certified_range(x, b)) return std::nullopt;
  double best = 0.0;
  for (int i = 0; i < 3; ++i) {
    const auto v = face_entry<Mul>(sc, d, a, b.extent[i], i);
    if (!v) return std::nullopt;
    best = std::max(best, *v);
  }
  return best;
}

// The classification's first stage kept (its answer where it decides; sat::run's stages where
// it does not), then on a hit the entering face from its signs.
template <class Shot>
Entry obb_enter(const Shot& x, const OrientedBox<double>& b, int det, bool* exact_used) {
  filters::staged::ObbFilter f = filters::staged::obb_filter(x, b);
  const int r = filters::staged::filter(f);
  const bool hit = r != filters::staged::unknown ? r == 1 : sat::run(nullptr, x, b);
  return entry_of(hit, x, b, exact_used, [&] { return solid_double(x, b, crossed_face(f, det, false)); });
}
}  // namespace enter_detail

// A segment or a ray against an oriented box.
inline Entry enter(const Segment<double>& seg, const OrientedBox<double>& b, bool* exact_used = nullptr) {
  check(seg, "segment");
  const int det = checked_orientation(b, "oriented box");
  return enter_detail::obb_enter(seg, b, det, exact_used);
}
inline Entry enter(const Ray<double>& ray, const OrientedBox<double>& b, bool* exact_used = nullptr) {
  check(ray, "ray");
  const int det = checked_orientation(b, "oriented box");
  return enter_detail::obb_enter(ray, b, det, exact_used);
}


}  // namespace cdref::oracle
