// tests/test_peers_fcl.cpp - the FCL adapters of `cdref peers` (src/peers/fcl.cpp) on hand cases
// whose exact answers are known: what FCL answers, and which cases each adapter's convention sets
// apart. Built where FCL is (libfcl-dev).
#include <catch2/catch.hpp>

#include "peers/fcl.hpp"
#include "peers_hand.hpp"

namespace test_peers_fcl {

using namespace cdref::peers;
using test_peers::adapter;
using test_peers::of;
using test_peers::values;

// the exact answer's classification, as the engine passes it to a convention test
Answer truth(bool cls) {
  Answer t{};
  t.cls = t.pred = cls;
  return t;
}
const double tiny = 0x1p-40;

// two unit-extent boxes on the identity frame, the second at (x, 0, 0)
Inputs boxes(double x) {
  return of({0, 0, 0, 1, 1, 1, 1, 0, 0, 0, 1, 0, 0, 0, 1, x, 0, 0, 1, 1, 1, 1, 0, 0, 0, 1, 0, 0, 0, 1});
}

TEST_CASE("FCL's adapters: hand cases with known answers, and the cases their conventions set apart", "[peers][fcl]") {
  const std::vector<Adapter> all = fcl_adapters();
  REQUIRE(all.size() == 7);
  for (const Adapter& a : all) CHECK(a.precision == 53);

  SECTION("obb-obb: OBB<double>::overlap and its 1e-6 margin") {
    const Adapter& a = adapter(all, "obb-obb");
    CHECK(a.run(boxes(2)).cls);  // touching faces
    CHECK_FALSE(a.run(boxes(3)).cls);
    CHECK_FALSE(a.differs(boxes(2), truth(true)));
    CHECK_FALSE(a.differs(boxes(3), truth(false)));
    // apart by 1e-7 along x: FCL's margin (1e-6 |R|-entries times the extents) calls it an overlap,
    // which is its convention, set apart; at 1e-5 both say apart
    CHECK(a.run(boxes(2 + 1e-7)).cls);
    CHECK(a.differs(boxes(2 + 1e-7), truth(false)));
    CHECK_FALSE(a.run(boxes(2 + 1e-5)).cls);
    CHECK_FALSE(a.differs(boxes(2 + 1e-5), truth(false)));
  }
  SECTION("triangle-box: fcl::collide with each solver") {
    for (const char* solver : {"GST_LIBCCD", "GST_INDEP"}) {
      const Adapter& a = adapter(all, "triangle-box", solver);
      INFO(solver);
      CHECK(a.run(of({-1, -1, 0.5, 1, -1, 0.5, 0, 1, 0.5, 0, 0, 0, 1, 1, 1})).cls);  // through the box
      CHECK_FALSE(a.run(of({-1, -1, 1.5, 1, -1, 1.5, 0, 1, 1.5, 0, 0, 0, 1, 1, 1})).cls);  // above it
      CHECK_FALSE(a.differs(of({-1, -1, 1.5, 1, -1, 1.5, 0, 1, 1.5, 0, 0, 0, 1, 1, 1}), truth(false)));
      CHECK_THROWS_AS(a.run(of({-1, -1, 0.5, 1, -1, 0.5, 0, 1, 0.5, 0, 0, 0, 1e308, 1, 1})), cdref::invalid_input);
    }
  }
  SECTION("triangle-triangle") {
    const Adapter& a = adapter(all, "triangle-triangle");
    CHECK(a.run(of({-1, -1, 0, 1, -1, 0, 0, 1, 0, 0, 0, -1, 0, 0, 1, 0.1, 0.1, 1})).cls);  // piercing
    CHECK_FALSE(a.run(of({-1, -1, 0, 1, -1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 2, 0.1, 0.1, 2})).cls);  // above
  }
  SECTION("sphere-triangle: contact, depth, distance, and FCL's epsilon-grown radius") {
    const Adapter& a = adapter(all, "sphere-triangle");
    const Inputs half = of({0, 0, 0.5, 1, -4, -4, 0, 4, -4, 0, 0, 4, 0});
    const Answer r = a.run(half);
    CHECK(r.cls);
    CHECK(values(a, r, "depth") == std::vector<double>{0.5});
    CHECK(values(a, r, "distance") == std::vector<double>{0});
    const Answer apart = a.run(of({0, 0, 3, 1, -4, -4, 0, 4, -4, 0, 0, 4, 0}));
    CHECK_FALSE(apart.cls);
    CHECK(values(a, apart, "distance") == std::vector<double>{2});
    CHECK_FALSE(a.differs(half, truth(true)));
    // touching at r = 4, where r + 2^-52 rounds to r: FCL's strict test says apart, the closed
    // solids touch: set apart
    const Inputs touching = of({0, 0, 4, 4, -4, -4, 0, 4, -4, 0, 0, 4, 0});
    CHECK_FALSE(a.run(touching).cls);
    CHECK(a.differs(touching, truth(true)));
    // at r = 0.5 the grown radius 0.5 + 2^-52 reaches across a gap of 2^-53: FCL's contact,
    // cdref's miss, set apart
    const Inputs gap = of({0, 0, 0.5 + 0x1p-53, 0.5, -4, -4, 0, 4, -4, 0, 0, 4, 0});
    CHECK(a.run(gap).cls);
    CHECK(a.differs(gap, truth(false)));
    CHECK_FALSE(a.differs(of({0, 0, 0.5 + tiny, 0.5, -4, -4, 0, 4, -4, 0, 0, 4, 0}), truth(false)));
    // a zero-area triangle far away: FCL's contact with any sphere, set apart
    CHECK(a.differs(of({0, 0, 0, 1, 0, 0, 10, 1, 0, 10, 2, 0, 10}), truth(false)));
  }
  SECTION("sphere-box and sphere-sphere: touching, half-way, apart") {
    const Adapter& b = adapter(all, "sphere-box");
    const Answer touching = b.run(of({2, 0, 0, 1, 0, 0, 0, 1, 1, 1}));
    CHECK(touching.cls);
    CHECK(values(b, touching, "depth") == std::vector<double>{0});
    CHECK(values(b, b.run(of({1.5, 0, 0, 1, 0, 0, 0, 1, 1, 1})), "depth") == std::vector<double>{0.5});
    CHECK(values(b, b.run(of({0.5, 0, 0, 1, 0, 0, 0, 1, 1, 1})), "depth") == std::vector<double>{1.5});
    const Answer far = b.run(of({2.5, 0, 0, 1, 0, 0, 0, 1, 1, 1}));
    CHECK_FALSE(far.cls);
    CHECK(values(b, far, "distance") == std::vector<double>{0.5});
    const Adapter& s = adapter(all, "sphere-sphere");
    CHECK(s.run(of({0, 0, 0, 1, 2, 0, 0, 1})).cls);
    CHECK(values(s, s.run(of({0, 0, 0, 1, 1.5, 0, 0, 1})), "depth") == std::vector<double>{0.5});
    CHECK(values(s, s.run(of({0, 0, 0, 1, 0, 0, 0, 1})), "depth") == std::vector<double>{2});  // concentric
    CHECK(values(s, s.run(of({0, 0, 0, 1, 2.5, 0, 0, 1})), "distance") == std::vector<double>{0.5});
  }
}

}  // namespace test_peers_fcl
