// Whose stresses: the defaults follow the body that deforms, the choice and
// its Poisson's ratio come from the bodies, and body 1 takes -q.
#include "halfspace/stress/stressed_body.hpp"

#include <gtest/gtest.h>

#include <array>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "halfspace/error.hpp"

namespace halfspace::stress {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(StressedBodyTest, ParsesOneAndTwoAndNamesTheOptionOtherwise) {
  EXPECT_EQ(parse_stressed_body("1", "--body"), StressedBody::body1);
  EXPECT_EQ(parse_stressed_body("2", "--body"), StressedBody::body2);
  const std::string message = error_of([] { parse_stressed_body("3", "--stress-body"); });
  EXPECT_NE(message.find("--stress-body 3 is invalid"), std::string::npos) << message;
  EXPECT_NE(message.find("1 (body 1) and 2 (body 2)"), std::string::npos) << message;
}

TEST(StressedBodyTest, DefaultsToTheBodyThatDeforms) {
  EXPECT_EQ(default_stressed_body(std::nullopt), StressedBody::body2);
  EXPECT_EQ(default_stressed_body(ElasticPair({2e11, 0.3}, {2e11, 0.3})), StressedBody::body2);
  EXPECT_EQ(default_stressed_body(ElasticPair({2e11, 0.3}, {kInf, 0.25})), StressedBody::body1);
  const LayeredMaterial coating{1e-6, {1e11, 0.25}, {2e11, 0.3}};
  EXPECT_EQ(default_stressed_body(ElasticPair::coated(coating)), StressedBody::body1);
}

TEST(StressedBodyTest, TakesThePoissonRatioOfTheChosenBody) {
  const ElasticPair rigid2({2e11, 0.28}, {kInf, 0.2});
  StressedBodyChoice c = choose_stressed_body(std::nullopt, std::nullopt, rigid2, "--body", "--nu");
  EXPECT_EQ(c.body, StressedBody::body1);
  EXPECT_EQ(c.poisson_ratio, 0.28);
  c = choose_stressed_body(StressedBody::body2, std::nullopt, rigid2, "--body", "--nu");
  EXPECT_EQ(c.body, StressedBody::body2);
  EXPECT_EQ(c.poisson_ratio, 0.2);
  // A given ratio wins over the body's own.
  c = choose_stressed_body(std::nullopt, 0.4, rigid2, "--body", "--nu");
  EXPECT_EQ(c.poisson_ratio, 0.4);
  // Unknown bodies: body 2 with the given ratio, or a message naming the option.
  c = choose_stressed_body(std::nullopt, 0.3, std::nullopt, "--body", "--nu");
  EXPECT_EQ(c.body, StressedBody::body2);
  std::string message =
      error_of([] { choose_stressed_body(std::nullopt, std::nullopt, std::nullopt, "--body", "--nu"); });
  EXPECT_NE(message.find("pass --nu NU"), std::string::npos) << message;
  message = error_of([] { choose_stressed_body(std::nullopt, 0.7, std::nullopt, "--body", "--nu"); });
  EXPECT_FALSE(message.empty());
}

TEST(StressedBodyTest, TwoElasticBodiesOfDifferentRatiosMustBeNamed) {
  const ElasticPair dissimilar({2e11, 0.3}, {7e10, 0.33});
  const std::string message =
      error_of([&] { choose_stressed_body(std::nullopt, std::nullopt, dissimilar, "--stress-body", "--stress-nu"); });
  EXPECT_NE(message.find("pass --stress-body 1 or 2, or --stress-nu NU"), std::string::npos) << message;
  EXPECT_EQ(choose_stressed_body(StressedBody::body2, std::nullopt, dissimilar, "b", "n").poisson_ratio, 0.33);
  EXPECT_EQ(choose_stressed_body(StressedBody::body1, std::nullopt, dissimilar, "b", "n").poisson_ratio, 0.3);
}

TEST(StressedBodyTest, ACoatedBodyIsBodyOne) {
  const ElasticPair coated = ElasticPair::coated({1e-6, {1e11, 0.25}, {2e11, 0.3}});
  EXPECT_EQ(choose_stressed_body(std::nullopt, std::nullopt, coated, "--body", "--nu").body, StressedBody::body1);
  const std::string message =
      error_of([&] { choose_stressed_body(StressedBody::body2, std::nullopt, coated, "--body", "--nu"); });
  EXPECT_NE(message.find("--body 2 is not available for a coated half-space"), std::string::npos) << message;
  // Each depth takes the layer's or the substrate's own ratio: a given one is refused, not ignored.
  const std::string given = error_of([&] { choose_stressed_body(std::nullopt, 0.4, coated, "--body", "--nu"); });
  EXPECT_NE(given.find("--nu 0.4 is not used for a coated half-space"), std::string::npos) << given;
  EXPECT_NE(given.find("(0.25) in the layer and the substrate's (0.3)"), std::string::npos) << given;
  EXPECT_NE(error_of([&] { choose_stressed_body(std::nullopt, 0.4, coated, "body=", "nu="); }).find("nu=0.4 is not"),
            std::string::npos);
}

TEST(StressedBodyTest, BodyOneTakesTheOppositeShear) {
  const std::vector<double> p{1.0, 2.0, 3.0};
  const std::vector<double> qx{0.5, -0.25, 0.0};
  const std::vector<double> qy{0.1, 0.2, -0.3};
  const SurfaceTractions result{p, qx, qy};
  std::array<std::vector<double>, 2> scratch;
  const SurfaceTractions on2 = tractions_on(StressedBody::body2, result, scratch);
  EXPECT_EQ(on2.body, StressedBody::body2);
  EXPECT_EQ(on2.shear_x.data(), qx.data());
  const SurfaceTractions on1 = tractions_on(StressedBody::body1, result, scratch);
  EXPECT_EQ(on1.body, StressedBody::body1);
  EXPECT_EQ(on1.pressure.data(), p.data());
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_EQ(on1.shear_x[i], -qx[i]);
    EXPECT_EQ(on1.shear_y[i], -qy[i]);
  }
  // No shear: nothing to turn.
  const SurfaceTractions pressure_only = tractions_on(StressedBody::body1, SurfaceTractions{p, {}, {}}, scratch);
  EXPECT_FALSE(pressure_only.has_shear());
}

}  // namespace
}  // namespace halfspace::stress
