// Exception types for bad input and configuration, and how their messages
// show numbers. Numerical outcomes (no convergence, breakdown) are never
// exceptions: solvers return them as status.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

namespace halfspace {

// Bad input or configuration: the message names the parameter or file, the
// offending value and the allowed range.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

// A file that cannot be read or written: missing, unreadable, wrong layout.
class FileError : public InputError {
 public:
  explicit FileError(const std::string& message) : InputError(message) {}
};

// A bad value of one named option or parameter. option() is its name as the
// library spells it ("approach", "tolerance", "adhesion.work"), value() its
// value as text and rule() the rest of the sentence ("is invalid: allowed
// range is (0, 1)"), so that a front end can restate it with its own
// spelling (a CLI flag, a Python keyword); what() is "option = value rule".
class OptionError : public InputError {
 public:
  OptionError(std::string option, std::string value, std::string rule);
  const std::string& option() const { return option_; }
  const std::string& value() const { return value_; }
  const std::string& rule() const { return rule_; }

 private:
  std::string option_;
  std::string value_;
  std::string rule_;
};

// A number as messages show it: six significant digits ("1.31072",
// "9.90393e-07"), what a user typed rather than the round-trip digits of
// the binary value ("1.3107199999999999"). Every message built from a
// double goes through it (or the same "{:.6g}" format).
std::string format_number(double value);

}  // namespace halfspace
