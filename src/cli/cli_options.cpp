#include "cli_options.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <utility>

#include "ppp_core/error.hpp"

namespace ppp {
namespace cli {

namespace {

bool parseInt(const std::string& text, int* value) {
  const char* end = text.data() + text.size();
  auto result = std::from_chars(text.data(), end, *value);
  return !text.empty() && result.ec == std::errc() && result.ptr == end;
}

bool splitPair(const std::string& text, char separator, std::string* first, std::string* second) {
  const auto at = text.find(separator);
  if (at == std::string::npos) return false;
  *first = text.substr(0, at);
  *second = text.substr(at + 1);
  return true;
}

}  // namespace

Size parseSize(const std::string& text, const std::string& option) {
  std::string w, h;
  Size size;
  if (!splitPair(text, 'x', &w, &h) || !parseInt(w, &size.width) || !parseInt(h, &size.height)) {
    throw InvalidArgument(option, "expected WIDTHxHEIGHT such as 20x20, got '" + text + "'");
  }
  validateGridSize(size.width, size.height, option.c_str());
  return size;
}

Cell parseCell(const std::string& text, const std::string& option) {
  std::string x, y;
  Cell cell;
  if (!splitPair(text, ',', &x, &y) || !parseInt(x, &cell.x) || !parseInt(y, &cell.y)) {
    throw InvalidArgument(option, "expected X,Y such as 0,0, got '" + text + "'");
  }
  return cell;
}

DifficultyWeights parseWeights(const std::vector<std::string>& assignments, const DifficultyWeights& base) {
  DifficultyWeights w = base;
  const std::pair<const char*, double*> fields[] = {
      {"start", &w.start},
      {"centre", &w.centre},
      {"top_right", &w.top_right},
      {"bottom_left", &w.bottom_left},
      {"goal", &w.goal},
      {"unused_obstacles", &w.unused_obstacles},
      {"horizontal_openness", &w.horizontal_openness},
      {"vertical_openness", &w.vertical_openness},
      {"one_turn_penalty", &w.one_turn_penalty},
  };
  for (const std::string& assignment : assignments) {
    std::string name, value;
    if (!splitPair(assignment, '=', &name, &value)) {
      throw InvalidArgument("--weight", "expected NAME=VALUE, got '" + assignment + "'");
    }
    double* target = nullptr;
    std::string valid;
    for (const auto& field : fields) {
      if (name == field.first) target = field.second;
      valid += valid.empty() ? field.first : std::string(", ") + field.first;
    }
    if (target == nullptr) throw InvalidArgument("--weight", "unknown weight '" + name + "'; valid: " + valid);
    char* end = nullptr;
    const double number = std::strtod(value.c_str(), &end);
    if (value.empty() || *end != '\0' || !std::isfinite(number)) {
      throw InvalidArgument("--weight " + name, "expected a finite number, got '" + value + "'");
    }
    *target = number;
  }
  w.validate();
  return w;
}

}  // namespace cli
}  // namespace ppp
