#pragma once

#include <string>
#include <vector>

namespace ppp {
namespace generator {

// set.csv, the index of a set directory written by writeProblemSetDirectory: a header, then one row per PPP
// (id, its .ppp file in the directory, fitness, fitness value, its characters, nearest_difference).

/// The columns of set.csv, in order.
std::vector<std::string> setCsvHeader();

/// The `.ppp` files set.csv text lists, in its order, as names in the set's directory; `csv_path` is named in
/// errors. Sets written before nearest_difference existed are read too. @throws ParseError naming `csv_path`, the
/// line and the field ("header", "file" or "set").
std::vector<std::string> parseSetCsv(const std::string& text, const std::string& csv_path);

}  // namespace generator
}  // namespace ppp
