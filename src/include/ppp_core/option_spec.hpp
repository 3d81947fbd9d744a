#pragma once

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iterator>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "ppp_core/grid.hpp"
#include "ppp_core/text_format.hpp"

namespace ppp {

// One declaration per option of an options struct: name, type, default, range and a one-line doc. The YAML
// reader and writer (option_yaml.hpp), the ROS parameter reader (ppp_msgs/node_parameters.h) and the command-line
// flags all work from the same list, so they accept and refuse the same values and --help, errors and config
// docs say the same thing.

/// Inclusive numeric bounds of an option (unbounded sides are infinite).
struct Bounds {
  double min = -std::numeric_limits<double>::infinity();  ///< Smallest value allowed.
  double max = std::numeric_limits<double>::infinity();   ///< Largest value allowed.
};

/// The kind of value an option holds: how sources parse it and which cases tests play (never the prose `type`).
enum class OptionKind {
  Integer,   ///< A whole number (signed or not).
  Number,    ///< A finite real number.
  Boolean,   ///< true or false.
  Text,      ///< Any string.
  TextList,  ///< A list of strings (or one comma-separated string).
  Cell,      ///< A grid cell [x, y].
  Custom,    ///< A value written in a form of its own (declareTextOption()); `examples` shows valid ones.
};

/// One valid value of an option that takes a fixed set of them.
struct OptionChoice {
  std::string name;  ///< The value as YAML, parameters and flags write it.
  std::string doc;   ///< What it means, one line.
};

/// One option of the struct `Options`.
template <typename Options>
struct OptionSpec {
  std::string name;  ///< YAML key, dotted for nested mappings ("weights.goal"); ROS "weights/goal"; flag --weights-goal.
  std::string type;  ///< What a value is, as errors say it ("an integer", "a list of strings", ...).
  std::string doc;   ///< One line for --help, errors and the config file.
  std::string flag;  ///< Command-line flag name without "--" when it is not derived from `name` ("" = derived).
  OptionKind kind = OptionKind::Text;  ///< The kind of value.
  Bounds bounds;     ///< Numeric range (ignored for other types).
  /// Whether a different value may give different results: such options make up an experiment's fingerprint, so
  /// a resumed run never mixes rows made under different values. Only pace and presentation options are false.
  bool affects_results = true;
  std::vector<std::string> examples;  ///< Valid values as YAML text, for docs and tests (Custom kinds).
  std::vector<OptionChoice> choices;  ///< The only values allowed, when the option takes a fixed set (else empty).
  /// The option that may not be given in the same source as this one (two forms of one setting), or "".
  std::string excludes;
  /// The value in `options` as YAML flow text ("" for an unset optional).
  std::function<std::string(const Options& options)> text;
  /// Sets the value from a YAML node; returns what is wrong with it ("" when nothing is).
  std::function<std::string(Options* options, const YAML::Node& node)> set;
  /// What is wrong with the value in `options` against the bounds ("" when nothing is).
  std::function<std::string(const Options& options)> check;
  /// The range as docs write it ("" when unbounded).
  std::string rangeText() const {
    const auto shown = [](double v) {
      return v == std::floor(v) && std::fabs(v) < 1e15 ? std::to_string(static_cast<long long>(v)) : formatShortest(v);
    };
    const bool low = std::isfinite(bounds.min), high = std::isfinite(bounds.max);
    if (low && high) return "[" + shown(bounds.min) + ", " + shown(bounds.max) + "]";
    if (low) return ">= " + shown(bounds.min);
    if (high) return "<= " + shown(bounds.max);
    return "";
  }
  /// The choices' names as errors list them ("crowding, tournament"), or joined by another `separator`.
  std::string choiceList(const std::string& separator = ", ") const {
    std::string list;
    for (const OptionChoice& choice : choices) list += (list.empty() ? "" : separator) + choice.name;
    return list;
  }
  /// A scalar value in `options` without YAML's quoting ("it's", not 'it''s'); "" when unset; a list or cell as
  /// its flow text.
  std::string plainText(const Options& options) const {
    const std::string flow = text(options);
    if (flow.empty()) return flow;
    const YAML::Node node = YAML::Load(flow);
    return node.IsScalar() ? node.Scalar() : flow;
  }
  /// The doc, followed by each choice with its meaning when the option takes a fixed set of values.
  std::string docWithChoices() const {
    std::string text = doc;
    for (std::size_t i = 0; i < choices.size(); ++i) {
      text += (i == 0 ? ": " : ", ") + choices[i].name + (choices[i].doc.empty() ? "" : " (" + choices[i].doc + ")");
    }
    return text;
  }
  /// This declaration restricted to `allowed`: any other value is refused as "unknown <noun> 'x'; valid: a, b"
  /// when read and when checked.
  OptionSpec withChoices(const std::string& noun, std::vector<OptionChoice> allowed) const {
    OptionSpec copy = *this;
    copy.choices = std::move(allowed);
    const auto problem = [noun, names = copy.choiceList(), choices = copy.choices](const std::string& text) {
      for (const OptionChoice& choice : choices) {
        if (choice.name == text) return std::string();
      }
      return "unknown " + noun + " '" + text + "'; valid: " + names;
    };
    const auto chosen = [copy, problem](const Options& options) { return problem(copy.plainText(options)); };
    copy.set = [set = set, chosen](Options* options, const YAML::Node& node) {
      const std::string wrong = set(options, node);  // a value of the wrong kind is refused as such first
      return wrong.empty() ? chosen(*options) : wrong;
    };
    copy.check = [check = check, chosen](const Options& options) {
      const std::string wrong = chosen(options);
      return wrong.empty() ? check(options) : wrong;
    };
    return copy;
  }
  /// This declaration, refused when `other` is given in the same source (a file, the flags or the parameters).
  OptionSpec excluding(const std::string& other) const {
    OptionSpec copy = *this;
    copy.excludes = other;
    return copy;
  }
  /// This declaration, marked as never changing a result (threads, pictures, hosts): out of the fingerprint.
  OptionSpec notAffectingResults() const {
    OptionSpec copy = *this;
    copy.affects_results = false;
    return copy;
  }
};

namespace option_detail {

inline std::string nodeText(const YAML::Node& node) {
  if (node.IsScalar()) return node.Scalar();
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a mapping";
  return "nothing";
}

/// A string as a YAML flow scalar: plain when that reads back as the same string, else single-quoted, or
/// double-quoted with escapes when it holds control characters (a single-quoted newline would be folded).
inline std::string quoted(const std::string& text) {
  const auto control = [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; };
  if (std::any_of(text.begin(), text.end(), control)) {
    std::string out = "\"";
    for (char c : text) {
      if (control(c)) {
        const char* digits = "0123456789abcdef";
        const auto byte = static_cast<unsigned char>(c);
        out += std::string("\\x") + digits[byte >> 4] + digits[byte & 15];
      } else if (c == '"' || c == '\\') {
        out += std::string("\\") + c;
      } else {
        out += c;
      }
    }
    return out + "\"";
  }
  bool plain = !text.empty();
  std::string lower;  // YAML reads its null and boolean words in more than one case (NULL, Null, True, ...)
  for (char c : text) {
    const bool ok = std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '/' || c == '.' || c == '-';
    plain = plain && ok;
    lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  if (plain && text.find_first_not_of("0123456789.-") != std::string::npos && lower != "true" && lower != "false" &&
      lower != "null" && lower != "yes" && lower != "no" && lower != "on" && lower != "off") {
    return text;
  }
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

template <typename T>
struct Value;

template <>
struct Value<int> {
  static constexpr OptionKind kKind = OptionKind::Integer;
  static constexpr const char* kType = "an integer";
  static bool parse(const YAML::Node& n, int* v) { return n.IsScalar() && YAML::convert<int>::decode(n, *v); }
  static std::string text(int v) { return std::to_string(v); }
  static double number(int v) { return v; }
};
template <>
struct Value<long> {
  static constexpr OptionKind kKind = OptionKind::Integer;
  static constexpr const char* kType = "an integer";
  static bool parse(const YAML::Node& n, long* v) { return n.IsScalar() && YAML::convert<long>::decode(n, *v); }
  static std::string text(long v) { return std::to_string(v); }
  static double number(long v) { return static_cast<double>(v); }
};
template <>
struct Value<std::uint64_t> {
  static constexpr OptionKind kKind = OptionKind::Integer;
  static constexpr const char* kType = "a non-negative integer";
  static bool parse(const YAML::Node& n, std::uint64_t* v) {
    unsigned long long u = 0;
    if (!n.IsScalar() || n.Scalar().empty() || n.Scalar()[0] == '-' || !YAML::convert<unsigned long long>::decode(n, u)) {
      return false;
    }
    *v = u;
    return true;
  }
  static std::string text(std::uint64_t v) { return std::to_string(v); }
  static double number(std::uint64_t v) { return static_cast<double>(v); }
};
template <>
struct Value<bool> {
  static constexpr OptionKind kKind = OptionKind::Boolean;
  static constexpr const char* kType = "true or false";
  static bool parse(const YAML::Node& n, bool* v) { return n.IsScalar() && YAML::convert<bool>::decode(n, *v); }
  static std::string text(bool v) { return v ? "true" : "false"; }
  static double number(bool v) { return v ? 1 : 0; }
};
template <>
struct Value<double> {
  static constexpr OptionKind kKind = OptionKind::Number;
  static constexpr const char* kType = "a number";
  static bool parse(const YAML::Node& n, double* v) {
    return n.IsScalar() && YAML::convert<double>::decode(n, *v) && std::isfinite(*v);
  }
  static std::string text(double v) { return formatShortest(v); }
  static double number(double v) { return v; }
};
template <>
struct Value<std::string> {
  static constexpr OptionKind kKind = OptionKind::Text;
  static constexpr const char* kType = "a string";
  static bool parse(const YAML::Node& n, std::string* v) {
    if (!n.IsScalar()) return false;
    *v = n.Scalar();
    return true;
  }
  static std::string text(const std::string& v) { return quoted(v); }
  static double number(const std::string&) { return 0; }
};
template <>
struct Value<std::vector<std::string>> {
  static constexpr OptionKind kKind = OptionKind::TextList;
  static constexpr const char* kType = "a list of strings";
  /// A list, or one comma-separated scalar ("a,b": what a command line or `_name:=a,b` gives).
  static bool parse(const YAML::Node& n, std::vector<std::string>* v) {
    v->clear();
    if (n.IsScalar()) {
      std::string item;
      for (char c : n.Scalar() + ",") {
        if (c != ',') {
          item += c;
        } else if (!item.empty()) {
          v->push_back(item);
          item.clear();
        }
      }
      return true;
    }
    if (!n.IsSequence()) return false;
    for (const YAML::Node& item : n) {
      if (!item.IsScalar()) return false;
      v->push_back(item.Scalar());
    }
    return true;
  }
  static std::string text(const std::vector<std::string>& v) {
    std::string out = "[";
    for (std::size_t i = 0; i < v.size(); ++i) out += (i > 0 ? ", " : "") + quoted(v[i]);
    return out + "]";
  }
  static double number(const std::vector<std::string>&) { return 0; }
};
template <>
struct Value<std::optional<Cell>> {
  static constexpr OptionKind kKind = OptionKind::Cell;
  static constexpr const char* kType = "a cell [x, y]";
  /// [x, y], or "x,y" as one scalar.
  static bool parse(const YAML::Node& n, std::optional<Cell>* v) {
    std::vector<int> xy;
    if (n.IsSequence()) {
      for (const YAML::Node& item : n) {
        int value = 0;
        if (!Value<int>::parse(item, &value)) return false;
        xy.push_back(value);
      }
    } else if (n.IsScalar()) {
      const std::size_t comma = n.Scalar().find(',');
      int x = 0, y = 0;
      if (comma == std::string::npos || !Value<int>::parse(YAML::Node(n.Scalar().substr(0, comma)), &x) ||
          !Value<int>::parse(YAML::Node(n.Scalar().substr(comma + 1)), &y)) {
        return false;
      }
      xy = {x, y};
    }
    if (xy.size() != 2) return false;
    *v = Cell{xy[0], xy[1]};
    return true;
  }
  static std::string text(const std::optional<Cell>& v) {
    return v ? "[" + std::to_string(v->x) + ", " + std::to_string(v->y) + "]" : "";
  }
  static double number(const std::optional<Cell>&) { return 0; }
};

}  // namespace option_detail

/// Declares option `name` of type T, reached through `field` (a captureless lambda returning the member).
template <typename Options, typename T>
OptionSpec<Options> declareOption(const std::string& name, const std::string& doc, T& (*field)(Options&),
                                  Bounds bounds = {}) {
  using V = option_detail::Value<T>;
  OptionSpec<Options> spec;
  spec.name = name;
  spec.type = V::kType;
  spec.doc = doc;
  spec.kind = V::kKind;
  spec.bounds = bounds;
  spec.text = [field](const Options& o) { return V::text(field(const_cast<Options&>(o))); };
  spec.set = [field](Options* o, const YAML::Node& node) -> std::string {
    T value{};
    if (!V::parse(node, &value)) return "expected " + std::string(V::kType) + ", got '" + option_detail::nodeText(node) + "'";
    field(*o) = value;
    return "";
  };
  const std::string range = spec.rangeText();
  spec.check = [field, bounds, range](const Options& o) -> std::string {
    const double value = V::number(field(const_cast<Options&>(o)));
    if (value >= bounds.min && value <= bounds.max) return "";
    return "expected " + std::string(V::kType) + (range[0] == '[' ? " in " : " ") + range + ", got " +
           V::text(field(const_cast<Options&>(o)));
  };
  return spec;
}

/// Declares option `name` whose value is written as text in a form of its own (a memory window "5x5"): `parse`
/// reads the text into the value and returns what is wrong ("" when nothing is), `show` writes it; `type` says
/// what a value is and `examples` are valid values (two or more, as YAML text).
template <typename Options, typename T>
OptionSpec<Options> declareTextOption(const std::string& name, const std::string& type, const std::string& doc,
                                      T& (*field)(Options&), std::string (*parse)(const std::string&, T*),
                                      std::string (*show)(T), const std::vector<std::string>& examples) {
  OptionSpec<Options> spec;
  spec.name = name;
  spec.type = type;
  spec.doc = doc;
  spec.kind = OptionKind::Custom;
  spec.examples = examples;
  spec.text = [field, show](const Options& o) { return option_detail::quoted(show(field(const_cast<Options&>(o)))); };
  spec.set = [field, parse, type](Options* o, const YAML::Node& node) -> std::string {
    if (!node.IsScalar()) return "expected " + type + ", got '" + option_detail::nodeText(node) + "'";
    T value{};
    const std::string problem = parse(node.Scalar(), &value);
    if (problem.empty()) field(*o) = value;
    return problem;
  };
  spec.check = [](const Options&) { return std::string(); };
  return spec;
}

/// The options of a member struct (`member` returns it) as options of the enclosing struct, under the same names.
template <typename Outer, typename Inner>
std::vector<OptionSpec<Outer>> nestedOptions(const std::vector<OptionSpec<Inner>>& specs, Inner& (*member)(Outer&)) {
  std::vector<OptionSpec<Outer>> nested;
  for (const OptionSpec<Inner>& inner : specs) {
    OptionSpec<Outer> spec;
    spec.name = inner.name;
    spec.type = inner.type;
    spec.doc = inner.doc;
    spec.flag = inner.flag;
    spec.kind = inner.kind;
    spec.bounds = inner.bounds;
    spec.affects_results = inner.affects_results;
    spec.examples = inner.examples;
    spec.choices = inner.choices;
    spec.excludes = inner.excludes;
    spec.text = [inner, member](const Outer& o) { return inner.text(member(const_cast<Outer&>(o))); };
    spec.set = [inner, member](Outer* o, const YAML::Node& node) { return inner.set(&member(*o), node); };
    spec.check = [inner, member](const Outer& o) { return inner.check(member(const_cast<Outer&>(o))); };
    nested.push_back(spec);
  }
  return nested;
}

/// The command-line flag of an option named `name`: "--" + the name with '_' and '.' as '-' ("--weights-goal").
inline std::string flagFor(const std::string& name) {
  std::string flag = "--" + name;
  for (char& c : flag) c = c == '_' || c == '.' ? '-' : c;
  return flag;
}

/// The command-line flag of a declared option: flagFor() its flag, or its name.
template <typename Options>
std::string flagName(const OptionSpec<Options>& spec) {
  return flagFor(spec.flag.empty() ? spec.name : spec.flag);
}

/// The flags that give `values` where they differ from `defaults`, as a shell reads them ("--memory 5x5
/// --budget 100"; see shellWord()).
template <typename Options>
std::string optionFlags(const std::vector<OptionSpec<Options>>& specs, const Options& values, const Options& defaults) {
  std::string flags;
  for (const OptionSpec<Options>& spec : specs) {
    const std::string value = spec.text(values);
    if (value != spec.text(defaults)) flags += (flags.empty() ? "" : " ") + flagName(spec) + " " + shellWord(value);
  }
  return flags;
}

/// The first option of `specs` given (`given(name)`) together with the one it excludes, or nullptr; `name` spells
/// option names as the source does.
template <typename Options, typename Given>
const OptionSpec<Options>* exclusionBroken(const std::vector<OptionSpec<Options>>& specs, Given given) {
  for (const OptionSpec<Options>& spec : specs) {
    if (!spec.excludes.empty() && given(spec.name) && given(spec.excludes)) return &spec;
  }
  return nullptr;
}

/// The declarations of `specs` that may change results (affects_results), in declaration order.
template <typename Options>
std::vector<OptionSpec<Options>> resultOptions(const std::vector<OptionSpec<Options>>& specs) {
  std::vector<OptionSpec<Options>> selected;
  std::copy_if(specs.begin(), specs.end(), std::back_inserter(selected), [](const auto& s) { return s.affects_results; });
  return selected;
}

/// The declaration of `specs` named `name`. @throws std::logic_error for a name not declared.
template <typename Options>
const OptionSpec<Options>& optionNamed(const std::vector<OptionSpec<Options>>& specs, const std::string& name) {
  const auto named = [&](const OptionSpec<Options>& spec) { return spec.name == name; };
  const auto found = std::find_if(specs.begin(), specs.end(), named);
  if (found == specs.end()) throw std::logic_error("no option '" + name + "' declared");
  return *found;
}

/// The declarations of `specs` named in `names`, in the order of `names` (a source that takes only some options).
/// @throws std::logic_error for a name not declared.
template <typename Options>
std::vector<OptionSpec<Options>> selectOptions(const std::vector<OptionSpec<Options>>& specs,
                                               const std::vector<std::string>& names) {
  std::vector<OptionSpec<Options>> selected;
  for (const std::string& name : names) selected.push_back(optionNamed(specs, name));
  return selected;
}

}  // namespace ppp
