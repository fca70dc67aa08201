// src/scene/parse.cpp - reading a scene file (nlohmann-json) into a Scene, refusing every
// fault with its place: a syntax error by line and column, anything else by JSON path
// (`/bodies/2/radius`). Nothing runs unless the whole file is valid.
#include "scene.hpp"

#include <cdref/det_sign.hpp>
#include <cdref/vec.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <map>
#include <set>
#include <algorithm>
#include <sstream>

#include "default_scene.hpp"  // generated from scenes/default.json

namespace cdref::scene {

using nlohmann::json;

const char* shape_name(Shape s) {
  switch (s) {
    case Shape::sphere: return "sphere";
    case Shape::box: return "box";
    case Shape::obb: return "oriented-box";
    case Shape::mesh: return "mesh";
    case Shape::ray: return "ray";
    case Shape::segment: return "segment";
  }
  return "?";
}
const char* effect_name(EffectKind k) {
  switch (k) {
    case EffectKind::trigger: return "trigger";
    case EffectKind::contact: return "contact";
    case EffectKind::raycast: return "raycast";
    case EffectKind::proximity: return "proximity";
    case EffectKind::time_of_impact: return "time-of-impact";
  }
  return "?";
}
bool Body::moves() const {
  if (!keyframes.empty()) return true;
  return velocity[0] != 0 || velocity[1] != 0 || velocity[2] != 0;
}

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw scene_error("at " + (path.empty() ? std::string("/") : path) + ": " + what);
}

std::string show(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

void only_keys(const json& j, const std::string& path, std::initializer_list<const char*> keys) {
  for (auto it = j.begin(); it != j.end(); ++it) {
    bool known = false;
    for (const char* k : keys) known = known || it.key() == k;
    if (!known) {
      std::string list;
      for (const char* k : keys) list += std::string(list.empty() ? "" : ", ") + k;
      fail(path + "/" + it.key(), "unknown key '" + it.key() + "' (expected one of: " + list + ")");
    }
  }
}

const json& need(const json& j, const std::string& path, const char* key) {
  if (!j.contains(key)) fail(path, std::string("missing '") + key + "'");
  return j.at(key);
}

double number(const json& j, const std::string& path) {
  if (!j.is_number()) fail(path, "expected a number, found " + std::string(j.type_name()));
  const double x = j.get<double>();
  if (!std::isfinite(x)) fail(path, "the number is not finite (" + show(x) + ")");
  return x;
}

V3 vec(const json& j, const std::string& path) {
  if (!j.is_array() || j.size() != 3) fail(path, "expected [x, y, z]");
  return {number(j[0], path + "/0"), number(j[1], path + "/1"), number(j[2], path + "/2")};
}

std::string text(const json& j, const std::string& path) {
  if (!j.is_string()) fail(path, "expected a string, found " + std::string(j.type_name()));
  const std::string t = j.get<std::string>();
  for (char c : t)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
      fail(path, "the string holds a control character (" + std::to_string(int(static_cast<unsigned char>(c))) +
                     "), which names and messages cannot show");
  return t;
}

bool zero(const V3& v) { return v[0] == 0 && v[1] == 0 && v[2] == 0; }

Body body(const json& j, const std::string& path) {
  if (!j.is_object()) fail(path, "a body is an object");
  Body b;
  b.name = text(need(j, path, "name"), path + "/name");
  if (b.name.empty() || b.name == "*" || b.name.rfind("group:", 0) == 0)
    fail(path + "/name", "a body's name must be non-empty, not '*' and not start with 'group:'");
  const std::string shape = text(need(j, path, "shape"), path + "/shape");
  if (shape == "sphere") {
    b.shape = Shape::sphere;
    only_keys(j, path, {"name", "group", "shape", "radius", "position", "velocity", "keyframes"});
    b.radius = number(need(j, path, "radius"), path + "/radius");
    if (b.radius < 0) fail(path + "/radius", "negative radius (" + show(b.radius) + ")");
  } else if (shape == "box" || shape == "oriented-box") {
    b.shape = shape == "box" ? Shape::box : Shape::obb;
    if (b.shape == Shape::box)
      only_keys(j, path, {"name", "group", "shape", "extent", "position", "velocity", "keyframes"});
    else
      only_keys(j, path, {"name", "group", "shape", "extent", "axes", "position", "velocity", "keyframes"});
    b.extent = vec(need(j, path, "extent"), path + "/extent");
    for (int i = 0; i < 3; ++i)
      if (b.extent[i] < 0)
        fail(path + "/extent/" + std::to_string(i), "negative extent (" + show(b.extent[i]) + ")");
    if (b.shape == Shape::obb) {
      const json& ax = need(j, path, "axes");
      if (!ax.is_array() || ax.size() != 3) fail(path + "/axes", "expected three axes [[x, y, z], ...]");
      for (int i = 0; i < 3; ++i) b.axes[i] = vec(ax[i], path + "/axes/" + std::to_string(i));
      const Vec3<double> a0(b.axes[0][0], b.axes[0][1], b.axes[0][2]), a1(b.axes[1][0], b.axes[1][1], b.axes[1][2]),
          a2(b.axes[2][0], b.axes[2][1], b.axes[2][2]);
      if (det3_sign(a0, a1, a2) == 0)
        fail(path + "/axes", "degenerate axes: the three axes are linearly dependent (decided exactly)");
    }
  } else if (shape == "mesh") {
    b.shape = Shape::mesh;
    only_keys(j, path, {"name", "group", "shape", "vertices", "faces", "position", "velocity", "keyframes"});
    const json& vs = need(j, path, "vertices");
    if (!vs.is_array() || vs.empty()) fail(path + "/vertices", "expected a non-empty list of [x, y, z]");
    for (std::size_t i = 0; i < vs.size(); ++i) b.vertices.push_back(vec(vs[i], path + "/vertices/" + std::to_string(i)));
    const json& fs = need(j, path, "faces");
    if (!fs.is_array() || fs.empty()) fail(path + "/faces", "expected a non-empty list of [i, j, k]");
    for (std::size_t f = 0; f < fs.size(); ++f) {
      const std::string fp = path + "/faces/" + std::to_string(f);
      if (!fs[f].is_array() || fs[f].size() != 3) fail(fp, "a face is three vertex indices [i, j, k]");
      std::array<int, 3> face{};
      for (int c = 0; c < 3; ++c) {
        const json& x = fs[f][c];
        if (!x.is_number_integer()) fail(fp + "/" + std::to_string(c), "a vertex index is a whole number");
        // as written (a negative index, or one past 2^63, is named as it is, not wrapped)
        if (!x.is_number_unsigned() || x.get<std::uint64_t>() >= b.vertices.size())
          fail(fp + "/" + std::to_string(c), "face names vertex " + x.dump() + ", but the mesh has " +
                                                 std::to_string(b.vertices.size()) + " vertices (0 to " +
                                                 std::to_string(b.vertices.size() - 1) + ")");
        face[c] = int(x.get<std::uint64_t>());
      }
      b.faces.push_back(face);
    }
  } else if (shape == "ray" || shape == "segment") {
    b.shape = shape == "ray" ? Shape::ray : Shape::segment;
    only_keys(j, path, {"name", "group", "shape", "direction", "attached_to", "position", "velocity", "keyframes"});
    b.direction = vec(need(j, path, "direction"), path + "/direction");
    if (b.shape == Shape::ray && zero(b.direction)) fail(path + "/direction", "a ray needs a nonzero direction");
  } else {
    fail(path + "/shape", "unknown shape '" + shape + "' (sphere, box, oriented-box, mesh, ray, segment)");
  }
  if (j.contains("group")) b.group = text(j["group"], path + "/group");
  b.position = j.contains("position") ? vec(j["position"], path + "/position") : V3{0, 0, 0};
  if (j.contains("velocity") && j.contains("keyframes"))
    fail(path, "a body moves with a velocity or with keyframes, not both");
  if (j.contains("velocity")) b.velocity = vec(j["velocity"], path + "/velocity");
  if (j.contains("keyframes")) {
    const json& ks = j["keyframes"];
    const std::string kp = path + "/keyframes";
    if (!ks.is_array() || ks.size() < 2) fail(kp, "expected at least two keyframes {time, position}");
    for (std::size_t i = 0; i < ks.size(); ++i) {
      const std::string p = kp + "/" + std::to_string(i);
      if (!ks[i].is_object()) fail(p, "a keyframe is {\"time\": t, \"position\": [x, y, z]}");
      only_keys(ks[i], p, {"time", "position"});
      Keyframe k{number(need(ks[i], p, "time"), p + "/time"), vec(need(ks[i], p, "position"), p + "/position")};
      if (!b.keyframes.empty() && !(k.time > b.keyframes.back().time))
        fail(p + "/time", "keyframe times must increase (" + show(k.time) + " after " + show(b.keyframes.back().time) + ")");
      b.keyframes.push_back(k);
    }
    if (j.contains("position")) fail(path + "/position", "a body with keyframes takes its position from them");
    b.position = b.keyframes.front().position;
  }
  return b;
}

// A body selector: a name, "group:NAME", "*" (every body that is not a sensor), or a list of them.
std::vector<int> select(const json& j, const std::string& path, const Scene& s) {
  std::vector<int> out;
  auto one = [&](const json& x, const std::string& p) {
    const std::string t = text(x, p);
    bool found = false;
    for (int i = 0; i < int(s.bodies.size()); ++i) {
      const Body& b = s.bodies[i];
      const bool m = t == "*" ? !b.sensor() : (t.rfind("group:", 0) == 0 ? b.group == t.substr(6) : b.name == t);
      if (m) {
        found = true;
        out.push_back(i);
      }
    }
    if (!found) fail(p, t.rfind("group:", 0) == 0 ? "no body is in " + t : "no body is named '" + t + "'");
  };
  if (j.is_array()) {
    if (j.empty()) fail(path, "an empty list of bodies");
    for (std::size_t i = 0; i < j.size(); ++i) one(j[i], path + "/" + std::to_string(i));
  } else {
    one(j, path);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

bool is_sphere(const Body& b) { return b.shape == Shape::sphere; }

Effect effect(const json& j, const std::string& path, const Scene& s) {
  if (!j.is_object()) fail(path, "an effect is an object");
  Effect e;
  const std::string type = text(need(j, path, "type"), path + "/type");
  if (type == "trigger") e.kind = EffectKind::trigger;
  else if (type == "contact") e.kind = EffectKind::contact;
  else if (type == "raycast") e.kind = EffectKind::raycast;
  else if (type == "proximity") e.kind = EffectKind::proximity;
  else if (type == "time-of-impact") e.kind = EffectKind::time_of_impact;
  else fail(path + "/type", "unknown effect '" + type + "' (trigger, contact, raycast, proximity, time-of-impact)");
  e.name = j.contains("name") ? text(j["name"], path + "/name") : type + "#" + path.substr(path.rfind('/') + 1);
  if (e.kind == EffectKind::raycast) {
    only_keys(j, path, {"type", "name", "sensor", "targets"});
    e.a = select(need(j, path, "sensor"), path + "/sensor", s);
    for (int a : e.a)
      if (!s.bodies[a].sensor())
        fail(path + "/sensor", "'" + s.bodies[a].name + "' is a " + shape_name(s.bodies[a].shape) + ", not a ray or segment");
    for (int b : select(need(j, path, "targets"), path + "/targets", s))
      if (!s.bodies[b].sensor()) e.b.push_back(b);
    if (e.b.empty()) fail(path + "/targets", "no target that is not a sensor");
    return e;
  }
  if (e.kind == EffectKind::proximity)
    only_keys(j, path, {"type", "name", "a", "b", "threshold"});
  else
    only_keys(j, path, {"type", "name", "a", "b"});
  e.a = select(need(j, path, "a"), path + "/a", s);
  e.b = select(need(j, path, "b"), path + "/b", s);
  // Every pair is checked through two representatives of each kind of body (shape, and
  // whether a mesh moves) on each side: a selector of 10^4 bodies is not 10^8 checks.
  auto reps = [&](const std::vector<int>& v) {
    std::map<std::pair<int, bool>, std::vector<int>> m;
    for (int x : v) {
      auto& r = m[{int(s.bodies[x].shape), s.bodies[x].moves()}];
      if (r.size() < 2) r.push_back(x);
    }
    return m;
  };
  bool any = false;
  for (const auto& [ka, ra] : reps(e.a))
    for (const auto& [kb, rb] : reps(e.b))
      for (int a : ra)
        for (int b : rb) {
          if (a == b) continue;
          any = true;
          const Body &A = s.bodies[a], &B = s.bodies[b];
          const std::string pair = "'" + A.name + "' and '" + B.name + "'";
          if (A.sensor() || B.sensor()) fail(path, pair + ": a sensor takes part in raycast effects only");
          if (e.kind == EffectKind::trigger) continue;
          const Body& X = is_sphere(A) ? A : B;  // the sphere first
          const Body& Y = is_sphere(A) ? B : A;
          if (!is_sphere(X))
            fail(path, pair + ": " + type + " needs a sphere in the pair (Chapter 3 defines penetration depth, "
                                        "distance and the space-time test for a sphere against a sphere, box, "
                                        "oriented box or triangle)");
          if (e.kind == EffectKind::time_of_impact) {
            if (Y.shape == Shape::obb)
              fail(path, pair + ": time-of-impact is defined for a sphere against a sphere, a box or a static mesh");
            if (Y.shape == Shape::mesh && Y.moves())
              fail(path, pair + ": time-of-impact against a mesh needs the mesh static");
          }
        }
  if (e.kind == EffectKind::proximity) {
    e.threshold = number(need(j, path, "threshold"), path + "/threshold");
    if (e.threshold < 0) fail(path + "/threshold", "negative threshold (" + show(e.threshold) + ")");
  }
  if (!any) fail(path, "the effect names no pair of distinct bodies");
  return e;
}

std::string place(const std::string& text, std::size_t byte) {
  std::size_t line = 1, col = 1;
  for (std::size_t i = 0; i + 1 < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      col = 1;
    } else {
      ++col;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(col);
}

}  // namespace

Scene parse_scene(const std::string& txt, const std::string& source) {
  json j;
  // Refused while parsing: a key given twice in one object (nlohmann keeps the last; a
  // scene must not mean something its author did not see) and nesting deeper than any
  // scene needs (a 10^6-deep array is refused, not built).
  constexpr int max_depth = 32;
  std::vector<std::set<std::string>> keys;
  const json::parser_callback_t check = [&](int depth, json::parse_event_t event, json& parsed) {
    if (depth > max_depth) throw scene_error(source + ": nesting deeper than " + std::to_string(max_depth) + " levels");
    if (event == json::parse_event_t::object_start) keys.emplace_back();
    if (event == json::parse_event_t::object_end && !keys.empty()) keys.pop_back();
    if (event == json::parse_event_t::key && !keys.empty()) {
      const std::string k = parsed.get<std::string>();
      if (!keys.back().insert(k).second)
        throw scene_error(source + ": the key '" + k + "' is given twice in one object (at depth " +
                          std::to_string(depth) + ")");
    }
    return true;
  };
  try {
    j = json::parse(txt, check);
  } catch (const json::parse_error& e) {
    // nlohmann's message is "[json.exception.parse_error.101] parse error at line L, column C: what"
    const std::string what = e.what();
    const auto at = what.find("parse error");
    const auto colon = at == std::string::npos ? at : what.find(": ", at);
    throw scene_error(source + ": " + place(txt, e.byte) + ": invalid JSON: " +
                      (colon == std::string::npos ? what : what.substr(colon + 2)));
  } catch (const json::exception& e) {
    // a number literal beyond double's range ("number overflow parsing '1e400'"): placed by
    // the first occurrence of the literal
    const std::string what = e.what();
    const auto q0 = what.find('\''), q1 = q0 == std::string::npos ? q0 : what.find('\'', q0 + 1);
    std::string where;
    if (q1 != std::string::npos) {
      const auto pos = txt.find(what.substr(q0 + 1, q1 - q0 - 1));
      if (pos != std::string::npos) where = place(txt, pos + 1) + ": ";
    }
    const auto sp = what.find("] ");
    throw scene_error(source + ": " + where + "invalid number: " + (sp == std::string::npos ? what : what.substr(sp + 2)) +
                      " (beyond double's range)");
  }
  Scene s;
  s.source = source;
  try {
    if (!j.is_object()) fail("", "a scene is an object {time_step, frames, bodies, effects}");
    only_keys(j, "", {"description", "time_step", "frames", "bodies", "effects"});
    if (j.contains("description") && !j["description"].is_string())
      fail("/description", "expected a string, found " + std::string(j["description"].type_name()));
    s.time_step = number(need(j, "", "time_step"), "/time_step");
    if (!(s.time_step > 0)) fail("/time_step", "the time step must be positive (" + show(s.time_step) + ")");
    const json& fr = need(j, "", "frames");
    if (!fr.is_number_integer() || fr.get<long long>() < 1 || fr.get<long long>() > 1000000)
      fail("/frames", "frames must be a whole number from 1 to 10^6");
    s.frames = int(fr.get<long long>());
    const json& bs = need(j, "", "bodies");
    if (!bs.is_array() || bs.empty()) fail("/bodies", "expected a non-empty list of bodies");
    std::set<std::string> names;
    std::vector<std::string> attach(bs.size());
    for (std::size_t i = 0; i < bs.size(); ++i) {
      const std::string p = "/bodies/" + std::to_string(i);
      s.bodies.push_back(body(bs[i], p));
      if (!names.insert(s.bodies.back().name).second)
        fail(p + "/name", "a second body named '" + s.bodies.back().name + "'");
      if (bs[i].contains("attached_to")) attach[i] = text(bs[i]["attached_to"], p + "/attached_to");
    }
    for (std::size_t i = 0; i < bs.size(); ++i) {
      if (attach[i].empty()) continue;
      const std::string p = "/bodies/" + std::to_string(i) + "/attached_to";
      for (int k = 0; k < int(s.bodies.size()); ++k)
        if (s.bodies[k].name == attach[i]) s.bodies[i].attached_to = k;
      if (s.bodies[i].attached_to < 0) fail(p, "no body is named '" + attach[i] + "'");
      if (s.bodies[s.bodies[i].attached_to].sensor()) fail(p, "a sensor is attached to a body, not to a sensor");
    }
    const json& es = need(j, "", "effects");
    if (!es.is_array() || es.empty()) fail("/effects", "expected a non-empty list of effects");
    for (std::size_t i = 0; i < es.size(); ++i) s.effects.push_back(effect(es[i], "/effects/" + std::to_string(i), s));
  } catch (const scene_error& e) {
    throw scene_error(source + ": " + e.what());
  }
  return s;
}

Scene load_scene(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw scene_error("cannot read " + path);
  std::stringstream ss;
  ss << f.rdbuf();
  return parse_scene(ss.str(), path);
}

Scene default_scene() { return parse_scene(default_scene_json, "built-in default (scenes/default.json)"); }

const char* precision_name(Precision p) {
  return p == Precision::float_ ? "float" : (p == Precision::double_ ? "double" : "exact");
}
Precision precision_by_name(const std::string& s) {
  if (s == "float") return Precision::float_;
  if (s == "double") return Precision::double_;
  if (s == "exact") return Precision::exact;
  throw std::invalid_argument("unknown precision '" + s + "' (float, double, exact)");
}

}  // namespace cdref::scene
