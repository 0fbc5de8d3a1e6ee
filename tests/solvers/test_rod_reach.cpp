// test_rod_reach.cpp: a tip held farther from the clamp than the rod reaches within the model's
// range is said to be out of reach before solving (issue 24, item 5): the band held 10 m away ended
// in "iteration_limit" after 834 integrations.
#include <gtest/gtest.h>

#include <cmath>

#include "rodshape/solvers/equilibrium_analysis.hpp"
#include "rodshape/solvers/rod_reach.hpp"
#include "support/input_error.hpp"
#include "support/solver_fixtures.hpp"

namespace rodshape {
namespace test_rod_reach {
namespace {

using testing::input_error_message;
using testing::kBandLength;

TEST(RodReach, MaxTipDistanceIsTheLengthTimesTheLargestStretch) {
  const ModelValidityLimits limits;  // 0.5 axial, 0.5 shear
  ClampedRod rod = testing::rubber_band();
  // |v| ≤ √(0.5² + 0.5² + 1.5²) for a rod straight and unstretched at rest.
  EXPECT_DOUBLE_EQ(max_tip_distance(rod.properties, limits), kBandLength * std::sqrt(2.75));
  rod.properties.model = ConstitutiveModel::Kirchhoff;
  EXPECT_DOUBLE_EQ(max_tip_distance(rod.properties, limits), kBandLength);
}

TEST(RodReach, ATipTenMetresAwayIsOutOfReachBeforeSolving) {
  const ClampedRod rod = testing::rubber_band();
  const ClampedTip far{Pose{{10.0, 0.0, 0.0}, Eigen::Matrix3d::Identity()}};
  const std::string message = input_error_message([&] { analyse_equilibrium(rod, far); });
  EXPECT_EQ(message.rfind("ClampedTip.pose: the position is 10 m from the clamp, out of reach", 0),
            0u)
      << message;
  EXPECT_NE(message.find("ShootingOptions.strain_limits.max_axial_strain = 0.5"), std::string::npos)
      << message;
  // A grasp is held as far.
  const GraspedTip grasped{far.pose, {false, false, false, true, false, false}};
  EXPECT_EQ(input_error_message([&] { analyse_equilibrium(rod, grasped); }).rfind("GraspedTip", 0),
            0u);
}

TEST(RodReach, AGraspSlidesAlongItsReleasedForceAxes) {
  // Released fx: the tip may slide along the grasp's x axis, so p_d = (10, 0, 0.2) holds it
  // anywhere on that line; the point nearest the clamp, (0, 0, 0.2), is within reach.
  const GraspedTip sliding{Pose{{10.0, 0.0, 0.2}, Eigen::Matrix3d::Identity()},
                           {true, false, false, false, false, false}};
  const auto nearest = nearest_held_position(Eigen::Vector3d::Zero(), sliding);
  ASSERT_TRUE(nearest.has_value());
  EXPECT_TRUE(nearest->isApprox(Eigen::Vector3d(0.0, 0.0, 0.2)));
  EXPECT_NO_THROW(check_within_reach(testing::rubber_band(), sliding, ModelValidityLimits{},
                                     "GraspedTip.pose", "limits"));
  EXPECT_FALSE(nearest_held_position(Eigen::Vector3d::Zero(), FreeTip{}).has_value());
}

TEST(RodReach, ATipWithinReachIsSolved) {
  // Straight along z, stretched by 20 %: within max_axial_strain = 0.5 and solved.
  const ClampedRod rod = testing::rubber_band();
  const ClampedTip stretched{Pose{{0.0, 0.0, 1.2 * kBandLength}, Eigen::Matrix3d::Identity()}};
  const EquilibriumAnalysis analysis = analyse_equilibrium(rod, stretched);
  EXPECT_TRUE(analysis.converged()) << analysis.brief();
  // An inextensible rod reaches its length and no farther.
  ClampedRod kirchhoff = testing::rubber_band(ConstitutiveModel::Kirchhoff);
  const std::string message =
      input_error_message([&] { analyse_equilibrium(kirchhoff, stretched); });
  EXPECT_NE(message.find("an inextensible rod (RodProperties.model = kirchhoff) of length 0.29 m"),
            std::string::npos)
      << message;
}

}  // namespace
}  // namespace test_rod_reach
}  // namespace rodshape
