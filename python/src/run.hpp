// What a solve or a sweep leaves behind for Python: the grid, the heights it
// was solved on (the caller's array, kept alive), the steps with their
// fields, and the provenance the result files record. Results and sweeps
// share one Run, so a step's arrays are views of the fields it owns.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "halfspace/analysis/contact_statistics.hpp"
#include "halfspace/analysis/load_sweep.hpp"
#include "halfspace/elastic_pair.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/io/result_metadata.hpp"
#include "halfspace/layered_material.hpp"
#include "halfspace/solvers/tangential_loading.hpp"
#include "halfspace/solvers/tangential_result.hpp"
#include "halfspace/surface/statistics.hpp"

namespace halfspace::python {

// Holds a Python object: made and destroyed with the GIL held.
struct Run {
  Grid grid;
  nb::object heights_owner;         // the numpy array heights points into
  std::span<const double> heights;  // m, one per cell
  io::SolveProvenance provenance;   // written into every result file
  surface::SurfaceStatistics surface;
  std::vector<analysis::SweepStep> steps;
  std::vector<std::vector<std::uint8_t>> contact;  // per step: 1 where p > 0
  // Attributes of a file the run was read from (read_result); empty for a solve.
  nb::dict stored_attributes;
  std::optional<LayeredMaterial> coating;  // a coated half-space, else none
  // Both bodies, when E1, nu1, E2, nu2 were given (or read from the file's
  // body1_E ... body2_nu), and with friction the coated body too.
  // Friction (halfspace.solve(friction=...), halfspace.history): the
  // tangential steps solved, what each imposed, and per step its
  // stick map (1 where a contact cell sticks). The steps are solved under
  // steps[0]'s pressure, or, a coupled history (dissimilar bodies), step k
  // under its own, steps[k + 1] (steps[0] is then the normal loading's).
  std::optional<ElasticPair> pair;
  std::vector<TangentialResult> tangential;
  std::vector<TangentialLoading> tangential_loads;
  std::vector<std::vector<std::uint8_t>> stick;

  // The index into `steps` of tangential step k's normal solution.
  std::size_t normal_of_tangential(std::size_t k) const { return steps.size() == tangential.size() + 1 ? k + 1 : 0; }

  std::vector<std::size_t> shape() const;
  // Fills contact from the steps' pressures.
  void mark_contact();
};

// The contact statistics of a solved result on `grid`.
inline analysis::ContactStatistics contact_statistics_of(const Grid& grid, const SolveResult& result) {
  return analysis::contact_statistics(grid, {result.pressure.data(), static_cast<std::size_t>(result.pressure.size())},
                                      {result.gap.data(), static_cast<std::size_t>(result.gap.size())});
}

// One step of a Run (the only one for a single solve).
struct Result {
  std::shared_ptr<Run> run;
  std::size_t step = 0;
  std::size_t tangential_step = 0;  // the friction step shown, when run->tangential has any

  const analysis::SweepStep& data() const { return run->steps[step]; }
  const SolveResult& result() const { return data().result; }
};

// Every step of a Run.
struct Sweep {
  std::shared_ptr<Run> run;
};

// Every tangential step of a frictional Run (halfspace.history).
struct History {
  std::shared_ptr<Run> run;
};

}  // namespace halfspace::python
