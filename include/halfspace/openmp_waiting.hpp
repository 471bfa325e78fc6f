// OpenMP threads that wait for work spin on their core for a while (GNU
// OpenMP: up to 300,000 spins per wait) unless OMP_WAIT_POLICY is passive.
// Alone on a machine that costs nothing; beside other busy processes the
// spinning threads take the cores those need, and solves run many times
// slower than alone (measured: docs/usage.md, Sharing the machine).
#pragma once

namespace halfspace {

// Makes this process's OpenMP threads wait passively unless the user chose a
// policy (OMP_WAIT_POLICY or GOMP_SPINCOUNT set and not empty). GNU OpenMP reads its
// environment once, when the library is loaded, before main: so this sets
// OMP_WAIT_POLICY=passive and executes the program again (same process,
// same arguments) from /proc/self/exe. Call it first thing in main. Returns
// only if nothing had to be done or the program could not be executed again
// (then it runs with the runtime's default waiting).
void use_passive_openmp_waiting(char** argv);

}  // namespace halfspace
