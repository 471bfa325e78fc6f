// The mixed film's trace as CSV (mixed_trace_writer.hpp). Each line is
// flushed: a trace read while the run goes, or after it was killed, ends
// at the last solve that ended.
#include "halfspace/io/mixed_trace_writer.hpp"

#include <fmt/format.h>

#include "halfspace/error.hpp"

namespace halfspace::io {

MixedTraceWriter::MixedTraceWriter(const std::filesystem::path& path)
    : path_(path), out_(path, std::ios::out | std::ios::trunc) {
  out_ << "solve,nx,ny,entrainment_speed,smoothing,start,checked_step_branches,status,newton_steps,"
          "gmres_iterations,most_gmres_per_step,line_search_halvings,watchdog_steps,relative_residual,"
          "contact_load_fraction,wall_seconds\n";
  out_.flush();
  if (!out_) throw FileError(fmt::format("cannot write the mixed film's trace to '{}'", path_.string()));
}

void MixedTraceWriter::write(const lubrication::MixedSolveRecord& r) {
  if (!failure_.empty()) return;
  ++solves_;
  out_ << fmt::format("{},{},{},{:.9g},{:.3g},{},{},{},{},{},{},{},{},{:.6g},{:.6g},{:.6g}\n", solves_, r.nx, r.ny,
                      r.entrainment_speed, r.smoothing, r.warm ? "warm" : "cold", r.checked_step_branches ? 1 : 0,
                      lubrication::to_string(r.status), r.newton_steps, r.krylov_iterations, r.most_krylov_per_step,
                      r.line_search_halvings, r.watchdog_steps, r.relative_residual, r.contact_load_fraction,
                      r.wall_seconds);
  out_.flush();
  if (!out_) {
    failure_ =
        fmt::format("writing the mixed film's trace to '{}' failed after {} solves", path_.string(), solves_ - 1);
  }
}

lubrication::MixedSolveTrace MixedTraceWriter::callback() {
  return [this](const lubrication::MixedSolveRecord& record) { write(record); };
}

}  // namespace halfspace::io
