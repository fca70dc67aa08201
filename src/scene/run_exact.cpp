// src/scene/run_exact.cpp - the exact scene run: rational positions (CGAL::Gmpq) and every
// query at that type, square roots in Quad. The only translation unit of the scene code that
// instantiates an exact type.
#include <cdref/exact/rationals.hpp>

#include "engine.hpp"

namespace cdref::scene {

Run run_exact(const Scene& s) { return engine::Engine<CGAL::Gmpq>(s, Precision::exact).run(); }

}  // namespace cdref::scene
