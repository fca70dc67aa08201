// tests/test_peers_embree.cpp - the Embree adapters of `cdref peers` (src/peers/embree.hpp) on
// hand cases whose exact answers are known: what Embree answers in its default and robust modes
// on one triangle and on a closed fan, and which cases each adapter's convention sets apart.
// Built where Embree is (libembree-dev).
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "peers/embree.hpp"
#include "peers_hand.hpp"

namespace test_peers_embree {

using namespace cdref::peers;
using test_peers::of;

const Adapter& adapter(const std::vector<Adapter>& all, const std::string& query, bool robust) {
  return test_peers::adapter(all, query, "robust", !robust);
}
double value(const Adapter& a, const Answer& r, const std::string& g) { return test_peers::values(a, r, g).front(); }
const Answer none{};
const double tiny = 0x1p-20;
// the float one ulp below x
double below(float x) { return double(std::nextafter(x, 0.0f)); }

TEST_CASE("Embree's adapters: hand cases with known answers in both modes, and the cases set apart", "[peers][embree]") {
  const std::vector<Adapter> all = embree::adapters();
  REQUIRE(all.size() == 4);
  for (const Adapter& a : all) CHECK(a.precision == 24);

  for (const bool robust : {false, true}) {
    INFO((robust ? "robust mode" : "default mode"));
    const Adapter& tri = adapter(all, "ray-triangle-cast", robust);
    // the unit triangle (0,0,0) (1,0,0) (0,1,0), shot straight down from height 1
    const Answer r = tri.run(of({0.25, 0.5, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, 0, 1, 0}));
    CHECK(r.cls);
    // exactly 1, 0.25 and 0.5; Embree's SSE2 code divides by the determinant through its
    // reciprocal (an approximation and a Newton step), one ulp of float below each here
    CHECK(value(tri, r, "lambda_enter") == below(1));
    CHECK(value(tri, r, "u") == below(0.25));
    CHECK(value(tri, r, "v") == below(0.5));
    CHECK(tri.run(of({0.25, 0.5, -1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0})).cls);  // the other face
    CHECK(tri.run(of({0.5, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, 0, 1, 0})).cls);     // an edge's midpoint
    CHECK_FALSE(tri.run(of({0.5, -tiny, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, 0, 1, 0})).cls);
    CHECK_FALSE(tri.run(of({0.25, 0.5, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0})).cls);  // behind the source
    CHECK(tri.differs(of({-1, 0.25, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0}), none));   // in the plane
    CHECK(tri.differs(of({0.5, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, 2, 0, 0}), none));    // zero area
    CHECK_FALSE(tri.differs(of({0.25, 0.5, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, 0, 1, 0}), none));
    // a source on the triangle: robust mode hits at 0, as cdref; default mode counts t > 0 only
    const Inputs on = of({0.25, 0.25, 0, 0, 0, -1, 0, 0, 0, 1, 0, 0, 0, 1, 0});
    CHECK(tri.differs(on, none) == !robust);
    CHECK(tri.run(on).cls == robust);

    // a closed flat fan of four triangles around the origin in z = 0 (ring (1,0,0) (0,1,0)
    // (-1,0,0) (0,-1,0)), shot straight down
    const Adapter& fan = adapter(all, "ray-fan-cast", robust);
    auto shot = [](double x, double y) {
      return of({x, y, 1, 0, 0, -1, 4, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0});
    };
    const Answer inside = fan.run(shot(0.25, 0.25));
    CHECK(inside.cls);
    CHECK(value(fan, inside, "lambda_enter") == below(1));
    CHECK(value(fan, inside, "hits") == 1);
    const Answer edge = fan.run(shot(0.5, 0));  // the edge the first and last triangles share
    CHECK(edge.cls);
    CHECK(value(fan, edge, "hits") == 2);
    const Answer vertex = fan.run(shot(0, 0));  // the shared centre: all four
    CHECK(vertex.cls);
    CHECK(value(fan, vertex, "hits") == 4);
    CHECK_FALSE(fan.run(shot(0.75, 0.75)).cls);  // outside the ring
    CHECK_FALSE(fan.differs(shot(0.25, 0.25), none));
    Inputs flat = shot(-2, 0.25);  // a shot in the fan's plane
    flat[2] = 0, flat[3] = 1, flat[5] = 0;
    CHECK(fan.differs(flat, none));
    Inputs bad = shot(0.25, 0.25);
    bad[6] = 9;
    CHECK_THROWS_AS(fan.run(bad), cdref::invalid_input);
  }
}

}  // namespace test_peers_embree
