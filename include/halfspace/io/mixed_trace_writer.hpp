// The trace of a mixed film's solve (lubricate --trace): one CSV line per
// Newton solve as it ends (lubrication::MixedSolveRecord), flushed at once,
// so that a run of hours can be followed while it runs and read afterwards
// for where its time went (docs/file-format.md#mixed-film-traces). Unlike
// the result files it is a log: it grows as the run goes and stays as far
// as the run got.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

#include "halfspace/lubrication/mixed_film.hpp"

namespace halfspace::io {

class MixedTraceWriter {
 public:
  // Creates (or truncates) the file and writes the header. Throws FileError
  // naming the path if it cannot be written.
  explicit MixedTraceWriter(const std::filesystem::path& path);

  // Appends the solve's line. A failed write (a full disk) does not stop
  // the solve it is called from (on several processes the others would
  // wait for this one): the trace stops there and failure() says why.
  void write(const lubrication::MixedSolveRecord& record);
  // Empty, or the message of the write that failed (naming the path).
  const std::string& failure() const { return failure_; }

  // The library's callback, writing into this object (which must outlive it).
  lubrication::MixedSolveTrace callback();

 private:
  std::filesystem::path path_;
  std::ofstream out_;
  int solves_ = 0;
  std::string failure_;
};

}  // namespace halfspace::io
