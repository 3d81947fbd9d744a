#include "ppp_core/line_cursor.hpp"

#include <cstdio>

#include "ppp_core/error.hpp"

namespace ppp {

bool LineCursor::next(std::string_view* line) {
  if (pos_ >= text_.size()) return false;
  std::size_t end = text_.find('\n', pos_);
  if (end == std::string::npos) end = text_.size();
  std::string_view view(text_.data() + pos_, end - pos_);
  if (!view.empty() && view.back() == '\r') view.remove_suffix(1);
  pos_ = end + 1;
  ++line_;
  *line = view;
  return true;
}

std::string_view LineCursor::require(const std::string& field, const std::string& expected) {
  std::string_view line;
  if (!next(&line)) fail(line_ + 1, field, "unexpected end of file; expected " + expected);
  return line;
}

void LineCursor::fail(const std::string& field, const std::string& what) const { fail(line_, field, what); }

void LineCursor::fail(int line, const std::string& field, const std::string& what) const {
  throw ParseError(source_, line, field, what);
}

std::vector<std::string_view> splitFields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) fields.push_back(line.substr(start, i - start));
  }
  return fields;
}

std::string quotedExcerpt(std::string_view text) {
  constexpr std::size_t kShown = 40;
  std::string shown;
  for (unsigned char c : text.substr(0, kShown)) {
    if (c >= 0x20 && c < 0x7f) {
      shown.push_back(static_cast<char>(c));
    } else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      shown += hex;
    }
  }
  if (text.size() > kShown) shown += "...";
  return "'" + shown + "'";
}

}  // namespace ppp
