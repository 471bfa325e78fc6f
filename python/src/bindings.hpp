// Shared pieces of the extension module halfspace._core: the array types it
// takes and returns, and the functions that add each part of the module.
#pragma once

#include <fmt/format.h>
#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/problem.hpp"

namespace halfspace::python {

namespace nb = nanobind;

// A float64 input array, C-contiguous, on the CPU (1D or 2D). The Python
// layer converts other dtypes and layouts once (np.ascontiguousarray), so
// what arrives here is the caller's own memory.
using InputArray = nb::ndarray<const double, nb::c_contig, nb::device::cpu>;
// A float64 array handed to numpy.
using OutputArray = nb::ndarray<nb::numpy, double>;

inline std::span<const double> values(const InputArray& array) {
  return {array.data(), array.size()};
}

// Refuses `heights` unless a 1D (n) or 2D (ny, nx) array; `what` names it.
inline void check_array_dimensions(const InputArray& heights, std::string_view what) {
  if (heights.ndim() != 1 && heights.ndim() != 2) {
    throw InputError(fmt::format("{} must be a 1D or 2D array, got {} dimensions", what, heights.ndim()));
  }
}

// The grid of the heights array (check_array_dimensions).
inline Grid array_grid(const InputArray& heights, double dx, double dy, Boundary boundary, std::string_view what) {
  check_array_dimensions(heights, what);
  return heights.ndim() == 1 ? Grid::line(heights.shape(0), dx, boundary)
                             : Grid::plane(heights.shape(1), heights.shape(0), dx, dy, boundary);
}

// Refuses heights with a NaN or an infinity, naming the first one's index:
// a contact or a film needs every height.
inline void require_finite_heights(const InputArray& heights, std::string_view what) {
  for (std::size_t k = 0; k < heights.size(); ++k) {
    if (!std::isfinite(heights.data()[k])) {
      throw InputError(fmt::format(
          "{} has a non-finite height at index {}: prepare it first (HeightMap.prepare(invalid='fill'))", what, k));
    }
  }
}

// A new numpy array owning `field` (moved, not copied), shaped `shape`.
OutputArray owning_array(Eigen::ArrayXd&& field, const std::vector<std::size_t>& shape);

// Python's spelling of the options of a problem or a film (problem.hpp):
// the keyword ("tol" for a film's tolerance), the coating's constants as
// the keys of the `coating` mapping.
class KeywordSpelling : public OptionSpelling {
 public:
  std::string name(std::string_view option) const override;
  std::string describe(std::string_view option, std::string_view value) const override;
};

// The options `given` names (the library's names, `names`: problem.hpp's
// problem_option_names, lubrication_problem.hpp's lubrication_option_names),
// None values left unset. A name not listed is refused as an unknown
// `what`, so a misspelt one never passes silently.
template <class Options, class Name>
Options options_from(const nb::dict& given, std::span<const Name> names, std::string_view what) {
  Options options;
  for (const auto& [key_object, value] : given) {
    if (value.is_none()) continue;
    const std::string key = nb::cast<std::string>(key_object);
    const auto found = std::ranges::find(names, key, &Name::name);
    if (found == names.end()) throw InputError(fmt::format("unknown {} '{}'", what, key));
    std::visit(
        [&](auto member) {
          using Member = std::remove_reference_t<decltype(options.*member)>;
          if constexpr (std::is_same_v<Member, bool>) {
            options.*member = nb::cast<bool>(value);
          } else {
            options.*member = nb::cast<typename Member::value_type>(value);
          }
        },
        found->field);
  }
  return options;
}

void bind_errors(nb::module_& module);
void bind_surfaces(nb::module_& module);
void bind_results(nb::module_& module);
void bind_solve(nb::module_& module);
void bind_paper(nb::module_& module);
void bind_stress(nb::module_& module);
void bind_lubricate(nb::module_& module);

}  // namespace halfspace::python
