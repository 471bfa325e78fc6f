// The elastic body's rule (make_body, problem.hpp), the one both the contact
// problem and the lubricated film apply: a coating first (it replaces the
// material options), then e_star, then both bodies' E and nu.
#include <fmt/ranges.h>

#include "halfspace/material.hpp"
#include "problem_rules.hpp"

namespace halfspace {
namespace {

class BodyRules : public detail::Checks {
 public:
  BodyRules(const BodyOptions& options, const OptionSpelling& spelling) : Checks(spelling), o_(options) {}

  std::optional<ProblemBody> body() const {
    if (auto coated = coating()) {
      const double e_star = plane_strain_modulus(coated->layer);
      return ProblemBody{e_star, coated, ElasticPair::coated(*coated)};
    }
    const detail::Presence constants = pair_constants();
    const std::vector<std::string> present = given(constants);
    if (o_.e_star && !present.empty()) {
      throw InputError(fmt::format("{} cannot be combined with {}: give either {} or all of {}", name("e_star"),
                                   fmt::join(present, ", "), name("e_star"), fmt::join(names(constants), ", ")));
    }
    if (o_.e_star) return ProblemBody{checked_composite_modulus(modulus("e_star", *o_.e_star)), {}, {}};
    if (present.empty()) return std::nullopt;
    return pair(constants, present);
  }

 private:
  detail::Presence pair_constants() const {
    return {
        {"E1", o_.e1.has_value()}, {"nu1", o_.nu1.has_value()}, {"E2", o_.e2.has_value()}, {"nu2", o_.nu2.has_value()}};
  }

  // A coated half-space from all five constants, or none.
  std::optional<LayeredMaterial> coating() const {
    const detail::Presence constants{{"layer_thickness", o_.layer_thickness.has_value()},
                                     {"layer_E", o_.layer_e.has_value()},
                                     {"layer_nu", o_.layer_nu.has_value()},
                                     {"substrate_E", o_.substrate_e.has_value()},
                                     {"substrate_nu", o_.substrate_nu.has_value()}};
    const std::vector<std::string> present = given(constants);
    if (present.empty()) return std::nullopt;
    std::vector<std::string> material = given(pair_constants());
    if (o_.e_star) material.insert(material.begin(), name("e_star"));
    if (!material.empty()) {
      throw InputError(
          fmt::format("{} cannot be combined with {}: a coated half-space against a rigid surface replaces the "
                      "material options",
                      fmt::join(present, ", "), fmt::join(material, ", ")));
    }
    if (present.size() < constants.size()) {
      throw InputError(fmt::format("incomplete coated half-space: missing {} (give all of {})",
                                   fmt::join(given(constants, false), ", "), fmt::join(names(constants), ", ")));
    }
    return LayeredMaterial{length("layer_thickness", *o_.layer_thickness),
                           {modulus("layer_E", *o_.layer_e), poisson("layer_nu", *o_.layer_nu)},
                           {modulus("substrate_E", *o_.substrate_e), poisson("substrate_nu", *o_.substrate_nu)}};
  }

  // E* of E1, nu1, E2, nu2 (E2 = inf: a rigid body 2), all four given.
  ProblemBody pair(const detail::Presence& constants, const std::vector<std::string>& present) const {
    if (present.size() < constants.size()) {
      throw InputError(fmt::format("incomplete material: missing {} (give all of {}, or {})",
                                   fmt::join(given(constants, false), ", "), fmt::join(names(constants), ", "),
                                   name("e_star")));
    }
    const bool rigid2 = std::isinf(*o_.e2) && *o_.e2 > 0.0;  // adds no compliance: E* = E1 / (1 - nu1^2)
    const ElasticBody body1{modulus("E1", *o_.e1), poisson("nu1", *o_.nu1)};
    const ElasticBody body2{rigid2 ? *o_.e2 : modulus("E2", *o_.e2), poisson("nu2", *o_.nu2)};
    const double e_star = rigid2 ? ElasticPair(body1, body2).composite_modulus() : composite_modulus(body1, body2);
    // nu near -1 makes a body's compliance vanish and E* grow without bound.
    require_in_range(fmt::format("the composite modulus E* = {:g} Pa of {}, {}, {}, {}", e_star, describe("E1", *o_.e1),
                                 describe("nu1", *o_.nu1), describe("E2", *o_.e2), describe("nu2", *o_.nu2)),
                     e_star, kMinModulus, kMaxModulus, "Pa");
    return ProblemBody{e_star, {}, ElasticPair(body1, body2)};
  }

  const BodyOptions& o_;
};

}  // namespace

std::optional<ProblemBody> make_body(const BodyOptions& options, const OptionSpelling& spelling) {
  return detail::spelled_errors(spelling, [&] { return BodyRules(options, spelling).body(); });
}

}  // namespace halfspace
