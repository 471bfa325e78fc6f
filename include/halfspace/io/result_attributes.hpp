// The one table of a solve's result attributes: name, unit and how to get
// the value from a SolveResult. Every writer takes its attributes from here
// (the single result's root, each sweep step's group, each method of the
// paper's files), so a new field of SolveResult is one line in
// src/io/result_attributes.cpp and appears in every file.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>

#include "halfspace/analysis/contact_statistics.hpp"
#include "halfspace/elastic_pair.hpp"
#include "halfspace/io/hdf5_output.hpp"
#include "halfspace/layered_material.hpp"
#include "halfspace/lubrication/film_summary.hpp"
#include "halfspace/solvers/solve_result.hpp"
#include "halfspace/solvers/tangential_result.hpp"

namespace halfspace::io {

// One attribute of a `Source` (SolveResult, TangentialResult, FilmSummary):
// its HDF5 name (docs/file-format.md#root-attributes), its SI unit in words
// (empty for counts, ratios and text), and its value, stored as float64,
// int64 or a variable-length UTF-8 string (an absent optional: not written).
template <class Source>
struct Attribute {
  std::string_view name;
  std::string_view unit;
  std::variant<double (*)(const Source&), std::int64_t (*)(const Source&), std::string (*)(const Source&),
               std::optional<double> (*)(const Source&)>
      value;
};
using ResultAttribute = Attribute<SolveResult>;
using TangentialAttribute = Attribute<TangentialResult>;
using FilmAttribute = Attribute<lubrication::FilmSummary>;

// Every attribute of a SolveResult, in the order they are written.
std::span<const ResultAttribute> result_attributes();

// Writes every attribute of result_attributes() on `node`, each name
// preceded by `prefix` (the paper's files keep one set per method: "pk_"),
// but those named in `skip` (names a file already uses for another fact).
void write_result_attributes(const Hdf5Node& node, const SolveResult& result, std::string_view prefix = {},
                             std::span<const std::string_view> skip = {});

// Friction: the attributes of a tangential load step (TangentialResult), in
// the same way, on a frictional result's root and each history step's group
// (docs/file-format.md#friction). stick_fraction and slip_fraction are
// fractions of the contact cells (p > 0), not of the grid. In the order
// they are written:
std::span<const TangentialAttribute> tangential_attributes();

// Writes every attribute of tangential_attributes() on `node`.
void write_tangential_attributes(const Hdf5Node& node, const TangentialResult& result);

// mean_gap, rms_gap, free_volume (float64) and clusters (int64): the contact
// statistics of a solve, on a result's root or a sweep step's group.
void write_contact_statistics_attributes(const Hdf5Node& node, const analysis::ContactStatistics& statistics);

// dimension, nx, ny (int64), dx, dy (float64, m; dy 0 in 1D) and boundary:
// the grid, on the root of every file that holds fields on it.
void write_grid_attributes(const Hdf5Node& node, const Grid& grid);

// layer_thickness (m), layer_E (Pa), layer_nu, substrate_E (Pa) and
// substrate_nu (float64): a coated half-space's constants, on a result's root.
void write_coating_attributes(const Hdf5Node& node, const LayeredMaterial& coating);

// body1_E (Pa), body1_nu, body2_E (Pa, inf for a rigid body 2) and body2_nu
// (float64): both bodies of a homogeneous pair, on a result's root.
void write_body_attributes(const Hdf5Node& node, const ElasticPair& bodies);

// The root attributes of a lubricated film's file (halfspace lubricate):
// the same table's form for a FilmSummary, absent optional values skipped.
void write_film_attributes(const Hdf5Node& node, const lubrication::FilmSummary& summary);

}  // namespace halfspace::io
