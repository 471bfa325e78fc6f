// The influence operator K as a multiplier on the grid of its transform, for
// solvers whose unknowns live there: the adhesive energy's displacement, whose
// stiffness K^-1 is a multiplier there but not on a free grid's own cells.
// Periodic grids: the grid itself. Free grids: the zero-padded (2ny, 2nx) (1D:
// 2nx) wrap-around grid of the DC-FFT, on which K is the circulant whose block
// of the grid's cells is InfluenceOperator::apply (its padding feels no
// interaction, so a stationary point has no pressure there).
#pragma once

#include <cstddef>
#include <span>

namespace halfspace::operators {

class CirculantForm {
 public:
  virtual ~CirculantForm() = default;

  // The cells of the transform grid this process holds, rows of row_stride()
  // cells, row-major.
  virtual std::size_t local_size() const = 0;
  // The cells of the transform grid on every process.
  virtual std::size_t size() const = 0;
  virtual std::size_t row_stride() const = 0;
  // Whether the transform grid is the grid itself (periodic) or padded (free).
  bool padded() const { return padded_; }

  // out = K in: the displacement (m) of pressures (Pa) on the transform grid;
  // the periodic mean mode is 0. Collective; in place allowed; allocates
  // nothing.
  virtual void apply(std::span<const double> in, std::span<double> out) = 0;
  // out = S in with S = K^-1, the stiffness (Pa/m), 0 at the periodic mean
  // mode. The same conventions.
  virtual void apply_inverse(std::span<const double> in, std::span<double> out) = 0;

 protected:
  explicit CirculantForm(bool padded) : padded_(padded) {}

 private:
  bool padded_;
};

}  // namespace halfspace::operators
