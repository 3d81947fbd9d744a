#include "ppp_generator/generator_options.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "generator_option_cases.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/text_file.hpp"

namespace ppp {
namespace generator {
namespace {

std::string errorOf(const GeneratorOptions& o) {
  try {
    o.validate();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(GeneratorOptionsTest, DefaultsAreValid) { EXPECT_EQ(errorOf(GeneratorOptions{}), "no error"); }

TEST(GeneratorOptionsTest, ShippedConfigHoldsTheDefaults) {
  // The node's built-in defaults and config/generator.yaml must not drift apart.
  const GeneratorOptions shipped = loadGeneratorOptions(PPP_CONFIG_DIR "/generator.yaml");
  EXPECT_EQ(generatorOptionsYaml(shipped), generatorOptionsYaml(GeneratorOptions{}));
}

TEST(GeneratorOptionsTest, BadOptionsNameTheOption) {
  GeneratorOptions o;
  o.fitness = "nope";
  EXPECT_EQ(errorOf(o).rfind("fitness: unknown fitness 'nope'; valid: turns, ", 0), 0u);
  o = {};
  o.population = 1;
  EXPECT_EQ(errorOf(o), "population: expected an integer in [2, 100000], got 1");
  o = {};
  o.matings = -1;
  EXPECT_EQ(errorOf(o), "matings: expected an integer in [0, 1000000000], got -1");
  o = {};
  o.width = 1;
  EXPECT_EQ(errorOf(o), "width: expected an integer in [2, 4096], got 1");
  o = {};
  o.height = 5000;
  EXPECT_EQ(errorOf(o), "height: expected an integer in [2, 4096], got 5000");
  o = {};
  o.max_obstacles = -3;
  EXPECT_EQ(errorOf(o), "max_obstacles: expected an integer in [0, 1048576], got -3");
  o = {};
  o.start = Cell{20, 0};
  EXPECT_EQ(errorOf(o), "start: cell (20, 0) is outside the 20x20 grid");
  // The pool's cells: 16 PPPs of 4096 x 4096 are 268,435,456 cells (the limit); a 17th is refused.
  o = {};
  o.width = o.height = 4096;
  o.population = 16;
  EXPECT_EQ(errorOf(o), "no error");
  o.population = 17;
  EXPECT_EQ(errorOf(o), "population: (population 17) x 4096 x 4096 = 285212672 grid cells held at once; at most "
                        "268435456: lower the population or the map size");
  o = {};
  o.population = 100000;  // the largest population fits on the default 20 x 20 map ...
  EXPECT_EQ(errorOf(o), "no error");
  o.width = o.height = 52;  // ... not on 52 x 52: 270,400,000 cells
  EXPECT_EQ(errorOf(o).rfind("population: (population 100000) x 52 x 52 = 270400000 grid cells", 0), 0u);
  o = {};
  o.archive = kMapElitesArchive;
  o.bins = 100;
  o.features = {"turns", "obstacles"};
  o.width = o.height = 1600;  // (60 + 10,000) x 1600^2 = 2.6e10
  EXPECT_EQ(errorOf(o).rfind("population: (population 60 + archive cells 10000) x 1600 x 1600", 0), 0u);
  o = {};
  o.goal = Cell{0, 0};
  EXPECT_EQ(errorOf(o), "goal: must differ from start (0, 0)");
  o = {};
  o.characters = "all";
  EXPECT_EQ(errorOf(o).rfind("characters: unknown character set 'all'", 0), 0u);
  o = {};
  o.tournament_size = 1;
  EXPECT_EQ(errorOf(o), "tournament_size: expected an integer in [2, 100000], got 1");
  o = {};
  o.mutation_rate = 1.5;
  EXPECT_EQ(errorOf(o), "mutation_rate: expected a number in [0, 1], got 1.5");
}

TEST(GeneratorOptionsTest, StringsWithControlCharactersRoundTrip) {
  // Found by generator_yaml_fuzz: a newline inside a single-quoted string was folded into a blank on reading.
  GeneratorOptions o;
  o.agents_file = "a\nb\tc 'd' \"e\" \\f\x7f";
  o.agents = {"x\ny", "plain"};
  const std::string yaml = generatorOptionsYaml(o);
  EXPECT_NE(yaml.find("agents_file: \"a\\x0ab\\x09c 'd' \\\"e\\\" \\\\f\\x7f\""), std::string::npos) << yaml;
  const GeneratorOptions back = parseGeneratorOptions(yaml, "round.yaml");
  EXPECT_EQ(back.agents_file, o.agents_file);
  EXPECT_EQ(back.agents, o.agents);
}

TEST(GeneratorOptionsTest, NullAndBooleanWordsInAnyCaseRoundTrip) {
  // Found by generator_yaml_fuzz: the name NULL in a list of strings was written plain and read back as null.
  GeneratorOptions o;
  o.agents = {"NULL", "Null", "null", "True", "OFF", "Yes", "plain"};
  const std::string yaml = generatorOptionsYaml(o);
  EXPECT_NE(yaml.find("agents: ['NULL', 'Null', 'null', 'True', 'OFF', 'Yes', plain]"), std::string::npos) << yaml;
  EXPECT_EQ(parseGeneratorOptions(yaml, "round.yaml").agents, o.agents);
}

class YamlFile : public ::testing::Test {
 protected:
  std::string write(const std::string& text) {
    std::ofstream(path_) << text;
    return path_;
  }
  void TearDown() override { std::filesystem::remove(path_); }
  std::string path_ = (std::filesystem::temp_directory_path() / "generator_options_test.yaml").string();
};

TEST_F(YamlFile, ReadsEveryKeyAndRoundTrips) {
  GeneratorOptions o;
  o.fitness = "difficulty";
  o.population = 12;
  o.matings = 345;
  o.width = 30;
  o.height = 25;
  o.start = Cell{1, 2};
  o.goal = Cell{28, 20};
  o.max_obstacles = 7;
  o.seed = 99;
  o.characters = "wei";
  o.weights.goal = 0.25;
  o.mutation_rate = 0.3;
  const GeneratorOptions back = loadGeneratorOptions(write(generatorOptionsYaml(o)));
  EXPECT_EQ(generatorOptionsYaml(back), generatorOptionsYaml(o));
  EXPECT_EQ(back.weights.goal, 0.25);
  EXPECT_EQ(back.goalCell(), (Cell{28, 20}));
}

TEST_F(YamlFile, UnknownKeyAndWrongTypeNameFileLineAndKey) {
  try {
    loadGeneratorOptions(write("fitness: turns\npopulaton: 5\n"));
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path_ + ":2: populaton: unknown key; valid keys: ", 0), 0u) << e.what();
  }
  try {
    loadGeneratorOptions(write("fitness: turns\nmatings: many\n"));
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(std::string(e.what()), path_ + ":2: matings: expected an integer, got 'many'");
  }
  try {
    loadGeneratorOptions(write("weights:\n  goal: 1\n  gaol: 2\n"));
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path_ + ":3: weights.gaol: unknown key", 0), 0u) << e.what();
  }
  try {
    loadGeneratorOptions(write("start: [1, 2, 3]\n"));
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(std::string(e.what()), path_ + ":1: start: expected a cell [x, y], got 'a list'");
  }
  EXPECT_THROW(loadGeneratorOptions(write("fitness: [unclosed\n")), ParseError);
  EXPECT_THROW(loadGeneratorOptions("/nonexistent/generator.yaml"), IoError);
}

/// YAML text setting `option` (dotted: a nested mapping) to `value`.
std::string yamlOf(const test::OptionCase& c) {
  const std::size_t dot = c.option.find('.');
  if (dot == std::string::npos) return c.option + ": " + c.value + "\n";
  return c.option.substr(0, dot) + ":\n  " + c.option.substr(dot + 1) + ": " + c.value + "\n";
}

TEST(GeneratorOptionSources, YamlAcceptsAndRefusesWhatEverySourceDoes) {
  // The same cases run against ROS parameters (generator_node_rostest) and flags (option_flags_test).
  const std::vector<test::OptionCase> cases = test::generatorOptionCases();
  EXPECT_GT(cases.size(), 100u);
  for (const test::OptionCase& c : cases) {
    std::string error;
    try {
      parseGeneratorOptions(yamlOf(c), "case.yaml").validate();
    } catch (const Error& e) {
      error = e.what();
    }
    const std::string key = c.option.substr(c.option.find('.') + 1);
    if (c.accepted) {
      EXPECT_EQ(error, "") << c.option << " = " << c.value;
    } else {
      EXPECT_NE(error.find(key + ": "), std::string::npos) << c.option << " = " << c.value << " gave: " << error;
    }
  }
}

TEST(GeneratorOptionSources, TheShippedConfigIsTheDeclarationsDefaults) {
  const std::string shipped = readTextFile(PPP_CONFIG_DIR "/generator.yaml", 1u << 20);
  EXPECT_NE(shipped.find(generatorOptionsYaml(GeneratorOptions{}, true)), std::string::npos)
      << "regenerate config/generator.yaml with `ppp generate --print-options`";
}

}  // namespace
}  // namespace generator
}  // namespace ppp
