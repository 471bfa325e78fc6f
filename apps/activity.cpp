// The running steps of the program, for messages about unforeseen failures.
#include "activity.hpp"

#include <exception>
#include <utility>
#include <vector>

namespace halfspace::app {
namespace {

// The steps running now, outermost first, and the one an exception left.
std::vector<std::string>& running() {
  static std::vector<std::string> steps;
  return steps;
}
std::string& left_by_exception() {
  static std::string step;
  return step;
}

}  // namespace

Activity::Activity(std::string description) : exceptions_at_start_(std::uncaught_exceptions()) {
  running().push_back(std::move(description));
}

Activity::~Activity() {
  // Destroyed by unwinding: inner steps go first, so the first one recorded
  // is where the exception was thrown.
  if (std::uncaught_exceptions() > exceptions_at_start_ && left_by_exception().empty()) {
    left_by_exception() = running().back();
  }
  running().pop_back();
}

std::string Activity::failed_while() {
  if (!left_by_exception().empty()) return left_by_exception();
  if (!running().empty()) return running().back();
  return "starting";
}

}  // namespace halfspace::app
