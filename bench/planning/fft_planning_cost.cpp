// FFTW planning cost against the time it saves: plans the transforms a
// pk-fourier solve makes (periodic: one n x n transform shared by operator
// and preconditioner; free: the padded (pruned) one and the n x n one) at one
// planning level, then times forward + backward pairs. One configuration per
// process, so that only the wisdom file (HALFSPACE_FFTW_WISDOM) carries
// anything over; scripts/fft-planning-cost.sh runs the grid of cases.
//
//   fft_planning_cost N periodic|free estimate|measure|patient THREADS [PAIRS]
//
// Prints one line: n boundary planning threads wisdom plan_s pair_s(per transform...).
#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/fft/fft_planning.hpp"
#include "halfspace/fft/fft_wisdom.hpp"
#include "halfspace/fft/grid_transform.hpp"
#include "halfspace/fft/padded_real_fft.hpp"
#include "halfspace/fft/real_fft.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/io/fft_wisdom_file.hpp"
#include "halfspace/threads.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Mean seconds of one forward + backward pair over `pairs`, after one warm-up.
double pair_seconds(halfspace::RealFft& fft, int pairs) {
  for (double& x : fft.input()) x = 1.0;
  fft.forward();
  fft.backward();
  const auto start = Clock::now();
  for (int k = 0; k < pairs; ++k) {
    fft.forward();
    fft.backward();
  }
  return seconds_since(start) / pairs;
}

// The same for the free operator's padded transform of an n x n block.
double pair_seconds(halfspace::PaddedRealFft& fft, int pairs) {
  std::vector<double> block(fft.block_rows() * fft.block_cols(), 1.0);
  fft.forward(block);
  fft.backward(block);
  const auto start = Clock::now();
  for (int k = 0; k < pairs; ++k) {
    fft.forward(block);
    fft.backward(block);
  }
  return seconds_since(start) / pairs;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr, "usage: %s N periodic|free estimate|measure|patient THREADS [PAIRS]\n", argv[0]);
    return 1;
  }
  try {
    const std::size_t n = std::stoul(argv[1]);
    const bool periodic = std::string(argv[2]) == "periodic";
    const halfspace::FftPlanning planning = halfspace::parse_fft_planning(argv[3]);
    halfspace::set_threads(std::stoi(argv[4]));
    const int pairs = argc > 5 ? std::stoi(argv[5]) : 10;

    halfspace::io::use_fft_wisdom_file();
    const auto start = Clock::now();
    std::unique_ptr<halfspace::PaddedRealFft> padded;
    if (!periodic) padded = std::make_unique<halfspace::PaddedRealFft>(n, n, planning);
    // The grid's own transform as the solvers make it (transposed in 2D).
    const std::shared_ptr<halfspace::RealFft> unpadded =
        halfspace::make_grid_transform(halfspace::Grid::plane(n, n, 1.0, 1.0, halfspace::Boundary::periodic), planning);
    const double plan = seconds_since(start);

    const halfspace::FftWisdomStatus wisdom = halfspace::fft_wisdom_status();
    std::string line = fmt::format("{} {} {} {} {} {:.3f}", n, argv[2], argv[3], halfspace::threads(),
                                   wisdom.loaded ? "loaded" : "none", plan);
    if (padded) line += fmt::format(" {:.5f}", pair_seconds(*padded, pairs));
    line += fmt::format(" {:.5f}", pair_seconds(*unpadded, pairs));
    std::printf("%s\n", line.c_str());
  } catch (const std::exception& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return 1;
  }
  return 0;
}
