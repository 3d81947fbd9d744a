#include "ppp_core/yaml_reader.hpp"

#include <gtest/gtest.h>

namespace ppp {
namespace {

TEST(YamlReaderTest, ReadsKnownKeysAndRejectsUnknownOnes) {
  const YAML::Node root = YAML::Load("runs: 12\nname: demo\nrate: 0.5\nextra: 1\n");
  YamlMapReader reader(root, "x.yaml");
  int runs = 0;
  std::string name;
  double rate = 0;
  bool flag = false;
  EXPECT_TRUE(reader.read("runs", &runs));
  EXPECT_TRUE(reader.read("name", &name));
  EXPECT_TRUE(reader.read("rate", &rate));
  EXPECT_FALSE(reader.read("flag", &flag));
  EXPECT_EQ(runs, 12);
  EXPECT_EQ(name, "demo");
  EXPECT_EQ(rate, 0.5);
  try {
    reader.rejectUnknownKeys();
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(std::string(e.what()), "x.yaml:4: extra: unknown key; valid keys: flag, name, rate, runs");
  }
}

TEST(YamlReaderTest, WrongTypeNamesLineAndExpectation) {
  const YAML::Node root = YAML::Load("a: 1\nsub:\n  runs: lots\n");
  YamlMapReader top(root, "y.yaml");
  YamlMapReader sub(top.lookup("sub"), "y.yaml", "sub");
  int runs = 0;
  try {
    sub.read("runs", &runs);
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(std::string(e.what()), "y.yaml:3: sub.runs: expected an integer, got 'lots'");
  }
}

TEST(YamlReaderTest, NotAMappingAndBadSyntax) {
  EXPECT_THROW(YamlMapReader(YAML::Load("- 1\n- 2\n"), "z.yaml"), ParseError);
  EXPECT_THROW(loadYamlFile("/nonexistent.yaml"), IoError);
}

TEST(YamlReaderTest, AListOrMappingAsAKeyIsAParseError) {
  // Found by experiment_yaml_fuzz: yaml-cpp's own exception escaped when a key was not a scalar.
  for (const char* text : {"runs: 1\n{a: 1}: 2\n", "[x, y]: 1\n"}) {
    const YAML::Node root = YAML::Load(text);
    YamlMapReader reader(root, "k.yaml");
    reader.lookup("runs");
    try {
      reader.rejectUnknownKeys();
      ADD_FAILURE() << "accepted " << text;
    } catch (const ParseError& e) {
      EXPECT_NE(std::string(e.what()).find("k.yaml:"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("yaml: expected plain keys, got a list or mapping as a key"),
                std::string::npos)
          << e.what();
    }
  }
}

TEST(YamlReaderTest, DifferenceNamesTheFirstKeyThatDiffers) {
  const auto difference = [](const char* there, const char* here) {
    return yamlDifference(YAML::Load(there), YAML::Load(here));
  };
  EXPECT_EQ(difference("a: 1\nb: [x, {c: 2}]\n", "a: 1\nb: [x, {c: 2}]\n"), "");
  EXPECT_EQ(difference("{b: 2, a: 1}", "{a: 1, b: 2}"), "");  // key order is not data
  EXPECT_EQ(difference("a: 1\nb: 2\n", "a: 1\nb: 3\n"), "b: '2' there, '3' here");
  EXPECT_EQ(difference("a: 1\n", "a: 1\nconnectivity: 8\n"), "connectivity: absent there, '8' here");
  EXPECT_EQ(difference("a: 1\nold: x\n", "a: 1\n"), "old: 'x' there, absent here");
  EXPECT_EQ(difference("agents: [{n: a}, {n: b, m: 1}]", "agents: [{n: a}, {n: b, m: 2}]"),
            "agents[1].m: '1' there, '2' here");
  EXPECT_EQ(difference("s: [1, 2]", "s: [1, 2, 3]"), "s: 2 items there, 3 here");
  EXPECT_EQ(difference("s: {a: 1}", "s: [1]"), "s: a mapping there, a list of 1 here");
  EXPECT_EQ(difference("1", "2"), "the document: '1' there, '2' here");
}

}  // namespace
}  // namespace ppp
