#include "ppp_generator/problem_set.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <numeric>
#include <set>

#include "ppp_core/csv.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/picture.hpp"
#include "ppp_core/ppp_file.hpp"
#include "ppp_core/problem_io.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_generator/diversity.hpp"
#include "ppp_generator/newick.hpp"
#include "ppp_generator/set_csv.hpp"
#include "ppp_generator/tree_json.hpp"
#include "ppp_generator/tree_html.hpp"

namespace ppp {
namespace generator {

namespace fs = std::filesystem;

namespace {

constexpr const char* kSetFile = "set.csv";
constexpr const char* kOptionsFile = "generator.yaml";
constexpr int kThumbnailCellPixels = 4;
constexpr std::size_t kMaxSetCsvBytes = 64u << 20;

/// Fills the set's diversity figures from its PPPs.
void fillDiversity(ProblemSet* set) {
  std::vector<Grid> grids;
  for (const Problem& p : set->problems) grids.push_back(decodeGrid(p));
  DiversityFigures figures = measureDiversity(grids);
  set->nearest = std::move(figures.nearest);
  set->diversity = figures.diversity;
}

std::string idOf(std::size_t index, std::size_t count) {
  const std::size_t digits = std::max<std::size_t>(3, std::to_string(count > 0 ? count - 1 : 0).size());
  const std::string number = std::to_string(index);
  return "ppp_" + std::string(digits > number.size() ? digits - number.size() : 0, '0') + number;
}

std::string readRequiredMetadata(const Problem& p, const std::string& key, const std::string& file) {
  const std::string* value = findMetadata(p.metadata, key);
  if (value == nullptr) throw ParseError(file, 0, "meta " + key, "missing; this file was not written by the generator");
  return *value;
}

void writeText(const fs::path& path, const std::string& text) { writeFileAtomically(path.string(), text); }

/// Moves `problems` into `set`, each evaluated with `weights`, and measures the set's diversity.
/// @throws ParseError naming `source` when the PPPs differ in size.
void fillProblems(ProblemSet* set, std::vector<Problem> problems, const DifficultyWeights& weights,
                  const std::string& source) {
  Evaluator evaluator(weights);
  for (Problem& problem : problems) {
    set->evaluations.push_back(evaluator.evaluate(problem));
    set->problems.push_back(std::move(problem));
  }
  try {
    fillDiversity(set);
  } catch (const InvalidArgument& e) {
    throw ParseError(source, 0, "set", std::string("PPPs of different sizes: ") + e.what());
  }
}

/// The set of `problems` (problem i read from where[i]), re-evaluated with `weights`. @throws ParseError.
ProblemSet buildSet(std::vector<Problem> problems, const std::vector<std::string>& where,
                    const DifficultyWeights& weights, const std::string& source) {
  ProblemSet set;
  for (std::size_t i = 0; i < problems.size(); ++i) {
    const Problem& problem = problems[i];
    set.fitness = readRequiredMetadata(problem, "fitness", where[i]);
    set.ids.push_back(readRequiredMetadata(problem, "id", where[i]));
    const std::string value = readRequiredMetadata(problem, "fitness_value", where[i]);
    char* end = nullptr;
    set.fitness_values.push_back(std::strtod(value.c_str(), &end));
    if (end == value.c_str() || *end != '\0') {
      throw ParseError(where[i], 0, "meta fitness_value", "not a number: " + value);
    }
  }
  fillProblems(&set, std::move(problems), weights, source);
  set.maximise = fitnessMaximises(set.fitness);
  return set;
}

/// The set of a directory without set.csv, problem i read from files[i]: each PPP named by its file's stem, with
/// the fitness its metadata gives when every PPP has the same known one (else none, every value 0).
ProblemSet buildPlainSet(std::vector<Problem> problems, const std::vector<std::string>& files,
                         const DifficultyWeights& weights, const std::string& dir) {
  const std::string* fitness = findMetadata(problems.front().metadata, "fitness");
  std::vector<double> values;
  for (const Problem& problem : problems) {
    const std::string* own = findMetadata(problem.metadata, "fitness");
    const std::string* value = findMetadata(problem.metadata, "fitness_value");
    char* end = nullptr;
    const double number = value != nullptr ? std::strtod(value->c_str(), &end) : 0;
    if (fitness == nullptr || own == nullptr || *own != *fitness || value == nullptr || end == value->c_str() ||
        *end != '\0') {
      fitness = nullptr;
      break;
    }
    values.push_back(number);
  }
  ProblemSet set;
  if (fitness != nullptr) {
    try {
      set.maximise = fitnessMaximises(*fitness);
      set.fitness = *fitness;
      set.fitness_values = values;
    } catch (const InvalidArgument&) {
      fitness = nullptr;  // a fitness this version does not know: none
    }
  }
  if (fitness == nullptr) set.fitness_values.assign(problems.size(), 0.0);
  set.ids = problemNames(files, dir);
  fillProblems(&set, std::move(problems), weights, dir);
  return set;
}

}  // namespace

std::vector<std::string> problemFilesIn(const std::string& dir) {
  std::error_code error;
  if (!fs::is_directory(dir, error)) throw IoError(dir, "is not a directory of PPP files");
  std::vector<std::string> files;
  for (fs::directory_iterator it(dir, error), end; !error && it != end; it.increment(error)) {
    const std::string extension = fileExtension(it->path().string());
    if ((extension == ".ppp" || extension == ".yaml" || extension == ".map") && it->is_regular_file(error)) {
      files.push_back(it->path().string());
    }
  }
  if (error) throw IoError(dir, "cannot list it: " + error.message());
  std::sort(files.begin(), files.end());
  return files;
}

namespace {

/// problemFilesIn(), refusing a directory without a PPP file. @throws IoError.
std::vector<std::string> mapFilesIn(const std::string& dir) {
  std::vector<std::string> files = problemFilesIn(dir);
  if (files.empty()) throw IoError(dir, "holds no PPP: no .ppp, map_server .yaml or MovingAI .map file");
  return files;
}

}  // namespace

ProblemSet makeProblemSet(const GeneratorOptions& options, const std::vector<Individual>& pool) {
  std::vector<int> order(pool.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return pool[a].score > pool[b].score; });
  ProblemSet set;
  set.fitness = options.fitness;
  set.maximise = fitnessMaximises(options.fitness);
  Evaluator evaluator(options.weights);
  for (std::size_t rank = 0; rank < order.size(); ++rank) {
    const Individual& individual = pool[order[rank]];
    Problem problem = individual.problem;
    const Evaluation evaluation = evaluator.evaluate(problem);
    const std::string id = idOf(rank, order.size());
    problem.metadata.clear();
    setMetadata(&problem.metadata, "id", id);
    setMetadata(&problem.metadata, "fitness", options.fitness);
    setMetadata(&problem.metadata, "fitness_value", formatNumber(individual.value));
    setMetadata(&problem.metadata, "generator_seed", std::to_string(options.seed));
    const auto values = characterVector(evaluation);
    for (std::size_t c = 0; c < values.size(); ++c) {
      setMetadata(&problem.metadata, "character." + characterNames()[c], formatNumber(values[c]));
    }
    set.ids.push_back(id);
    set.problems.push_back(std::move(problem));
    set.evaluations.push_back(evaluation);
    set.fitness_values.push_back(individual.value);
  }
  fillDiversity(&set);
  return set;
}

Taxonomy buildTaxonomy(const ProblemSet& set, CharacterSet characters) {
  if (set.problems.empty()) throw InvalidArgument("set", "no PPPs to build a taxonomy of");
  Taxonomy taxonomy;
  taxonomy.characters = characters;
  const Eigen::MatrixXd raw = characters == CharacterSet::Barn ? barnCharacterMatrix(set.problems)
                                                               : characterMatrix(set.evaluations, characters);
  taxonomy.normalised = normaliseColumns(raw);
  taxonomy.distances = euclideanDistances(taxonomy.normalised);
  taxonomy.tree = upgma(taxonomy.distances);
  return taxonomy;
}

void writeTreeFiles(const std::string& dir, const ProblemSet& set, const Taxonomy& taxonomy) {
  const fs::path root(dir);
  writeText(root / "tree.nwk", toNewick(taxonomy.tree, set.ids) + "\n");
  writeText(root / "tree.json", treeToJson(taxonomy.tree, set.ids).dump(1) + "\n");
  PictureOptions thumbnail;
  thumbnail.cell_pixels = kThumbnailCellPixels;
  thumbnail.grid_lines = false;
  std::vector<std::string> thumbnails;
  for (const Problem& problem : set.problems) {
    thumbnails.push_back(encodePng(renderProblemRgb(problem, {}, thumbnail), pictureWidth(problem.width, thumbnail),
                                   pictureHeight(problem.height, thumbnail)));
  }
  const std::string title = "PPP taxonomy: " + std::to_string(set.problems.size()) + " PPPs, fitness " +
                            set.fitness + ", " + characterSetName(taxonomy.characters) + " characters";
  writeText(root / "tree.html", treeHtml(taxonomy.tree, set.ids, thumbnails, title));
}

void checkOutputDirectory(const std::string& dir) {
  const fs::path root(dir);
  std::error_code error;
  if (fs::exists(root, error)) {
    if (!fs::is_directory(root)) throw IoError(dir, "exists and is not a directory");
    if (!fs::is_empty(root, error) && !fs::exists(root / kSetFile)) {
      throw IoError(dir, "holds files but no " + std::string(kSetFile) + "; refusing to replace something that is "
                         "not a PPP set");
    }
  }
  const fs::path parent = root.has_parent_path() ? root.parent_path() : fs::path(".");
  fs::create_directories(parent, error);
  const fs::path probe = parent / (root.filename().string() + ".write-check");
  if (!fs::create_directory(probe, error) && !fs::exists(probe)) {
    throw IoError(dir, "cannot create the output directory: " + error.message());
  }
  fs::remove(probe, error);
}

namespace {

/// writeProblemSetDirectory(), with generator.yaml only when `options` is given (the taxonomy over the default
/// characters otherwise).
void writeSetDirectory(const std::string& dir, const ProblemSet& set, const GeneratorOptions* options,
                       const std::map<std::string, std::string>& extra_files) {
  checkOutputDirectory(dir);
  const fs::path root(dir);
  const fs::path parent = root.has_parent_path() ? root.parent_path() : fs::path(".");
  const fs::path staging = parent / (root.filename().string() + ".partial");
  std::error_code error;
  fs::remove_all(staging, error);
  if (!fs::create_directory(staging, error)) throw IoError(staging.string(), "cannot create: " + error.message());
  {
    CsvWriter csv((staging / kSetFile).string(), setCsvHeader());
    for (std::size_t i = 0; i < set.problems.size(); ++i) {
      const std::string file = set.ids[i] + ".ppp";
      writePppFile(set.problems[i], (staging / file).string());
      std::vector<std::string> row{set.ids[i], file, set.fitness, formatNumber(set.fitness_values[i])};
      for (double value : characterVector(set.evaluations[i])) row.push_back(formatNumber(value));
      row.push_back(formatNumber(set.nearest[i]));
      csv.write(row);
    }
  }
  if (options != nullptr) writeText(staging / kOptionsFile, generatorOptionsYaml(*options));
  for (const auto& [name, contents] : extra_files) writeText(staging / name, contents);
  const GeneratorOptions defaults;
  const std::string& characters = (options != nullptr ? *options : defaults).characters;
  writeTreeFiles(staging.string(), set, buildTaxonomy(set, parseCharacterSet(characters)));
  if (fs::exists(root)) fs::remove_all(root, error);
  fs::rename(staging, root, error);
  if (error) throw IoError(dir, "cannot move the finished set into place: " + error.message());
}

}  // namespace

void writeProblemSetDirectory(const std::string& dir, const ProblemSet& set, const GeneratorOptions& options,
                              const std::map<std::string, std::string>& extra_files) {
  writeSetDirectory(dir, set, &options, extra_files);
}

void writeDerivedSetDirectory(const std::string& dir, const ProblemSet& set) { writeSetDirectory(dir, set, nullptr, {}); }

std::vector<std::string> problemNames(const std::vector<std::string>& files, const std::string& dir) {
  std::vector<std::string> names;
  std::set<std::string> seen;
  for (const std::string& file : files) {
    names.push_back(fs::path(file).stem().string());
    if (!seen.insert(names.back()).second) {
      throw ParseError(file, 0, "file",
                       "a second PPP named '" + names.back() + "' in " + dir + " (a directory's PPPs are named by "
                       "their file names without the extension)");
    }
  }
  return names;
}

std::vector<std::string> problemSetFiles(const std::string& dir) {
  if (!hasProblemSet(dir)) return mapFilesIn(dir);
  const fs::path root(dir);
  const std::string csv_path = (root / kSetFile).string();
  std::vector<std::string> files = parseSetCsv(readTextFile(csv_path, kMaxSetCsvBytes), csv_path);
  for (std::string& file : files) file = (root / file).string();
  return files;
}

ProblemSet readProblemSetDirectory(const std::string& dir) {
  const fs::path root(dir);
  const std::vector<std::string> files = problemSetFiles(dir);
  GeneratorOptions options;
  if (fs::exists(root / kOptionsFile)) options = loadGeneratorOptions((root / kOptionsFile).string());
  std::vector<Problem> problems;
  if (!hasProblemSet(dir)) {
    for (const std::string& file : files) problems.push_back(readProblemFile(file));
    return buildPlainSet(std::move(problems), files, options.weights, dir);
  }
  for (const std::string& file : files) problems.push_back(readPppFile(file));
  return buildSet(std::move(problems), files, options.weights, (root / kSetFile).string());
}

bool hasProblemSet(const std::string& dir) { return fs::exists(fs::path(dir) / kSetFile); }

bool evolvedWith(const std::string& dir, const GeneratorOptions& options) {
  const fs::path file = fs::path(dir) / kOptionsFile;
  if (!fs::exists(file)) return false;
  return generatorOptionsYaml(loadGeneratorOptions(file.string())) == generatorOptionsYaml(options);
}

ProblemSet problemSetFromProblems(std::vector<Problem> problems, const DifficultyWeights& weights,
                                  const std::string& source) {
  if (problems.empty()) throw ParseError(source, 0, "set", "holds no PPPs");
  const std::vector<std::string> sources(problems.size(), source);
  return buildSet(std::move(problems), sources, weights, source);
}

}  // namespace generator
}  // namespace ppp
