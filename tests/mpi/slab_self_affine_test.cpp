// The self-affine surface made on slabs against the serial one (run by ctest
// under mpiexec -np 1, 2, 3 and 5 in the MPI build): every process also makes
// the whole serial surface, and its rows of make_self_affine_slab must equal
// it within kTolerance of the largest height, on even and odd grids, by rms
// height and by rms slope, with more processes than spectrum columns too.
// Exits non-zero on a mismatch, printing it.
#include "halfspace/mpi/slab_self_affine.hpp"

#include <fmt/format.h>

#include <Eigen/Core>
#include <cmath>
#include <cstdio>
#include <string>

#include "halfspace/mpi/mpi_communicator.hpp"
#include "halfspace/mpi/session.hpp"
#include "halfspace/mpi/slab_fft.hpp"
#include "halfspace/surface/self_affine.hpp"

namespace {

using namespace halfspace;

// FFTW-MPI's inverse transform and the sums over the processes round
// differently from the serial ones: equal to rounding.
constexpr double kTolerance = 1e-12;

int failures = 0;

void check(const Grid& grid, const surface::SelfAffineSpec& spec, const std::string& what,
           const mpi::MpiCommunicator& comm) {
  const std::string where =
      fmt::format("{} grid, {}, seed {}, {} processes", grid.shape_string(), what, spec.seed, comm.size());
  const Eigen::ArrayXd whole = surface::make_self_affine_surface(grid, spec);
  const Eigen::ArrayXd slab = mpi::make_self_affine_slab(grid, spec, comm);
  const mpi::SlabLayout layout = mpi::slab_layout(grid.nx(), grid.ny(), comm);
  const double largest = whole.abs().maxCoeff();
  double worst = 0.0;
  if (static_cast<std::size_t>(slab.size()) != layout.local_size()) {
    std::printf("FAIL %s: process %d holds %zu heights, its slab has %zu cells\n", where.c_str(), comm.rank(),
                static_cast<std::size_t>(slab.size()), layout.local_size());
    ++failures;
  } else {
    const auto rows = whole.segment(static_cast<Eigen::Index>(layout.first_row * grid.nx()), slab.size());
    worst = slab.size() > 0 ? (slab - rows).abs().maxCoeff() / largest : 0.0;
  }
  worst = comm.max(worst);
  if (!(worst <= kTolerance)) {
    if (comm.rank() == 0) std::printf("FAIL %s: differs by %.2e of the largest height\n", where.c_str(), worst);
    ++failures;
  } else if (comm.rank() == 0) {
    std::printf("%s: largest difference %.2e of the largest height\n", where.c_str(), worst);
  }
}

}  // namespace

int main(int argc, char** argv) {
  mpi::Session session(argc, argv);
  const mpi::MpiCommunicator comm(MPI_COMM_WORLD);
  surface::SelfAffineSpec by_height;
  by_height.hurst = 0.8;
  by_height.rms_height = 1e-6;
  by_height.seed = 7;
  surface::SelfAffineSpec by_slope;
  by_slope.hurst = 0.5;
  by_slope.rms_slope = 0.1;
  by_slope.seed = 12345;
  by_slope.rolloff = 2e-5;  // a roll-off below the longest wavelength
  for (const Grid& grid :
       {Grid::plane(64, 50, 1e-6, 1e-6, Boundary::periodic), Grid::plane(33, 17, 1e-6, 2e-6, Boundary::periodic),
        Grid::plane(6, 40, 1e-6, 1e-6, Boundary::periodic)}) {
    check(grid, by_height, "rms height", comm);
    check(grid, by_slope, "rms slope", comm);
  }
  const int total = static_cast<int>(comm.max(static_cast<double>(failures)));
  return total == 0 ? 0 : 1;
}
