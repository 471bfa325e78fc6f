// The public face of halfspace in one include: the types a user of the
// library calls (grid, height maps and their readers and writers, the elastic
// bodies, the problem builder, loads, solver options, the progress callback
// and the solve, results and their statistics, load sweeps, subsurface
// stresses, the tangential (friction) step and the lubricated film). Exactly
// the headers this one reaches are installed (CMakeLists.txt); the others
// under halfspace/ are the engine's parts (transforms, kernels,
// preconditioners, level transfer), for the library's own code and tests.
// docs/architecture.md says which folder holds what.
#pragma once

#include "halfspace/analysis/adhesion_sweep.hpp"
#include "halfspace/analysis/contact_statistics.hpp"
#include "halfspace/analysis/load_sweep.hpp"
#include "halfspace/analysis/sweep_table.hpp"
#include "halfspace/elastic_pair.hpp"
#include "halfspace/error.hpp"
#include "halfspace/geometry/builtin_surface.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/height_map.hpp"
#include "halfspace/io/friction_history_writer.hpp"
#include "halfspace/io/height_map_reader.hpp"
#include "halfspace/io/height_map_writer.hpp"
#include "halfspace/io/result_metadata.hpp"
#include "halfspace/io/result_reader.hpp"
#include "halfspace/io/result_writer.hpp"
#include "halfspace/io/stress_writer.hpp"
#include "halfspace/io/sweep_writer.hpp"
#include "halfspace/layered_material.hpp"
#include "halfspace/lubrication/cavitation_solver.hpp"
#include "halfspace/lubrication/elastic_film.hpp"
#include "halfspace/lubrication/film.hpp"
#include "halfspace/lubrication/film_forces.hpp"
#include "halfspace/lubrication/film_shear.hpp"
#include "halfspace/lubrication/film_summary.hpp"
#include "halfspace/lubrication/load_control.hpp"
#include "halfspace/lubrication/lubricant.hpp"
#include "halfspace/lubrication/mixed_film.hpp"
#include "halfspace/material.hpp"
#include "halfspace/problem.hpp"
#include "halfspace/solvers/adhesion_law.hpp"
#include "halfspace/solvers/contact_conditions.hpp"
#include "halfspace/solvers/coupled_step.hpp"
#include "halfspace/solvers/friction_options.hpp"
#include "halfspace/solvers/frictional_solve.hpp"
#include "halfspace/solvers/interface_law.hpp"
#include "halfspace/solvers/loading.hpp"
#include "halfspace/solvers/solve_result.hpp"
#include "halfspace/solvers/solver_factory.hpp"
#include "halfspace/solvers/solver_options.hpp"
#include "halfspace/solvers/surface_solve.hpp"
#include "halfspace/solvers/tangential_solver.hpp"
#include "halfspace/stress/sliding_traction.hpp"
#include "halfspace/stress/stress_tensor.hpp"
#include "halfspace/stress/stress_volume.hpp"
#include "halfspace/surface/preparation.hpp"
#include "halfspace/surface/self_affine.hpp"
#include "halfspace/surface/statistics.hpp"
#include "halfspace/threads.hpp"
