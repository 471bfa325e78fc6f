// The extension module halfspace._core: the library's front door for the
// Python package (python/halfspace), which adds keywords, defaults and docs.
#include <fmt/format.h>

#include <exception>

#include "bindings.hpp"
#include "halfspace/error.hpp"
#include "halfspace/io/fft_wisdom_file.hpp"
#include "halfspace/material.hpp"
#include "halfspace/threads.hpp"
#include "halfspace/version.hpp"

namespace halfspace::python {
namespace {

// Made once at import and never freed: a static nb::object would be
// released after the interpreter has shut down.
PyObject* input_error = nullptr;
PyObject* file_error = nullptr;

}  // namespace

std::string KeywordSpelling::name(std::string_view option) const {
  if (option == "tolerance") return "tol";
  if (option == "max_iterations") return "max_iter";
  if (option == "mixed") return "mixed=True";
  if (option == "layer_thickness") return "coating['thickness']";
  if (option.starts_with("layer_") || option.starts_with("substrate_")) return fmt::format("coating['{}']", option);
  return std::string(option);
}

std::string KeywordSpelling::describe(std::string_view option, std::string_view value) const {
  return fmt::format("{}={}", name(option), value);
}

OutputArray owning_array(Eigen::ArrayXd&& field, const std::vector<std::size_t>& shape) {
  auto* owned = new Eigen::ArrayXd(std::move(field));
  nb::capsule owner(owned, [](void* p) noexcept { delete static_cast<Eigen::ArrayXd*>(p); });
  return OutputArray(owned->data(), shape.size(), shape.data(), owner);
}

void bind_errors(nb::module_& module) {
  input_error = PyErr_NewExceptionWithDoc(
      "halfspace.InputError", "Bad input or options: the message names the parameter, its value and the rule.",
      PyExc_ValueError, nullptr);
  file_error = PyErr_NewExceptionWithDoc("halfspace.FileError",
                                         "A file that cannot be read or written: missing, unreadable, wrong layout.",
                                         PyExc_OSError, nullptr);
  if (!input_error || !file_error) throw nb::python_error();
  module.attr("InputError") = nb::handle(input_error);
  module.attr("FileError") = nb::handle(file_error);
  // FileError derives from InputError in C++, so it is tried first.
  nb::register_exception_translator([](const std::exception_ptr& thrown, void*) {
    try {
      std::rethrow_exception(thrown);
    } catch (const FileError& error) {
      PyErr_SetString(file_error, error.what());
    } catch (const OptionError& error) {
      // Named as the keyword (make_problem spells the problem's own).
      const std::string message = fmt::format("{}={} {}", error.option(), error.value(), error.rule());
      PyErr_SetString(input_error, message.c_str());
    } catch (const InputError& error) {
      PyErr_SetString(input_error, error.what());
    }
  });
}

}  // namespace halfspace::python

NB_MODULE(_core, module) {
  using namespace halfspace;
  using namespace halfspace::python;
  module.doc() = "The compiled core of halfspace; use the package halfspace, not this module.";
  module.attr("__version__") = kVersion;
  module.attr("git_hash") = kGitHash;
  bind_errors(module);
  // Measured plans keep their wisdom in the user's cache, as the program's do.
  io::use_fft_wisdom_file();

  module.def("default_threads", &default_threads,
             "The threads a solve uses when none is asked for (affinity, cgroup quota, OMP_NUM_THREADS).");
  module.def("max_threads", &max_threads, "The largest thread count a solve accepts.");
  module.def(
      "composite_modulus",
      [](double e1, double nu1, double e2, double nu2) {
        return composite_modulus({e1, nu1}, {e2, nu2});
      },
      nb::arg("E1"), nb::arg("nu1"), nb::arg("E2"), nb::arg("nu2"),
      "E* (Pa) from 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2.");

  bind_surfaces(module);
  bind_results(module);
  bind_solve(module);
  bind_paper(module);
  bind_stress(module);
  bind_lubricate(module);
}
