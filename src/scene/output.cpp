// src/scene/output.cpp - a scene's runs as JSON and as a picture (SVG, top view), and the
// `cdref scene` command.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <memory>
#include <optional>
#include <set>
#include <sstream>

#include <cdref/error.hpp>

#include "../options.hpp"
#include "../output.hpp"
#include "scene.hpp"

namespace cdref::scene {

std::string event_text(const Scene& s, const Event& e);  // compare.cpp

namespace {

using nlohmann::json;

json event_json(const Scene& s, const Event& e) {
  return {{"frame", e.frame},
          {"effect", s.effects[e.effect].name},
          {"type", effect_name(s.effects[e.effect].kind)},
          {"kind", e.kind},
          {"a", s.bodies[e.a].name},
          {"b", e.b >= 0 ? json(s.bodies[e.b].name) : json(nullptr)},
          {"values", e.values}};
}

}  // namespace

std::string to_json(const Scene& s, const std::vector<Run>& runs, const std::vector<Comparison>& cmps) {
  json j;
  j["scene"] = s.source;
  j["frames"] = s.frames;
  j["time_step"] = s.time_step;
  for (const Run& r : runs) {
    json jr;
    jr["precision"] = precision_name(r.precision);
    for (const Event& e : r.events) jr["events"].push_back(event_json(s, e));
    if (r.events.empty()) jr["events"] = json::array();
    jr["counts"] = r.counts;
    jr["naive"] = r.naive;
    jr["seconds"] = r.seconds;
    j["runs"].push_back(jr);
  }
  for (const Comparison& c : cmps) {
    json jc;
    jc["approximate"] = precision_name(c.approx);
    jc["reference"] = precision_name(c.reference);
    jc["matched"] = c.matched;
    jc["missing"] = json::array();
    jc["extra"] = json::array();
    jc["moved"] = json::array();
    for (const Event& e : c.missing) jc["missing"].push_back(event_json(s, e));
    for (const Event& e : c.extra) jc["extra"].push_back(event_json(s, e));
    for (const auto& [r, a] : c.shifted) jc["moved"].push_back({{"reference", event_json(s, r)}, {"approximate", event_json(s, a)}});
    for (const auto& [name, d] : c.values)
      jc["values"][name] = {{"compared", d.compared}, {"max_abs", d.max_abs}, {"max_ulps", d.max_ulps}, {"where", d.where}};
    j["comparisons"].push_back(jc);
  }
  return j.dump(1) + "\n";
}

// ---- the picture: the scene from above (x to the right, y up), the bodies where they start
// (outlines) and their paths, each run's events as marks on the path of the body concerned,
// and the events on which the runs disagree circled in red ----
std::string to_svg(const Scene& s, const std::vector<Run>& runs, const std::vector<Comparison>& cmps) {
  const Run& ref = runs.back();
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  auto grow = [&](double x, double y) {
    lo[0] = std::min(lo[0], x), hi[0] = std::max(hi[0], x);
    lo[1] = std::min(lo[1], y), hi[1] = std::max(hi[1], y);
  };
  // the view: every body where it starts, and the paths of the bodies in the scene's bounds
  // (a body that leaves them, like a ball thrown through a wall, is drawn to the edge)
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const Body& b = s.bodies[i];
    {
      const V3& p = ref.path.front()[i];
      double rx = 0, ry = 0;
      if (b.shape == Shape::sphere) rx = ry = b.radius;
      if (b.shape == Shape::box) rx = b.extent[0], ry = b.extent[1];
      if (b.shape == Shape::obb)
        for (int a = 0; a < 3; ++a) rx += std::fabs(b.axes[a][0] * b.extent[a]), ry += std::fabs(b.axes[a][1] * b.extent[a]);
      grow(p[0] - rx, p[1] - ry);
      grow(p[0] + rx, p[1] + ry);
      if (b.shape == Shape::mesh)
        for (const V3& v : b.vertices) grow(p[0] + v[0], p[1] + v[1]);
    }
  }
  // the scene far from the origin is drawn relative to its own corner
  const double W = 900, margin = 30, span = std::max({hi[0] - lo[0], hi[1] - lo[1], 1e-9});
  const double k = (W - 2 * margin) / span;
  const double H = std::ceil((hi[1] - lo[1]) * k + 2 * margin + 90);
  auto X = [&](double x) { return margin + (x - lo[0]) * k; };
  auto Y = [&](double y) { return H - 90 - margin - (y - lo[1]) * k; };
  std::ostringstream o;
  o.precision(6);
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
    << "<defs><clipPath id=\"view\"><rect x=\"" << margin / 2 << "\" y=\"" << Y(hi[1]) - margin / 2 << "\" width=\""
    << (hi[0] - lo[0]) * k + margin << "\" height=\"" << (hi[1] - lo[1]) * k + margin << "\"/></clipPath></defs>\n"
    << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    << "<text x=\"" << margin << "\" y=\"18\" font-size=\"14\">" << s.source << ": top view, " << s.frames + 1
    << " frames of " << s.time_step << " s (x from " << lo[0] << ", y from " << lo[1] << ")</text>\n";
  o << "<g clip-path=\"url(#view)\">\n";
  const char* fill[] = {"#d9e6f2", "#e8e8e8", "#f2e6d9", "#e6f2d9"};
  // meshes (floors, ramps) underneath, the other bodies over them, the names over everything
  std::vector<std::size_t> order;
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t i = 0; i < s.bodies.size(); ++i)
      if ((s.bodies[i].shape == Shape::mesh) == (pass == 0)) order.push_back(i);
  std::ostringstream names;
  names.precision(6);
  for (std::size_t i : order) {
    const Body& b = s.bodies[i];
    const V3& p = ref.path.front()[i];
    const char* f = fill[i % 4];
    if (b.shape == Shape::sphere) {
      o << "<circle cx=\"" << X(p[0]) << "\" cy=\"" << Y(p[1]) << "\" r=\"" << b.radius * k << "\" fill=\"" << f
        << "\" fill-opacity=\"0.6\" stroke=\"#555\"/>\n";
    } else if (b.shape == Shape::box) {
      o << "<rect x=\"" << X(p[0] - b.extent[0]) << "\" y=\"" << Y(p[1] + b.extent[1]) << "\" width=\""
        << 2 * b.extent[0] * k << "\" height=\"" << 2 * b.extent[1] * k << "\" fill=\"" << f << "\" stroke=\"#555\"/>\n";
    } else if (b.shape == Shape::obb) {
      // the outline of the footprint: the box's corners projected, their convex hull
      std::vector<std::pair<double, double>> c;
      for (int m = 0; m < 8; ++m) {
        double x = p[0], y = p[1];
        for (int a = 0; a < 3; ++a) {
          const double sg = ((m >> a) & 1) ? 1 : -1;
          x += sg * b.extent[a] * b.axes[a][0];
          y += sg * b.extent[a] * b.axes[a][1];
        }
        c.push_back({x, y});
      }
      std::sort(c.begin(), c.end());
      std::vector<std::pair<double, double>> h;
      auto cross = [](auto o_, auto a, auto b_) {
        return (a.first - o_.first) * (b_.second - o_.second) - (a.second - o_.second) * (b_.first - o_.first);
      };
      for (int pass = 0; pass < 2; ++pass) {
        const std::size_t base = h.size();
        for (std::size_t q = 0; q < c.size(); ++q) {
          const auto& pt = pass == 0 ? c[q] : c[c.size() - 1 - q];
          while (h.size() >= base + 2 && cross(h[h.size() - 2], h.back(), pt) <= 0) h.pop_back();
          h.push_back(pt);
        }
        h.pop_back();
      }
      o << "<polygon points=\"";
      for (const auto& [x, y] : h) o << X(x) << "," << Y(y) << " ";
      o << "\" fill=\"" << f << "\" stroke=\"#555\"/>\n";
    } else if (b.shape == Shape::mesh) {
      for (const auto& face : b.faces) {
        o << "<polygon points=\"";
        for (int c = 0; c < 3; ++c) o << X(p[0] + b.vertices[face[c]][0]) << "," << Y(p[1] + b.vertices[face[c]][1]) << " ";
        o << "\" fill=\"" << f << "\" fill-opacity=\"0.5\" stroke=\"#999\"/>\n";
      }
    } else {
      const double len = b.shape == Shape::segment ? 1 : span / std::max(1e-300, std::hypot(b.direction[0], b.direction[1])) * 0.25;
      o << "<line x1=\"" << X(p[0]) << "\" y1=\"" << Y(p[1]) << "\" x2=\"" << X(p[0] + len * b.direction[0])
        << "\" y2=\"" << Y(p[1] + len * b.direction[1]) << "\" stroke=\"#c80\" stroke-dasharray=\"6 3\"/>\n";
    }
    double lx = p[0], ly_ = p[1];
    if (b.shape == Shape::mesh) {  // a mesh is named at its first face's centre
      lx += (b.vertices[b.faces[0][0]][0] + b.vertices[b.faces[0][1]][0] + b.vertices[b.faces[0][2]][0]) / 3;
      ly_ += (b.vertices[b.faces[0][0]][1] + b.vertices[b.faces[0][1]][1] + b.vertices[b.faces[0][2]][1]) / 3;
    }
    names << "<text x=\"" << X(lx) + 4 << "\" y=\"" << Y(ly_) - 4 << "\" fill=\"#333\">" << b.name << "</text>\n";
  }
  // paths: the reference run's, and each other run's where it leaves it by more than a pixel
  const char* colour[] = {"#1f77b4", "#2ca02c", "#000"};
  for (std::size_t r = 0; r < runs.size(); ++r)
    for (std::size_t i = 0; i < s.bodies.size(); ++i) {
      bool moves = false;
      for (const auto& fr : runs[r].path) moves = moves || fr[i] != runs[r].path.front()[i];
      if (!moves) continue;
      o << "<polyline fill=\"none\" stroke=\"" << colour[std::min<std::size_t>(r, 2)] << "\" stroke-width=\""
        << (r + 1 == runs.size() ? 1 : 2.5) << "\" stroke-opacity=\"0.6\" points=\"";
      double px = -1e300, py = -1e300;  // points closer than half a pixel to the last are left out
      for (std::size_t f = 0; f < runs[r].path.size(); ++f) {
        const double x = X(runs[r].path[f][i][0]), y = Y(runs[r].path[f][i][1]);
        if (std::hypot(x - px, y - py) < 0.5 && f + 1 < runs[r].path.size()) continue;
        o << x << "," << y << " ";
        px = x, py = y;
      }
      o << "\"/>\n";
    }
  // events: a mark at the position of body a at the event's frame, per run
  std::set<std::tuple<int, int, std::string, int, int>> disputed;
  for (const Comparison& c : cmps) {
    for (const Event& e : c.missing) disputed.insert({e.frame, e.effect, e.kind, e.a, e.b});
    for (const Event& e : c.extra) disputed.insert({e.frame, e.effect, e.kind, e.a, e.b});
    for (const auto& [x, y] : c.shifted) {
      disputed.insert({x.frame, x.effect, x.kind, x.a, x.b});
      disputed.insert({y.frame, y.effect, y.kind, y.a, y.b});
    }
  }
  for (std::size_t r = 0; r < runs.size(); ++r)
    for (const Event& e : runs[r].events) {
      const V3& p = runs[r].path[std::min<std::size_t>(e.frame, runs[r].path.size() - 1)][e.a];
      const bool bad = disputed.count({e.frame, e.effect, e.kind, e.a, e.b}) > 0;
      o << "<circle cx=\"" << X(p[0]) << "\" cy=\"" << Y(p[1]) << "\" r=\"" << (bad ? 7 : 4) << "\" fill=\""
        << (bad ? "none" : colour[std::min<std::size_t>(r, 2)]) << "\" stroke=\"" << (bad ? "#d62728" : "none")
        << "\" stroke-width=\"2\"><title>" << precision_name(runs[r].precision) << ": " << event_text(s, e)
        << "</title></circle>\n";
    }
  o << names.str() << "</g>\n";
  // legend
  double ly = H - 70;
  for (std::size_t r = 0; r < runs.size(); ++r, ly += 16)
    o << "<circle cx=\"" << margin + 5 << "\" cy=\"" << ly - 4 << "\" r=\"4\" fill=\"" << colour[std::min<std::size_t>(r, 2)]
      << "\"/><text x=\"" << margin + 15 << "\" y=\"" << ly << "\">" << precision_name(runs[r].precision)
      << " run: paths and events (" << runs[r].events.size() << ")</text>\n";
  std::size_t nd = 0;
  for (const Comparison& c : cmps) nd += c.missing.size() + c.extra.size() + c.shifted.size();
  o << "<circle cx=\"" << margin + 5 << "\" cy=\"" << ly - 4 << "\" r=\"6\" fill=\"none\" stroke=\"#d62728\" stroke-width=\"2\"/>"
    << "<text x=\"" << margin + 15 << "\" y=\"" << ly << "\">events on which the runs disagree (" << nd
    << "): missing, extra or at another frame</text>\n</svg>\n";
  return o.str();
}

namespace {

struct SceneOptions {
  std::string file, json_out, svg_out;
  std::vector<std::string> precisions, compare_pairs;
  bool quiet = false;
};

int scene_run(const SceneOptions& o) {
  const std::string &file = o.file, &json_out = o.json_out, &svg_out = o.svg_out;
  const bool quiet = o.quiet;
  std::vector<Precision> only;
  std::vector<std::pair<Precision, Precision>> compares;
  for (const std::string& p : o.precisions) only.push_back(precision_by_name(p));
  for (const std::string& v : o.compare_pairs) {
    const auto comma = v.find(',');
    if (comma == std::string::npos) throw std::invalid_argument("--compare wants two precisions, e.g. float,exact, not '" + v + "'");
    compares.push_back({precision_by_name(v.substr(0, comma)), precision_by_name(v.substr(comma + 1))});
  }
  // the outputs first: a path that cannot be written is refused before the scene runs
  std::optional<cli::io::Output> json_file, svg_file;
  if (!json_out.empty()) json_file.emplace(json_out, "--json");
  if (!svg_out.empty()) svg_file.emplace(svg_out, "--svg");
  // (with --json - or --svg -, standard output is the data's: the logs go to standard error)
  std::ostream& human = json_out == "-" || svg_out == "-" ? std::cerr : std::cout;
  const Scene s = file.empty() ? default_scene() : load_scene(file);
  if (only.empty() && compares.empty()) compares = {{Precision::float_, Precision::exact}, {Precision::double_, Precision::exact}};
  // each precision runs once; the logs printed are those asked for with --precision, or the
  // reference runs of the comparisons
  std::vector<Precision> order;
  auto want = [&](Precision p) {
    if (std::find(order.begin(), order.end(), p) == order.end()) order.push_back(p);
  };
  for (const auto& [x, y] : compares) want(x), want(y);
  for (Precision p : only) want(p);
  std::sort(order.begin(), order.end());
  // A run its type cannot carry through (a value beyond float's range) is reported and left
  // out; the other runs and their comparisons are still printed and written.
  std::vector<Run> runs;
  std::vector<std::string> failed;
  for (Precision p : order) {
    try {
      runs.push_back(run_scene(s, p));
    } catch (const invalid_input& e) {
      failed.push_back(e.what());
    }
  }
  auto has = [&](Precision p) {
    return std::any_of(runs.begin(), runs.end(), [p](const Run& r) { return r.precision == p; });
  };
  auto run_of = [&](Precision p) -> const Run& {
    for (const Run& r : runs)
      if (r.precision == p) return r;
    throw std::logic_error("scene: a run is missing");
  };
  std::vector<Comparison> cmps;
  for (const auto& [x, y] : compares)
    if (has(x) && has(y)) cmps.push_back(compare(s, run_of(x), run_of(y)));
  if (!quiet) {
    std::set<Precision> logged(only.begin(), only.end());
    if (only.empty())
      for (const auto& [x, y] : compares) logged.insert(y);
    for (Precision p : logged)
      if (has(p)) print_log(human, s, run_of(p));
    for (const Comparison& c : cmps) {
      human << "\n";
      print_comparison(human, s, c);
    }
  }
  cli::io::Outputs all;
  if (json_file) all.attempt([&] {
      json_file->stream() << to_json(s, runs, cmps);
      json_file->commit();
    });
  if (svg_file && !runs.empty()) all.attempt([&] {
      svg_file->stream() << to_svg(s, runs, cmps);
      svg_file->commit();
    });
  for (const std::string& f : failed) std::cerr << "cdref: " << s.source << ": " << f << "\n";
  all.finish();
  return failed.empty() ? 0 : 1;
}

}  // namespace

void add_scene_command(cli::Program& program) {
  auto o = std::make_shared<SceneOptions>();
  program
      .add("scene",
           "run a scene (JSON, see docs/scenes.md; no FILE: the built-in default, scenes/default.json) evaluating only "
           "the queries its effects name, and print its event log; --compare float,exact runs both and prints the "
           "events they disagree on and the differences of the continuous outputs (default: float,exact and "
           "double,exact)",
           [o] { return scene_run(*o); })
      .positional("FILE", o->file, "the scene file (default: the built-in scene)")
      .choices("--precision", o->precisions, {"float", "double", "exact"},
               "run at this precision and print its log (repeatable)")
      .texts("--compare", o->compare_pairs, "compare two precisions, e.g. float,exact (repeatable)")
      .text("--json", o->json_out, "write the runs and comparisons as JSON to this file (- for standard output)")
      .text("--svg", o->svg_out, "draw the top view with the events to this SVG")
      .flag("--quiet", o->quiet, "no log on standard output");
}

}  // namespace cdref::scene
