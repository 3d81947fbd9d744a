#pragma once

#include <string>

#include "ppp_core/problem.hpp"

namespace ppp {

/// Largest `.ppp` file the reader accepts, checked before reading it.
constexpr std::size_t kMaxPppFileBytes = 64u << 20;

/// Serialises a problem in the `.ppp v1` text format (see docs/reference/ppp-format.md).
/// @throws InvalidArgument when the problem itself is invalid.
std::string formatPpp(const Problem& problem);

/// Parses `.ppp v1` text; `source` names the file in error messages.
/// @throws ParseError "<source>:<line>: <field>: <what is wrong>" for any malformed or inconsistent input.
Problem parsePpp(const std::string& text, const std::string& source);

/// Reads and parses a `.ppp` file. @throws IoError, ParseError.
Problem readPppFile(const std::string& path);

/// Writes a problem as a `.ppp` file, atomically (temporary file, then rename). @throws IoError, InvalidArgument.
void writePppFile(const Problem& problem, const std::string& path);

}  // namespace ppp
