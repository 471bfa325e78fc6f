// What the program is doing, kept so that a failure nobody foresaw (out of
// memory, above all) can still say what was being done when it happened:
// "out of memory while building the solver (pk-multilevel on the 4096x4096
// grid)" rather than "std::bad_alloc".
#pragma once

#include <string>

namespace halfspace::app {

// Marks one step of a run for its lifetime; steps nest.
class Activity {
 public:
  explicit Activity(std::string description);
  ~Activity();
  Activity(const Activity&) = delete;
  Activity& operator=(const Activity&) = delete;

  // The innermost step an exception left, if one did (the first to see it
  // unwind); else the innermost step still running; else "starting".
  static std::string failed_while();

 private:
  int exceptions_at_start_;
};

}  // namespace halfspace::app
