#pragma once

#include <stdexcept>
#include <string>

namespace ppp {

/// Base of every error the PPP libraries throw for bad input; what() names the culprit.
class Error : public std::runtime_error {
 public:
  /// Wraps a complete, human-readable message.
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

/// A file or directory could not be opened, read or written.
class IoError : public Error {
 public:
  /// Message: "<path>: <what failed>".
  IoError(const std::string& path, const std::string& what) : Error(path + ": " + what) {}
};

/// A text file is malformed; what() reads "<file>:<line>: <field>: <what is wrong>".
class ParseError : public Error {
 public:
  /// Records where the problem is so callers can point the user at it.
  ParseError(const std::string& file, int line, const std::string& field, const std::string& what)
      : Error(file + ":" + std::to_string(line) + ": " + field + ": " + what),
        file_(file),
        line_(line),
        field_(field) {}
  /// The file being parsed.
  const std::string& file() const { return file_; }
  /// The 1-based line of the fault (0 when the fault is the file as a whole).
  int line() const { return line_; }
  /// The field or keyword at fault.
  const std::string& field() const { return field_; }

 private:
  std::string file_;
  int line_;
  std::string field_;
};

/// An option or parameter is out of range; what() reads "<name>: <what was expected>".
class InvalidArgument : public Error {
 public:
  /// Names the option and the expectation it violates.
  InvalidArgument(const std::string& name, const std::string& what)
      : Error(name + ": " + what), name_(name), problem_(what) {}
  /// The option or parameter at fault.
  const std::string& name() const { return name_; }
  /// What is wrong with it (the message without the name).
  const std::string& problem() const { return problem_; }

 private:
  std::string name_;
  std::string problem_;
};

}  // namespace ppp
