// Passive OpenMP waiting for a program (the halfspace program, the film
// benchmarks), by executing it again with the policy in its environment
// (see the header for why).
#include "halfspace/openmp_waiting.hpp"

#include <unistd.h>

#include <cstdlib>

namespace halfspace {

namespace {

// Set and not empty (the runtime ignores an empty value).
bool chosen(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0';
}

}  // namespace

void use_passive_openmp_waiting(char** argv) {
  if (chosen("OMP_WAIT_POLICY") || chosen("GOMP_SPINCOUNT")) return;
  // Set before the exec, so that the second start returns above: never a loop.
  if (::setenv("OMP_WAIT_POLICY", "passive", 1) != 0) return;
  ::execv("/proc/self/exe", argv);
}

}  // namespace halfspace
