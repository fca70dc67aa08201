// tests/test_peers_rapier.cpp - the Rapier adapters of `cdref peers` (src/peers/rapier.hpp) on hand
// cases whose exact answers are known: what Rapier's WebAssembly build answers through its node
// process, alone and a block at a time, the case its convention sets apart, and a request it
// refuses by name. Built where node and the package are (scripts/deps.sh).
#include <catch2/catch.hpp>

#include "peers/rapier.hpp"
#include "peers_hand.hpp"

namespace test_peers_rapier {

using namespace cdref::peers;
using test_peers::adapter;
using test_peers::of;
using test_peers::values;

const Answer none{};

TEST_CASE("Rapier's adapters: hand cases with known answers, alone and told as a block", "[peers][rapier]") {
  const std::vector<Adapter> all = rapier::adapters();
  REQUIRE(all.size() == 9);
  for (const Adapter& a : all) {
    CHECK(a.precision == 24);
    CHECK(a.prefetch);
  }
  CHECK(rapier::node().version() == CDREF_RAPIER_VERSION);

  SECTION("ray-sphere-cast") {
    const Adapter& a = adapter(all, "ray-sphere-cast");
    const Answer r = a.run(of({0, 0, -5, 0, 0, 1, 0, 0, 0, 1}));
    CHECK(r.cls);
    CHECK(values(a, r, "lambda_enter") == std::vector<double>{4});
    CHECK(values(a, r, "normal") == std::vector<double>{0, 0, -1});
    CHECK_FALSE(a.run(of({0, 0, 5, 0, 0, 1, 0, 0, 0, 1})).cls);  // behind the source
    CHECK(a.differs(of({0, 0, 0, 0, 0, 1, 0, 0, 0, 1}), none));   // a source inside: set apart
    CHECK(a.differs(of({0, 0, -1, 0, 0, 1, 0, 0, 0, 1}), none));  // and on the sphere
    CHECK_FALSE(a.differs(of({0, 0, -1.5, 0, 0, 1, 0, 0, 0, 1}), none));
  }
  SECTION("ray-box-cast and ray-triangle-cast") {
    const Adapter& b = adapter(all, "ray-box-cast");
    const Answer r = b.run(of({-5, 0.5, 0.25, 1, 0, 0, 0, 0, 0, 1, 1, 1}));
    CHECK(r.cls);
    CHECK(values(b, r, "lambda_enter") == std::vector<double>{4});
    CHECK(values(b, r, "normal") == std::vector<double>{-1, 0, 0});
    const Answer inside = b.run(of({0, 0, 0, 1, 0, 0, 0, 0, 0, 1, 1, 1}));
    CHECK(values(b, inside, "lambda_enter") == std::vector<double>{0});
    CHECK(values(b, inside, "normal") == std::vector<double>{0, 0, 0});
    const Adapter& t = adapter(all, "ray-triangle-cast");
    const Answer h = t.run(of({0.25, 0.25, -1, 0, 0, 2, 0, 0, 0, 1, 0, 0, 0, 1, 0}));
    CHECK(h.cls);
    CHECK(values(t, h, "lambda_enter") == std::vector<double>{0.5});
    CHECK_FALSE(t.run(of({-0.25, 0.25, -1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0})).cls);
    CHECK(t.differs(of({-1, 0.25, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0}), none));  // in the plane
  }
  SECTION("proximities: touching, half-way, apart") {
    const Adapter& s = adapter(all, "sphere-sphere");
    CHECK(s.run(of({0, 0, 0, 1, 2, 0, 0, 1})).cls);
    CHECK(values(s, s.run(of({0, 0, 0, 1, 1.5, 0, 0, 1})), "depth") == std::vector<double>{0.5});
    const Answer apart = s.run(of({0, 0, 0, 1, 2.5, 0, 0, 1}));
    CHECK_FALSE(apart.cls);
    CHECK(values(s, apart, "distance") == std::vector<double>{0.5});
    const Adapter& b = adapter(all, "sphere-box");
    CHECK(values(b, b.run(of({1.5, 0, 0, 1, 0, 0, 0, 1, 1, 1})), "depth") == std::vector<double>{0.5});
    CHECK_FALSE(b.run(of({2.5, 0, 0, 1, 0, 0, 0, 1, 1, 1})).cls);
    const Adapter& t = adapter(all, "sphere-triangle");
    const Answer h = t.run(of({0, 0, 0.5, 1, -4, -4, 0, 4, -4, 0, 0, 4, 0}));
    CHECK(h.cls);
    CHECK(values(t, h, "depth") == std::vector<double>{0.5});
    CHECK(values(t, t.run(of({0, 0, 3, 1, -4, -4, 0, 4, -4, 0, 0, 4, 0})), "distance") == std::vector<double>{2});
  }
  SECTION("intersection tests, alone and told as a block (the same answers, in the block's order)") {
    const Adapter& bb = adapter(all, "box-box");
    const std::vector<Inputs> cases = {of({0, 0, 0, 1, 1, 1, 2, 0.5, 0, 1, 1, 1}), of({0, 0, 0, 1, 1, 1, 3, 0, 0, 1, 1, 1}),
                                       of({0, 0, 0, 1, 1, 1, 2, 2, 2, 1, 1, 1})};
    std::vector<bool> alone;
    for (const Inputs& c : cases) alone.push_back(bb.run(c).cls);
    CHECK(alone == std::vector<bool>{true, false, true});
    bb.prefetch(cases.data(), cases.size());
    for (std::size_t k = 0; k < cases.size(); ++k) CHECK(bb.run(cases[k]).cls == alone[k]);
    const Adapter& tb = adapter(all, "triangle-box");
    CHECK(tb.run(of({-1, -1, 0.5, 1, -1, 0.5, 0, 1, 0.5, 0, 0, 0, 1, 1, 1})).cls);
    CHECK_FALSE(tb.run(of({-1, -1, 1.5, 1, -1, 1.5, 0, 1, 1.5, 0, 0, 0, 1, 1, 1})).cls);
    const Adapter& tt = adapter(all, "triangle-triangle");
    CHECK(tt.run(of({-1, -1, 0, 1, -1, 0, 0, 1, 0, 0, 0, -1, 0, 0, 1, 0.1, 0.1, 1})).cls);
    CHECK_FALSE(tt.run(of({-1, -1, 0, 1, -1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 2, 0.1, 0.1, 2})).cls);
  }
  SECTION("a request the process cannot read is refused by its message; the process goes on") {
    CHECK_THROWS_WITH(rapier::node().ask("bb", {1, 2}), Catch::Contains("Rapier refused the case: 'bb' takes 12 numbers"));
    CHECK_THROWS_WITH(rapier::node().ask("nope", {}), Catch::Contains("unknown operation"));
    CHECK(rapier::node().version() == CDREF_RAPIER_VERSION);
  }
}

}  // namespace test_peers_rapier
