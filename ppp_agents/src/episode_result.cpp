#include "ppp_agents/episode_result.hpp"

#include <array>
#include <charconv>
#include <string_view>

#include "ppp_core/csv.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/failure_signature.hpp"

namespace ppp {
namespace agents {

namespace {

constexpr std::size_t kFields = 17;  // of a row, as resultCsvHeader()

template <typename T>
T parseNumber(std::string_view text, const std::string& source, int line, const char* field) {
  T value{};
  const char* end = text.data() + text.size();
  const auto result = std::from_chars(text.data(), end, value);
  if (text.empty() || result.ec != std::errc() || result.ptr != end) {
    throw ParseError(source, line, field, "expected a whole number, got '" + std::string(text) + "'");
  }
  return value;
}

/// A 0 or 1 field.
bool parseFlag(std::string_view text, const std::string& source, int line, const char* field) {
  if (text != "0" && text != "1") throw ParseError(source, line, field, "expected 0 or 1, got '" + std::string(text) + "'");
  return text == "1";
}

/// A path or optimal length: a whole number, or one with decimals (diagonal moves), never negative but for -1
/// (no optimal length known).
double parseLength(std::string_view text, const std::string& source, int line, const char* field) {
  double value = 0;
  const char* end = text.data() + text.size();
  const auto result = std::from_chars(text.data(), end, value);
  if (text.empty() || result.ec != std::errc() || result.ptr != end || !((value >= 0 || value == -1) && value < 1e15)) {
    throw ParseError(source, line, field, "expected a length, got '" + std::string(text) + "'");
  }
  return value;
}

/// An optional whole number: -1 (or `none`) for an empty field.
int parseOptional(std::string_view text, int none, const std::string& source, int line, const char* field) {
  if (text.empty()) return none;
  const int value = parseNumber<int>(text, source, line, field);
  if (value < 0) throw ParseError(source, line, field, "expected a whole number of at least 0, got '" + std::string(text) + "'");
  return value;
}

/// The diagnosis fields of `r`, checked against its pass, soft failure and against each other.
void parseDiagnosis(std::string_view kind, std::string_view step, std::string_view period, std::string_view endless,
                    const std::string& source, int line, EpisodeResult* r) {
  const char* named = diagnosis::kindNamed(kind);
  if (!kind.empty() && named == nullptr) {
    throw ParseError(source, line, "diagnosis", "expected one of stuck, loop, confined, wandering, detour, "
                                                "missed_route, no_route, reported or nothing, got '" + std::string(kind) + "'");
  }
  r->diagnosis = std::string(kind);
  const bool clean_pass = r->passed && !r->soft_failure;
  if (clean_pass != kind.empty() || (r->soft_failure != (r->diagnosis == diagnosis::kDetour))) {
    throw ParseError(source, line, "diagnosis",
                     "'" + r->diagnosis + "' does not fit pass " + (r->passed ? "1" : "0") + ", soft_failure " +
                         (r->soft_failure ? "1" : "0") + " (a clean pass has none, a soft failure is a detour)");
  }
  r->diagnosis_step = parseOptional(step, -1, source, line, "diagnosis_step");
  r->loop_period = parseOptional(period, 0, source, line, "loop_period");
  r->endless_step = parseOptional(endless, -1, source, line, "endless_step");
  const bool loop = r->diagnosis == diagnosis::kLoop;
  if (loop != (r->loop_period >= 2)) {
    throw ParseError(source, line, "loop_period", "a loop has a period of at least 2, and only a loop has one");
  }
  if (!loop && r->endless_step >= 0) throw ParseError(source, line, "endless_step", "only a loop is endless");
  if (r->diagnosis_step > r->steps || r->endless_step > r->steps) {
    throw ParseError(source, line, "diagnosis_step", "a step after the run's last (" + std::to_string(r->steps) + ")");
  }
}

/// The signature field of `r`, checked for its form and against the diagnosis and reason it must agree with.
void parseSignature(std::string_view text, const std::string& source, int line, EpisodeResult* r) {
  std::string why;
  if (!isWellFormedSignature(text, &why)) throw ParseError(source, line, "signature", why);
  r->signature = std::string(text);
  if (r->diagnosis.empty() != r->signature.empty()) {
    throw ParseError(source, line, "signature", "a failed or soft-failed run has a signature, a clean pass none");
  }
  if (r->signature.empty()) return;
  const std::string how = failureHow(diagnosisOf(*r), r->reason);
  if (r->signature.compare(0, r->signature.find('/'), how) != 0) {
    throw ParseError(source, line, "signature",
                     "'" + r->signature + "' does not begin with '" + how + "/', as its diagnosis and reason say");
  }
}

/// A row from its fields in header order (any count: a wrong one is named).
template <typename Field>
EpisodeResult rowFromFields(const Field* f, std::size_t count, const std::string& source, int line) {
  if (count != kFields) {
    throw ParseError(source, line, "row",
                     "expected " + std::to_string(kFields) + " fields, got " + std::to_string(count));
  }
  EpisodeResult r;
  r.set = f[0];
  r.problem = f[1];
  r.agent = f[2];
  r.run = parseNumber<int>(f[3], source, line, "run");
  r.seed = parseNumber<std::uint64_t>(f[4], source, line, "seed");
  r.passed = parseFlag(f[5], source, line, "pass");
  r.steps = parseNumber<int>(f[6], source, line, "steps");
  r.bumps = parseNumber<int>(f[7], source, line, "bumps");
  r.path_length = parseLength(f[8], source, line, "path_length");
  r.optimal_length = parseLength(f[9], source, line, "optimal_length");
  r.reason = f[10];
  r.soft_failure = parseFlag(f[11], source, line, "soft_failure");
  if (r.soft_failure && !r.passed) throw ParseError(source, line, "soft_failure", "a soft failure is a passed run");
  parseDiagnosis(f[12], f[13], f[14], f[15], source, line, &r);
  parseSignature(f[16], source, line, &r);
  return r;
}

void appendText(const std::string& value, std::string* out) {
  if (value.find_first_of(",\"\r\n") == std::string::npos) {
    *out += value;
  } else {
    *out += csvField(value);
  }
}

template <typename T>
void appendNumber(T value, std::string* out) {
  char digits[24];
  const auto result = std::to_chars(digits, digits + sizeof digits, value);
  out->append(digits, result.ptr);
}

/// A length as results.csv writes it: a whole number as such (every length of the 4-connected model), else with
/// eight decimals, as MovingAI's scenario files do; a length that rounds to a whole number at eight decimals is
/// written as that number, so that writing what was read back gives the same text.
void appendLength(double value, std::string* out) {
  char digits[48];
  const auto whole = static_cast<long long>(value);
  if (static_cast<double>(whole) == value) {
    out->append(digits, std::to_chars(digits, digits + sizeof digits, whole).ptr);
    return;
  }
  std::size_t length =
      static_cast<std::size_t>(std::to_chars(digits, digits + sizeof digits, value, std::chars_format::fixed, 8).ptr - digits);
  if (std::string_view(digits, length).substr(length - 9) == ".00000000") length -= 9;
  out->append(digits, length);
}

/// An optional whole number: nothing when it is `none`.
void appendOptional(int value, int none, std::string* out) {
  if (value != none) appendNumber(value, out);
}

std::string optionalText(int value, int none) {
  std::string text;
  appendOptional(value, none, &text);
  return text;
}

std::string lengthText(double value) {
  std::string text;
  appendLength(value, &text);
  return text;
}

}  // namespace

const std::vector<std::string>& resultCsvHeader() {
  static const std::vector<std::string> header = {"set",   "problem", "agent",       "run",            "seed",
                                                  "pass",  "steps",   "bumps",       "path_length",    "optimal_length",
                                                  "reason", "soft_failure", "diagnosis", "diagnosis_step",
                                                  "loop_period", "endless_step", "signature"};
  return header;
}

std::vector<std::string> toCsvFields(const EpisodeResult& r) {
  return {r.set,
          r.problem,
          r.agent,
          std::to_string(r.run),
          std::to_string(r.seed),
          r.passed ? "1" : "0",
          std::to_string(r.steps),
          std::to_string(r.bumps),
          lengthText(r.path_length),
          lengthText(r.optimal_length),
          r.reason,
          r.soft_failure ? "1" : "0",
          r.diagnosis,
          optionalText(r.diagnosis_step, -1),
          optionalText(r.loop_period, 0),
          optionalText(r.endless_step, -1),
          r.signature};
}

Diagnosis diagnosisOf(const EpisodeResult& result) {
  Diagnosis d;
  const char* kind = diagnosis::kindNamed(result.diagnosis);
  d.kind = kind != nullptr ? kind : "";
  d.step = result.diagnosis_step;
  d.period = result.loop_period;
  d.endless_step = result.endless_step;
  return d;
}

void setDiagnosis(const Diagnosis& d, EpisodeResult* result) {
  result->diagnosis = d.kind;
  result->diagnosis_step = d.step;
  result->loop_period = d.period;
  result->endless_step = d.endless_step;
}

EpisodeResult fromCsvFields(const std::vector<std::string>& f, const std::string& source, int line) {
  return rowFromFields(f.data(), f.size(), source, line);
}

void appendCsvRow(const EpisodeResult& r, std::string* out) {
  appendText(r.set, out);
  *out += ',';
  appendText(r.problem, out);
  *out += ',';
  appendText(r.agent, out);
  *out += ',';
  appendNumber(r.run, out);
  *out += ',';
  appendNumber(r.seed, out);
  *out += r.passed ? ",1," : ",0,";
  appendNumber(r.steps, out);
  *out += ',';
  appendNumber(r.bumps, out);
  *out += ',';
  appendLength(r.path_length, out);
  *out += ',';
  appendLength(r.optimal_length, out);
  *out += ',';
  appendText(r.reason, out);
  *out += r.soft_failure ? ",1," : ",0,";
  *out += r.diagnosis;
  *out += ',';
  appendOptional(r.diagnosis_step, -1, out);
  *out += ',';
  appendOptional(r.loop_period, 0, out);
  *out += ',';
  appendOptional(r.endless_step, -1, out);
  *out += ',';
  *out += r.signature;
  *out += '\n';
}

EpisodeResult parseCsvRow(std::string_view line, const std::string& source, int line_number) {
  if (line.find('"') != std::string_view::npos) {
    return fromCsvFields(splitCsvLine(std::string(line), source, line_number), source, line_number);
  }
  std::array<std::string_view, kFields> fields;
  std::size_t count = 0;
  std::size_t begin = 0;
  for (;;) {
    const std::size_t comma = line.find(',', begin);
    const std::string_view field = line.substr(begin, comma == std::string_view::npos ? line.npos : comma - begin);
    if (count < kFields) fields[count] = field;
    ++count;
    if (comma == std::string_view::npos) break;
    begin = comma + 1;
  }
  return rowFromFields(fields.data(), count, source, line_number);
}

std::vector<std::string> splitCsvLine(const std::string& line, const std::string& source, int line_number) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  if (quoted) throw ParseError(source, line_number, "row", "unterminated quoted field");
  return fields;
}

}  // namespace agents
}  // namespace ppp
