#include "ppp_core/text_format.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <system_error>

namespace ppp {

namespace {

/// std::to_chars into a buffer that grows until the text fits (fixed notation of 1e300 needs 300 digits).
template <class... Format>
std::string toChars(double value, Format... format) {
  std::string out(32, '\0');
  for (;;) {
    const auto result = std::to_chars(out.data(), out.data() + out.size(), value, format...);
    if (result.ec == std::errc()) {
      out.resize(static_cast<std::size_t>(result.ptr - out.data()));
      return out;
    }
    out.resize(out.size() * 2);
  }
}

bool isContinuationByte(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

}  // namespace

std::string formatFixed(double value, int decimals) { return toChars(value, std::chars_format::fixed, decimals); }

std::string formatGeneral(double value, int significant_digits) {
  return toChars(value, std::chars_format::general, significant_digits);
}

std::string formatShortest(double value) { return toChars(value); }

std::size_t displayLength(const std::string& text) {
  return static_cast<std::size_t>(
      std::count_if(text.begin(), text.end(), [](char c) { return !isContinuationByte(c); }));
}

std::string shortenText(const std::string& text, std::size_t limit) {
  if (displayLength(text) <= limit) return text;
  if (limit == 0) return "";
  std::size_t kept = 0;
  std::size_t i = 0;
  for (; i < text.size(); ++i) {
    if (!isContinuationByte(text[i])) {
      if (kept == limit - 1) break;
      ++kept;
    }
  }
  return text.substr(0, i) + "\xE2\x80\xA6";  // U+2026 HORIZONTAL ELLIPSIS
}

std::string shellWord(const std::string& word) {
  const bool safe = !word.empty() && std::all_of(word.begin(), word.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || std::string("._-/+=:,@").find(c) != std::string::npos;
  });
  if (safe) return word;
  std::string quoted = "'";
  for (const char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string escapeMarkup(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string formatHex64(std::uint64_t value) {
  std::string text(16, '0');
  for (std::size_t i = 16; i-- > 0; value >>= 4) text[i] = "0123456789abcdef"[value & 0xf];
  return text;
}

std::string joinNames(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

double tickStep(double top) {
  const double raw = top / 5;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double scaled = raw / magnitude;
  const double nice = scaled < 1.5 ? 1 : scaled < 3.5 ? 2 : scaled < 7.5 ? 5 : 10;
  return nice * magnitude;
}

}  // namespace ppp
