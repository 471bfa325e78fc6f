// The subsurface stresses on slabs against the serial ones (run by ctest
// under mpiexec -np 1, 2 and 3 in the MPI build): every process makes the
// same surface tractions whole, computes the stresses serially
// (serial_layout) and on its slab of rows (mpi::DistributedLayout), and each
// of the nine fields at every depth must equal the serial field's rows within
// 1e-12 of the serial field's largest magnitude, the largest von Mises stress
// within 1e-12 relative and at the same cell: on periodic and free grids,
// under a pressure alone and under a pressure with the shear tractions of a
// frictional contact, and below a coated body (periodic and free; with the
// shear, periodic only); a grid of two rows leaves a process without rows.
// Exits non-zero on a mismatch, printing it.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "halfspace/mpi/distributed_layout.hpp"
#include "halfspace/mpi/mpi_communicator.hpp"
#include "halfspace/mpi/session.hpp"
#include "halfspace/mpi/slab_fft.hpp"
#include "halfspace/stress/stress_volume.hpp"
#include "halfspace/stress/subsurface_stress.hpp"

namespace {

using namespace halfspace;

// Transforms on slabs round unlike the serial ones (and sum the spectra of a
// free grid's coefficients quadrant by quadrant): equal to rounding.
constexpr double kTolerance = 1e-12;
constexpr std::size_t kFields = stress::kComponentCount + 3;

int failures = 0;

void report(bool ok, const std::string& where, const std::string& what, double error, int rank) {
  if (!ok) {
    if (rank == 0) std::printf("FAIL %s: %s differs by %.3g\n", where.c_str(), what.c_str(), error);
    ++failures;
  }
}

// The surface tractions of a frictional contact: a Hertzian pressure on an
// off-centre ellipse with a ripple, and a shear of about 0.3 times it with a
// stick zone, both crossing the slabs' edges.
struct Tractions {
  std::vector<double> pressure;
  std::vector<double> shear_x;
  std::vector<double> shear_y;
};

Tractions make_tractions(const Grid& grid) {
  Tractions t;
  t.pressure.resize(grid.size());
  t.shear_x.resize(grid.size());
  t.shear_y.resize(grid.size());
  const double a = 0.3 * static_cast<double>(grid.nx()) * grid.dx();
  const double b = 0.35 * static_cast<double>(grid.ny()) * grid.dy();
  for (std::size_t j = 0; j < grid.ny(); ++j) {
    for (std::size_t i = 0; i < grid.nx(); ++i) {
      const double x = (static_cast<double>(i) - 0.5 * static_cast<double>(grid.nx()) + 0.3) * grid.dx();
      const double y = (static_cast<double>(j) - 0.5 * static_cast<double>(grid.ny()) + 0.2) * grid.dy();
      const double r2 = x * x / (a * a) + y * y / (b * b);
      const double p = r2 < 1.0 ? 1e9 * std::sqrt(1.0 - r2) * (1.0 + 0.1 * std::sin(2e5 * x)) : 0.0;
      const double stick = r2 < 0.25 ? std::sqrt(0.25 - r2) / 0.5 : 0.0;
      const std::size_t k = j * grid.nx() + i;
      t.pressure[k] = p;
      t.shear_x[k] = 0.3 * (p - 0.6e9 * stick);
      t.shear_y[k] = -0.1 * p;
    }
  }
  return t;
}

// The nine fields at every depth, (nz, cells held) each, and the maximum.
struct Fields {
  std::array<std::vector<double>, kFields> values;
  stress::VonMisesMaximum maximum;
};

Fields stresses_of(stress::SubsurfaceStress& stresses, const stress::SurfaceTractions& tractions,
                   std::span<const double> depths) {
  Fields fields;
  fields.maximum = stress::stresses_by_depth(stresses, tractions, depths, [&](const stress::StressSlice& slice) {
    for (std::size_t c = 0; c < stress::kComponentCount; ++c) {
      fields.values[c].insert(fields.values[c].end(), slice.components[c].begin(), slice.components[c].end());
    }
    const std::array<const std::vector<double>*, 3> derived = {&slice.von_mises, &slice.max_shear, &slice.hydrostatic};
    for (std::size_t f = 0; f < 3; ++f) {
      std::vector<double>& into = fields.values[stress::kComponentCount + f];
      into.insert(into.end(), derived[f]->begin(), derived[f]->end());
    }
  });
  return fields;
}

void check(const Grid& grid, const std::optional<LayeredMaterial>& coating, bool shear,
           const mpi::MpiCommunicator& comm) {
  const std::string where =
      fmt::format("{} {} grid{}{}, {} processes", grid.shape_string(), grid.periodic() ? "periodic" : "free",
                  coating ? ", coated" : "", shear ? ", pressure and shear" : ", pressure", comm.size());
  const Tractions whole = make_tractions(grid);
  const double side = std::min(static_cast<double>(grid.nx()) * grid.dx(), static_cast<double>(grid.ny()) * grid.dy());
  // Near the surface, about the layer's thickness, and deep.
  const std::vector<double> depths = {0.3 * grid.dx(), 0.05 * side, 0.11 * side, 0.4 * side};
  const double nu = 0.3;
  const auto serial_tractions = [&](const Tractions& t) {
    return shear ? stress::SurfaceTractions{t.pressure, t.shear_x, t.shear_y}
                 : stress::SurfaceTractions{t.pressure, {}, {}};
  };
  const mpi::DistributedLayout layout(comm);
  const mpi::SlabLayout slab = mpi::slab_layout(grid.nx(), grid.ny(), comm);
  const std::size_t begin = slab.first_row * grid.nx();
  const std::size_t cells = slab.local_size();
  const auto rows_of = [&](const std::vector<double>& field) {
    return std::span<const double>(field.data() + begin, cells);
  };
  const stress::SurfaceTractions mine =
      shear ? stress::SurfaceTractions{rows_of(whole.pressure), rows_of(whole.shear_x), rows_of(whole.shear_y)}
            : stress::SurfaceTractions{rows_of(whole.pressure), {}, {}};
  Fields want;
  Fields got;
  if (coating) {
    stress::SubsurfaceStress serial(grid, *coating);
    stress::SubsurfaceStress slabs(grid, *coating, layout);
    want = stresses_of(serial, serial_tractions(whole), depths);
    got = stresses_of(slabs, mine, depths);
  } else {
    stress::SubsurfaceStress serial(grid, nu);
    stress::SubsurfaceStress slabs(grid, nu, layout);
    want = stresses_of(serial, serial_tractions(whole), depths);
    got = stresses_of(slabs, mine, depths);
  }
  const std::array<const char*, 3> derived = {"von_mises", "max_shear", "hydrostatic"};
  double worst = 0.0;
  for (std::size_t f = 0; f < kFields; ++f) {
    const std::string name = f < stress::kComponentCount ? stress::kComponentNames[f] : derived[f - 6];
    for (std::size_t d = 0; d < depths.size(); ++d) {
      const double* w = want.values[f].data() + d * grid.size();
      double scale = 0.0;
      for (std::size_t k = 0; k < grid.size(); ++k) scale = std::max(scale, std::abs(w[k]));
      const double* g = got.values[f].data() + d * cells;
      double error = got.values[f].size() == depths.size() * cells ? 0.0 : INFINITY;
      for (std::size_t k = 0; k < cells && std::isfinite(error); ++k) {
        error = std::max(error, std::abs(g[k] - w[begin + k]));
      }
      error = comm.max(error) / std::max(scale, 1e-300);
      worst = std::max(worst, error);
      report(error <= kTolerance, where, fmt::format("{} at depth {}", name, d), error, comm.rank());
    }
  }
  const double value_error = std::abs(got.maximum.value - want.maximum.value) / want.maximum.value;
  report(value_error <= kTolerance, where, "the largest von Mises stress", value_error, comm.rank());
  const bool same_cell =
      got.maximum.x == want.maximum.x && got.maximum.y == want.maximum.y && got.maximum.z == want.maximum.z;
  report(same_cell, where,
         fmt::format("the largest von Mises stress's position ({}, {}, {} m against {}, {}, {} m)", got.maximum.x,
                     got.maximum.y, got.maximum.z, want.maximum.x, want.maximum.y, want.maximum.z),
         1.0, comm.rank());
  if (comm.rank() == 0) {
    std::printf("%s: largest difference %.3g of a field's maximum; von Mises maximum %.6g Pa at (%g, %g, %g) m\n",
                where.c_str(), worst, want.maximum.value, want.maximum.x, want.maximum.y, want.maximum.z);
  }
}

}  // namespace

int main(int argc, char** argv) {
  mpi::Session session(argc, argv);
  {
    const mpi::MpiCommunicator world(MPI_COMM_WORLD);
    // A stiff layer on steel, thin enough for a free grid (t <= L/8).
    const LayeredMaterial coating{8e-6, {4.2e11, 0.22}, {2.1e11, 0.3}};
    for (const Boundary boundary : {Boundary::periodic, Boundary::free}) {
      // Rows not a multiple of the process counts: slabs of unequal height;
      // an odd row count too.
      for (const Grid& grid : {Grid::plane(32, 26, 4e-6, 5e-6, boundary), Grid::plane(24, 19, 5e-6, 4e-6, boundary)}) {
        check(grid, std::nullopt, false, world);
        check(grid, std::nullopt, true, world);
        check(grid, coating, false, world);
        // Shear below a coating: periodic grids only (layered_fourier_shear_stress.hpp).
        if (boundary == Boundary::periodic) check(grid, coating, true, world);
      }
      // Two rows: on three processes one holds none (it still takes part in
      // every transform, reduction and write).
      check(Grid::plane(24, 2, 5e-6, 4e-6, boundary), std::nullopt, true, world);
    }
    int total = failures;
    MPI_Allreduce(&failures, &total, 1, MPI_INT, MPI_SUM, world.get());
    failures = total;
  }
  if (failures > 0 && session.rank() == 0) std::printf("%d mismatch(es)\n", failures);
  return failures == 0 ? 0 : 1;
}
