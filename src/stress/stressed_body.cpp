// The choice of the stressed body: defaults that follow the elastic one.
#include "halfspace/stress/stressed_body.hpp"

#include <fmt/format.h>

#include <cmath>

#include "halfspace/error.hpp"
#include "halfspace/stress/subsurface_stress.hpp"

namespace halfspace::stress {

StressedBody parse_stressed_body(std::string_view text, std::string_view option) {
  if (text == "1") return StressedBody::body1;
  if (text == "2") return StressedBody::body2;
  throw InputError(fmt::format("{} {} is invalid: allowed values are 1 (body 1) and 2 (body 2)", option, text));
}

int body_number(StressedBody body) {
  return body == StressedBody::body1 ? 1 : 2;
}

StressedBody default_stressed_body(const std::optional<ElasticPair>& bodies) {
  if (!bodies) return StressedBody::body2;
  const bool rigid2 = std::isinf(bodies->body2().youngs_modulus);
  return bodies->coating() || rigid2 ? StressedBody::body1 : StressedBody::body2;
}

StressedBodyChoice choose_stressed_body(std::optional<StressedBody> requested, std::optional<double> given,
                                        const std::optional<ElasticPair>& bodies, std::string_view body_option,
                                        std::string_view nu_option) {
  const StressedBody body = requested.value_or(default_stressed_body(bodies));
  if (bodies && bodies->coating()) {
    if (body == StressedBody::body2) {
      throw InputError(fmt::format(
          "{} 2 is not available for a coated half-space: body 2 is the rigid counter-body, and the stresses are "
          "the coated body's (body 1); drop {} or pass 1",
          body_option, body_option));
    }
    if (given) {
      const LayeredMaterial& coating = *bodies->coating();
      throw InputError(fmt::format(
          "{}{}{} is not used for a coated half-space: its stresses take the layer's Poisson's ratio ({}) in the "
          "layer and the substrate's ({}) below it; drop {}",
          nu_option, nu_option.ends_with('=') ? "" : " ", format_number(*given),
          format_number(coating.layer.poissons_ratio), format_number(coating.substrate.poissons_ratio), nu_option));
    }
    return {body, bodies->body1().poissons_ratio};
  }
  if (given) return {body, checked_poisson_ratio(*given)};
  if (bodies && !requested && default_stressed_body(bodies) == StressedBody::body2 &&
      bodies->body1().poissons_ratio != bodies->body2().poissons_ratio) {
    // Two elastic bodies of different Poisson's ratios: which one is meant
    // is the user's to say.
    throw InputError(fmt::format(
        "the stresses of which body? Both bodies deform and their Poisson's ratios differ (nu1 = {:g}, nu2 = {:g}): "
        "pass {} 1 or 2, or {} NU",
        bodies->body1().poissons_ratio, bodies->body2().poissons_ratio, body_option, nu_option));
  }
  if (bodies) {
    const ElasticBody& own = body == StressedBody::body1 ? bodies->body1() : bodies->body2();
    return {body, own.poissons_ratio};
  }
  throw InputError(fmt::format(
      "no Poisson's ratio given: pass {} NU, the Poisson's ratio of the body whose stresses are wanted (E* alone "
      "does not fix it; -1 < NU <= 0.5), or both bodies' constants (E1, nu1, E2, nu2)",
      nu_option));
}

std::unique_ptr<SubsurfaceStress> make_subsurface_stress(const Grid& grid,
                                                         const std::optional<LayeredMaterial>& coating,
                                                         const StressedBodyChoice& body, const solvers::Layout& layout,
                                                         FftPlanning planning) {
  if (coating) return std::make_unique<SubsurfaceStress>(grid, *coating, layout, planning);
  return std::make_unique<SubsurfaceStress>(grid, body.poisson_ratio, layout, planning);
}

}  // namespace halfspace::stress
