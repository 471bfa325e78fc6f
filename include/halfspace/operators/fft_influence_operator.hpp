// K p applied matrix-free by FFT convolution (real-to-complex FFTW plans made
// once). Periodic grids multiply by the Fourier kernel 2/(E* |q|); free grids
// convolve with Love's (2D) or plane-strain strip (1D) coefficients by zero
// padding to twice the size per axis (DC-FFT, Liu, Wang & Liu 2000).
#pragma once

#include <memory>

#include "halfspace/fft/fft_planning.hpp"
#include "halfspace/operators/influence_operator.hpp"

namespace halfspace {

class FftInfluenceOperator final : public InfluenceOperator {
 public:
  // e_star: composite modulus (Pa). Makes the plans and the kernel spectrum;
  // the threads in force (set_threads) are used by the plans.
  FftInfluenceOperator(const Grid& grid, double e_star, FftPlanning planning = FftPlanning::estimate);
  ~FftInfluenceOperator() override;
  FftInfluenceOperator(const FftInfluenceOperator&) = delete;
  FftInfluenceOperator& operator=(const FftInfluenceOperator&) = delete;

  const Grid& grid() const override;
  void apply(std::span<const double> pressure, std::span<double> displacement) override;
  double self_influence() const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace halfspace
