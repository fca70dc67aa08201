// cdref/oracle/polygon.hpp - the fast exact classification oracle for the polygon queries
// (Section 3.4) at double inputs: the triangle oracles over the polygon's fan (book/polygon.hpp),
// stopping at the first triangle (or pair) that meets. The inputs are checked once; each fan
// triangle then goes through its oracle's stages without the checks again (its vertices are the
// polygon's). The stage reported is the most expensive one any triangle needed; a stage alone
// decides the polygon when it decides a meeting triangle, or every triangle apart.
#pragma once

#include <cdref/oracle/ray_triangle.hpp>
#include <cdref/oracle/separating_axes.hpp>
#include <cdref/oracle/sphere_triangle.hpp>
#include <cdref/oracle/triangle_triangle.hpp>
#include <cdref/robust/polygon.hpp>

namespace cdref::oracle {

namespace polygon {

inline constexpr int unknown = 2;

// The union over `count` parts of a classification with stages.
template <class Classify>
bool union_classify(int count, Classify one, Stage* used) {
  Stage worst = Stage::filter;
  bool any = false;
  for (int k = 0; k < count && !any; ++k) {
    Stage s = Stage::filter;
    any = one(k, &s);
    if (int(s) > int(worst)) worst = s;
  }
  if (used) *used = worst;
  return any;
}
// One stage over the parts: 1 if it decides some part meets, 0 if it decides every part apart.
template <class AtStage>
int union_stage(int count, AtStage at) {
  bool unsure = false;
  for (int k = 0; k < count; ++k) {
    const int r = at(k);
    if (r == 1) return 1;
    unsure = unsure || r != 0;
  }
  return unsure ? unknown : 0;
}

template <class Shot>
int at_stage(Stage st, const Shot& s, const Polygon<double>& p) {
  return union_stage(p.triangles(), [&](int k) { return ray_triangle::at_stage(st, s, p.triangle(k)); });
}
inline int at_stage(Stage st, const Sphere<double>& s, const Polygon<double>& p) {
  return union_stage(p.triangles(), [&](int k) { return sphere_triangle::at_stage(st, s, p.triangle(k)); });
}
inline int at_stage(Stage st, const Polygon<double>& p, const Box<double>& b) {
  return union_stage(p.triangles(), [&](int k) {
    const int r = sat::at_stage(st, p.triangle(k), b);
    return r == 0 || r == 1 ? r : unknown;
  });
}
inline int at_stage(Stage st, const Polygon<double>& a, const Polygon<double>& b) {
  if (st == Stage::filter) return triangle_triangle::polygon_filter(a, b);
  const int nb = b.triangles();
  return union_stage(a.triangles() * nb,
                     [&](int k) { return triangle_triangle::at_stage(st, a.triangle(k / nb), b.triangle(k % nb)); });
}

}  // namespace polygon

inline bool classify(const Segment<double>& s, const Polygon<double>& p, Stage* used = nullptr) {
  check(s, "segment");
  check(p);
  return polygon::union_classify(
      p.triangles(), [&](int k, Stage* st) { return classify_triangle_cast(s, p.triangle(k), st); }, used);
}
inline bool classify(const Ray<double>& r, const Polygon<double>& p, Stage* used = nullptr) {
  check(r, "ray");
  check(p);
  return polygon::union_classify(
      p.triangles(), [&](int k, Stage* st) { return classify_triangle_cast(r, p.triangle(k), st); }, used);
}
inline bool classify(const Sphere<double>& s, const Polygon<double>& p, Stage* used = nullptr) {
  check(s, "sphere");
  check(p);
  return polygon::union_classify(
      p.triangles(), [&](int k, Stage* st) { return classify_checked(s, p.triangle(k), st); }, used);
}
inline bool classify(const Polygon<double>& p, const Box<double>& b, Stage* used = nullptr) {
  check(p);
  check(b, "box");
  return polygon::union_classify(p.triangles(), [&](int k, Stage* st) { return sat::run(st, p.triangle(k), b); }, used);
}
inline bool classify(const Polygon<double>& a, const Polygon<double>& b, Stage* used = nullptr) {
  check(a, "polygon A");
  check(b, "polygon B");
  // the pairs' first stage at once, the plane signs its static bound cannot tell on double words
  // (triangle_words.hpp, polygon_on_words), then pair by pair
  bool words = false;
  if (const int f = triangle_triangle::polygon_on_words(a, b, &words); f != triangle_triangle::unknown) {
    if (used) *used = words ? Stage::expansion : Stage::filter;
    return f != 0;
  }
  const int nb = b.triangles();
  return polygon::union_classify(
      a.triangles() * nb, [&](int k, Stage* st) { return classify(a.triangle(k / nb), b.triangle(k % nb), st); }, used);
}

}  // namespace cdref::oracle
