// src/scene/scene.hpp - scenes: bodies that move, the effects a scene asks for, and runs of
// the scene at float, double and exact precision whose event logs can be compared.
//
// A scene (its JSON schema is in docs/scenes.md) is read once into the plain description
// below, in doubles: the numbers of the file are those doubles at every precision. A run
// (run_scene) then moves the bodies and evaluates only the queries its effects name:
//   - at float and double, as an engine would: p_{k+1} = p_k + v dt in the run's type (the
//     rounding accumulates frame by frame), and every query is the book's at that type;
//   - at exact precision, p_k = p_0 + v (k dt) exactly (rationals), and every query is the
//     exact formulation (the book at CGAL::Gmpq with square roots in Quad, the solid's
//     formulation for oriented boxes), so its events and values are the truth.
// compare() pairs the events of two runs and measures the continuous outputs' differences.
#pragma once

#include <array>
#include <cstdint>
#include <iosfwd>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace cdref::cli {
class Program;
}

namespace cdref::scene {

using V3 = std::array<double, 3>;

// A malformed scene: the message names the place (line and column, or the JSON path).
class scene_error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class Shape { sphere, box, obb, mesh, ray, segment };
const char* shape_name(Shape s);

struct Keyframe {
  double time;
  V3 position;
};

struct Body {
  std::string name;
  std::string group;
  Shape shape = Shape::sphere;
  double radius = 0;                        // sphere
  V3 extent{};                              // box, obb: half-sizes
  std::array<V3, 3> axes{};                 // obb: the edge directions (independent)
  std::vector<V3> vertices;                 // mesh: local coordinates
  std::vector<std::array<int, 3>> faces;    // mesh: vertex indices
  V3 direction{};                           // ray: direction; segment: target - source
  int attached_to = -1;                     // sensors: the body whose position carries them
  // The pose: position (a sensor's source; for an attached sensor, its offset from the body)
  // and a motion: constant velocity, or keyframes (linear between them, held after the last).
  V3 position{};
  V3 velocity{};
  std::vector<Keyframe> keyframes;
  bool moves() const;
  bool sensor() const { return shape == Shape::ray || shape == Shape::segment; }
};

enum class EffectKind { trigger, contact, raycast, proximity, time_of_impact };
const char* effect_name(EffectKind k);

struct Effect {
  EffectKind kind = EffectKind::trigger;
  std::string name;
  // The bodies it concerns: every pair (a in `a`, b in `b`, a != b); raycast: a holds the
  // sensors, b the targets.
  std::vector<int> a, b;
  double threshold = 0;                    // proximity
};

struct Scene {
  std::string source;  // the file name, or "built-in default"
  double time_step = 0;
  int frames = 0;
  std::vector<Body> bodies;
  std::vector<Effect> effects;
};

// Reads a scene; throws scene_error naming the place of the first fault.
Scene parse_scene(const std::string& text, const std::string& source);
Scene load_scene(const std::string& path);
// The built-in default scene (scenes/default.json, compiled in).
Scene default_scene();

enum class Precision { float_, double_, exact };
const char* precision_name(Precision p);
Precision precision_by_name(const std::string& s);

// An event: something an effect reports at a frame. kind: "begin", "end" (trigger, contact,
// proximity), "hit" (a sensor's first hit changes body: b is the body, -1 for none),
// "impact" (time of impact within the step ending at `frame`).
// values: contact: depth, normal xyz, witness a xyz, witness b xyz; proximity: distance,
// witnesses; raycast: lambda, point xyz, normal xyz; impact: time, centre of the sphere xyz.
struct Event {
  int frame = 0;
  int effect = 0;
  std::string kind;
  int a = -1, b = -1;
  std::vector<double> values;
};
// The continuous outputs of every frame in which an effect holds (contact, proximity,
// raycast) and of every impact: compared between runs value by value.
struct Sample {
  int frame = 0;
  int effect = 0;
  int a = -1, b = -1;
  std::vector<double> values;  // as in Event
};

struct Run {
  Precision precision = Precision::double_;
  std::vector<Event> events;
  std::vector<Sample> samples;
  // Queries evaluated, by kind: "intersect" (trigger-level tests, mid-phase included),
  // "proximity", "cast" (sensor rays), "sweep" (time-of-impact casts on configuration
  // space obstacles), "broad" (pairs the broad phase reported).
  std::map<std::string, std::uint64_t> counts;
  // Every quantity for every pair every frame: frames x (body pairs x 4 + sensor-body pairs)
  // with a mesh counting as its triangles.
  std::uint64_t naive = 0;
  std::vector<std::vector<V3>> path;  // body positions per frame (rounded to double)
  double seconds = 0;
};

Run run_scene(const Scene& s, Precision p);

struct ValueDiff {
  std::size_t compared = 0;
  double max_abs = 0;   // scene units (seconds for a time of impact)
  double max_ulps = 0;  // ulps of the approximate run's type at the exact value
  std::string where;    // the sample of the largest difference
};
struct Comparison {
  Precision approx, reference;
  std::vector<Event> missing;                       // in the reference only
  std::vector<Event> extra;                         // in the approximate run only
  std::vector<std::pair<Event, Event>> shifted;     // (reference, approximate) at another frame
  std::size_t matched = 0;
  std::map<std::string, ValueDiff> values;          // by effect kind and quantity
};
Comparison compare(const Scene& s, const Run& approx, const Run& reference);

void print_log(std::ostream& out, const Scene& s, const Run& r);
void print_comparison(std::ostream& out, const Scene& s, const Comparison& c);
std::string to_json(const Scene& s, const std::vector<Run>& runs, const std::vector<Comparison>& cmps);
std::string to_svg(const Scene& s, const std::vector<Run>& runs, const std::vector<Comparison>& cmps);

// Adds `cdref scene` to the command line (src/scene/output.cpp).
void add_scene_command(cli::Program& program);

}  // namespace cdref::scene
