// Reads back a result file written by write_result (or one step of a sweep
// written by write_sweep_result): its fields and every attribute, for front
// ends that hand results to users as data (the Python package's read_result).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace halfspace::io {

using AttributeValue = std::variant<double, std::int64_t, std::string>;

struct StoredResult {
  // The group that was read: "/" for a single result, "/steps/007" for a step.
  std::string group = "/";
  // Every float64, integer and string attribute of the group (and, for a
  // step, of the root, the step's own taking precedence), in file order.
  std::vector<std::pair<std::string, AttributeValue>> attributes;
  std::vector<std::size_t> shape;  // (ny, nx) or (n,)
  Eigen::ArrayXd height;           // m; the root's /height
  Eigen::ArrayXd pressure;         // Pa
  Eigen::ArrayXd gap;              // m
  Eigen::ArrayXd displacement;     // m
  std::vector<std::uint8_t> contact;
  std::vector<double> residual_history;
  std::vector<std::int64_t> cluster_sizes;  // a sweep step's; empty otherwise
  // A friction result's tangential step (docs/file-format.md#friction);
  // empty when the file has none.
  Eigen::ArrayXd shear_x, shear_y;                                      // Pa
  Eigen::ArrayXd slip_x, slip_y;                                        // m
  Eigen::ArrayXd tangential_displacement_x, tangential_displacement_y;  // m
  std::vector<std::uint8_t> stick;                                      // 1 where a contact cell sticks
  int steps = 0;  // a sweep file's number of steps; 0 for a single result

  // The attribute `name`, or nullptr.
  const AttributeValue* find(const std::string& name) const;
};

// Reads the result in `path`: the root of a single result, or step `step`
// (0-based) of a sweep file when step >= 0 (a sweep file with step < 0
// reads its last step). Throws FileError naming the file and what is wrong
// (missing, not a halfspace result, a dataset of the wrong shape, a step out
// of range).
StoredResult read_result(const std::filesystem::path& path, int step = -1);

}  // namespace halfspace::io
