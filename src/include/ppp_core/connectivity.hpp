#pragma once

#include <cstdint>
#include <string>

#include <yaml-cpp/yaml.h>

#include "ppp_core/option_spec.hpp"

namespace ppp {

/// The move model, named by its number of neighbours as configs, parameters, flags and messages write it.
enum class Connectivity : std::uint8_t {
  Four = 4,   ///< Stay and the four straight moves (the dissertation's model, the default).
  Eight = 8,  ///< Also the four diagonal moves, each only when both cells beside it are free (MovingAI's rule).
};

/// The model's number of neighbours (4 or 8), as it is written.
constexpr int neighbours(Connectivity connectivity) { return static_cast<int>(connectivity); }

namespace option_detail {

/// A Connectivity option is read and written as its number; which numbers are allowed is the declaration's choices.
template <>
struct Value<Connectivity> {
  static constexpr OptionKind kKind = OptionKind::Integer;
  static constexpr const char* kType = "an integer";
  static bool parse(const YAML::Node& n, Connectivity* v) {
    int number = 0;
    if (!n.IsScalar() || !YAML::convert<int>::decode(n, number) || number < 0 || number > 255) return false;
    *v = static_cast<Connectivity>(number);
    return true;
  }
  static std::string text(Connectivity v) { return std::to_string(neighbours(v)); }
  static double number(Connectivity v) { return neighbours(v); }
};

}  // namespace option_detail
}  // namespace ppp
