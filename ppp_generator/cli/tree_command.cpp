#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <string>

#include "generator_commands.hpp"
#include "option_flags.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/ppp_file.hpp"
#include "ppp_generator/diverse_selection.hpp"
#include "ppp_generator/generator_options.hpp"
#include "ppp_generator/newick.hpp"
#include "ppp_generator/problem_set.hpp"

namespace ppp {
namespace cli {

namespace {

/// The generator's `characters` option, as tree and select take it (--characters, its choices and default).
const std::vector<OptionSpec<generator::GeneratorOptions>>& characterSpecs() {
  static const std::vector<OptionSpec<generator::GeneratorOptions>> specs =
      selectOptions(generator::generatorOptionSpecs(), {"characters"});
  return specs;
}

/// The character set given with --characters (the option's default when not given). @throws InvalidArgument.
std::string characterFlag(const CLI::App& command, const std::map<std::string, std::string>& given) {
  generator::GeneratorOptions options;
  applyOptionFlags(command, characterSpecs(), given, &options);
  return options.characters;
}

struct TreeFlags {
  CLI::App* command = nullptr;
  std::string dir;
  std::map<std::string, std::string> options;  ///< --characters, when given.
};

struct SelectFlags {
  CLI::App* command = nullptr;
  std::string dir;
  int k = 0;
  std::string prefer = "medoid";
  std::map<std::string, std::string> options;  ///< --characters, when given.
  std::string copy_to;
};

void runTree(const TreeFlags& f) {
  const std::string names = characterFlag(*f.command, f.options);
  const auto characters = generator::parseCharacterSet(names);
  const ProblemSet set = generator::readProblemSetDirectory(f.dir);
  const generator::Taxonomy taxonomy = generator::buildTaxonomy(set, characters);
  generator::writeTreeFiles(f.dir, set, taxonomy);
  std::cout << generator::toNewick(taxonomy.tree, set.ids) << "\n";
  std::cerr << "wrote tree.nwk, tree.json and tree.html (" << names << " characters) to " << f.dir << "\n";
}

void runSelect(const SelectFlags& f) {
  const auto characters = generator::parseCharacterSet(characterFlag(*f.command, f.options));
  if (f.prefer != "medoid" && f.prefer != "hardest") {
    throw InvalidArgument("--prefer", "expected medoid or hardest, got '" + f.prefer + "'");
  }
  const ProblemSet set = generator::readProblemSetDirectory(f.dir);
  const generator::Taxonomy taxonomy = generator::buildTaxonomy(set, characters);
  const std::vector<double> hardness = set.hardness();
  const auto chosen =
      generator::selectDiverse(taxonomy.tree, taxonomy.distances, f.k, f.prefer == "hardest" ? &hardness : nullptr);
  if (!f.copy_to.empty()) std::filesystem::create_directories(f.copy_to);
  for (int index : chosen) {
    std::cout << set.ids[index] << ".ppp\n";
    if (!f.copy_to.empty()) {
      writePppFile(set.problems[index], (std::filesystem::path(f.copy_to) / (set.ids[index] + ".ppp")).string());
    }
  }
}

}  // namespace

void addTreeCommand(CLI::App& app) {
  auto flags = std::make_shared<TreeFlags>();
  CLI::App* command =
      app.add_subcommand("tree", "Rebuild a set's UPGMA taxonomy (tree.nwk, tree.json, tree.html) over a character set");
  command->add_option("dir", flags->dir, "Set directory written by ppp generate")->required();
  static const generator::GeneratorOptions defaults;
  addOptionFlags(command, characterSpecs(), &defaults, &flags->options);
  flags->command = command;
  command->callback([flags] { runTree(*flags); });
}

void addSelectCommand(CLI::App& app) {
  auto flags = std::make_shared<SelectFlags>();
  CLI::App* command = app.add_subcommand(
      "select", "Pick k diverse PPPs: cut the taxonomy into k clusters and take one representative of each");
  command->add_option("dir", flags->dir, "Set directory written by ppp generate")->required();
  command->add_option("-k", flags->k, "Number of PPPs to pick")->required();
  command->add_option("--prefer", flags->prefer, "Representative: medoid (most central) or hardest (best fitness)")
      ->capture_default_str();
  static const generator::GeneratorOptions defaults;
  addOptionFlags(command, characterSpecs(), &defaults, &flags->options);
  flags->command = command;
  command->add_option("--copy-to", flags->copy_to, "Also copy the picked .ppp files into this directory");
  command->callback([flags] { runSelect(*flags); });
}

}  // namespace cli
}  // namespace ppp
