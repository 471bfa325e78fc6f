// Whose stresses: a contact has two bodies, and under shear tractions their
// stress fields differ by more than their Poisson's ratios (body 1 takes -q,
// body 2 q: surface_traction.hpp). The rule is the library's, once; the
// program's --stress-body / --body and Python's body= map onto it
// (docs/theory.md, "Stresses under shear tractions").
#pragma once

#include <memory>
#include <optional>
#include <string_view>

#include "halfspace/elastic_pair.hpp"
#include "halfspace/stress/subsurface_stress.hpp"
#include "halfspace/stress/surface_traction.hpp"

namespace halfspace::stress {

// "1" or "2"; throws InputError naming `option`, the value and the allowed
// values otherwise.
StressedBody parse_stressed_body(std::string_view text, std::string_view option);
int body_number(StressedBody body);

// The body a user most likely means when none is named: the one that
// deforms. Body 1 when it is coated (ElasticPair::coated) or body 2 is rigid
// (E2 = inf); body 2 otherwise, and when the bodies are not known.
StressedBody default_stressed_body(const std::optional<ElasticPair>& bodies);

// What the stresses are computed for.
struct StressedBodyChoice {
  StressedBody body = StressedBody::body2;
  double poisson_ratio = 0.0;  // the body's; unused for a coated body (each depth takes its own)
};

// The body (`requested`, else the default) and its Poisson's ratio: `given`
// if set, else the body's own from `bodies`. Throws InputError naming the
// options: body 2 of a coated result (the rigid counter-body: only the
// coated body's field is computed), `given` for a coated result (each depth
// takes the layer's or the substrate's own), no Poisson's ratio to be had (neither
// `given` nor the bodies), or none named for two elastic bodies of different
// Poisson's ratios. Options are named as the front end spells them.
StressedBodyChoice choose_stressed_body(std::optional<StressedBody> requested, std::optional<double> given,
                                        const std::optional<ElasticPair>& bodies, std::string_view body_option,
                                        std::string_view nu_option);

// The stress field of the chosen body: the coated body's, each depth with
// its layer's or substrate's constants, where `coating` is set; else the
// homogeneous half-space of `body`'s Poisson's ratio.
std::unique_ptr<SubsurfaceStress> make_subsurface_stress(const Grid& grid,
                                                         const std::optional<LayeredMaterial>& coating,
                                                         const StressedBodyChoice& body, const solvers::Layout& layout,
                                                         FftPlanning planning = FftPlanning::estimate);

}  // namespace halfspace::stress
