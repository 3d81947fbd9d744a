#pragma once

#include <map>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "ppp_core/evaluation.hpp"
#include "ppp_core/problem.hpp"
#include "ppp_core/problem_set.hpp"
#include "ppp_generator/genetic_algorithm.hpp"
#include "ppp_generator/generator_options.hpp"
#include "ppp_generator/taxonomy.hpp"

namespace ppp {
namespace generator {

/// The UPGMA taxonomy of a set over one character set.
struct Taxonomy {
  CharacterSet characters = CharacterSet::Extended;  ///< Characters used.
  Eigen::MatrixXd normalised;  ///< One row per PPP, every character scaled to [0, 1] across the set.
  Eigen::MatrixXd distances;   ///< Euclidean distances between rows.
  Tree tree;                   ///< UPGMA tree; leaf i is PPP i.
};

/// Orders the final pool fittest first (stable), names the PPPs and annotates each with its id, the fitness
/// name and value, the generator seed and its characters.
ProblemSet makeProblemSet(const GeneratorOptions& options, const std::vector<Individual>& pool);

/// Builds the taxonomy of a set. @throws InvalidArgument for an empty set.
Taxonomy buildTaxonomy(const ProblemSet& set, CharacterSet characters);

/// Writes the set as a directory: one `.ppp` per PPP, `set.csv`, `generator.yaml`, the tree files and
/// `extra_files` (name -> contents, e.g. a hunt's archive). Everything is written to a temporary sibling
/// directory first and renamed into place, so the directory is either complete or untouched. An existing
/// directory is replaced only if it holds a PPP set.
/// @throws IoError when the directory cannot be written or holds something else.
void writeProblemSetDirectory(const std::string& dir, const ProblemSet& set, const GeneratorOptions& options,
                              const std::map<std::string, std::string>& extra_files = {});

/// Writes a set the generator did not evolve (PPPs shrunk from another set's, say) as writeProblemSetDirectory()
/// does, without generator.yaml: its taxonomy over the default characters. An experiment reads it as a
/// `directory` set. @throws IoError as writeProblemSetDirectory().
void writeDerivedSetDirectory(const std::string& dir, const ProblemSet& set);

/// Checks, before a long run, that `dir` can be created or replaced. @throws IoError saying why not.
void checkOutputDirectory(const std::string& dir);

/// Writes tree.nwk, tree.json and tree.html (with thumbnails) for a set into `dir`. @throws IoError.
void writeTreeFiles(const std::string& dir, const ProblemSet& set, const Taxonomy& taxonomy);

/// The PPP files of a directory (without reading them): those its `set.csv` lists, in its order, when it has one
/// (a set ppp generate or ppp shrink wrote); otherwise every `.ppp`, map_server `.yaml` and MovingAI `.map` file
/// in it, in file-name order (a corpus, or any user's suite).
/// @throws IoError when it is not a readable directory or holds no such file; ParseError naming set.csv, its
/// line and field.
std::vector<std::string> problemSetFiles(const std::string& dir);

/// Every .ppp, map_server .yaml and MovingAI .map file of `dir`, in file-name order (none, possibly).
/// @throws IoError when it is not a readable directory.
std::vector<std::string> problemFilesIn(const std::string& dir);

/// The names of the PPPs in `files` (of the directory `dir`): each file's name without its extension.
/// @throws ParseError naming the second of two files of one name.
std::vector<std::string> problemNames(const std::vector<std::string>& files, const std::string& dir);

/// Reads the PPPs of a directory (problemSetFiles()) as a set and re-evaluates every PPP. A set's PPPs carry their
/// id, fitness and fitness value; a plain directory's are named by their file names without the extension (two
/// files of one name are refused), keep the fitness their metadata gives when every PPP has the same one, and
/// otherwise belong to no fitness (ProblemSet::fitness "", every value 0). A map_server or MovingAI map gets the
/// start and goal `ppp convert` gives it by default. @throws IoError, ParseError naming the file.
ProblemSet readProblemSetDirectory(const std::string& dir);

/// Whether `dir` holds a set written by writeProblemSetDirectory (its set.csv).
bool hasProblemSet(const std::string& dir);

/// Whether the set in `dir` was evolved with `options` (its stored generator.yaml means the same options).
/// @throws IoError, ParseError.
bool evolvedWith(const std::string& dir, const GeneratorOptions& options);

/// A set rebuilt from its PPPs as written or published (each carrying the metadata id, fitness and
/// fitness_value), re-evaluated with `weights`; errors name `source` (a file or topic). @throws ParseError.
ProblemSet problemSetFromProblems(std::vector<Problem> problems, const DifficultyWeights& weights,
                                  const std::string& source);

}  // namespace generator
}  // namespace ppp
