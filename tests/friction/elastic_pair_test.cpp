// The two bodies' compliance factors, E* and Dundurs' beta.
#include "halfspace/elastic_pair.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "halfspace/error.hpp"

namespace halfspace {
namespace {

TEST(ElasticPair, CompliancesAddOverBothBodies) {
  const ElasticBody steel{2.1e11, 0.3};
  const ElasticBody aluminium{7e10, 0.33};
  const ElasticPair pair(steel, aluminium);
  const double g1 = steel.youngs_modulus / (2.0 * 1.3);
  const double g2 = aluminium.youngs_modulus / (2.0 * 1.33);
  EXPECT_DOUBLE_EQ(pair.shear_compliance(), 1.0 / g1 + 1.0 / g2);
  EXPECT_DOUBLE_EQ(pair.directional_compliance(), 0.3 / g1 + 0.33 / g2);
  EXPECT_DOUBLE_EQ(pair.coupling_compliance(), 0.4 / g1 - 0.34 / g2);
  EXPECT_NEAR(pair.composite_modulus(), composite_modulus(steel, aluminium), 1e-12 * pair.composite_modulus());
  // Dundurs (1969): beta = ((1 - 2 nu1)/G1 - (1 - 2 nu2)/G2) / (2 ((1 - nu1)/G1 + (1 - nu2)/G2)).
  EXPECT_NEAR(pair.dundurs_beta(), (0.4 / g1 - 0.34 / g2) / (2.0 * (0.7 / g1 + 0.67 / g2)), 1e-15);
  EXPECT_FALSE(pair.similar());
}

TEST(ElasticPair, SimilarBodiesUncoupleAndARigidBodyDropsOut) {
  const ElasticBody steel{2.1e11, 0.3};
  EXPECT_TRUE(ElasticPair::similar(steel).similar());
  EXPECT_EQ(ElasticPair::similar(steel).dundurs_beta(), 0.0);
  const ElasticPair on_rigid = ElasticPair::on_rigid(steel);
  EXPECT_DOUBLE_EQ(on_rigid.shear_compliance(), 2.6 / 2.1e11);
  EXPECT_DOUBLE_EQ(on_rigid.composite_modulus(), 2.1e11 / 0.91);
  // A rigid sphere on an elastic half-space: beta = (1 - 2 nu)/(2 (1 - nu)).
  EXPECT_NEAR(on_rigid.dundurs_beta(), 0.4 / 1.4, 1e-15);
}

TEST(ElasticPair, RefusesBodiesOutOfRange) {
  EXPECT_THROW(ElasticPair({-1.0, 0.3}, {1e9, 0.3}), InputError);
  EXPECT_THROW(ElasticPair({std::numeric_limits<double>::infinity(), 0.3}, {1e9, 0.3}), InputError);
  EXPECT_THROW(ElasticPair({1e9, 0.6}, {1e9, 0.3}), InputError);
  EXPECT_THROW(ElasticPair({1e9, 0.3}, {std::numeric_limits<double>::quiet_NaN(), 0.3}), InputError);
}

}  // namespace
}  // namespace halfspace
