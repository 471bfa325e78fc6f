// The MPI environment of a program: MPI_Init_thread (funneled: OpenMP threads
// inside a process never call MPI), FFTW's threads and FFTW-MPI, and
// MPI_Finalize at the end. Compiled only with HALFSPACE_MPI.
#pragma once

namespace halfspace::mpi {

class Session {
 public:
  // Throws std::runtime_error if MPI does not give funneled thread support.
  Session(int& argc, char**& argv);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  // MPI_COMM_WORLD's size and this process's rank in it.
  int size() const { return size_; }
  int rank() const { return rank_; }

  // Ends every process of MPI_COMM_WORLD with `code` (MPI_Abort): for a
  // failure on one process in the middle of collective work, where the
  // others cannot learn of it otherwise.
  [[noreturn]] static void abort(int code);

 private:
  int size_ = 1;
  int rank_ = 0;
};

}  // namespace halfspace::mpi
