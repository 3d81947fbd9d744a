#include "ppp_core/csv.hpp"

#include "ppp_core/error.hpp"
#include "ppp_core/text_format.hpp"

namespace ppp {

std::string csvField(const std::string& value) {
  if (value.find_first_of(",\"\r\n") == std::string::npos) return value;
  std::string quoted = "\"";
  for (char c : value) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

std::string csvLine(const std::vector<std::string>& fields) {
  std::string line;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i > 0) line += ',';
    line += csvField(fields[i]);
  }
  return line;
}

CsvWriter::CsvWriter(const std::string& path, const std::vector<std::string>& header)
    : path_(path), columns_(header.size()), out_(path, true) {
  write(header);
}

void CsvWriter::write(const std::vector<std::string>& row) {
  if (row.size() != columns_) {
    throw InvalidArgument(path_, "row of " + std::to_string(row.size()) + " fields, header has " +
                                     std::to_string(columns_));
  }
  out_.append(csvLine(row) + '\n');
}

std::string formatNumber(double value) { return formatGeneral(value, 6); }

}  // namespace ppp
