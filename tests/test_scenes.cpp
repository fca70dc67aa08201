// tests/test_scenes.cpp - scenes: the exact run against answers derived by hand, the far
// scene's float-against-exact differences (pinned, with the arithmetic that explains them),
// only the queries an effect needs, and malformed scenes refused with their place.
#include <catch2/catch.hpp>
#include <cdref/exact.hpp>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "scene.hpp"

// This file's names in a namespace of its own: the test files are compiled several to a unit
// (tests/CMakeLists.txt).
namespace cdref_test_scenes {

using namespace cdref::scene;
using Q = CGAL::Gmpq;

namespace {

Scene far_scene() { return load_scene(std::string(CDREF_SOURCE_DIR) + "/scenes/far.json"); }

int effect_index(const Scene& s, const std::string& name) {
  for (int i = 0; i < int(s.effects.size()); ++i)
    if (s.effects[i].name == name) return i;
  FAIL("no effect " << name);
  return -1;
}
std::vector<const Event*> events(const Scene& s, const Run& r, const std::string& effect, const std::string& kind) {
  const int e = effect_index(s, effect);
  std::vector<const Event*> out;
  for (const Event& x : r.events)
    if (x.effect == e && x.kind == kind) out.push_back(&x);
  return out;
}

double rounded(const Q& q) { return cdref::number_traits<Q>::to_double(q); }

std::string error_of(const std::string& text) {
  try {
    parse_scene(text, "t.json");
  } catch (const scene_error& e) {
    return e.what();
  }
  return "(accepted)";
}

const char* head = R"("time_step": 0.25, "frames": 40, )";

}  // namespace

TEST_CASE("the default scene's exact events are the ones derived by hand", "[scene]") {
  const Scene s = default_scene();
  const Run r = run_scene(s, Precision::exact);
  // The ball leaves y = -1 at 5 units per second towards the wall's face y = -4 + 0.1 and
  // touches it when its centre is one radius 0.11 away: t = (-1 - (-4 + 0.1 + 0.11)) / 5 with
  // the file's doubles taken exactly, in the step that ends at frame ceil(t / dt) = 34.
  const auto hit = events(s, r, "ball-hits-wall", "impact");
  REQUIRE(hit.size() == 1);
  const Q t = (Q(-1.0) - (Q(-4.0) + Q(0.1) + Q(0.11))) / Q(5.0);
  CHECK(hit[0]->values[0] == rounded(t));
  CHECK(hit[0]->frame == 34);
  CHECK(hit[0]->values[2] == rounded(Q(-1.0) + Q(-5.0) * t));  // the centre's y at impact
  // The avatar (radius 0.4) reaches the crate's face x = 2.5 at x = 2.1, t = 2.1 / 1.4 = 1.5:
  // frame 90 is at 90 dt = 1.4999999999999998... (dt is the double below 1/60), so the
  // contact begins at frame 91 and not at 90.
  const auto push = events(s, r, "push", "begin");
  REQUIRE(push.size() == 1);
  CHECK(push[0]->frame == 91);
  CHECK(Q(90) * Q(s.time_step) < Q(1.5));
  CHECK(Q(91) * Q(s.time_step) > Q(1.5));
  // The door's area (radius 2.5 around (10, 1.3, 1.1)) meets the avatar (radius 0.4, height
  // 0.45, walking x = 6 + 1.4 (t - 5) along y = 1.3) when (x - 10)^2 + 0.65^2 = 2.9^2:
  // t = 5 + (4 - sqrt(2.9^2 - 0.65^2)) / 1.4 = 5.838..., frame ceil(t / dt) = 351.
  const double t_door = 5 + (4 - std::sqrt(2.9 * 2.9 - 0.65 * 0.65)) / 1.4;
  const auto door = events(s, r, "door-opens", "begin");
  REQUIRE(door.size() == 1);
  CHECK(door[0]->frame == int(std::ceil(t_door / s.time_step)));
  CHECK(door[0]->frame == 351);
  // Nothing bumps into the door: it has slid open before the avatar arrives.
  CHECK(events(s, r, "door-bump", "begin").empty());
  // float and double agree with the exact run on every event of the scene near the origin
  for (Precision p : {Precision::float_, Precision::double_}) {
    const Comparison c = compare(s, run_scene(s, p), r);
    CHECK(c.missing.empty());
    CHECK(c.extra.empty());
    CHECK(c.shifted.empty());
    CHECK(c.matched == r.events.size());
  }
}

TEST_CASE("a million units from the origin the exact events stay, and float's move", "[scene]") {
  const Scene near = default_scene(), far = far_scene();
  const Run exact_near = run_scene(near, Precision::exact), exact_far = run_scene(far, Precision::exact);
  // The shift by 10^6 is exact, and so is every exact query: the same events at the same frames.
  const Comparison same = compare(far, exact_far, exact_near);
  CHECK(same.missing.empty());
  CHECK(same.extra.empty());
  CHECK(same.shifted.empty());
  // double: every event at its frame, continuous outputs within a few nano-units
  const Comparison d = compare(far, run_scene(far, Precision::double_), exact_far);
  CHECK(d.missing.empty());
  CHECK(d.extra.empty());
  CHECK(d.shifted.empty());
  for (const auto& [name, v] : d.values) CHECK(v.max_abs < 1e-8);
  // float: positions near 10^6 are multiples of 1/16. The ball's step (0.7, -5) / 60 rounds to
  // (0, -1/16) every frame (0.0117 is below half a spacing; -0.0833 is nearer -0.0625 than
  // -0.125), so it needs ceil((3.79 - small) / 0.0625) = 45 frames to reach the wall instead
  // of 34.
  const Run f = run_scene(far, Precision::float_);
  const auto hit = events(far, f, "ball-hits-wall", "impact");
  REQUIRE(hit.size() == 1);
  CHECK(hit[0]->frame == 45);
  CHECK(float(1e6f - 1.0f + float(-5.0 * far.time_step)) == 1e6f - 1.0625f);
  const Comparison c = compare(far, f, exact_far);
  // pinned: seven events come at another frame (the ball's impact, the contact, both trigger
  // events of the door, the ramp, two of the sensor's changes); none is missing or extra
  CHECK(c.missing.empty());
  CHECK(c.extra.empty());
  CHECK(c.shifted.size() == 7);
  CHECK(c.matched == 6);
  // a time of impact 0.186 s late (11 frames), and contact depths off by more than 0.01
  CHECK(c.values.at("ball-hits-wall time").max_abs > 0.18);
  CHECK(c.values.at("push depth").max_abs > 0.01);
}

TEST_CASE("times of impact on the grown box and triangle: faces, edges and corners", "[scene]") {
  // A sphere of radius 1 at 1 unit per second along x against the box [-1, 1]^3: at height
  // y = 0 it meets the face x = -1 at x = -2; at y = 1.5 the edge (x, y) = (-1, 1) at
  // x = -1 - sqrt(0.75); at y = z = 1.5 the corner at x = -1 - sqrt(0.5).
  auto scene = [](const std::string& y, const std::string& z, const std::string& target) {
    return std::string("{") + head + R"("bodies": [
      {"name": "s", "shape": "sphere", "radius": 1, "position": [-5, )" + y + ", " + z + R"(], "velocity": [1, 0, 0]},
      )" + target + R"(],
      "effects": [{"type": "time-of-impact", "a": "s", "b": "t"}]})";
  };
  const std::string box = R"({"name": "t", "shape": "box", "extent": [1, 1, 1]})";
  const std::string tri = R"({"name": "t", "shape": "mesh", "vertices": [[-1, -3, -3], [-1, 3, -3], [-1, 0, 1]], "faces": [[0, 1, 2]]})";
  struct Case {
    const char *y, *z;
    std::string target;
    double t;
  } cases[] = {
      {"0", "0", box, 3.0},
      {"1.5", "0", box, double(4 - std::sqrt(0.75L))},
      {"1.5", "1.5", box, double(4 - std::sqrt(0.5L))},
      {"0", "0", tri, 3.0},                       // the triangle's face (x = -1)
      {"0", "1.5", tri, double(4 - std::sqrt(0.75L))},  // its vertex (-1, 0, 1), from above it
  };
  for (const Case& c : cases) {
    const Scene s = parse_scene(scene(c.y, c.z, c.target), "toi");
    for (Precision p : {Precision::exact, Precision::double_}) {
      const Run r = run_scene(s, p);
      REQUIRE(r.events.size() == 1);
      INFO("y " << c.y << " z " << c.z << " at " << precision_name(p));
      // the analytic time in long double, rounded: within one ulp of the exact one
      CHECK(std::fabs(r.events[0].values[0] - c.t) <= std::nextafter(c.t, 10.0) - c.t);
      CHECK(r.events[0].frame == int(std::ceil(c.t / 0.25)));
    }
  }
}

TEST_CASE("a scene evaluates only what its effects need", "[scene]") {
  // Two spheres far apart and one pair near: a trigger runs the boolean test on the pairs the
  // broad phase reports and nothing else.
  const std::string bodies = R"("bodies": [
      {"name": "a", "shape": "sphere", "radius": 1, "position": [0, 0, 0], "velocity": [1, 0, 0]},
      {"name": "b", "shape": "sphere", "radius": 1, "position": [5, 0, 0]},
      {"name": "c", "shape": "sphere", "radius": 1, "position": [100, 0, 0]},
      {"name": "d", "shape": "box", "extent": [1, 1, 1], "position": [0, 100, 0]}],)";
  const Scene trig = parse_scene(std::string("{") + head + bodies + R"("effects": [{"type": "trigger", "a": "a", "b": "*"}]})", "t");
  const Run r = run_scene(trig, Precision::double_);
  CHECK(r.counts.at("proximity") == 0);
  CHECK(r.counts.at("sweep") == 0);
  CHECK(r.counts.at("cast") == 0);
  // a meets b between x = 3 and x = 7 (t = 3 .. 7 s, frames 12 .. 28): tested only when the
  // broad phase reports them, which is when their bounds overlap (the same frames)
  CHECK(r.counts.at("intersect") == r.counts.at("broad"));
  CHECK(r.counts.at("intersect") == 17);
  REQUIRE(r.events.size() == 2);
  CHECK(r.events[0].frame == 12);
  CHECK(r.events[1].frame == 29);
  // a contact runs proximity only where the boolean test says overlap
  const Scene con = parse_scene(std::string("{") + head + bodies + R"("effects": [{"type": "contact", "a": "a", "b": "b"}]})", "t");
  const Run rc = run_scene(con, Precision::double_);
  CHECK(rc.counts.at("proximity") == 17);
  CHECK(rc.counts.at("intersect") == 17);
  CHECK(rc.naive == 41u * (4 * 3 / 2 * 4));
}

TEST_CASE("a malformed scene is refused with its place, before anything runs", "[scene][errors]") {
  const std::string sphere = R"({"name": "s", "shape": "sphere", "radius": 1})";
  auto with = [&](const std::string& bodies, const std::string& effects) {
    return std::string("{") + head + "\"bodies\": [" + bodies + "], \"effects\": [" + effects + "]}";
  };
  const std::string trig = R"({"type": "trigger", "a": "s", "b": "t"})";
  struct Bad {
    std::string text, where;
  } bad[] = {
      {"{\"time_step\": 0.25,\n \"frames\": 3 \"bodies\": []}", "line 2, column 21: invalid JSON"},
      {"{\"time_step\": 1e400}", "line 1, column 15: invalid number"},
      {with(R"({"name": "s", "shape": "sphere", "radius": -1})", trig), "at /bodies/0/radius: negative radius"},
      {with(R"({"name": "s", "shape": "cone"})", trig), "at /bodies/0/shape: unknown shape 'cone'"},
      {with(sphere + R"(, {"name": "t", "shape": "oriented-box", "extent": [1, 1, 1], "axes": [[1, 0, 0], [0, 1, 0], [1, 1, 0]]})", trig),
       "at /bodies/1/axes: degenerate axes"},
      {with(sphere + R"(, {"name": "t", "shape": "mesh", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "faces": [[0, 1, 3]]})", trig),
       "at /bodies/1/faces/0/2: face names vertex 3"},
      {with(sphere, trig), "at /effects/0/b: no body is named 't'"},
      {with(sphere + ", " + R"({"name": "t", "shape": "sphere", "radius": 1})", R"({"type": "explode", "a": "s", "b": "t"})"),
       "at /effects/0/type: unknown effect 'explode'"},
      {with(R"({"name": "s", "shape": "box", "extent": [1, 1, 1]}, {"name": "t", "shape": "box", "extent": [1, 1, 1]})",
            R"({"type": "contact", "a": "s", "b": "t"})"),
       "contact needs a sphere in the pair"},
      {with(sphere + R"(, {"name": "t", "shape": "sphere", "radius": 1, "colour": "red"})", trig),
       "at /bodies/1/colour: unknown key 'colour'"},
      {with(sphere + R"(, {"name": "t", "shape": "ray", "direction": [0, 0, 0]})", trig), "a ray needs a nonzero direction"},
      {with(sphere + R"(, {"name": "t", "shape": "box", "extent": [1, -1, 1]})", trig), "at /bodies/1/extent/1: negative extent"},
      {std::string("{\"time_step\": -1, \"frames\": 3, \"bodies\": [], \"effects\": []}"), "at /time_step: the time step must be positive"},
  };
  for (const Bad& b : bad) {
    INFO(b.text);
    const std::string e = error_of(b.text);
    CHECK(e.find(b.where) != std::string::npos);
    CHECK(e.rfind("t.json: ", 0) == 0);
  }
}

TEST_CASE("a sphere passing another at exactly touching distance touches at one frame", "[scene]") {
  // grazing.json: the passer (radius 1) moves along y = 2 past the post (radius 1) at the
  // origin; x = -1.6 + k (0.4 x 0.25), and -1.6 is exactly -4 x 0.4 in binary, so at k = 16 the
  // exact run has x = 0: distance 2 = the radii's sum, touching at that frame alone.
  const Scene s = load_scene(std::string(CDREF_SOURCE_DIR) + "/scenes/grazing.json");
  CHECK(Q(-1.6) + Q(16) * Q(0.4) * Q(0.25) == Q(0));
  const Run exact = run_scene(s, Precision::exact);
  const auto begin = events(s, exact, "graze", "begin"), end = events(s, exact, "graze", "end");
  REQUIRE(begin.size() == 1);
  REQUIRE(end.size() == 1);
  CHECK(begin[0]->frame == 16);
  CHECK(end[0]->frame == 17);
  const auto near = events(s, exact, "near", "begin");
  REQUIRE(near.size() == 1);
  CHECK(near[0]->values[0] == 0.0);  // distance exactly 0
  // double accumulates x += 0.1 sixteen times from -1.6; it touches at frame 16 exactly when
  // its test (x^2 + 4 <= 4 in double) holds there
  double x = -1.6;
  for (int k = 0; k < 16; ++k) x += 0.4 * 0.25;
  const bool touches = x * x + 4.0 <= 4.0;
  const Run d = run_scene(s, Precision::double_);
  CHECK(events(s, d, "graze", "begin").size() == (touches ? 1u : 0u));
}

TEST_CASE("the scene files in scenes/ load and run at every precision", "[scene]") {
  for (const char* f : {"default.json", "far.json", "grazing.json"}) {
    const Scene s = load_scene(std::string(CDREF_SOURCE_DIR) + "/scenes/" + f);
    CHECK(!run_scene(s, Precision::float_).events.empty());
  }
}

}  // namespace cdref_test_scenes
