// Files of the Table 1 reproduction: per test a CSV and an HDF5 file with the
// same columns, and one Markdown summary table for all tests run.
//
// Columns (SI): x (m), gap (the initial gap x^2/(2R), m), p_lemke, p_lcpquad,
// p_pk, p_hertz (Pa), then any extra pressures of the demonstrations
// (p_lcpquad_si, p_lcpquad_si_approach, p_lemke_eq4).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "halfspace/paper/reproduction.hpp"

namespace halfspace::paper {

// testN.csv: a header line, then one line per node, values to 17 digits.
// Throws FileError naming the path if it cannot be written.
void write_csv(const std::filesystem::path& path, const TestReproduction& run);

// testN.h5: one float64 dataset per column, shape (N,), each with a `units`
// attribute, and root attributes describing the test, the Hertz solution and
// every method's outcome (format "halfspace-paper-test"; see docs/paper.md).
// Throws FileError naming the path if it cannot be written.
void write_hdf5(const std::filesystem::path& path, const TestReproduction& run, const ReproductionOptions& options);

// The summary table (Markdown) of the tests in `runs`, with a short legend.
std::string summary_markdown(const std::vector<TestReproduction>& runs, const ReproductionOptions& options);

}  // namespace halfspace::paper
