// FFTW's threads must be set up before FFTW-MPI (fftw3-mpi.h: fftw_init_threads
// first, then fftw_mpi_init); both under the planner's lock.
#include "halfspace/mpi/session.hpp"

#include <fftw3-mpi.h>
#include <mpi.h>

#include <cstdlib>
#include <mutex>
#include <stdexcept>

#include "../fft/fftw_planner.hpp"

namespace halfspace::mpi {

Session::Session(int& argc, char**& argv) {
  int provided = MPI_THREAD_SINGLE;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  if (provided < MPI_THREAD_FUNNELED) {
    MPI_Finalize();
    throw std::runtime_error("the MPI library does not support threads (MPI_THREAD_FUNNELED)");
  }
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  const std::lock_guard<std::mutex> lock(fft::detail::fftw_planner_mutex());
  fft::detail::init_fftw_threads();
  fftw_mpi_init();
}

Session::~Session() {
  {
    const std::lock_guard<std::mutex> lock(fft::detail::fftw_planner_mutex());
    fftw_mpi_cleanup();
  }
  MPI_Finalize();
}

void Session::abort(int code) {
  MPI_Abort(MPI_COMM_WORLD, code);
  std::abort();  // MPI_Abort does not return; for the compiler
}

}  // namespace halfspace::mpi
