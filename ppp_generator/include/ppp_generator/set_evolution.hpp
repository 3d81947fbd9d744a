#pragma once

#include <map>
#include <string>
#include <vector>

#include "ppp_generator/fitness.hpp"
#include "ppp_generator/generator_options.hpp"
#include "ppp_generator/genetic_algorithm.hpp"
#include "ppp_generator/problem_set.hpp"

namespace ppp {
namespace generator {

/// One evolved set and what else belongs in its directory.
struct EvolvedSet {
  ProblemSet set;                                  ///< The PPPs, fittest first.
  std::map<std::string, std::string> extra_files;  ///< File name -> contents (archive.csv, archive.svg).
  std::string summary;                             ///< One line of counters for the user.
};

/// Evolves a set as `options` say with `fitness` (built from options.fitness by makeFitness, or the failure
/// fitness of the episode engine): the genetic algorithm, or the MAP-Elites archive (archive: map_elites).
/// `progress` is called every `progress_interval` matings and at the end.
/// @throws InvalidArgument naming the option; Interrupted when `stop` says stop.
EvolvedSet evolveSet(const GeneratorOptions& options, Fitness fitness, const ProgressCallback& progress = {},
                     long progress_interval = 1000, const StopCheck& stop = {});

/// Evolves a set with evolveSet and writes its directory (writeProblemSetDirectory plus the extra files); when
/// stopped it writes nothing. @throws InvalidArgument, IoError, Interrupted.
EvolvedSet evolveSetDirectory(const std::string& dir, const GeneratorOptions& options, Fitness fitness,
                              const ProgressCallback& progress = {}, const StopCheck& stop = {});

}  // namespace generator
}  // namespace ppp
