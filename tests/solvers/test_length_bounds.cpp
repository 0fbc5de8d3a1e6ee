// test_length_bounds.cpp: the ends of the length range (physical_bounds.hpp, kLength: 1e-4 …
// 1e4 m) are solvable, so the range refuses only what cannot be (issue 24, item 5). The band
// scaled geometrically (length, section and tip pose times k, E as it is) holds the same shape
// scaled: it converges to the default tolerances and is stable, as at k = 1.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <numbers>

#include "rodshape/core/physical_bounds.hpp"
#include "rodshape/solvers/equilibrium_analysis.hpp"

namespace rodshape {
namespace test_length_bounds {
namespace {

TEST(LengthBounds, TheBandScaledToEitherEndOfTheLengthRangeConvergesAndIsStable) {
  for (const double length : {bounds::kLength.min, bounds::kLength.max}) {
    SCOPED_TRACE(length);
    const double k = length / 0.29;
    RodDescription band;
    band.length = length;
    // The band's section, capped at the section range's 100 m (its shape stays slender).
    const double side = std::min(0.02 * k, bounds::kSectionSize.max / 2);
    band.section = CrossSection::rectangle(side, side);
    band.material = Material{3.2e6, 0.5, 1392.0};
    ClampedRod rod;
    rod.properties = make_rod_properties(band);
    Pose tip;
    tip.position = Eigen::Vector3d(0.12, 0.0, 0.22) * k;
    tip.rotation =
        Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
    const EquilibriumAnalysis analysis = analyse_equilibrium(rod, ClampedTip{tip});
    EXPECT_TRUE(analysis.converged()) << analysis.brief();
    ASSERT_TRUE(analysis.stability.has_value());
    EXPECT_TRUE(analysis.stability->stable);
  }
}

}  // namespace
}  // namespace test_length_bounds
}  // namespace rodshape
