#pragma once

#include <string>
#include <vector>

#include "ppp_core/append_file.hpp"

namespace ppp {

/// Quotes a CSV field when it holds a comma, quote or line break (RFC 4180).
std::string csvField(const std::string& value);

/// Joins fields into one CSV line (without the line break).
std::string csvLine(const std::vector<std::string>& fields);

/// Writes CSV rows to a file, each row written whole at once, so nothing written is lost if the process dies.
class CsvWriter {
 public:
  /// Creates (or truncates) the file and writes the header row. @throws IoError.
  CsvWriter(const std::string& path, const std::vector<std::string>& header);
  /// Appends one row; it must have as many fields as the header. @throws IoError, InvalidArgument.
  void write(const std::vector<std::string>& row);

 private:
  std::string path_;
  std::size_t columns_;
  AppendFile out_;
};

/// Formats a double with up to 6 significant digits, no trailing zeros ("0.5625"), whatever the C locale.
std::string formatNumber(double value);

}  // namespace ppp
