// The operators every layout makes on its transforms, and the serial
// layout: the whole grid on this process, one slab.
#include "halfspace/solvers/layout.hpp"

#include "halfspace/fft/grid_transform.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"
#include "halfspace/operators/single_precision_fft_operator.hpp"
#include "halfspace/solvers/fourier_preconditioner.hpp"
#include "halfspace/solvers/level_transfer.hpp"
#include "halfspace/solvers/solver_options.hpp"

namespace halfspace::solvers {
namespace {

class SerialLayout final : public Layout {
 public:
  explicit SerialLayout(bool estimated_plans) : estimated_plans_(estimated_plans) {}

  std::unique_ptr<operators::SpectralTransforms> make_transforms(
      const Grid& grid, FftPlanning planning, const operators::TransformsShape& shape) const override {
    return operators::make_serial_transforms(grid, estimated_plans_ ? FftPlanning::estimate : planning, shape);
  }
  // Periodic grids: the double transform for the products K p, and one in
  // single precision for the step's products and M^-1, living in the double
  // transform's spectrum (idle between the products K p, and it holds
  // exactly the single transform's spectrum and real array; the real array
  // is the products' scratch), and the single-precision K multiplying by the
  // double one's symbol. Free grids: the
  // products stay double (they need the zero-padded transform); M^-1 in
  // single precision in the padded buffer.
  ElasticOperators make_mixed_operators(const Grid& grid, const HalfSpace& half_space, bool fourier,
                                        FftPlanning planning) const override {
    if (estimated_plans_) planning = FftPlanning::estimate;
    ElasticOperators made;
    if (grid.periodic()) {
      auto exact =
          std::make_unique<FftInfluenceOperator>(grid, half_space, make_transforms(grid, planning, {.count = 1}));
      const EvenSymbol& kernel = exact->symbol();
      auto single = make_single_grid_transform(grid, planning, exact->transforms()->workspace());
      auto inner = std::make_unique<SinglePrecisionFftOperator>(*exact, single);
      made.op = std::move(exact);
      made.single.kernel = [op = inner.get()](std::span<const float> in, std::span<float> out) { op->apply(in, out); };
      made.single.scratch = single->input();
      made.inner = std::move(inner);
      if (fourier) {
        auto preconditioner = std::make_unique<FourierPreconditioner>(grid, half_space, kernel, single);
        made.single.precondition = [m = preconditioner.get()](std::span<const float> in, std::span<float> out) {
          m->apply(in, out);
        };
        made.fourier = std::move(preconditioner);
      }
      return made;
    }
    auto op = std::make_unique<FftInfluenceOperator>(grid, half_space, make_transforms(grid, planning, {.count = 1}));
    if (fourier) {
      made.fourier = std::make_unique<FourierPreconditioner>(
          grid, half_space, make_single_grid_transform(grid, planning, op->transforms()->workspace()));
    }
    made.op = std::move(op);
    return made;
  }
  RowSlab rows(const Grid& grid) const override { return {0, grid.dimension() == 1 ? 1 : grid.ny()}; }
  const linalg::Communicator& communicator() const override { return linalg::serial_communicator(); }

 private:
  bool estimated_plans_;
};

}  // namespace

ElasticOperators Layout::make_operators(const Grid& grid, const HalfSpace& half_space, bool fourier,
                                        FftPlanning planning) const {
  ElasticOperators made;
  auto op = std::make_unique<FftInfluenceOperator>(grid, half_space, make_transforms(grid, planning, {.count = 1}));
  if (fourier) {
    made.fourier = make_fourier_preconditioner(
        *op, [&](const operators::TransformsShape& shape) { return make_transforms(grid, planning, shape); });
  }
  made.op = std::move(op);
  return made;
}

std::unique_ptr<TangentialOperator> Layout::make_tangential_operator(const Grid& grid, const ElasticPair& pair,
                                                                     FftPlanning planning) const {
  return std::make_unique<TangentialOperator>(grid, pair, make_transforms(grid, planning));
}

// Every level whole here (the MultilevelSolver's default).
std::unique_ptr<LevelTransfer> Layout::level_transfer(const Grid& /*fine*/, std::size_t /*min_cells_per_axis*/) const {
  return nullptr;
}

ElasticOperators Layout::make_mixed_operators(const Grid& /*grid*/, const HalfSpace& /*half_space*/, bool /*fourier*/,
                                              FftPlanning /*planning*/) const {
  throw SolverOptionError("precision", "mixed",
                          "is not available with more than one process yet: use precision double (one process "
                          "solves mixed)");
}

const Layout& serial_layout() {
  static const SerialLayout serial(false);
  return serial;
}

const Layout& redundant_layout() {
  static const SerialLayout redundant(true);
  return redundant;
}

}  // namespace halfspace::solvers
