#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace ppp {

/// Walks a text file line by line (ends `\n` or `\r\n`) and raises ParseErrors that point at the current line.
class LineCursor {
 public:
  /// Walks `text`, naming `source` in errors; both must outlive the cursor.
  LineCursor(const std::string& text, const std::string& source) : text_(text), source_(source) {}

  /// The next line without its terminator; false at the end of the text.
  bool next(std::string_view* line);

  /// The next line. @throws ParseError "unexpected end of file; expected <expected>" on the line after the last.
  std::string_view require(const std::string& field, const std::string& expected);

  /// @throws ParseError for `field` at the current line.
  [[noreturn]] void fail(const std::string& field, const std::string& what) const;
  /// @throws ParseError for `field` at the 1-based `line` (0: the file as a whole).
  [[noreturn]] void fail(int line, const std::string& field, const std::string& what) const;

  /// The 1-based number of the line last returned, 0 before the first.
  int line() const { return line_; }

 private:
  const std::string& text_;
  const std::string& source_;
  std::size_t pos_ = 0;
  int line_ = 0;
};

/// The fields of a line, separated by runs of spaces and tabs.
std::vector<std::string_view> splitFields(std::string_view line);

/// `text` in single quotes for an error message: cut after 40 characters with "...", bytes outside printable
/// ASCII shown as \xNN.
std::string quotedExcerpt(std::string_view text);

}  // namespace ppp
