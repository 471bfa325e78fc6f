// The agreement: one MPI_Allreduce finds the lowest failing rank (or none),
// which then broadcasts the kind of its error and its message.
#include "halfspace/mpi/agreement.hpp"

#include <new>
#include <stdexcept>
#include <string>

#include "halfspace/error.hpp"

namespace halfspace::mpi {
namespace {

enum class ErrorKind : int { input = 1, file = 2, memory = 3, other = 4 };

std::pair<ErrorKind, std::string> classify(std::exception_ptr error) {
  try {
    std::rethrow_exception(error);
  } catch (const FileError& e) {
    return {ErrorKind::file, e.what()};
  } catch (const InputError& e) {
    return {ErrorKind::input, e.what()};
  } catch (const std::bad_alloc&) {
    return {ErrorKind::memory, "out of memory"};
  } catch (const std::exception& e) {
    return {ErrorKind::other, e.what()};
  } catch (...) {
    return {ErrorKind::other, "unknown error"};
  }
}

}  // namespace

void agree_on_outcome(const MpiCommunicator& comm, std::exception_ptr error) {
  const int mine = error ? comm.rank() : comm.size();
  int first = mine;
  check(MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, comm.get()), "MPI_Allreduce");
  if (first == comm.size()) return;
  std::pair<ErrorKind, std::string> what{ErrorKind::other, {}};
  if (comm.rank() == first) what = classify(error);
  int header[2] = {static_cast<int>(what.first), static_cast<int>(what.second.size())};
  check(MPI_Bcast(header, 2, MPI_INT, first, comm.get()), "MPI_Bcast");
  what.first = static_cast<ErrorKind>(header[0]);
  what.second.resize(static_cast<std::size_t>(header[1]));
  check(MPI_Bcast(what.second.data(), header[1], MPI_CHAR, first, comm.get()), "MPI_Bcast");
  if (comm.rank() == first) std::rethrow_exception(error);
  switch (what.first) {
    case ErrorKind::file:
      throw FileError(what.second);
    case ErrorKind::input:
      throw InputError(what.second);
    case ErrorKind::memory:
      throw std::bad_alloc();
    case ErrorKind::other:
      break;
  }
  throw std::runtime_error(what.second);
}

}  // namespace halfspace::mpi
