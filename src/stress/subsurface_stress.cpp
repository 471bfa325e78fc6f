// Subsurface stresses by FFT.
//
// Periodic: sigma_c(q, z) = S_c(q, z) B(q) p(q) with the closed-form
// multipliers S_c of fourier_stress.hpp and B(q) = sinc(qx dx/2) sinc(qy dy/2)
// the transform of a cell: the pressure is constant on each cell, as on free
// grids, so that both boundaries answer the same question (the field's
// content above the Nyquist wavenumber, whose stresses fall like
// exp(-pi z/dx), is left out: docs/theory.md). One forward FFT of p for all
// depths, then per depth and component one multiplication and one inverse
// FFT. Odd multipliers
// (xz, yz, xy) are set to zero on a Nyquist row or column: there the sine
// they stand for vanishes on the grid, and the c2r transform needs a
// Hermitian spectrum.
//
// Coated (periodic): the same (B included), with the multipliers of the bonded layer
// (layered_fourier_stress.hpp); each mode's six coefficients are solved once
// when the grid is set up, and each depth evaluates g, g', g'' per mode.
//
// Coated, free grids: the same split as the free coated kernel
// (docs/theory.md, "Stresses in a coated half-space"): Love's rectangle (the
// strip in 1D) with the Poisson's ratio of the depth's body, plus the remainder D = S_layered -
// S_homogeneous, which decays like exp(-q min(z, 2t - z)), added to each
// bin of the coefficients' spectrum as its DFT on the padded grid (the alias
// images summed with the cell's transform).
//
// Shear tractions (q_x, q_y; surface_traction.hpp) add their own terms:
// periodic grids the Cerruti multipliers of fourier_shear_stress.hpp times
// their spectra, free grids the cell coefficients of
// rectangle_shear_stress.hpp convolved like the pressure's, each term summed
// in the spectrum before the one inverse transform per component. Their
// Nyquist rows and columns are zeroed by their own parities. Coated bodies
// take the layered shear multipliers of layered_fourier_shear_stress.hpp
// (periodic grids: LayeredShearModes; free grids: the remainder of each
// shear, as the pressure's, against Cerruti's rectangle).
//
// Free: sigma_c(i) = sum_j C_c(x_i - x_j, z) p_j with the exact cell
// coefficients C_c of rectangle_stress.hpp, a linear convolution done on the
// (2ny, 2nx) zero-padded grid (Liu, Wang & Liu 2000). The coefficients change
// with depth, so each depth evaluates them once on the quadrant of
// non-negative offsets (each component is even or odd in each axis), and each
// component fills the wrap-around array, transforms it and multiplies it
// into the kept pressure spectrum before the pruned inverse transform.
//
// The transforms are a layout's (solvers/layout.hpp): the whole grid here
// (serial), or this process's slab of rows with the spectrum's columns it
// holds (mpi::DistributedLayout). Every loop runs over the spectrum entries
// held here, each naming its mode (row ky, column kx of the whole
// spectrum), so the same code serves both; the coefficients of a free grid
// are evaluated on the quadrant rows this process's slab meets, and the
// largest von Mises stress is reduced over the processes
// (stress_volume.cpp).
#include "halfspace/stress/subsurface_stress.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <optional>
#include <string_view>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/kernels/layered_fourier.hpp"
#include "halfspace/kernels/periodic_fourier.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/stress/fourier_shear_stress.hpp"
#include "halfspace/stress/layered_fourier_shear_stress.hpp"
#include "halfspace/stress/layered_fourier_stress.hpp"
#include "halfspace/stress/rectangle_shear_stress.hpp"
#include "halfspace/stress/rectangle_stress.hpp"

namespace halfspace::stress {
namespace {

double component_of(const StressTensor& s, std::size_t c) {
  switch (static_cast<Component>(c)) {
    case Component::xx:
      return s.xx;
    case Component::yy:
      return s.yy;
    case Component::zz:
      return s.zz;
    case Component::xy:
      return s.xy;
    case Component::xz:
      return s.xz;
    case Component::yz:
      return s.yz;
  }
  return 0.0;
}

// Signed offset (cells) of wrap-around index k on a 2n-periodic axis; the
// middle index n only ever meets padding (any value would do) and gets 0 via
// `valid` = false.
std::ptrdiff_t wrapped_offset(std::size_t k, std::size_t n, bool& valid) {
  valid = k != n;
  return k < n ? static_cast<std::ptrdiff_t>(k) : static_cast<std::ptrdiff_t>(k) - static_cast<std::ptrdiff_t>(2 * n);
}

}  // namespace

double checked_poisson_ratio(double nu) {
  if (!(nu > -1.0 && nu <= 0.5)) {
    throw InputError(fmt::format("Poisson's ratio nu = {} is invalid: allowed range is -1 < nu <= 0.5", nu));
  }
  return nu;
}

void require_coated_stress_grid(const Grid& grid, const LayeredMaterial& coating) {
  if (grid.periodic()) return;
  const double length = static_cast<double>(grid.nx()) * grid.dx();
  const double side = grid.dimension() == 1 ? length : std::min(length, static_cast<double>(grid.ny()) * grid.dy());
  if (coating.thickness > kFreeCoatedStressThicknessRatio * side) {
    throw InputError(fmt::format(
        "subsurface stresses in a coated half-space on a free grid need a layer thickness t <= L/8, L the domain's "
        "shorter side: t = {:.6g} m, L = {:.6g} m on the free {} grid (use --boundary periodic, or a larger domain)",
        coating.thickness, side, grid.shape_string()));
  }
}

double checked_depth(double depth) {
  if (!(std::isfinite(depth) && depth > 0.0)) {
    throw InputError(fmt::format("depth = {} m is invalid: a depth below the surface must be finite and > 0 m", depth));
  }
  return depth;
}

DepthRange allowed_depth_range(const Grid& grid) {
  const bool line = grid.dimension() == 1;
  const double finer = line ? grid.dx() : std::min(grid.dx(), grid.dy());
  const double length = static_cast<double>(grid.nx()) * grid.dx();
  const double longer = line ? length : std::max(length, static_cast<double>(grid.ny()) * grid.dy());
  return {kShallowestDepthPerCell * finer, kDeepestDepthPerDomain * longer};
}

double checked_depth(const Grid& grid, double depth) {
  checked_depth(depth);
  const DepthRange range = allowed_depth_range(grid);
  if (!(depth >= range.shallowest && depth <= range.deepest)) {
    throw InputError(fmt::format(
        "depth = {:.6g} m is outside the allowed range {:.6g} to {:.6g} m on the {} {} grid (dx = {:.6g} m): from "
        "{:g} of a cell, where the field is the surface pressure, to {:g} times the domain's longer side, below which "
        "it is that of the mean pressure (periodic) or of a point load (free)",
        depth, range.shallowest, range.deepest, to_string(grid.boundary()), grid.shape_string(), grid.dx(),
        kShallowestDepthPerCell, kDeepestDepthPerDomain));
  }
  return depth;
}

struct SubsurfaceStress::Impl {
  Impl(const Grid& g, const LayeredMaterial& coating, const solvers::Layout& layout, FftPlanning planning)
      : Impl(g, coating.layer.poissons_ratio, layout, planning, &coating) {}

  Impl(const Grid& g, double poisson, const solvers::Layout& layout, FftPlanning planning,
       const LayeredMaterial* coating = nullptr)
      : grid(g), nu(checked_poisson_ratio(poisson)) {
    if (coating) {
      require_coated_stress_grid(grid, *coating);
      layered.emplace(*coating);
    }
    const bool line = grid.dimension() == 1;
    rows = line ? 1 : grid.ny();
    slab = layout.rows(grid);
    transforms = layout.make_transforms(grid, planning);
    held = transforms->spectrum_blocks() * transforms->spectrum_length();
    spectra[0].resize(held);
    if (grid.periodic()) {
      decay.resize(held);
      kx.resize(grid.nx() / 2 + 1);
      ky.resize(rows);
      for (std::size_t c = 0; c < kx.size(); ++c) kx[c] = kernels::dft_wavenumber(c, grid.nx(), grid.dx());
      for (std::size_t r = 0; r < rows; ++r) ky[r] = line ? 0.0 : kernels::dft_wavenumber(r, grid.ny(), grid.dy());
      // The pressure is constant on each cell, as on free grids: its
      // spectrum is the samples' DFT times the cell's transform.
      cell_x.resize(kx.size());
      cell_y.resize(rows);
      for (std::size_t c = 0; c < kx.size(); ++c) cell_x[c] = kernels::cell_sinc(0.5 * kx[c] * grid.dx());
      for (std::size_t r = 0; r < rows; ++r) cell_y[r] = line ? 1.0 : kernels::cell_sinc(0.5 * ky[r] * grid.dy());
      if (layered) solve_modes();
    } else {
      summed.resize(held);
      quadrant_cols = grid.nx() + 1;
      choose_quadrant_rows(line);
      for (auto& q : quadrants[0]) q.resize(quadrant_rows.size() * quadrant_cols);
      if (layered) {
        for (auto& part : remainder[0]) part.resize(held);
      }
    }
  }

  // The quadrant rows |dj| the wrap-around rows of this process's slab read:
  // its rows j (offsets j) and the padding rows ny + j (offsets ny - j).
  // Serially every row 0 .. ny.
  void choose_quadrant_rows(bool line) {
    const std::size_t none = rows + 1;
    quadrant_slot.assign(line ? 1 : rows + 1, none);
    const auto use = [&](std::size_t offset) {
      if (quadrant_slot[offset] == none) quadrant_slot[offset] = 0;
    };
    if (line) {
      use(0);
    } else {
      for (std::size_t j = slab.first; j < slab.first + slab.count; ++j) {
        use(j);
        use(rows - j);
      }
    }
    quadrant_rows.clear();
    for (std::size_t offset = 0; offset < quadrant_slot.size(); ++offset) {
      if (quadrant_slot[offset] == none) continue;
      quadrant_slot[offset] = quadrant_rows.size();
      quadrant_rows.push_back(offset);
    }
  }

  // The field values held here: this process's rows.
  std::size_t local_size() const { return transforms->local_size(); }
  const linalg::Communicator& communicator() const { return transforms->communicator(); }

  // Throws InputError unless `field` has the size of the cells held here
  // and finite values; on every process if any process's are not finite.
  void check_field(std::span<const double> field, std::string_view name) const {
    check_field_size(fmt::format("subsurface stress: the {}", name), field.size(), grid, local_size());
    const auto bad = std::find_if(field.begin(), field.end(), [](double v) { return !std::isfinite(v); });
    const bool here = bad != field.end();
    if (communicator().max(here ? 1.0 : 0.0) == 0.0) return;
    if (!here) throw InputError(fmt::format("subsurface stress: a {} value on another process is not finite", name));
    const auto k = static_cast<std::size_t>(bad - field.begin()) + slab.first * grid.nx();
    throw InputError(fmt::format("subsurface stress: {} value {} at index {} is not finite", name, *bad, k));
  }

  // Whether a shear along x and one along y are given on any process: a
  // process without rows holds empty spans either way.
  std::array<bool, 2> shears_given(const SurfaceTractions& tractions) const {
    return {communicator().max(tractions.shear_x.empty() ? 0.0 : 1.0) > 0.0,
            communicator().max(tractions.shear_y.empty() ? 0.0 : 1.0) > 0.0};
  }

  void check_tractions(const SurfaceTractions& tractions) const {
    const std::array<bool, 2> shear = shears_given(tractions);
    check_field(tractions.pressure, "pressure");
    if (shear[0]) check_field(tractions.shear_x, "shear traction along x");
    if (shear[1]) check_field(tractions.shear_y, "shear traction along y");
  }

  void set_tractions(const SurfaceTractions& tractions) {
    check_tractions(tractions);
    has_pressure = false;
    const std::array<bool, 2> shear = shears_given(tractions);
    active = {true, shear[0], shear[1]};
    const std::array<std::span<const double>, kTractionCount> fields = {tractions.pressure, tractions.shear_x,
                                                                        tractions.shear_y};
    for (std::size_t t = 0; t < kTractionCount; ++t) {
      if (!active[t]) continue;
      if (t > 0) allocate_shear(t);
      transform_field(fields[t], spectra[t]);
    }
    if (layered && grid.periodic() && (active[1] || active[2]) && !layered_shear) {
      std::vector<double> mode_kx(held);
      std::vector<double> mode_ky(held);
      for_each_mode([&](std::size_t k, std::size_t r, std::size_t c) {
        mode_kx[k] = kx[c];
        mode_ky[k] = ky[r];
      });
      layered_shear.emplace(layered->material(), std::move(mode_kx), std::move(mode_ky));
    }
    has_pressure = true;
  }

  // The spectrum and (free grids) the coefficient quadrants of a shear, made
  // once, the first time it is set.
  void allocate_shear(std::size_t t) {
    spectra[t].resize(spectra[0].size());
    if (!grid.periodic()) {
      for (auto& q : quadrants[t]) q.resize(quadrant_rows.size() * quadrant_cols);
      if (layered) {
        if (!antiplane) antiplane.emplace(layered->material());
        for (auto& part : remainder[t]) part.resize(held);
      }
    }
  }

  // The field's spectrum (periodic: its DFT; free: that of the zero-padded field) into `into`.
  void transform_field(std::span<const double> field, std::vector<std::complex<double>>& into) {
    const std::span<const std::complex<double>> spectrum = transforms->forward(0, field);
    linalg::for_each_index(held, [&](std::size_t k) { into[k] = spectrum[k]; });
  }

  void compute(double depth, const std::array<std::span<double>, kComponentCount>& fields) {
    checked_depth(grid, depth);
    if (!has_pressure) throw InputError("subsurface stress: no pressure was set before computing stresses");
    for (std::size_t c = 0; c < kComponentCount; ++c) {
      check_field_size(fmt::format("subsurface stress: the {} field", kComponentNames[c]), fields[c].size(), grid,
                       local_size());
    }
    if (grid.periodic()) {
      compute_periodic(depth, fields);
    } else {
      compute_free(depth, fields);
    }
  }

  // Each mode's layer and substrate coefficients, for every depth.
  void solve_modes() {
    modes.resize(held);
    profiles.resize(held);
    decay.clear();
    decay.shrink_to_fit();
    for_each_mode(
        [&](std::size_t k, std::size_t r, std::size_t c) { modes[k] = layered->solve(std::hypot(kx[c], ky[r])); });
  }

  // f(k, row, col) for each spectrum entry k held here, in parallel over
  // its blocks (serially the spectrum's rows, on slabs its columns).
  template <class F>
  void for_each_mode(const F& f) const {
    const std::size_t length = transforms->spectrum_length();
    linalg::for_each_row(transforms->spectrum_blocks(), length, [&](std::size_t block) {
      for (std::size_t k = block * length; k < (block + 1) * length; ++k) {
        const operators::SpectrumMode mode = transforms->mode(k);
        f(k, mode.row, mode.col);
      }
    });
  }

  double poisson_ratio_at(double z) const {
    if (!layered || layered->body_at(z) == Body::layer) return nu;
    return layered->material().substrate.poissons_ratio;
  }

  void compute_periodic(double z, const std::array<std::span<double>, kComponentCount>& fields) {
    const std::size_t cols = grid.nx() / 2 + 1;
    const bool nyquist_col = grid.nx() % 2 == 0;
    const bool nyquist_row = rows > 1 && rows % 2 == 0;
    const double inverse_n = 1.0 / static_cast<double>(grid.size());
    const double body_nu = poisson_ratio_at(z);
    if (layered) {
      const Body body = layered->body_at(z);
      for_each_mode(
          [&](std::size_t k, std::size_t, std::size_t) { profiles[k] = layered->profile(modes[k], z, body); });
      if (layered_shear && (active[1] || active[2])) layered_shear->evaluate(z, body);
    } else {
      for_each_mode(
          [&](std::size_t k, std::size_t r, std::size_t c) { decay[k] = std::exp(-std::hypot(kx[c], ky[r]) * z); });
    }
    for (std::size_t component = 0; component < kComponentCount; ++component) {
      std::span<std::complex<double>> spectrum = transforms->spectrum(0);
      const auto kind = static_cast<Component>(component);
      for_each_mode([&](std::size_t k, std::size_t r, std::size_t c) {
        {
          std::complex<double> sum = 0.0;
          for (std::size_t t = 0; t < kTractionCount; ++t) {
            if (!active[t]) continue;
            const auto traction = static_cast<Traction>(t);
            const bool zero = (odd_in_y(kind, traction) && nyquist_row && r == rows / 2) ||
                              (odd_in_x(kind, traction) && nyquist_col && c == cols - 1);
            if (zero) continue;
            const std::complex<double> multiplier =
                !layered ? fourier_traction_stress_component(kind, traction, kx[c], ky[r], z, decay[k], nu)
                : traction == Traction::pressure ? layered_stress_component(kind, kx[c], ky[r], profiles[k], body_nu)
                                                 : layered_shear->component(kind, traction, k, body_nu);
            sum += spectra[t][k] * multiplier;
          }
          spectrum[k] = sum * (cell_x[c] * cell_y[r] * inverse_n);
        }
      });
      transforms->backward(0, fields[component]);
    }
  }

  // The remainder of a coated body at depth z, per traction set and bin of
  // the padded grid's half spectrum: sum over the alias images K of D(k +
  // K) times the cell's transform over its area, sinc(Kx dx/2) sinc(Ky
  // dy/2) (the DFT of the remainder's cell coefficients, as
  // LayeredKernel::remainder_cell_spectrum for the displacement). D is the
  // layered multiplier less the homogeneous one of the depth's body: the
  // pressure's (layered_fourier_stress.hpp against fourier_stress.hpp) or a
  // shear's (layered_fourier_shear_stress.hpp against
  // fourier_shear_stress.hpp). A multiplier odd in exactly one axis is
  // imaginary: its imaginary part is kept; the components odd in x (in y)
  // are 0 on the Nyquist column (row), as the DFT of an odd sequence is.
  void compute_remainder(double z) {
    const Body body = layered->body_at(z);
    const double body_nu = poisson_ratio_at(z);
    const double t = layered->thickness();
    // D falls like exp(-q (2t - z)) in the layer (the wave reflected at the
    // interface), like exp(-q z) below it; beyond 45 decay lengths it is
    // below 1e-16 of its scale.
    const double decay_length = body == Body::layer ? 2.0 * t - z : z;
    const double q_negligible = 45.0 / decay_length;
    using Parts = std::array<std::array<double, kComponentCount>, kTractionCount>;
    const auto imaginary = [](Component kind, Traction traction) {
      return odd_in_x(kind, traction) != odd_in_y(kind, traction);
    };
    const auto difference = [&](double kx, double ky, Parts& out) {
      const double q = std::hypot(kx, ky);
      const AiryProfile profile = layered->profile(layered->solve(q), z, body);
      const bool shear = active[1] || active[2];
      const AiryProfile longitudinal = shear ? layered->profile(layered->solve_shear(q), z, body) : AiryProfile{};
      const AntiplaneProfile transverse = shear ? antiplane->profile(q, z, body) : AntiplaneProfile{};
      const double decay = std::exp(-q * z);
      for (std::size_t tr = 0; tr < kTractionCount; ++tr) {
        if (!active[tr]) continue;
        const auto traction = static_cast<Traction>(tr);
        for (std::size_t c = 0; c < kComponentCount; ++c) {
          const auto kind = static_cast<Component>(c);
          const std::complex<double> layered_part =
              traction == Traction::pressure
                  ? layered_stress_component(kind, kx, ky, profile, body_nu)
                  : layered_shear_stress_component(kind, traction, kx, ky, longitudinal, transverse, body_nu);
          const std::complex<double> d =
              layered_part - fourier_traction_stress_component(kind, traction, kx, ky, z, decay, body_nu);
          out[tr][c] = imaginary(kind, traction) ? d.imag() : d.real();
        }
      }
    };
    // The q = 0 image: D's components even in both axes tend to
    // direction-dependent limits A + B cos(2 phi); the bin takes their
    // angular mean A (the cos(2 phi) part is a kernel whose integral over the
    // period vanishes); the others' mean is 0. A line (plane strain) has one
    // direction, x, and its limit.
    const bool line = grid.dimension() == 1;
    Parts at_zero{};
    {
      const double small = 1e-6 / t;
      Parts along_x{};
      Parts along_y{};
      difference(small, 0.0, along_x);
      difference(0.0, small, along_y);
      for (std::size_t tr = 0; tr < kTractionCount; ++tr) {
        for (std::size_t k = 0; k < kComponentCount; ++k) {
          const auto kind = static_cast<Component>(k);
          const auto traction = static_cast<Traction>(tr);
          if (odd_in_x(kind, traction) || (!line && odd_in_y(kind, traction))) continue;
          at_zero[tr][k] = line ? along_x[tr][k] : 0.5 * (along_x[tr][k] + along_y[tr][k]);
        }
      }
    }
    const std::size_t padded_rows = line ? 1 : 2 * rows;
    const std::size_t padded_cols = 2 * grid.nx();
    const double dx = grid.dx();
    const double dy = grid.dy();
    for_each_mode([&](std::size_t bin, std::size_t r, std::size_t c) {
      const double qy = line ? 0.0 : kernels::dft_wavenumber(r, padded_rows, dy);
      const double qx = kernels::dft_wavenumber(c, padded_cols, dx);
      Parts sum{};
      Parts d{};
      // A line's dy is no spacing: one image row.
      kernels::for_each_alias_image(qx, qy, dx, dy, line, kernels::LayeredKernel::kAliasImages, q_negligible,
                                    [&](double kx, double ky, double shape) {
                                      if (kx == 0.0 && ky == 0.0) {
                                        d = at_zero;
                                      } else {
                                        difference(kx, ky, d);
                                      }
                                      for (std::size_t tr = 0; tr < kTractionCount; ++tr) {
                                        for (std::size_t k = 0; k < kComponentCount; ++k)
                                          sum[tr][k] += d[tr][k] * shape;
                                      }
                                    });
      const bool nyquist_col = c == grid.nx();
      const bool nyquist_row = r == rows;
      for (std::size_t tr = 0; tr < kTractionCount; ++tr) {
        if (!active[tr]) continue;
        const auto traction = static_cast<Traction>(tr);
        for (std::size_t k = 0; k < kComponentCount; ++k) {
          const auto kind = static_cast<Component>(k);
          const bool zero = (nyquist_col && odd_in_x(kind, traction)) || (nyquist_row && odd_in_y(kind, traction));
          remainder[tr][k][bin] = zero ? 0.0 : sum[tr][k];
        }
      }
    });
  }

  void compute_free(double z, const std::array<std::span<double>, kComponentCount>& fields) {
    const bool line = grid.dimension() == 1;
    const double dx = grid.dx();
    const double dy = grid.dy();
    const double body_nu = poisson_ratio_at(z);
    if (layered) compute_remainder(z);
    for (std::size_t t = 0; t < kTractionCount; ++t) {
      if (active[t]) fill_quadrant(static_cast<Traction>(t), z, body_nu, line, dx, dy);
    }

    const double inverse_n = 1.0 / transforms->transform_size();
    for (std::size_t component = 0; component < kComponentCount; ++component) {
      const auto kind = static_cast<Component>(component);
      std::span<std::complex<double>> spectrum = summed;
      bool first = true;
      for (std::size_t t = 0; t < kTractionCount; ++t) {
        if (!active[t]) continue;
        const auto traction = static_cast<Traction>(t);
        std::span<const std::complex<double>> kernel_spectrum =
            transform_coefficients(quadrants[t][component], odd_in_x(kind, traction), odd_in_y(kind, traction), line);
        const std::vector<std::complex<double>>& traction_spectrum = spectra[t];
        if (layered) {
          // The remainder's multiplier: real, or i times the stored value
          // for the imaginary ones (odd in exactly one axis).
          const bool imaginary = odd_in_x(kind, traction) != odd_in_y(kind, traction);
          const std::vector<double>& part = remainder[t][component];
          linalg::for_each_index(spectrum.size(), [&](std::size_t k) {
            const std::complex<double> added = imaginary ? std::complex<double>(0.0, part[k]) : part[k];
            const std::complex<double> term = traction_spectrum[k] * (kernel_spectrum[k] + added) * inverse_n;
            spectrum[k] = first ? term : spectrum[k] + term;
          });
        } else if (first) {
          linalg::for_each_index(spectrum.size(), [&](std::size_t k) {
            spectrum[k] = traction_spectrum[k] * kernel_spectrum[k] * inverse_n;
          });
        } else {
          linalg::for_each_index(spectrum.size(), [&](std::size_t k) {
            spectrum[k] += traction_spectrum[k] * kernel_spectrum[k] * inverse_n;
          });
        }
        first = false;
      }
      // The transforms' own spectrum, free again once the coefficients are in.
      const std::span<std::complex<double>> into = transforms->spectrum(0);
      linalg::for_each_index(held, [&](std::size_t k) { into[k] = summed[k]; });
      transforms->backward(0, fields[component]);
    }
  }

  // The cell coefficients of one traction at depth z on the quadrant of
  // non-negative offsets.
  void fill_quadrant(Traction traction, double z, double body_nu, bool line, double dx, double dy) {
    auto& quadrant = quadrants[static_cast<std::size_t>(traction)];
    linalg::for_each_row(quadrant_rows.size(), quadrant_cols, [&](std::size_t slot) {
      const std::size_t dj = quadrant_rows[slot];
      for (std::size_t di = 0; di < quadrant_cols; ++di) {
        const double x = static_cast<double>(di) * dx;
        const double y = static_cast<double>(dj) * dy;
        StressTensor s;
        if (traction == Traction::pressure) {
          s = line ? strip_stress(x, z, 0.5 * dx, body_nu) : rectangle_stress(x, y, z, 0.5 * dx, 0.5 * dy, body_nu);
        } else {
          s = line ? strip_shear_stress(traction, x, z, 0.5 * dx, body_nu)
                   : rectangle_shear_stress(traction, x, y, z, 0.5 * dx, 0.5 * dy, body_nu);
        }
        const std::size_t k = slot * quadrant_cols + di;
        for (std::size_t c = 0; c < kComponentCount; ++c) quadrant[c][k] = component_of(s, c);
      }
    });
  }

  // The DFT of the wrap-around array of the (2ny, 2nx) padded grid filled
  // from a quadrant (mirrored with the component's parities), on the
  // spectrum entries held here.
  std::span<const std::complex<double>> transform_coefficients(const std::vector<double>& values, bool odd_x,
                                                               bool odd_y, bool line) {
    const std::size_t nx = grid.nx();
    return transforms->transform_wraparound([&](std::size_t r, std::size_t c) {
      bool row_valid = true;
      const std::ptrdiff_t dj = line ? 0 : wrapped_offset(r, rows, row_valid);
      bool col_valid = true;
      const std::ptrdiff_t di = wrapped_offset(c, nx, col_valid);
      if (!row_valid || !col_valid) return 0.0;
      const double row_sign = odd_y && dj < 0 ? -1.0 : 1.0;
      const double sign = odd_x && di < 0 ? -row_sign : row_sign;
      const std::size_t row_base = quadrant_slot[static_cast<std::size_t>(std::abs(dj))] * quadrant_cols;
      return sign * values[row_base + static_cast<std::size_t>(std::abs(di))];
    });
  }

  Grid grid;
  double nu;
  std::size_t rows = 1;
  bool has_pressure = false;
  // The rows of the grid held here, and the layout's transforms of its
  // fields, whose spectrum entries held here number `held`.
  solvers::RowSlab slab;
  std::unique_ptr<operators::SpectralTransforms> transforms;
  std::size_t held = 0;
  // Per traction (Traction order): whether it was set, and its spectrum.
  static constexpr std::size_t kTractionCount = 3;
  std::array<bool, kTractionCount> active{true, false, false};
  std::array<std::vector<std::complex<double>>, kTractionCount> spectra;
  // Periodic grids.
  std::vector<double> decay;  // exp(-|q| z) on the half spectrum, for the current depth
  std::vector<double> kx;
  std::vector<double> ky;
  std::vector<double> cell_x;  // sinc(kx dx / 2): a cell's transform over its width
  std::vector<double> cell_y;
  // Coated bodies (periodic grids): the solved modes and, per depth, their g, g', g''.
  std::optional<LayeredFourierStress> layered;
  std::vector<LayeredMode> modes;
  std::vector<AiryProfile> profiles;
  // ...and under shear, made when a shear is first set (the entries held here).
  std::optional<LayeredShearModes> layered_shear;
  // Free grids: a component's spectrum summed over the tractions, and the
  // quadrant rows (offsets |dj|) evaluated here, each row's slot among them.
  std::vector<std::complex<double>> summed;
  std::vector<std::size_t> quadrant_rows;
  std::vector<std::size_t> quadrant_slot;
  std::size_t quadrant_cols = 0;
  // Per traction, the coefficients at non-negative offsets (shears' made when first set).
  std::array<std::array<std::vector<double>, kComponentCount>, kTractionCount> quadrants;
  // Coated bodies (free grids): per traction (shears' made when first set),
  // the remainder's spectrum at the current depth (real part, or imaginary
  // for the odd multipliers), on the coefficients' half spectrum; and the
  // antiplane problem of the shears.
  std::array<std::array<std::vector<double>, kComponentCount>, kTractionCount> remainder;
  std::optional<LayeredAntiplane> antiplane;
};

SubsurfaceStress::SubsurfaceStress(const Grid& grid, double nu, FftPlanning planning)
    : SubsurfaceStress(grid, nu, solvers::serial_layout(), planning) {}

SubsurfaceStress::SubsurfaceStress(const Grid& grid, const LayeredMaterial& coating, FftPlanning planning)
    : SubsurfaceStress(grid, coating, solvers::serial_layout(), planning) {}

SubsurfaceStress::SubsurfaceStress(const Grid& grid, double nu, const solvers::Layout& layout, FftPlanning planning)
    : impl_(std::make_unique<Impl>(grid, nu, layout, planning)) {}

SubsurfaceStress::SubsurfaceStress(const Grid& grid, const LayeredMaterial& coating, const solvers::Layout& layout,
                                   FftPlanning planning)
    : impl_(std::make_unique<Impl>(grid, coating, layout, planning)) {}

SubsurfaceStress::~SubsurfaceStress() = default;

const Grid& SubsurfaceStress::grid() const {
  return impl_->grid;
}

solvers::RowSlab SubsurfaceStress::rows() const {
  return impl_->slab;
}

std::size_t SubsurfaceStress::local_size() const {
  return impl_->local_size();
}

const linalg::Communicator& SubsurfaceStress::communicator() const {
  return impl_->communicator();
}

double SubsurfaceStress::poisson_ratio() const {
  return impl_->nu;
}

double SubsurfaceStress::poisson_ratio(double depth) const {
  return impl_->poisson_ratio_at(depth);
}

bool SubsurfaceStress::coated() const {
  return impl_->layered.has_value();
}

bool SubsurfaceStress::in_layer(double depth) const {
  return impl_->layered && impl_->layered->body_at(depth) == Body::layer;
}

std::optional<LayeredMaterial> SubsurfaceStress::coating() const {
  if (!impl_->layered) return std::nullopt;
  return impl_->layered->material();
}

void SubsurfaceStress::set_pressure(std::span<const double> pressure) {
  impl_->set_tractions({pressure, {}, {}});
}

void SubsurfaceStress::set_tractions(const SurfaceTractions& tractions) {
  impl_->set_tractions(tractions);
}

bool SubsurfaceStress::has_shear(const SurfaceTractions& tractions) const {
  const std::array<bool, 2> shear = impl_->shears_given(tractions);
  return shear[0] || shear[1];
}

void SubsurfaceStress::check_tractions(const SurfaceTractions& tractions) const {
  impl_->check_tractions(tractions);
}

void SubsurfaceStress::compute(double depth, const std::array<std::span<double>, kComponentCount>& fields) {
  impl_->compute(depth, fields);
}

}  // namespace halfspace::stress
