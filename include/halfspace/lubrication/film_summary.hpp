// What a lubricated film's result file carries at its root, rigid or
// elastic: one record, written through the attribute table of
// io/result_attributes.hpp so every writer names it alike.
#pragma once

#include <optional>
#include <string>

namespace halfspace::lubrication {

struct FilmSummary {
  std::string model;           // "rigid" or "elastic"
  std::string status;          // FilmStatus as text
  std::string message;         // why it did not converge; empty when converged
  double load = 0.0;           // N (N/m on a profile)
  double mean_pressure = 0.0;  // Pa
  // Rigid: the separation (the minimum film); elastic: h0, the offset of
  // h = h0 + gap + K p (m).
  double separation = 0.0;
  double central_film_thickness = 0.0;  // m: at the undeformed gap's minimum
  double minimum_film_thickness = 0.0;  // m
  double max_pressure = 0.0;            // Pa
  double cavitated_fraction = 0.0;      // nodes with theta < 1
  double viscosity = 0.0;               // Pa s, ambient
  long long iterations = 0;             // sweeps (rigid) or Newton steps (elastic)
  long long film_solves = 0;            // films solved by the load search (1 elastic)
  double relative_residual = 0.0;       // the mass balance measured after the solve
  double solve_seconds = 0.0;
  // The rigid film's flows (absent for the elastic one), and the film's
  // friction (film_shear.hpp; both films).
  std::optional<double> inflow, outflow, friction_force_x, friction_force_y, friction_coefficient;
};

}  // namespace halfspace::lubrication
