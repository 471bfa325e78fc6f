// Exception types for bad input and configuration. Numerical outcomes (no
// convergence, breakdown) are never exceptions: solvers return them as status.
#pragma once

#include <stdexcept>
#include <string>

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

}  // namespace halfspace
