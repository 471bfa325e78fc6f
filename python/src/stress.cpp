// halfspace.subsurface_stress: the stress field below a solved contact
// (stress/stress_volume.hpp), as `halfspace stress` computes it, with each
// field handed to numpy without a copy.
#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "bindings.hpp"
#include "halfspace/error.hpp"
#include "halfspace/stress/stress_volume.hpp"
#include "halfspace/stress/stressed_body.hpp"
#include "run.hpp"

namespace halfspace::python {
namespace {

// A numpy array taking over `field` (moved), shaped (nz, ny, nx) or (nz, n).
OutputArray volume_array(std::vector<double>&& field, const std::vector<std::size_t>& shape) {
  auto* owned = new std::vector<double>(std::move(field));
  nb::capsule owner(owned, [](void* p) noexcept { delete static_cast<std::vector<double>*>(p); });
  return OutputArray(owned->data(), shape.size(), shape.data(), owner);
}

nb::dict subsurface_stress(const Result& result, const std::vector<double>& depths, std::optional<double> nu,
                           std::optional<std::string> body) {
  const Grid& grid = result.run->grid;
  const Eigen::ArrayXd& pressure = result.result().pressure;
  const std::optional<LayeredMaterial>& coating = result.run->coating;
  // Whose stresses: the library's rule (stress/stressed_body.hpp), with the
  // result's bodies or coating.
  const std::optional<stress::StressedBody> requested =
      body ? std::optional(stress::parse_stressed_body(*body, "body=")) : std::nullopt;
  const std::optional<ElasticPair> bodies = coating ? std::optional(ElasticPair::coated(*coating)) : result.run->pair;
  const stress::StressedBodyChoice choice = stress::choose_stressed_body(requested, nu, bodies, "body=", "nu=");
  // A friction result's shear tractions act beside the pressure, as in
  // `halfspace stress`; body 1 (a coated body) carries -q.
  const bool sheared = result.tangential_step < result.run->tangential.size();
  stress::StressVolume volume = [&] {
    nb::gil_scoped_release release;
    stress::SurfaceTractions tractions{{pressure.data(), grid.size()}, {}, {}};
    std::array<std::vector<double>, 2> body1_shear;
    if (sheared) {
      const TangentialState& state = result.run->tangential[result.tangential_step].state;
      tractions = stress::tractions_on(
          choice.body, {tractions.pressure, {state.shear_x.data(), grid.size()}, {state.shear_y.data(), grid.size()}},
          body1_shear);
    }
    return coating ? stress::compute_stress_volume(grid, tractions, depths, *coating)
                   : stress::compute_stress_volume(grid, tractions, depths, choice.poisson_ratio);
  }();
  std::vector<std::size_t> shape{depths.size()};
  if (grid.dimension() == 2) shape.push_back(grid.ny());
  shape.push_back(grid.nx());
  nb::dict out;
  out["depths"] = depths;
  for (std::size_t c = 0; c < stress::kComponentCount; ++c) {
    out[stress::kComponentNames[c]] = volume_array(std::move(volume.components[c]), shape);
  }
  out["von_mises"] = volume_array(std::move(volume.von_mises), shape);
  out["max_shear"] = volume_array(std::move(volume.max_shear), shape);
  out["hydrostatic"] = volume_array(std::move(volume.hydrostatic), shape);
  if (coating) out["in_layer"] = std::vector<bool>(volume.in_layer.begin(), volume.in_layer.end());
  const stress::VonMisesMaximum& peak = volume.max_von_mises;
  out["max_von_mises"] = peak.value;
  out["max_von_mises_position"] = nb::make_tuple(peak.x, peak.y, peak.z);
  out["tractions"] = sheared ? "pressure and shear" : "pressure";
  out["body"] = stress::body_number(choice.body);
  return out;
}

}  // namespace

void bind_stress(nb::module_& module) {
  module.def("subsurface_stress", &subsurface_stress, nb::arg("result"), nb::arg("depths"), nb::arg("nu").none(),
             nb::arg("body").none());
}

}  // namespace halfspace::python
