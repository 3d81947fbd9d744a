// Generator options as `ppp generate` flags: every declared option has its flag, and the flags accept and refuse
// the same values as YAML and ROS parameters (the shared cases of generator_option_cases.hpp), naming the flag.
#include "option_flags.hpp"

#include <gtest/gtest.h>

#include "generator_option_cases.hpp"
#include "ppp_generator/generator_options.hpp"

namespace ppp {
namespace cli {
namespace {

using generator::GeneratorOptions;
using generator::generatorOptionSpecs;

const GeneratorOptions kDefaults;

/// What parsing `--FLAG VALUE` and validating gives: "" when accepted, else the error.
std::string flagError(const std::string& flag, const std::string& value) {
  CLI::App app;
  std::map<std::string, std::string> given;
  addOptionFlags(&app, generatorOptionSpecs(), &kDefaults, &given);
  GeneratorOptions options;
  try {
    app.parse(std::vector<std::string>{value, flag});  // CLI11 takes the arguments in reverse
    applyOptionFlags(app, generatorOptionSpecs(), given, &options);
    options.validate();
  } catch (const InvalidArgument& e) {
    return namingTheFlag(app, generatorOptionSpecs(), e).what();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(OptionFlagsTest, EveryOptionHasADocumentedFlag) {
  CLI::App app;
  std::map<std::string, std::string> given;
  addOptionFlags(&app, generatorOptionSpecs(), &kDefaults, &given);
  EXPECT_EQ(given.size(), generatorOptionSpecs().size());
  const std::string help = app.help();
  for (const char* expected : {"--max-bar-length", "--max-block-side", "--weights-one-turn-penalty",
                               "--population INT in [2, 100000]", "PPPs in the pool (default 60)", "--start X,Y",
                               "--features A,B,...", "--seed INT "}) {
    EXPECT_NE(help.find(expected), std::string::npos) << expected << " missing from:\n" << help;
  }
}

TEST(OptionFlagsTest, FlagsAcceptAndRefuseWhatEverySourceDoes) {
  for (const generator::test::OptionCase& c : generator::test::generatorOptionCases()) {
    std::string flag = "--" + c.option;
    for (char& ch : flag) ch = ch == '_' || ch == '.' ? '-' : ch;
    const std::string error = flagError(flag, c.value);
    if (c.accepted) {
      EXPECT_EQ(error, "") << flag << " " << c.value;
    } else {
      EXPECT_EQ(error.rfind(flag + ": ", 0), 0u) << flag << " " << c.value << " gave: " << error;
    }
  }
}

TEST(OptionFlagsTest, ASizeFlagMovesTheDefaultGoal) {
  EXPECT_EQ(flagError("--width", "30"), "");
  CLI::App app;
  std::map<std::string, std::string> given;
  addOptionFlags(&app, generatorOptionSpecs(), &kDefaults, &given);
  app.parse(std::vector<std::string>{"30", "--width"});
  GeneratorOptions options;
  applyOptionFlags(app, generatorOptionSpecs(), given, &options);
  EXPECT_EQ(options.goalCell(), (Cell{29, 19}));
}

}  // namespace
}  // namespace cli
}  // namespace ppp
