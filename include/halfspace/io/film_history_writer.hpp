// Writes a transient film's steps (lubricate --time-step;
// lubrication/transient_film.hpp) as they are solved: one HDF5 file with a
// group of fields per step and the history table, and the same table as CSV
// beside it (docs/file-format.md#transient-films), both appearing only when
// complete (write_output_set), as a friction history's.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <span>
#include <string>

#include "halfspace/grid.hpp"
#include "halfspace/io/hdf5_output.hpp"
#include "halfspace/lubrication/transient_film.hpp"

namespace halfspace::io {

// Receives each solved step (the initial state first).
using FilmStepSink = std::function<void(const lubrication::TransientStep&)>;

// /steps/NNN (zero-padded to the digits of `steps`, at least 3): pressure,
// film, fluid_fraction and the step's attributes step, time, separation,
// load, minimum_film_thickness, max_pressure, cavitated_fraction,
// fluid_volume, inflow, outflow, film_solves, iterations, status, message;
// /history/<column> (float64, one entry per step) for every CSV column;
// root: history_steps, history_csv_md5 and what fill_root writes (the last
// step as a single film result). `run(sink)` solves the steps, passing
// each to the sink; `steps` is the number of time steps after the initial
// state. The CSV (history_csv_path(path)) has the columns step, time,
// separation, load, minimum_film_thickness, max_pressure,
// cavitated_fraction, fluid_volume, inflow, outflow, film_solves (s, m, N
// or N/m, Pa, m^3 or m^2 on a profile, m^3/s or m^2/s).
// Throws FileError naming the path if a file cannot be written, and
// InputError if a step's fields do not match the grid or no step came.
void write_film_history(const std::filesystem::path& path, const Grid& grid, std::size_t steps,
                        const std::function<void(const FilmStepSink&)>& run,
                        const std::function<void(const Hdf5Node& root)>& fill_root);

}  // namespace halfspace::io
