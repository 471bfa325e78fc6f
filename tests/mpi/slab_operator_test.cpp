// The normal operator and the Fourier preconditioner on slab transforms
// (mpi/slab_spectral_transforms.hpp) against the serial ones (HALFSPACE_MPI
// builds; ctest runs it on 2 and 3 processes), on grids whose rows and
// spectrum columns split unevenly, leaving some process without rows or
// without columns. Free grids: FftInfluenceOperator's product of a random
// pressure must equal the serial operator's rows within kTolerance of the
// largest displacement, in place too, with the same K_ii; the Fourier
// preconditioner, on unpadded slab transforms in the operator's buffer,
// likewise against the serial one; the circulant form (K and K^-1 on the
// whole zero-padded grid, the adhesive solver's) of a random field on the
// padded grid against the serial operator's form, each process's rows j and
// ny + j, in place too (or both refusing a kernel that is not positive
// definite). Periodic grids: the product, the preconditioner sharing the
// operator's transforms, K_ii (equal bits) and the circulant form's K^-1.
// Every process builds the whole random field and the serial product and
// compares its own rows.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <random>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/half_space.hpp"
#include "halfspace/material.hpp"
#include "halfspace/mpi/mpi_communicator.hpp"
#include "halfspace/mpi/session.hpp"
#include "halfspace/mpi/slab_fft.hpp"
#include "halfspace/mpi/slab_spectral_transforms.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"
#include "halfspace/operators/spectral_transforms.hpp"
#include "halfspace/solvers/fourier_preconditioner.hpp"

namespace {

using namespace halfspace;

// Rounding of two different transform orders, relative to the largest value.
constexpr double kTolerance = 1e-13;
constexpr double kEStar = 1.2e11;

struct Checker {
  const mpi::MpiCommunicator& comm;
  int failures = 0;

  // Agreed on every process: whether this process's `got` rows match the
  // rows of `whole` (relative to the largest of `whole`).
  void rows(const char* what, const Grid& grid, const mpi::SlabLayout& layout, std::span<const double> got,
            const std::vector<double>& whole) {
    double largest = 0.0;
    for (double v : whole) largest = std::max(largest, std::abs(v));
    double worst = 0.0;
    for (std::size_t k = 0; k < got.size(); ++k) {
      worst = std::max(worst, std::abs(got[k] - whole[layout.first_row * layout.nx + k]));
    }
    worst = comm.max(worst) / largest;
    report(worst <= kTolerance, fmt::format("{} on the {} grid: largest difference {:.2e} of the largest value", what,
                                            grid.shape_string(), worst));
  }

  // The same for a field on the padded (2ny, 2nx) grid: this process's
  // `got` holds its rows j, then its rows ny + j, each 2nx wide.
  void padded_rows(const std::string& what, const Grid& grid, const mpi::SlabLayout& layout,
                   std::span<const double> got, const std::vector<double>& whole) {
    double largest = 0.0;
    for (double v : whole) largest = std::max(largest, std::abs(v));
    const std::size_t width = 2 * layout.nx;
    const std::size_t half = layout.rows * width;
    double worst = got.size() == 2 * half ? 0.0 : INFINITY;
    for (std::size_t k = 0; k < std::min(got.size(), 2 * half); ++k) {
      const std::size_t row = layout.first_row + (k % half) / width + (k < half ? 0 : layout.ny);
      worst = std::max(worst, std::abs(got[k] - whole[row * width + k % width]));
    }
    worst = comm.max(worst) / largest;
    report(worst <= kTolerance, fmt::format("{} on the {} grid: largest difference {:.2e} of the largest value", what,
                                            grid.shape_string(), worst));
  }

  void report(bool ok, const std::string& message) {
    if (!ok) ++failures;
    if (comm.rank() == 0) std::printf("%s: %s\n", ok ? "ok" : "FAIL", message.c_str());
  }
};

void check_free_grid(Checker& check, std::size_t nx, std::size_t ny, const HalfSpace& body) {
  const mpi::MpiCommunicator& comm = check.comm;
  const Grid grid = Grid::plane(nx, ny, 2e-6, 3e-6, Boundary::free);
  std::mt19937_64 random(nx * 1000 + ny);
  std::uniform_real_distribution<double> uniform(0.0, 1e6);
  std::vector<double> pressure(grid.size());
  for (double& p : pressure) p = uniform(random);

  const bool coated = std::holds_alternative<LayeredMaterial>(body);
  const std::string what = coated ? fmt::format("coated (t = {:g} m)", std::get<LayeredMaterial>(body).thickness)
                                  : std::string("homogeneous");
  FftInfluenceOperator serial(grid, body);
  std::vector<double> expected(grid.size());
  serial.apply(pressure, expected);

  FftInfluenceOperator distributed(grid, body,
                                   mpi::make_slab_transforms(grid, comm, FftPlanning::estimate, {.count = 1}));
  const mpi::SlabLayout layout = mpi::slab_layout(nx, ny, comm);
  if (distributed.local_size() != layout.local_size()) {
    check.report(false, fmt::format("{}: local size {} is not the slab's {}", grid.shape_string(),
                                    distributed.local_size(), layout.local_size()));
    return;
  }
  const std::span<const double> mine(pressure.data() + layout.first_row * nx, layout.local_size());
  std::vector<double> got(layout.local_size());
  distributed.apply(mine, got);
  check.rows(fmt::format("K p, {},", what).c_str(), grid, layout, got, expected);
  std::vector<double> in_place(mine.begin(), mine.end());
  distributed.apply(in_place, in_place);
  check.rows("K p in place", grid, layout, in_place, expected);
  // Homogeneous or with the remainder in the coefficients, K_ii is the same
  // coefficient; with a spectral remainder, a sum over the spectrum in
  // another order.
  const double self_difference = std::abs(distributed.self_influence() - serial.self_influence());
  check.report(coated ? self_difference <= kTolerance * serial.self_influence() : self_difference == 0.0,
               fmt::format("K_ii, {}, on the {} grid: {} (serial {})", what, grid.shape_string(),
                           distributed.self_influence(), serial.self_influence()));

  solvers::FourierPreconditioner serial_fourier(grid, body);
  std::vector<double> preconditioned(grid.size());
  serial_fourier.apply(pressure, preconditioned);
  // In the operator's padded buffer, as the solvers use it: neither may
  // disturb the other between products.
  solvers::FourierPreconditioner fourier(
      grid, body,
      mpi::make_slab_transforms(grid, comm, FftPlanning::estimate,
                                {.count = 1, .unpadded = true, .workspace = distributed.transforms()->workspace()}));
  fourier.apply(mine, got);
  check.rows("Fourier preconditioner", grid, layout, got, preconditioned);
  distributed.apply(mine, got);
  check.rows("K p after the preconditioner", grid, layout, got, expected);

  // The circulant form on the whole padded grid.
  std::vector<double> field(4 * grid.size());
  for (double& v : field) v = uniform(random);
  operators::CirculantForm* serial_form = nullptr;
  try {
    serial_form = &serial.circulant_form();
  } catch (const InputError&) {
  }
  operators::CirculantForm* form = nullptr;
  try {
    form = &distributed.circulant_form();
  } catch (const InputError&) {
  }
  if (!serial_form || !form) {
    check.report(!serial_form && !form,
                 fmt::format("circulant form, {}, on the {} grid: {} (serial: {})", what, grid.shape_string(),
                             form ? "made" : "refused", serial_form ? "made" : "refused"));
    return;
  }
  const std::size_t width = 2 * nx;
  std::vector<double> local;
  for (const std::size_t first : {layout.first_row, ny + layout.first_row}) {
    local.insert(local.end(), field.begin() + static_cast<std::ptrdiff_t>(first * width),
                 field.begin() + static_cast<std::ptrdiff_t>((first + layout.rows) * width));
  }
  check.report(form->padded() && form->local_size() == local.size() && form->size() == field.size() &&
                   form->row_stride() == width,
               fmt::format("circulant form, {}, on the {} grid: {} cells here of {}, rows of {}", what,
                           grid.shape_string(), form->local_size(), form->size(), form->row_stride()));
  std::vector<double> whole(field.size());
  std::vector<double> out(local.size());
  serial_form->apply(field, whole);
  form->apply(local, out);
  check.padded_rows(fmt::format("circulant K, {},", what), grid, layout, out, whole);
  serial_form->apply_inverse(field, whole);
  form->apply_inverse(local, out);
  check.padded_rows(fmt::format("circulant K^-1, {},", what), grid, layout, out, whole);
  form->apply_inverse(local, local);
  check.padded_rows("circulant K^-1 in place", grid, layout, local, whole);
}

void check_periodic_grid(Checker& check, std::size_t nx, std::size_t ny, const HalfSpace& body) {
  const mpi::MpiCommunicator& comm = check.comm;
  const Grid grid = Grid::plane(nx, ny, 2e-6, 3e-6, Boundary::periodic);
  std::mt19937_64 random(nx * 1000 + ny + 7);
  std::uniform_real_distribution<double> uniform(0.0, 1e6);
  std::vector<double> pressure(grid.size());
  for (double& p : pressure) p = uniform(random);
  const std::string what = std::holds_alternative<LayeredMaterial>(body) ? "coated" : "homogeneous";

  FftInfluenceOperator serial(grid, body);
  solvers::FourierPreconditioner serial_fourier(grid, body);
  std::shared_ptr<operators::SpectralTransforms> transforms =
      mpi::make_slab_transforms(grid, comm, FftPlanning::estimate, {.count = 1});
  FftInfluenceOperator distributed(grid, body, transforms);
  solvers::FourierPreconditioner fourier(grid, body, transforms);
  const mpi::SlabLayout layout = mpi::slab_layout(nx, ny, comm);
  const std::span<const double> mine(pressure.data() + layout.first_row * nx, layout.local_size());
  std::vector<double> expected(grid.size());
  std::vector<double> got(layout.local_size());
  serial.apply(pressure, expected);
  distributed.apply(mine, got);
  check.rows(fmt::format("periodic K p, {},", what).c_str(), grid, layout, got, expected);
  serial_fourier.apply(pressure, expected);
  fourier.apply(mine, got);
  check.rows(fmt::format("periodic preconditioner, {},", what).c_str(), grid, layout, got, expected);
  // The inverse of the operator's symbol (the layouts' arrangement): a slab
  // not holding the mean mode divides its first entry too.
  solvers::FourierPreconditioner serial_inverted(grid, body, serial.symbol(), serial.transforms());
  solvers::FourierPreconditioner inverted(grid, body, distributed.symbol(), transforms);
  serial_inverted.apply(pressure, expected);
  inverted.apply(mine, got);
  check.rows(fmt::format("periodic preconditioner on K's symbol, {},", what).c_str(), grid, layout, got, expected);
  check.report(distributed.self_influence() == serial.self_influence() && distributed.local_size() == got.size(),
               fmt::format("periodic K_ii, {}, on the {} grid: {} (serial {})", what, grid.shape_string(),
                           distributed.self_influence(), serial.self_influence()));
  serial.circulant_form().apply_inverse(pressure, expected);
  distributed.circulant_form().apply_inverse(mine, got);
  check.rows(fmt::format("periodic circulant K^-1, {},", what).c_str(), grid, layout, got, expected);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    mpi::Session session(argc, argv);
    int failures = 0;
    {
      const mpi::MpiCommunicator comm(MPI_COMM_WORLD);
      Checker check{comm};
      // 51 rows split 26/25 and 17/17/17, the 65 padded spectrum columns
      // 33/32 and 22/22/21; 2 rows leave a third process without rows, the 4
      // columns of a 3 x 9 grid leave it without columns; 2 x 2 is the
      // smallest grid.
      for (const auto& [nx, ny] : {std::pair<std::size_t, std::size_t>{64, 51}, {45, 32}, {17, 2}, {3, 9}, {2, 2}}) {
        check_free_grid(check, nx, ny, kEStar);
        check_periodic_grid(check, nx, ny, kEStar);
      }
      // Coated: a layer thin against the 128 um x 153 um domain (its
      // remainder in the padded spectrum) and a thick one (in the cell
      // coefficients).
      const ElasticBody layer{3e11, 0.25};
      const ElasticBody substrate{7e10, 0.33};
      for (const double thickness : {4e-6, 1e-4})
        check_free_grid(check, 64, 51, LayeredMaterial{thickness, layer, substrate});
      check_periodic_grid(check, 64, 51, LayeredMaterial{4e-6, layer, substrate});
      failures = check.failures;
    }
    return failures == 0 ? 0 : 1;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return 2;
  }
}
