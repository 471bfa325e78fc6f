// Love's coefficients k(|i|, |j|) on the (2ny, 2nx) wrap-around grid are the
// quadrant 0 <= i <= nx, 0 <= j <= ny mirrored in both axes
// (NormalKernel::write_padded), so their DFT is real and is the 2D
// DCT-I (FFTW's REDFT00) of the quadrant: kx = 0 .. nx, ky = 0 .. ny, and
// ky > ny reads 2ny - ky. Each process evaluates the quadrant rows FFTW-MPI
// gives it, transforms them along x, FFTW-MPI transposes the quadrant to the
// padded transform's columns, and each process transforms its columns along
// y: it never holds more than its share of the quadrant. A coated body whose
// remainder goes in spectrally (NormalKernel::spectral_remainder) adds it
// to its columns' bins, and K_ii is then the inverse DFT at offset 0, summed
// over the processes' columns.
//
// The circulant form (the adhesive energy's grid) is the whole (2ny, 2nx)
// wrap-around grid, its padding rows ny + j held by the process holding row
// j: each half is transformed as a top half by the pruned transform, and a
// shift by ny rows multiplies the spectrum by (-1)^ky, so the whole
// spectrum is A + (-1)^ky B, and the bottom half of an inverse is the top
// half of the inverse of (-1)^ky times the spectrum.
#include "halfspace/mpi/slab_free_operator.hpp"

#include <fftw3-mpi.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <complex>
#include <limits>
#include <memory>
#include <mutex>
#include <new>
#include <stdexcept>
#include <utility>
#include <vector>

#include "../fft/fftw_planner.hpp"
#include "halfspace/error.hpp"
#include "halfspace/kernels/normal_kernel.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/operators/circulant_form.hpp"
#include "halfspace/threads.hpp"

namespace halfspace::mpi {
namespace {

const Grid& checked_free_grid(const Grid& grid) {
  if (grid.dimension() != 2 || grid.periodic()) {
    throw InputError(fmt::format("SlabFreeOperator: the distributed operator needs a free 2D grid, not a {} {}D one",
                                 to_string(grid.boundary()), grid.dimension()));
  }
  return grid;
}

// The one-off buffer and plans of the coefficients' transform, released
// whatever happens.
class QuadrantTransform {
 public:
  explicit QuadrantTransform(std::size_t values) : values_(fftw_alloc_real(std::max<std::size_t>(values, 1))) {
    if (values_ == nullptr) throw std::bad_alloc();
  }
  ~QuadrantTransform() {
    const std::lock_guard<std::mutex> lock(fft::detail::fftw_planner_mutex());
    for (fftw_plan plan : plans_) fftw_destroy_plan(plan);
    fftw_free(values_);
  }
  QuadrantTransform(const QuadrantTransform&) = delete;
  QuadrantTransform& operator=(const QuadrantTransform&) = delete;

  double* values() { return values_; }
  // Keeps `plan` to destroy it; throws std::runtime_error if it is null.
  fftw_plan keep(fftw_plan plan) {
    if (plan == nullptr) throw std::runtime_error("FFTW-MPI could not plan the free operator's coefficient transform");
    plans_.push_back(plan);
    return plan;
  }

 private:
  double* values_;
  std::vector<fftw_plan> plans_;
};

// howmany DCT-I (REDFT00) of n values each, contiguous, in place.
fftw_plan dct_rows(QuadrantTransform& buffer, std::size_t n, std::size_t howmany) {
  const int length[1] = {static_cast<int>(n)};
  const fftw_r2r_kind kind[1] = {FFTW_REDFT00};
  return buffer.keep(fftw_plan_many_r2r(1, length, static_cast<int>(howmany), buffer.values(), nullptr, 1,
                                        static_cast<int>(n), buffer.values(), nullptr, 1, static_cast<int>(n), kind,
                                        FFTW_ESTIMATE | FFTW_DESTROY_INPUT));
}

// K and K^-1 on the whole padded grid, this process's rows j and ny + j,
// each 2nx wide: local arrays [the rows j | the rows ny + j].
class SlabPaddedCirculantForm final : public operators::CirculantForm {
 public:
  // `top` is the operator's transform (its buffer used only inside a
  // product); `kernel` and `stiffness` on this process's columns, folded in
  // ky as SlabFreeOperator's symbol, with 1/N of one transform pair in.
  SlabPaddedCirculantForm(SlabPaddedRealFft& top, std::unique_ptr<SlabPaddedRealFft> bottom, std::vector<double> kernel,
                          std::vector<double> stiffness)
      : CirculantForm(true),
        top_(top),
        bottom_(std::move(bottom)),
        kernel_(std::move(kernel)),
        stiffness_(std::move(stiffness)) {}
  std::size_t local_size() const override { return 4 * top_.layout().local_size(); }
  std::size_t size() const override { return static_cast<std::size_t>(top_.padded_size()); }
  std::size_t row_stride() const override { return 2 * top_.layout().nx; }
  void apply(std::span<const double> in, std::span<double> out) override { multiply(in, out, kernel_); }
  void apply_inverse(std::span<const double> in, std::span<double> out) override { multiply(in, out, stiffness_); }

 private:
  void multiply(std::span<const double> in, std::span<double> out, const std::vector<double>& symbol) {
    assert(in.size() == local_size() && out.size() == local_size());
    const std::size_t half = local_size() / 2;
    // In place is safe: both halves are read before either is written.
    top_.forward_wide(in.first(half));
    bottom_->forward_wide(in.subspan(half));
    const std::size_t ny = top_.layout().ny;
    const std::size_t padded_rows = 2 * ny;
    std::complex<double>* a = top_.spectrum().data();
    std::complex<double>* b = bottom_->spectrum().data();
    linalg::for_each_row(top_.layout().columns, padded_rows, [&](std::size_t c) {
      const double* column = symbol.data() + c * (ny + 1);
      for (std::size_t r = 0; r < padded_rows; ++r) {
        const std::size_t k = c * padded_rows + r;
        const double sign = r % 2 == 0 ? 1.0 : -1.0;
        const std::complex<double> product = (a[k] + sign * b[k]) * column[r <= ny ? r : padded_rows - r];
        a[k] = product;
        b[k] = sign * product;
      }
    });
    top_.backward_wide(out.first(half));
    bottom_->backward_wide(out.subspan(half));
  }

  SlabPaddedRealFft& top_;
  std::unique_ptr<SlabPaddedRealFft> bottom_;
  std::vector<double> kernel_;
  std::vector<double> stiffness_;
};

}  // namespace

SlabFreeOperator::~SlabFreeOperator() = default;

SlabFreeOperator::SlabFreeOperator(const Grid& grid, const HalfSpace& half_space, const MpiCommunicator& comm,
                                   FftPlanning planning)
    : grid_(checked_free_grid(grid)), planning_(planning) {
  const kernels::NormalKernel kernel(grid, half_space);
  fft_ = std::make_unique<SlabPaddedRealFft>(grid.nx(), grid.ny(), comm, planning);
  const SlabLayout& layout = fft_->layout();
  const std::size_t nx = grid.nx();
  const std::size_t ny = grid.ny();

  // The quadrant's rows here, and after the transpose its columns, which
  // must be the padded transform's (both FFTW-MPI's default block of nx + 1).
  const ptrdiff_t n[2] = {static_cast<ptrdiff_t>(ny + 1), static_cast<ptrdiff_t>(nx + 1)};
  ptrdiff_t rows = 0;
  ptrdiff_t first_row = 0;
  ptrdiff_t columns = 0;
  ptrdiff_t first_column = 0;
  const ptrdiff_t allocation = fftw_mpi_local_size_many_transposed(
      2, n, 1, FFTW_MPI_DEFAULT_BLOCK, FFTW_MPI_DEFAULT_BLOCK, comm.get(), &rows, &first_row, &columns, &first_column);
  if (static_cast<std::size_t>(columns) != layout.columns ||
      static_cast<std::size_t>(first_column) != layout.first_column) {
    throw std::logic_error("FFTW-MPI distributes the free operator's coefficient columns unlike its transform's");
  }
  QuadrantTransform quadrant(static_cast<std::size_t>(allocation));
  double* values = quadrant.values();
  const std::vector<double> rows_here =
      kernel.free_quadrant(static_cast<std::size_t>(first_row), static_cast<std::size_t>(rows));
  std::copy(rows_here.begin(), rows_here.end(), values);
  fftw_plan along_x = nullptr;
  fftw_plan transpose = nullptr;
  fftw_plan along_y = nullptr;
  {
    const std::lock_guard<std::mutex> lock(fft::detail::fftw_planner_mutex());
    fftw_plan_with_nthreads(threads());
    if (rows > 0) along_x = dct_rows(quadrant, nx + 1, static_cast<std::size_t>(rows));
    transpose = quadrant.keep(fftw_mpi_plan_many_transpose(
        n[0], n[1], 1, FFTW_MPI_DEFAULT_BLOCK, FFTW_MPI_DEFAULT_BLOCK, values, values, comm.get(), FFTW_ESTIMATE));
    if (columns > 0) along_y = dct_rows(quadrant, ny + 1, static_cast<std::size_t>(columns));
  }
  if (along_x != nullptr) fftw_execute(along_x);
  fftw_execute(transpose);
  if (along_y != nullptr) fftw_execute(along_y);
  // FFTW's transforms are unnormalised: fold 1/N of the padded grid in.
  const double inverse_n = 1.0 / fft_->padded_size();
  symbol_.resize(layout.columns * (ny + 1));
  linalg::for_each_index(symbol_.size(), [&](std::size_t k) { symbol_[k] = values[k] * inverse_n; });
  if (!kernel.spectral_remainder()) {
    self_ = kernel.self_influence();
    return;
  }
  linalg::for_each_row(layout.columns, ny + 1, [&](std::size_t c) {
    for (std::size_t r = 0; r <= ny; ++r) {
      symbol_[c * (ny + 1) + r] += kernel.padded_remainder(r, layout.first_column + c) * inverse_n;
    }
  });
  // The inverse DFT at offset 0: every bin of the (2ny, 2nx) spectrum, the
  // columns other than kx = 0 and nx and the rows other than ky = 0 and ny
  // standing for two each.
  double sum = 0.0;
  for (std::size_t c = 0; c < layout.columns; ++c) {
    const std::size_t kx = layout.first_column + c;
    double column = 0.0;
    for (std::size_t r = 0; r <= ny; ++r) column += (r == 0 || r == ny ? 1.0 : 2.0) * symbol_[c * (ny + 1) + r];
    sum += (kx == 0 || kx == nx ? 1.0 : 2.0) * column;
  }
  std::array<double, 1> total{sum};
  comm.sum(total);
  self_ = total[0];
}

void SlabFreeOperator::apply(std::span<const double> pressure, std::span<double> displacement) {
  assert(pressure.size() == local_size() && displacement.size() == local_size());
  // In place is safe: forward() reads all of the pressure before backward()
  // writes the displacement.
  fft_->forward(pressure);
  const std::size_t ny = grid_.ny();
  const std::size_t padded_rows = 2 * ny;
  std::span<std::complex<double>> spectrum = fft_->spectrum();
  linalg::for_each_row(fft_->layout().columns, padded_rows, [&](std::size_t c) {
    std::complex<double>* column = spectrum.data() + c * padded_rows;
    const double* symbol = symbol_.data() + c * (ny + 1);
    for (std::size_t r = 0; r <= ny; ++r) column[r] *= symbol[r];
    for (std::size_t r = ny + 1; r < padded_rows; ++r) column[r] *= symbol[padded_rows - r];
  });
  fft_->backward(displacement);
}

CirculantForm& SlabFreeOperator::circulant_form() {
  if (!circulant_) {
    // As FftInfluenceOperator's padded form: the kernel's eigenvalues k =
    // N symbol must be positive, and K^-1 is 1/(N k) with 1/N of the pair.
    const double n = fft_->padded_size();
    double smallest = std::numeric_limits<double>::infinity();
    for (const double value : symbol_) smallest = std::min(smallest, value * n);
    smallest = -fft_->communicator().max(-smallest);
    if (!(smallest > 0.0)) {
      throw InputError(
          fmt::format("the free {} grid's padded influence kernel is not positive definite (smallest eigenvalue {:g} "
                      "m/Pa), so it has no inverse (stiffness) to minimise an energy with; use a periodic grid",
                      grid_.shape_string(), smallest));
    }
    std::vector<double> stiffness(symbol_.size());
    linalg::for_each_index(symbol_.size(), [&](std::size_t k) { stiffness[k] = 1.0 / (n * (n * symbol_[k])); });
    circulant_ = std::make_unique<SlabPaddedCirculantForm>(
        *fft_, std::make_unique<SlabPaddedRealFft>(grid_.nx(), grid_.ny(), fft_->communicator(), planning_), symbol_,
        std::move(stiffness));
  }
  return *circulant_;
}

}  // namespace halfspace::mpi
