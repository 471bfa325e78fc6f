// Errors that reach every MPI process. A phase that can fail (reading the
// options and the surface, writing the result) ends on every process with an
// agreement on its outcome: if it threw anywhere, every process throws the
// error of the lowest rank that failed, with its type and message, so that
// the program prints one message, exits with the same code everywhere and no
// process waits for another that gave up. Compiled only with HALFSPACE_MPI.
#pragma once

#include <exception>
#include <utility>

#include "halfspace/mpi/mpi_communicator.hpp"

namespace halfspace::mpi {

// Collective. Returns if `error` is null on every process; otherwise throws,
// on every process, the lowest failing rank's error as InputError, FileError
// (both with its message), std::bad_alloc, or std::runtime_error (any other
// exception, with its what()).
void agree_on_outcome(const MpiCommunicator& comm, std::exception_ptr error);

// Runs phase() on every process, then agree_on_outcome. Collective.
template <class Phase>
void run_agreed(const MpiCommunicator& comm, Phase&& phase) {
  std::exception_ptr error;
  try {
    std::forward<Phase>(phase)();
  } catch (...) {
    error = std::current_exception();
  }
  agree_on_outcome(comm, error);
}

}  // namespace halfspace::mpi
