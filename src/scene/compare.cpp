// src/scene/compare.cpp - two runs of a scene side by side: the events one has and the other
// has not (or has at another frame), and the differences of the continuous outputs, in
// scene units and in ulps of the approximate run's type.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <map>
#include <ostream>
#include <tuple>

#include "scene.hpp"

namespace cdref::scene {

namespace {

// The names of an effect's values (Event::values), grouped: a group's difference is the
// largest over its components.
struct Group {
  const char* name;
  int from, count;
};
std::vector<Group> groups(EffectKind k) {
  switch (k) {
    case EffectKind::contact: return {{"depth", 0, 1}, {"normal", 1, 3}, {"witness a", 4, 3}, {"witness b", 7, 3}};
    case EffectKind::proximity: return {{"distance", 0, 1}, {"witness a", 1, 3}, {"witness b", 4, 3}};
    case EffectKind::raycast: return {{"lambda", 0, 1}, {"point", 1, 3}, {"normal", 4, 3}};
    case EffectKind::time_of_impact: return {{"time", 0, 1}, {"centre", 1, 3}};
    default: return {};
  }
}

// The spacing of the approximate type at the larger magnitude of the two values.
double ulp(double x, Precision p) {
  x = std::fabs(x);
  if (p == Precision::float_) {
    const float f = std::max(float(x), FLT_MIN);
    return double(std::nextafter(f, INFINITY)) - double(f);
  }
  const double d = std::max(x, DBL_MIN);
  return std::nextafter(d, INFINITY) - d;
}

std::string who(const Scene& s, int a, int b) {
  return s.bodies[a].name + (b >= 0 ? "/" + s.bodies[b].name : std::string("/none"));
}

void measure(const Scene& s, Comparison& c, const Event& ref, const std::vector<double>& rv,
             const std::vector<double>& av, int frame) {
  const Effect& ef = s.effects[ref.effect];
  if (rv.size() != av.size()) return;
  for (const Group& g : groups(ef.kind)) {
    ValueDiff& d = c.values[ef.name + " " + g.name];
    ++d.compared;
    for (int i = g.from; i < g.from + g.count; ++i) {
      const double diff = std::fabs(rv[i] - av[i]);
      const double u = diff / ulp(std::max(std::fabs(rv[i]), std::fabs(av[i])), c.approx);
      if (diff > d.max_abs || (diff == d.max_abs && u > d.max_ulps)) {
        d.max_abs = diff;
        d.max_ulps = u;
        d.where = "frame " + std::to_string(frame) + " " + who(s, ref.a, ref.b);
      }
    }
  }
}

}  // namespace

Comparison compare(const Scene& s, const Run& approx, const Run& reference) {
  Comparison c;
  c.approx = approx.precision;
  c.reference = reference.precision;
  std::vector<std::pair<const Event*, const Event*>> impacts;
  // each run's events grouped by (effect, kind, a, b), in frame order within a group: sorted
  // pointers, 8 bytes an event (a scene with millions of events compares in their size)
  auto key = [](const Event* e) { return std::tie(e->effect, e->kind, e->a, e->b); };
  auto grouped = [&](const Run& r) {
    std::vector<const Event*> v;
    v.reserve(r.events.size());
    for (const Event& e : r.events) v.push_back(&e);
    std::stable_sort(v.begin(), v.end(), [&](const Event* x, const Event* y) { return key(x) < key(y); });
    return v;
  };
  const std::vector<const Event*> R = grouped(reference), A = grouped(approx);
  std::vector<Event> extra_unmatched;  // events of groups the reference does not have
  std::size_t ri = 0, ai = 0;
  while (ri < R.size() || ai < A.size()) {
    // the next group: the smaller key of the two runs'
    const bool take_r = ri < R.size() && (ai == A.size() || !(key(A[ai]) < key(R[ri])));
    const bool take_a = ai < A.size() && (ri == R.size() || !(key(R[ri]) < key(A[ai])));
    std::size_t r_end = ri, a_end = ai;
    if (take_r)
      while (r_end < R.size() && key(R[r_end]) == key(R[ri])) ++r_end;
    if (take_a)
      while (a_end < A.size() && key(A[a_end]) == key(A[ai])) ++a_end;
    if (!take_r) {
      for (std::size_t k = ai; k < a_end; ++k) extra_unmatched.push_back(*A[k]);
      ai = a_end;
      continue;
    }
    std::vector<const Event*> r_left, a_left;
    std::size_t i = ri, j = ai;
    while (i < r_end || j < a_end) {  // both lists are in frame order
      if (j == a_end || (i < r_end && R[i]->frame < A[j]->frame)) {
        r_left.push_back(R[i++]);
      } else if (i == r_end || A[j]->frame < R[i]->frame) {
        a_left.push_back(A[j++]);
      } else {
        ++c.matched;
        if (R[i]->kind == "impact") impacts.push_back({R[i], A[j]});
        ++i, ++j;
      }
    }
    const std::size_t m = std::min(r_left.size(), a_left.size());
    for (std::size_t k = 0; k < m; ++k) {
      c.shifted.push_back({*r_left[k], *a_left[k]});
      if (r_left[k]->kind == "impact") impacts.push_back({r_left[k], a_left[k]});
    }
    for (std::size_t k = m; k < r_left.size(); ++k) c.missing.push_back(*r_left[k]);
    for (std::size_t k = m; k < a_left.size(); ++k) c.extra.push_back(*a_left[k]);
    ri = r_end, ai = a_end;
  }
  c.extra.insert(c.extra.end(), extra_unmatched.begin(), extra_unmatched.end());
  auto by_frame = [](const Event& x, const Event& y) { return x.frame < y.frame; };
  std::stable_sort(c.missing.begin(), c.missing.end(), by_frame);
  std::stable_sort(c.extra.begin(), c.extra.end(), by_frame);
  // continuous outputs: impacts as paired above; every other sample where both runs have it
  for (const auto& [r, a] : impacts) measure(s, c, *r, r->values, a->values, r->frame);
  auto skey = [](const Sample* x) { return std::make_tuple(x->frame, x->effect, x->a, x->b); };
  std::vector<const Sample*> AS;  // sorted by (frame, effect, a, b); the last of equal keys counts
  for (const Sample& x : approx.samples)
    if (s.effects[x.effect].kind != EffectKind::time_of_impact) AS.push_back(&x);
  std::stable_sort(AS.begin(), AS.end(), [&](const Sample* x, const Sample* y) { return skey(x) < skey(y); });
  for (const Sample& x : reference.samples) {
    if (s.effects[x.effect].kind == EffectKind::time_of_impact) continue;
    auto it = std::upper_bound(AS.begin(), AS.end(), skey(&x), [&](const auto& k, const Sample* y) { return k < skey(y); });
    if (it == AS.begin() || skey(*(it - 1)) != skey(&x)) continue;
    --it;
    Event e;
    e.effect = x.effect;
    e.a = x.a;
    e.b = x.b;
    measure(s, c, e, x.values, (*it)->values, x.frame);
  }
  return c;
}

std::string event_text(const Scene& s, const Event& e) {
  const Effect& ef = s.effects[e.effect];
  char buf[64];
  std::snprintf(buf, sizeof buf, "frame %5d  ", e.frame);
  std::string out = buf;
  out += std::string(effect_name(ef.kind)) + " '" + ef.name + "' " + e.kind + " " + who(s, e.a, e.b);
  const auto gs = groups(ef.kind);
  if (!e.values.empty() && !gs.empty()) {
    out += " (";
    for (std::size_t g = 0; g < gs.size(); ++g) {
      if (g) out += ", ";
      out += gs[g].name;
      out += " ";
      for (int i = gs[g].from; i < gs[g].from + gs[g].count; ++i) {
        std::snprintf(buf, sizeof buf, "%s%.9g", i == gs[g].from ? "" : " ", e.values[i]);
        out += buf;
      }
    }
    out += ")";
  }
  return out;
}

void print_log(std::ostream& out, const Scene& s, const Run& r) {
  out << "scene " << s.source << " at " << precision_name(r.precision) << ": " << s.frames + 1 << " frames of "
      << s.time_step << " s, " << s.bodies.size() << " bodies, " << s.effects.size() << " effects\n";
  for (const Event& e : r.events) out << "  " << event_text(s, e) << "\n";
  std::uint64_t evaluated = 0;
  out << "  queries evaluated:";
  for (const auto& [k, n] : r.counts) {
    out << " " << k << " " << n;
    if (k != "broad") evaluated += n;
  }
  char buf[160];
  std::snprintf(buf, sizeof buf,
                "\n  %llu pair queries against %llu for every quantity of every pair every frame (%.3g%%); %.3g s\n",
                (unsigned long long)evaluated, (unsigned long long)r.naive,
                r.naive ? 100.0 * double(evaluated) / double(r.naive) : 0.0, r.seconds);
  out << buf;
}

void print_comparison(std::ostream& out, const Scene& s, const Comparison& c) {
  out << precision_name(c.approx) << " against " << precision_name(c.reference) << ": " << c.matched
      << " events at the same frame, " << c.missing.size() << " missing, " << c.extra.size() << " extra, "
      << c.shifted.size() << " at another frame\n";
  for (const Event& e : c.missing) out << "  missing  " << event_text(s, e) << "\n";
  for (const Event& e : c.extra) out << "  extra    " << event_text(s, e) << "\n";
  for (const auto& [r, a] : c.shifted)
    out << "  moved    " << event_text(s, r) << "\n           -> frame " << a.frame << " at "
        << precision_name(c.approx) << "\n";
  if (!c.values.empty()) {
    out << "  largest differences of the continuous outputs (scene units; ulps of " << precision_name(c.approx)
        << "):\n";
    for (const auto& [name, d] : c.values) {
      char buf[200];
      std::snprintf(buf, sizeof buf, "    %-34s %-10.3g %-10.3g over %zu%s%s\n", name.c_str(), d.max_abs, d.max_ulps,
                    d.compared, d.where.empty() ? "" : ", largest at ", d.where.c_str());
      out << buf;
    }
  }
}

}  // namespace cdref::scene
