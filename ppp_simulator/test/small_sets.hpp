#pragma once

#include <vector>

#include "ppp_simulator/experiment_config.hpp"

namespace ppp {
namespace simulator {

/// Two small evolved sets for tests, `turns` and `difficulty`: population 4, `matings` matings, side x side maps.
inline std::vector<SetSpec> smallSetSpecs(int matings, int side) {
  std::vector<SetSpec> specs;
  for (const char* name : {"turns", "difficulty"}) {
    generator::GeneratorOptions g;
    g.fitness = name;
    g.population = 4;
    g.matings = matings;
    g.width = g.height = side;
    specs.push_back(SetSpec{name, g, ""});
  }
  return specs;
}

}  // namespace simulator
}  // namespace ppp
