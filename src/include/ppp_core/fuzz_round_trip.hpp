#pragma once

#include <functional>
#include <string>

#include "ppp_core/error.hpp"
#include "ppp_core/fuzz_finding.hpp"

namespace ppp {
namespace fuzz {

/// The check of a fuzz target for a text reader and its writer: `parse(text, source)` returns a value or throws
/// ppp::Error, `format(value)` accepts every value `parse` returns, parsing the formatted text gives back a value
/// `same` as the one read (equal, by default), and formatting that gives the same text again. Anything else is a
/// finding of `target` (which aborts).
template <class Parse, class Format, class Same = std::equal_to<>>
void checkTextRoundTrip(const char* target, const std::string& text, const std::string& source, const Parse& parse,
                        const Format& format, const Same& same = Same()) {
  decltype(parse(text, source)) read;
  try {
    read = parse(text, source);
  } catch (const Error&) {
    return;  // rejecting bad input with a ppp::Error is the contract
  }
  std::string formatted;
  try {
    formatted = format(read);
  } catch (const Error& e) {
    finding(target, "the writer refuses what the reader accepted", e.what());
  }
  decltype(read) reread;
  try {
    reread = parse(formatted, "formatted " + source);
  } catch (const Error& e) {
    finding(target, "the reader rejects the writer's output",
            std::string(e.what()) + "\n--- formatted ---\n" + formatted);
  }
  if (!same(reread, read)) finding(target, "writing and reading again changed the value", formatted);
  if (format(reread) != formatted) finding(target, "writing what was read back gave different text", formatted);
}

}  // namespace fuzz
}  // namespace ppp
