// tests/test_peers_open3d.cpp - the Open3D adapters of `cdref peers` (src/peers/open3d.cpp) on hand
// cases whose exact answers are known: the closest point and distance RaycastingScene gives, the
// case its float routine would abort the process on (refused by name, the process going on), and
// what its ray cast answers on Debian. Built where Open3D is (libopen3d-dev).
#include <catch2/catch.hpp>

#include "peers/open3d.hpp"
#include "peers_hand.hpp"

namespace test_peers_open3d {

using namespace cdref::peers;
using test_peers::adapter;
using test_peers::of;
using test_peers::values;

const Answer none{};

TEST_CASE("Open3D's adapters: hand cases with known answers, and the cases they refuse", "[peers][open3d]") {
  const std::vector<Adapter> all = open3d_adapters();
  REQUIRE(all.size() == 3);
  for (const Adapter& a : all) CHECK(a.precision == 24);

  SECTION("point-triangle: closest point and distance") {
    const Adapter& a = adapter(all, "point-triangle");
    const Answer above = a.run(of({0.25, 0.25, 2, 0, 0, 0, 1, 0, 0, 0, 1, 0}));
    CHECK_FALSE(above.cls);
    CHECK(values(a, above, "distance") == std::vector<double>{2});
    CHECK(values(a, above, "witness_b") == std::vector<double>{0.25, 0.25, 0});
    const Answer beyond = a.run(of({3, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0}));  // the vertex v1 is closest
    CHECK(values(a, beyond, "distance") == std::vector<double>{2});
    CHECK(values(a, beyond, "witness_b") == std::vector<double>{1, 0, 0});
    CHECK(a.run(of({0.25, 0.25, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0})).cls);  // on the triangle
    CHECK_FALSE(a.differs(of({0.25, 0.25, 2, 0, 0, 0, 1, 0, 0, 0, 1, 0}), none));
    // coordinates near 6e9 overflow a product of its float walk (va = d3 d6 - d5 d4), and its
    // Eigen assertion would end the process: refused by name instead
    CHECK_THROWS_WITH(a.run(of({-4066283075.5, -4060217505, 430058015, -2040325228, -5991736128, -204868286,
                                -6092240923, -2128698882, 1064984316, -2839398422, -6408484210, 7502849739})),
                      Catch::Contains("Open3D's closest-point routine would abort"));
    // two equal vertices (v0 = v1) and a point beside the edge to v2: the walk takes the zero edge
    // v0 v1 and divides 0 by 0, refused as well
    CHECK_THROWS_WITH(a.run(of({1, 0.5, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0})), Catch::Contains("would abort"));
  }
  SECTION("ray-triangle-cast: on Debian every ray misses (each ray's mask is 0)") {
    const Adapter& a = adapter(all, "ray-triangle-cast");
    CHECK_FALSE(a.run(of({0.25, 0.25, -1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0})).cls);  // through the middle
    CHECK(a.differs(of({-1, 0.25, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0}), none));     // in the plane
    CHECK(a.differs(of({0, 0, -1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 2, 0, 0}), none));        // zero area
    CHECK_FALSE(a.differs(of({0.25, 0.25, -1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0}), none));
    // on a closed fan (a square pyramid's four sides round the apex), a shot at the apex: no hit
    // either, a leak at the mesh level
    const Adapter& f = adapter(all, "ray-fan-cast");
    const Inputs apex = of({0, 0, 5, 0, 0, -1, 4, 1, 0, 0, 1, 1, 1, -1, 1, -1, -1, -1, -1, -1, -1, 1, -1});
    CHECK_FALSE(f.run(apex).cls);
    CHECK_FALSE(f.differs(apex, none));
  }
}

}  // namespace test_peers_open3d
