#pragma once

// Numbers and text for files and pictures people read (CSV, YAML, SVG, HTML): the same bytes whatever the C
// locale says.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace ppp {

/// `value` with `decimals` digits after the point, as printf's "%.*f" in the C locale: (2.46, 1) -> "2.5".
std::string formatFixed(double value, int decimals);

/// `value` with up to `significant_digits` significant digits, as printf's "%.*g" in the C locale: 0.5625 -> "0.5625".
std::string formatGeneral(double value, int significant_digits);

/// The shortest text that reads back as exactly `value`, independent of the C locale: 0.1 -> "0.1".
std::string formatShortest(double value);

/// Characters of UTF-8 text as displayed: every byte but the continuation bytes.
std::size_t displayLength(const std::string& text);

/// `text` cut to at most `limit` displayed characters, the last one then an ellipsis (U+2026); never splits a
/// UTF-8 sequence. A limit of 0 gives "".
std::string shortenText(const std::string& text, std::size_t limit);

/// Escapes `& < > " '` so text can go into HTML or SVG, as element text or inside a quoted attribute.
std::string escapeMarkup(const std::string& text);

/// One shell word: `word` as is when made of letters, digits and ._-/+=:,@ only, else single-quoted.
std::string shellWord(const std::string& word);

/// `value` as 16 lowercase hex digits ("00000000000000ff"): a hash in a file name or a CSV column.
std::string formatHex64(std::uint64_t value);

/// The items separated by ", " (for error messages listing the valid names).
std::string joinNames(const std::vector<std::string>& items);

/// A 1-2-5 step (..., 0.5, 1, 2, 5, 10, ...) giving about five axis ticks from 0 up to `top` (> 0).
double tickStep(double top);

}  // namespace ppp
