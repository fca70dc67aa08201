// src/scene/run_float.cpp - scene runs at float and double (the engine's float instantiations).
#include "engine.hpp"

namespace cdref::scene {

Run run_exact(const Scene& s);  // run_exact.cpp

Run run_scene(const Scene& s, Precision p) {
  switch (p) {
    case Precision::float_: return engine::Engine<float>(s, p).run();
    case Precision::double_: return engine::Engine<double>(s, p).run();
    case Precision::exact: return run_exact(s);
  }
  throw std::logic_error("run_scene: unknown precision");
}

}  // namespace cdref::scene
