#include "ppp_generator/generator_options.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "ppp_core/error.hpp"

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
  EXPECT_EQ(errorOf(o), "population: expected at least 2, got 1");
  o = {};
  o.matings = -1;
  EXPECT_EQ(errorOf(o), "matings: expected a count >= 0, got -1");
  o = {};
  o.width = 1;
  EXPECT_EQ(errorOf(o), "size: expected width and height in [2, 4096], got 1x20");
  o = {};
  o.height = 5000;
  EXPECT_EQ(errorOf(o), "size: expected width and height in [2, 4096], got 20x5000");
  o = {};
  o.max_obstacles = -3;
  EXPECT_EQ(errorOf(o).rfind("max_obstacles: expected a budget in [0, ", 0), 0u);
  o = {};
  o.start = Cell{20, 0};
  EXPECT_EQ(errorOf(o), "start: cell (20, 0) is outside the 20x20 grid");
  o = {};
  o.goal = Cell{0, 0};
  EXPECT_EQ(errorOf(o), "goal: must differ from start (0, 0)");
  o = {};
  o.characters = "all";
  EXPECT_EQ(errorOf(o).rfind("characters: unknown character set 'all'", 0), 0u);
  o = {};
  o.tournament_size = 1;
  EXPECT_EQ(errorOf(o), "tournament_size: expected at least 2, got 1");
  o = {};
  o.mutation_rate = 1.5;
  EXPECT_EQ(errorOf(o).rfind("mutation_rate: expected a probability in [0, 1]", 0), 0u);
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
    EXPECT_EQ(std::string(e.what()), path_ + ":1: start: expected [x, y]");
  }
  EXPECT_THROW(loadGeneratorOptions(write("fitness: [unclosed\n")), ParseError);
  EXPECT_THROW(loadGeneratorOptions("/nonexistent/generator.yaml"), IoError);
}

}  // namespace
}  // namespace generator
}  // namespace ppp
