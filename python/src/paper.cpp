// halfspace.paper.reproduce: Table 1 of the seed paper as arrays (the
// columns of `halfspace paper`'s testN.csv) and its summary numbers.
#include <nanobind/stl/string.h>

#include <vector>

#include "bindings.hpp"
#include "halfspace/paper/reproduction.hpp"
#include "halfspace/threads.hpp"

namespace halfspace::python {
namespace {

OutputArray column(Eigen::ArrayXd&& values) {
  const auto n = static_cast<std::size_t>(values.size());
  return owning_array(std::move(values), {n});
}

nb::dict reproduce(int test, double load) {
  paper::ReproductionOptions options;
  options.load = load;
  options.validate();
  const paper::PaperTest& chosen = paper::table1_test(test);
  paper::TestReproduction run = [&] {
    nb::gil_scoped_release release;
    // At most 500 cells: one thread is fastest (as `halfspace paper` runs it).
    set_threads(1);
    return paper::reproduce(chosen, options);
  }();
  const std::size_t n = run.contact.x.size();
  // The summary first: the columns below take the results' arrays over.
  nb::dict summary;
  summary["test"] = chosen.number;
  summary["nodes"] = chosen.nodes;
  summary["load"] = run.contact.load;
  summary["e_star"] = run.contact.e_star;
  summary["radius"] = run.contact.radius;
  summary["hertz_half_width"] = run.contact.hertz.half_width;
  summary["hertz_peak"] = run.contact.hertz.peak;
  summary["contact_nodes"] = paper::contact_nodes(run.lemke);
  summary["lemke_vs_lcpquad"] = run.lemke_vs_lcpquad;
  summary["lemke_vs_pk"] = run.lemke_vs_pk;
  summary["lcpquad_vs_pk"] = run.lcpquad_vs_pk;
  summary["all_converged"] = run.all_converged();
  summary["pk_iterations"] = run.pk.iterations;
  nb::dict out;
  out["x"] =
      column(Eigen::ArrayXd(Eigen::Map<const Eigen::ArrayXd>(run.contact.x.data(), static_cast<Eigen::Index>(n))));
  out["gap"] = column(std::move(run.contact.initial_gap));
  out["p_lemke"] = column(std::move(run.lemke.pressure));
  out["p_lcpquad"] = column(std::move(run.lcpquad.pressure));
  out["p_pk"] = column(std::move(run.pk.pressure));
  out["p_hertz"] = column(std::move(run.hertz_pressure));
  out["summary"] = summary;
  return out;
}

}  // namespace

void bind_paper(nb::module_& module) {
  module.def("paper_reproduce", &reproduce, nb::arg("test"), nb::arg("load"));
}

}  // namespace halfspace::python
