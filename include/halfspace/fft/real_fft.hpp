// A real-to-complex / complex-to-real FFTW plan pair (RAII) over buffers it
// owns: the one place the library touches FFTW's planner.
#pragma once

#include <algorithm>
#include <complex>
#include <cstddef>
#include <span>
#include <type_traits>

#include "halfspace/fft/fft_planning.hpp"

struct fftw_plan_s;   // FFTW's opaque plan types (double and single precision),
struct fftwf_plan_s;  // so that <fftw3.h> stays private

namespace halfspace::fft {

// Where the transforms write. separate: three buffers (input, spectrum,
// output). overwrite_input: backward() writes over the input, which saves a
// real array when the input need not survive. (Zero-padded transforms are
// PaddedRealFft's.)
enum class FftOutput { separate, overwrite_input };

// How a 2D spectrum is laid out. row_major: FFTW's own, rows x (cols/2 + 1),
// ky along the rows. transposed: (cols/2 + 1) x rows, each kx a block of
// every ky, as a slab transform's (FFTW_MPI_TRANSPOSED_OUT). A transposed
// transform takes the rows a few at a time through a small buffer and then
// the kx blocks as contiguous transforms; FFTW's 2D plan instead runs down
// columns whose entries lie a row apart, on a different page each at large
// sizes, and grows faster than N log N (docs/performance.md).
enum class FftLayout { row_major, transposed };

// FFTW's plan type for each precision.
template <class Real>
struct FftwPlanOf;
template <>
struct FftwPlanOf<double> {
  using type = fftw_plan_s*;
};
template <>
struct FftwPlanOf<float> {
  using type = fftwf_plan_s*;
};

// Forward (r2c) and backward (c2r) transforms of a 1D (n) or 2D (rows, cols,
// row-major) real array, in double (RealFft) or single precision
// (SingleRealFft: FFTW's fftwf_ interface, for the inner products of a
// mixed-precision solve, solver_options.hpp's Precision). The buffers are FFTW-aligned and owned here; the plans
// are made once, under a process-wide lock (FFTW's planner is not thread-safe),
// with the thread count in force (set_threads); measure and patient plans
// read and extend the wisdom store of fft_wisdom.hpp. Executing is thread-safe
// for distinct objects. Transforms are unnormalised: backward(forward(x)) = N x
// with N = rows * cols.
template <class Real>
class BasicRealFft {
 public:
  using value_type = Real;

  // 1D transform of n real values; the spectrum has n/2 + 1 entries.
  // Throws InputError if a length is 0 or exceeds INT_MAX (FFTW's limit).
  BasicRealFft(std::size_t n, FftPlanning planning, FftOutput output = FftOutput::separate);
  // 2D transform of a (rows, cols) real array; the spectrum is (rows, cols/2 + 1),
  // or (cols/2 + 1, rows) transposed (with rows > 1).
  BasicRealFft(std::size_t rows, std::size_t cols, FftPlanning planning, FftOutput output = FftOutput::separate,
               FftLayout layout = FftLayout::row_major);
  // The 2D (rows > 1) or 1D (rows = 1) transform with FftOutput::overwrite_input
  // over `workspace`, memory it does not own (FFTW-aligned, at least
  // workspace_size(rows, cols) values): the spectrum, then the real array.
  // For memory that is idle while this transform runs, such as another
  // transform's buffer; planning and every transform overwrite it. Throws
  // InputError if the workspace is too small.
  BasicRealFft(std::size_t rows, std::size_t cols, FftPlanning planning, std::span<std::complex<Real>> workspace,
               FftLayout layout = FftLayout::row_major);
  static std::size_t workspace_size(std::size_t rows, std::size_t cols) {
    return rows * (cols / 2 + 1) + (rows * cols + 1) / 2;
  }
  ~BasicRealFft();
  BasicRealFft(BasicRealFft&& other) noexcept;
  BasicRealFft& operator=(BasicRealFft&& other) noexcept;
  BasicRealFft(const BasicRealFft&) = delete;
  BasicRealFft& operator=(const BasicRealFft&) = delete;

  std::size_t rows() const { return rows_; }
  std::size_t cols() const { return cols_; }
  std::size_t real_size() const { return rows_ * cols_; }
  std::size_t spectrum_cols() const { return cols_ / 2 + 1; }
  std::size_t spectrum_size() const { return rows_ * spectrum_cols(); }
  // The threads the transform runs on: one below 256^2 (detail::transform_threads).
  int team() const { return team_; }
  // The spectrum as blocks x length: rows x spectrum_cols() (row-major) or
  // spectrum_cols() x rows (transposed).
  bool transposed() const { return transposed_; }
  std::size_t spectrum_blocks() const { return transposed_ ? spectrum_cols() : rows_; }
  std::size_t spectrum_length() const { return transposed_ ? rows_ : spectrum_cols(); }

  // (rows, cols), row-major. Read by forward() and never modified by it, so
  // values written once stay (unless FftOutput::overwrite_input, where
  // backward() writes here). All buffers are zero after construction.
  // With FftOutput::overwrite_input (and buffers of its own) this real array
  // is only made on the first call of input(), output(), forward() or
  // backward(): users that only transform their own arrays (forward_from,
  // backward_into) never hold it.
  std::span<Real> input() { return {real_input(), real_size()}; }
  // Written by forward(), read (and destroyed) by backward(); (rows, cols/2 + 1),
  // or transposed.
  std::span<std::complex<Real>> spectrum() { return {spectrum_, spectrum_size()}; }
  // Written by backward(); the input buffer itself with FftOutput::overwrite_input.
  std::span<Real> output() {
    real_input();
    return {output_, real_size()};
  }

  // spectrum = DFT(input), sum_x input(x) exp(-i q x).
  void forward();
  // output = inverse DFT(spectrum) without 1/N; overwrites the spectrum.
  void backward();

  // The same transforms on the caller's arrays (FFTW's new-array execute),
  // which saves the copy into input() and out of output() when the array's
  // length is real_size() and its alignment is that of the planned buffers;
  // otherwise they do nothing and return false, and the caller copies.
  // `values` must not overlap spectrum().
  bool forward_from(std::span<const Real> values);
  bool backward_into(std::span<Real> values);
  // Whether forward_from / backward_into take `values` directly.
  bool takes_input(std::span<const Real> values) const;
  bool takes_output(std::span<const Real> values) const;

  // The transposed layout's transforms in parts, so that a caller can work
  // on a few kx columns while they are in cache between the two ways
  // (SpectralTransforms::apply_pair): forward_rows_from(values) leaves the
  // rows' DFTs in the spectrum, its columns not yet transformed;
  // transform_columns(first, count, forward) takes the columns [first,
  // first + count) one way on the calling thread (threads may take disjoint
  // columns at once); backward_rows_into(values) takes the rows back once
  // every column went back. Together the same transforms as forward_from
  // and backward_into, whose conditions on `values` (takes_input,
  // takes_output) they need, as they need columns_in_parts().
  bool columns_in_parts() const { return transposed_ && columns_aligned_; }
  void forward_rows_from(std::span<const Real> values);
  void transform_columns(std::size_t first, std::size_t count, bool forward);
  void backward_rows_into(std::span<Real> values);
  // The columns transform_columns is planned to take at once.
  static constexpr std::size_t kColumnBlock = 8;
  // A single-precision transform of double fields: forward_rows_from and
  // backward_rows_into with `values` in double, each block of rows rounded
  // into a thread's buffer on the way in and widened from it on the way
  // out; where takes_double_rows() (single precision, columns_in_parts()).
  bool takes_double_rows() const;
  void forward_rows_from(std::span<const double> values) requires(!std::is_same_v<Real, double>);
  void backward_rows_into(std::span<double> values) requires(!std::is_same_v<Real, double>);

 private:
  using Plan = typename FftwPlanOf<Real>::type;

  void make_plans(int rank, const int* dims, FftPlanning planning, FftOutput output,
                  std::complex<Real>* workspace = nullptr);
  // The transposed layout's plans (the planner's lock held): the rows' in
  // blocks (src/fft/row_blocks.hpp; and one of the rows left over) between
  // the real array and a block buffer, the kx blocks' in place; false if
  // FFTW fails.
  bool make_transposed_plans(unsigned flags);
  void release() noexcept;
  // The transposed layout's transforms: spectrum = DFT(in); out = inverse
  // DFT(spectrum), without 1/N.
  void transposed_forward(const Real* in);
  void transposed_backward(Real* out);
  // Their row parts (the columns left to the caller).
  void transposed_forward_rows(const Real* in);
  void transposed_backward_rows(Real* out);
  // A block's rows between a thread's buffer (rows of spectrum_cols()) and
  // the kx columns.
  void scatter_rows(const std::complex<Real>* buffer, std::size_t first, std::size_t count);
  void gather_rows(std::complex<Real>* buffer, std::size_t first, std::size_t count) const;
  // A thread's block of real rows (single precision, transposed).
  Real* row_real(int thread) const;
  // A thread's block buffer (transposed).
  std::complex<Real>* row_buffer(int thread) const;
  // input_, made (zeroed, FFTW-aligned) if it was left to first use.
  Real* real_input();

  std::size_t rows_ = 0;
  std::size_t cols_ = 0;
  Real* input_ = nullptr;
  std::complex<Real>* spectrum_ = nullptr;
  Real* output_ = nullptr;
  Plan forward_plan_ = nullptr;  // row-major: the 2D plans; transposed: the kx blocks'
  Plan backward_plan_ = nullptr;
  bool transposed_ = false;
  Plan rows_forward_[2] = {nullptr, nullptr};  // transposed: a full block of rows, and the rows left over
  Plan rows_backward_[2] = {nullptr, nullptr};
  std::complex<Real>* row_buffers_ = nullptr;  // transposed: a block's spectrum rows per thread
  Real* row_reals_ = nullptr;                  // transposed, single precision: a block's real rows per thread
  // transposed: kColumnBlock kx columns and a single one, on one thread
  // (transform_columns); every column starts at the spectrum's alignment.
  Plan columns_forward_[2] = {nullptr, nullptr};
  Plan columns_backward_[2] = {nullptr, nullptr};
  bool columns_aligned_ = false;
  bool streaming_ = false;  // the rows' scatter into the columns by streaming stores
  int team_ = 1;            // threads (detail::transform_threads); a transposed transform's row buffers
  bool owns_buffers_ = true;
  bool lazy_input_ = false;  // overwrite_input, own buffers: input_ made on first use
  // fftw_alignment_of the planned real arrays: new-array execution needs the same.
  int input_alignment_ = 0;
  int output_alignment_ = 0;
};

using RealFft = BasicRealFft<double>;
using SingleRealFft = BasicRealFft<float>;
extern template class BasicRealFft<double>;
extern template class BasicRealFft<float>;

// body(first, count) for the kx columns of `fft` in groups of
// kColumnBlock (count fewer in the last), in parallel.
template <class Real, class Body>
void for_each_column_group(const BasicRealFft<Real>& fft, Body&& body) {
  const std::size_t columns = fft.spectrum_cols();
  constexpr std::size_t kGroup = BasicRealFft<Real>::kColumnBlock;
  const auto groups = static_cast<std::ptrdiff_t>((columns + kGroup - 1) / kGroup);
#pragma omp parallel for schedule(static) num_threads(fft.team())
  for (std::ptrdiff_t group = 0; group < groups; ++group) {
    const std::size_t first = static_cast<std::size_t>(group) * kGroup;
    body(first, std::min(kGroup, columns - first));
  }
}

// out = the unnormalised inverse transform of the spectrum of in once
// multiply(first, count) has worked on its kx columns [first, first +
// count): the rows forward, then each few columns forward, multiplied and
// back while they are in cache, then the rows back (the spectrum is read
// and written once instead of three times). The same conditions as
// transform_pair_by_columns below.
template <class Real, class Value, class Multiply>
void transform_by_columns(BasicRealFft<Real>& fft, std::span<const Value> in, std::span<Value> out,
                          Multiply&& multiply) {
  fft.forward_rows_from(in);
  for_each_column_group(fft, [&](std::size_t first, std::size_t count) {
    fft.transform_columns(first, count, true);
    multiply(first, count);
    fft.transform_columns(first, count, false);
  });
  fft.backward_rows_into(out);
}

// out_a, out_b = the unnormalised inverse transforms of the spectra of in_a,
// in_b once multiply(first, count) has worked on the kx columns [first,
// first + count) of both: the rows of both forward, then each few columns
// of both forward, multiplied and back while they are in cache, then the
// rows of both back. a and b are transforms of one shape with
// columns_in_parts(), and take the values as their forward_rows_from and
// backward_rows_into do; multiply may run on several threads at once for
// disjoint columns. The inputs are read before the outputs are written.
template <class Real, class Value, class Multiply>
void transform_pair_by_columns(BasicRealFft<Real>& a, BasicRealFft<Real>& b, std::span<const Value> in_a,
                               std::span<const Value> in_b, std::span<Value> out_a, std::span<Value> out_b,
                               Multiply&& multiply) {
  a.forward_rows_from(in_a);
  b.forward_rows_from(in_b);
  for_each_column_group(a, [&](std::size_t first, std::size_t count) {
    a.transform_columns(first, count, true);
    b.transform_columns(first, count, true);
    multiply(first, count);
    a.transform_columns(first, count, false);
    b.transform_columns(first, count, false);
  });
  a.backward_rows_into(out_a);
  b.backward_rows_into(out_b);
}

}  // namespace halfspace::fft

// The library and its front ends name these without the folder's namespace.
namespace halfspace {
using fft::FftLayout;
using fft::FftOutput;
using fft::RealFft;
using fft::SingleRealFft;
}  // namespace halfspace
