// The result attributes table (result_attributes.hpp). Adding a field of
// SolveResult to every output file is one line below, plus its row in
// docs/file-format.md.
#include "halfspace/io/result_attributes.hpp"

#include <algorithm>
#include <array>
#include <type_traits>

namespace halfspace::io {
namespace {

using Number = double (*)(const SolveResult&);
using Integer = std::int64_t (*)(const SolveResult&);
using Text = std::string (*)(const SolveResult&);

const std::array<ResultAttribute, 25> kResultAttributes{{
    {"total_force", "N (N/m in 1D)", Number{[](const SolveResult& r) { return r.total_force; }}},
    {"mean_pressure", "Pa", Number{[](const SolveResult& r) { return r.mean_pressure; }}},
    {"approach", "m", Number{[](const SolveResult& r) { return r.approach; }}},
    {"contact_fraction", "", Number{[](const SolveResult& r) { return r.contact_fraction; }}},
    {"max_pressure", "Pa", Number{[](const SolveResult& r) { return r.max_pressure; }}},
    // Hardness cap: H (0 for none) and the cells at it over all cells.
    {"hardness", "Pa", Number{[](const SolveResult& r) { return r.hardness.value_or(0.0); }}},
    {"plastic_fraction", "", Number{[](const SolveResult& r) { return r.plastic_fraction; }}},
    {"solver", "", Text{[](const SolveResult& r) { return r.solver; }}},
    {"status", "", Text{[](const SolveResult& r) { return std::string(to_string(r.status)); }}},
    {"message", "", Text{[](const SolveResult& r) { return r.message; }}},
    {"converged", "", Integer{[](const SolveResult& r) { return std::int64_t{r.converged() ? 1 : 0}; }}},
    {"iterations", "", Integer{[](const SolveResult& r) { return std::int64_t{r.iterations}; }}},
    {"operator_applications", "", Integer{[](const SolveResult& r) { return std::int64_t{r.operator_applications}; }}},
    {"preconditioner_applications", "",
     Integer{[](const SolveResult& r) { return std::int64_t{r.preconditioner_applications}; }}},
    {"coarse_levels", "", Integer{[](const SolveResult& r) { return std::int64_t{r.coarse.levels}; }}},
    {"coarse_iterations", "", Integer{[](const SolveResult& r) { return std::int64_t{r.coarse.iterations}; }}},
    {"coarse_operator_work", "", Number{[](const SolveResult& r) { return r.coarse.operator_work; }}},
    {"coarse_preconditioner_work", "", Number{[](const SolveResult& r) { return r.coarse.preconditioner_work; }}},
    {"deflation_block", "", Integer{[](const SolveResult& r) { return static_cast<std::int64_t>(r.deflation.block); }}},
    {"deflated_iterations", "",
     Integer{[](const SolveResult& r) { return std::int64_t{r.deflation.deflated_iterations}; }}},
    {"deflation_declined", "", Integer{[](const SolveResult& r) { return std::int64_t{r.deflation.declined}; }}},
    {"undeflated_rate", "", Number{[](const SolveResult& r) { return r.deflation.fast_rate; }}},
    {"residual", "", Number{[](const SolveResult& r) { return r.residual; }}},
    {"tolerance", "", Number{[](const SolveResult& r) { return r.tolerance; }}},
    {"solve_seconds", "s", Number{[](const SolveResult& r) { return r.wall_seconds; }}},
}};

// Friction (a tangential load step): the coefficient, the step's totals and
// the state it leaves.
using TangentialNumber = double (*)(const TangentialResult&);
using TangentialInteger = std::int64_t (*)(const TangentialResult&);
using TangentialText = std::string (*)(const TangentialResult&);

const std::array<TangentialAttribute, 18> kTangentialAttributes{{
    {"friction_coefficient", "", TangentialNumber{[](const TangentialResult& r) { return r.friction_coefficient; }}},
    {"tangential_force_x", "N (N/m in 1D)", TangentialNumber{[](const TangentialResult& r) { return r.force_x; }}},
    {"tangential_force_y", "N (N/m in 1D)", TangentialNumber{[](const TangentialResult& r) { return r.force_y; }}},
    {"tangential_approach_x", "m", TangentialNumber{[](const TangentialResult& r) { return r.state.approach_x; }}},
    {"tangential_approach_y", "m", TangentialNumber{[](const TangentialResult& r) { return r.state.approach_y; }}},
    {"stick_fraction", "", TangentialNumber{[](const TangentialResult& r) { return r.stick_fraction; }}},
    {"slip_fraction", "", TangentialNumber{[](const TangentialResult& r) { return r.slip_fraction; }}},
    {"dissipated_energy", "J (J/m in 1D)",
     TangentialNumber{[](const TangentialResult& r) { return r.dissipated_energy; }}},
    {"gross_sliding", "", TangentialInteger{[](const TangentialResult& r) { return std::int64_t{r.gross_sliding}; }}},
    {"tangential_status", "",
     TangentialText{[](const TangentialResult& r) { return std::string(to_string(r.status)); }}},
    {"tangential_converged", "",
     TangentialInteger{[](const TangentialResult& r) { return std::int64_t{r.converged() ? 1 : 0}; }}},
    {"tangential_iterations", "",
     TangentialInteger{[](const TangentialResult& r) { return std::int64_t{r.iterations}; }}},
    {"tangential_coarse_levels", "",
     TangentialInteger{[](const TangentialResult& r) { return std::int64_t{r.coarse.levels}; }}},
    {"tangential_residual", "", TangentialNumber{[](const TangentialResult& r) { return r.residual; }}},
    {"tangential_tolerance", "", TangentialNumber{[](const TangentialResult& r) { return r.tolerance; }}},
    {"dundurs_beta", "", TangentialNumber{[](const TangentialResult& r) { return r.dundurs_beta; }}},
    {"normal_tangential_coupling", "",
     TangentialInteger{[](const TangentialResult& r) { return std::int64_t{r.coupled ? 1 : 0}; }}},
    {"coupling_alternations", "",
     TangentialInteger{[](const TangentialResult& r) { return std::int64_t{r.coupling_alternations}; }}},
}};

using lubrication::FilmSummary;
using FilmNumber = double (*)(const FilmSummary&);
using FilmInteger = std::int64_t (*)(const FilmSummary&);
using FilmText = std::string (*)(const FilmSummary&);
using FilmOptional = std::optional<double> (*)(const FilmSummary&);

const std::array<FilmAttribute, 21> kFilmAttributes{{
    {"model", "", FilmText{[](const FilmSummary& f) { return f.model; }}},
    {"status", "", FilmText{[](const FilmSummary& f) { return f.status; }}},
    {"message", "", FilmText{[](const FilmSummary& f) { return f.message; }}},
    {"converged", "", FilmInteger{[](const FilmSummary& f) { return std::int64_t{f.status == "converged" ? 1 : 0}; }}},
    {"load", "N (N/m in 1D)", FilmNumber{[](const FilmSummary& f) { return f.load; }}},
    {"mean_pressure", "Pa", FilmNumber{[](const FilmSummary& f) { return f.mean_pressure; }}},
    {"separation", "m", FilmNumber{[](const FilmSummary& f) { return f.separation; }}},
    {"central_film_thickness", "m", FilmNumber{[](const FilmSummary& f) { return f.central_film_thickness; }}},
    {"minimum_film_thickness", "m", FilmNumber{[](const FilmSummary& f) { return f.minimum_film_thickness; }}},
    {"max_pressure", "Pa", FilmNumber{[](const FilmSummary& f) { return f.max_pressure; }}},
    {"cavitated_fraction", "", FilmNumber{[](const FilmSummary& f) { return f.cavitated_fraction; }}},
    {"viscosity", "Pa s", FilmNumber{[](const FilmSummary& f) { return f.viscosity; }}},
    {"iterations", "", FilmInteger{[](const FilmSummary& f) { return std::int64_t{f.iterations}; }}},
    {"film_solves", "", FilmInteger{[](const FilmSummary& f) { return std::int64_t{f.film_solves}; }}},
    {"relative_residual", "", FilmNumber{[](const FilmSummary& f) { return f.relative_residual; }}},
    {"solve_seconds", "s", FilmNumber{[](const FilmSummary& f) { return f.solve_seconds; }}},
    {"inflow", "m^3/s (m^2/s in 1D)", FilmOptional{[](const FilmSummary& f) { return f.inflow; }}},
    {"outflow", "m^3/s (m^2/s in 1D)", FilmOptional{[](const FilmSummary& f) { return f.outflow; }}},
    {"friction_force_x", "N (N/m in 1D)", FilmOptional{[](const FilmSummary& f) { return f.friction_force_x; }}},
    {"friction_force_y", "N (N/m in 1D)", FilmOptional{[](const FilmSummary& f) { return f.friction_force_y; }}},
    {"friction_coefficient", "", FilmOptional{[](const FilmSummary& f) { return f.friction_coefficient; }}},
}};

// Writes each attribute of `table` of `source` on `node`, its name after
// `prefix`, but those named in `skip` and absent optional values.
template <class Source>
void write_table(const Hdf5Node& node, std::span<const Attribute<Source>> table, const Source& source,
                 std::string_view prefix = {}, std::span<const std::string_view> skip = {}) {
  for (const Attribute<Source>& attribute : table) {
    if (std::find(skip.begin(), skip.end(), attribute.name) != skip.end()) continue;
    const std::string name = std::string(prefix) + std::string(attribute.name);
    std::visit(
        [&](auto get) {
          const auto value = get(source);
          using Value = std::decay_t<decltype(value)>;
          if constexpr (std::is_same_v<Value, double>) {
            node.write_double_attribute(name, value);
          } else if constexpr (std::is_same_v<Value, std::int64_t>) {
            node.write_int64_attribute(name, value);
          } else if constexpr (std::is_same_v<Value, std::string>) {
            node.write_string_attribute(name, value);
          } else if (value) {
            node.write_double_attribute(name, *value);
          }
        },
        attribute.value);
  }
}

}  // namespace

std::span<const TangentialAttribute> tangential_attributes() {
  return kTangentialAttributes;
}

void write_tangential_attributes(const Hdf5Node& node, const TangentialResult& result) {
  write_table<TangentialResult>(node, kTangentialAttributes, result);
}

void write_film_attributes(const Hdf5Node& node, const lubrication::FilmSummary& summary) {
  write_table<lubrication::FilmSummary>(node, kFilmAttributes, summary);
}

std::span<const ResultAttribute> result_attributes() {
  return kResultAttributes;
}

void write_result_attributes(const Hdf5Node& node, const SolveResult& result, std::string_view prefix,
                             std::span<const std::string_view> skip) {
  write_table<SolveResult>(node, kResultAttributes, result, prefix, skip);
  // Adhesion: written only for adhesive solves, so other files keep their
  // attributes (docs/file-format.md#adhesion).
  if (const AdhesionRecord& a = result.adhesion; !a.law.empty()) {
    const auto named = [&](std::string_view base) { return std::string(prefix) + std::string(base); };
    node.write_string_attribute(named("adhesion_law"), a.law);
    node.write_double_attribute(named("work_of_adhesion"), a.work);
    node.write_double_attribute(named("adhesion_range"), a.range);
    node.write_double_attribute(named("adhesion_stress"), a.stress);
    node.write_double_attribute(named("adhesive_force"), a.adhesive_force);
    node.write_double_attribute(named("interaction_fraction"), a.interaction_fraction);
    node.write_double_attribute(named("repulsive_contact_fraction"), a.repulsive_contact_fraction);
  }
}

void write_contact_statistics_attributes(const Hdf5Node& node, const analysis::ContactStatistics& statistics) {
  node.write_double_attribute("mean_gap", statistics.mean_gap);
  node.write_double_attribute("rms_gap", statistics.rms_gap);
  node.write_double_attribute("free_volume", statistics.free_volume);
  node.write_int64_attribute("clusters", statistics.clusters());
}

// Coated half-space (docs/file-format.md#root-attributes).
void write_grid_attributes(const Hdf5Node& node, const Grid& grid) {
  node.write_int64_attribute("dimension", grid.dimension());
  node.write_int64_attribute("nx", static_cast<std::int64_t>(grid.nx()));
  node.write_int64_attribute("ny", static_cast<std::int64_t>(grid.ny()));
  node.write_double_attribute("dx", grid.dx());
  node.write_double_attribute("dy", grid.dimension() == 1 ? 0.0 : grid.dy());
  node.write_string_attribute("boundary", to_string(grid.boundary()));
}

void write_coating_attributes(const Hdf5Node& node, const LayeredMaterial& coating) {
  node.write_double_attribute("layer_thickness", coating.thickness);
  node.write_double_attribute("layer_E", coating.layer.youngs_modulus);
  node.write_double_attribute("layer_nu", coating.layer.poissons_ratio);
  node.write_double_attribute("substrate_E", coating.substrate.youngs_modulus);
  node.write_double_attribute("substrate_nu", coating.substrate.poissons_ratio);
}

void write_body_attributes(const Hdf5Node& node, const ElasticPair& bodies) {
  node.write_double_attribute("body1_E", bodies.body1().youngs_modulus);
  node.write_double_attribute("body1_nu", bodies.body1().poissons_ratio);
  node.write_double_attribute("body2_E", bodies.body2().youngs_modulus);
  node.write_double_attribute("body2_nu", bodies.body2().poissons_ratio);
}

}  // namespace halfspace::io
