#pragma once

#include <string>
#include <vector>

#include "ppp_generator/breeder.hpp"
#include "ppp_generator/generator_options.hpp"

namespace ppp {
namespace generator {

/// The PPPs a search starts from when options.initial_pool names a directory: its PPP files (problemSetFiles():
/// a set's in its order, else every .ppp, map_server .yaml and MovingAI .map in file-name order), decoded by `breeder` (scored when the fitness is not batched), repeats skipped, at most
/// options.population of them; empty when options.initial_pool is empty.
/// @throws InvalidArgument("initial_pool", ...) naming the file when a PPP's size, start or goal differ from
/// the options', it holds more descriptors than max_obstacles or the robot cannot reach its goal, and when the
/// directory cannot be listed or holds no PPP file; ParseError for a malformed file.
std::vector<Individual> initialPoolIndividuals(const GeneratorOptions& options, Breeder* breeder);

}  // namespace generator
}  // namespace ppp
