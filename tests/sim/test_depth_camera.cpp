// test_depth_camera.cpp: the simulated depth camera against known geometry. A straight rod of
// radius r across the camera's view at depth D: with zero noise every point lies on its surface and
// the visible pixels number about its projected area; the Kinect's axial noise spreads the points
// by about σ_z(D); a box in front of half the rod hides that half; the rod folded back hides its
// far part behind its near one; a link capsule hides the band behind it; the Panda's capsules are
// placed in the world; flying pixels and the range; the same seed gives the same cloud.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "rodshape/error.hpp"
#include "rodshape/samples/panda.hpp"
#include "rodshape/sim/depth_camera.hpp"
#include "support/input_error.hpp"

namespace rodshape {
namespace test_depth_camera {
namespace {

constexpr double kDepth = 1.0;    // m, D: the rod's axis from the camera
constexpr double kRadius = 0.01;  // m, r
constexpr double kLength = 0.3;   // m, L: along the camera's x

/// A camera at the world's origin looking along +z, noise off, every visible pixel kept.
DepthSensorModel exact_camera() {
  DepthSensorModel model;
  model.camera = Pose{};
  model.noise = {0.0, 0.0, 0.0, 0.0, 0.0};
  model.points = DepthSensorModel::kMaxPoints;
  return model;
}

/// The nodes p_i of a polyline, sampled every `step` metres along each of its legs.
PlantFrame rod_through(const std::vector<Eigen::Vector3d>& corners, double step = 0.003) {
  PlantFrame frame;
  frame.configuration.p.push_back(corners.front());
  for (std::size_t k = 0; k + 1 < corners.size(); ++k) {
    const int pieces = static_cast<int>(std::ceil((corners[k + 1] - corners[k]).norm() / step));
    for (int i = 1; i <= pieces; ++i)
      frame.configuration.p.push_back(corners[k] +
                                      (corners[k + 1] - corners[k]) * (double(i) / pieces));
  }
  return frame;
}

PlantFrame straight_rod() {
  return rod_through({{-0.5 * kLength, 0.0, kDepth}, {0.5 * kLength, 0.0, kDepth}});
}

/// Distance from p to the straight rod's axis (the segment).
double to_axis(const Eigen::Vector3d& p) {
  const double x = std::clamp(p.x(), -0.5 * kLength, 0.5 * kLength);
  return (p - Eigen::Vector3d(x, 0.0, kDepth)).norm();
}

TEST(DepthCamera, ZeroNoisePointsLieOnTheSurface) {
  DepthCamera camera(exact_camera(), 1);
  const CloudFrame cloud = camera.observe(straight_rod(), kRadius);
  ASSERT_GT(cloud.points.size(), 500u);
  EXPECT_EQ(static_cast<int>(cloud.points.size()), camera.visible_pixels());
  for (const Eigen::Vector3d& p : cloud.points) {
    EXPECT_NEAR(to_axis(p), kRadius, 1e-9);  // a quadratic's root near a tangent ray
    EXPECT_LT(p.z(), kDepth);                // the side facing the camera
  }
}

TEST(DepthCamera, VisiblePixelsAreTheProjectedArea) {
  // A cylinder of length L and radius r with its two end caps (half-balls: a disc together) at
  // depth D projects to about f_x f_y (2 r L + π r²) / D² pixels (the perspective widening,
  // D / √(D² − r²), is 5e-5 here). A pixel counts when its centre is inside. Along a pixel row
  // the count is the width rounded to whole rows (8 rows for 7.3 px: +9 %), so the rod is turned
  // by 35° in the image: the count then differs from the area by about √(perimeter) pixels (a
  // lattice count), some 2 % of ~840.
  const DepthSensorModel model = exact_camera();
  const Eigen::Vector3d half = 0.5 * kLength * Eigen::Vector3d(std::cos(0.61), std::sin(0.61), 0);
  const Eigen::Vector3d middle(0.0, 0.0, kDepth);
  DepthCamera camera(model, 1);
  camera.observe(rod_through({middle - half, middle + half}), kRadius);
  const double area = model.focal_x() * model.focal_y() *
                      (2.0 * kRadius * kLength + std::numbers::pi * kRadius * kRadius) /
                      (kDepth * kDepth);
  EXPECT_NEAR(camera.visible_pixels(), area, 0.03 * area);
}

TEST(DepthCamera, AxialNoiseSpreadsPointsBySigmaZ) {
  DepthSensorModel model = exact_camera();
  model.noise = DepthNoiseModel{};
  model.noise.incidence = 0.0;
  model.noise.lateral_pixels = 0.0;
  DepthCamera camera(model, 7);
  const CloudFrame cloud = camera.observe(straight_rod(), kRadius);
  // Along the ray, the noise moves a point off the surface by σ_z ε cos θ (θ the incidence):
  // its RMS over the facing half-cylinder is σ_z / √2 · √(1 + …) ∈ (0.6, 1) σ_z.
  const double sigma = model.noise.axial_sigma(kDepth);
  double sum2 = 0.0, worst = 0.0;
  for (const Eigen::Vector3d& p : cloud.points) {
    const double off = to_axis(p) - kRadius;
    sum2 += off * off;
    worst = std::max(worst, std::abs(off));
  }
  const double rms = std::sqrt(sum2 / static_cast<double>(cloud.points.size()));
  EXPECT_GT(rms, 0.6 * sigma);
  EXPECT_LT(rms, 1.0 * sigma);
  EXPECT_LT(worst, 5.0 * sigma);
}

TEST(DepthCamera, KeepsTheModelsPointsPerFrameAtRandom) {
  DepthSensorModel model = exact_camera();
  model.points = 100;
  DepthCamera camera(model, 3);
  const CloudFrame cloud = camera.observe(straight_rod(), kRadius);
  EXPECT_EQ(cloud.points.size(), 100u);
  // Spread along the rod, not the first 100 pixels in image order (x from −L/2 to L/2).
  double least = 1.0, most = -1.0;
  for (const Eigen::Vector3d& p : cloud.points) {
    least = std::min(least, p.x());
    most = std::max(most, p.x());
  }
  EXPECT_LT(least, -0.3 * kLength);
  EXPECT_GT(most, 0.3 * kLength);
}

TEST(DepthCamera, ABoxInFrontOfHalfTheRodHidesThatHalf) {
  const DepthSensorModel model = exact_camera();
  DepthCamera open(model, 1), hidden(model, 1);
  open.observe(straight_rod(), kRadius);
  // Its right edge on the optical axis's plane x = 0: every ray with x < 0 meets it at z = 0.5.
  DepthOccluders occluders;
  occluders.obstacles = {{"board", BoxObstacle{{-0.15, 0.0, 0.5}, {0.3, 0.2, 0.05}}}};
  const CloudFrame cloud = hidden.observe(straight_rod(), kRadius, occluders);
  for (const Eigen::Vector3d& p : cloud.points) EXPECT_GT(p.x(), 0.0);
  EXPECT_NEAR(hidden.visible_pixels(), 0.5 * open.visible_pixels(), 0.03 * open.visible_pixels());
}

TEST(DepthCamera, ATableBelowTheRodHidesNothing) {
  DepthCamera camera(exact_camera(), 1);
  DepthOccluders occluders;  // the half-space y > 0.05 (image y is down): below the rod
  occluders.obstacles = {{"table", HalfSpaceObstacle{{0.0, 1.0, 0.0}, 0.05}}};
  DepthCamera open(exact_camera(), 1);
  open.observe(straight_rod(), kRadius);
  camera.observe(straight_rod(), kRadius, occluders);
  EXPECT_EQ(camera.visible_pixels(), open.visible_pixels());
}

TEST(DepthCamera, TheRodHidesItselfWhereItFoldsBack) {
  // Out along z = 1, back along z = 0.9, in front of the first leg.
  const double near = 0.9;
  const PlantFrame folded = rod_through(
      {{-0.15, 0.0, kDepth}, {0.15, 0.0, kDepth}, {0.15, 0.0, near}, {-0.15, 0.0, near}});
  DepthCamera camera(exact_camera(), 1);
  const CloudFrame cloud = camera.observe(folded, kRadius);
  int far_points = 0;
  for (const Eigen::Vector3d& p : cloud.points)
    if (std::abs(p.x()) < 0.13 && p.z() > near + kRadius) ++far_points;
  EXPECT_EQ(far_points, 0);
  EXPECT_GT(cloud.points.size(), 500u);
}

TEST(DepthCamera, ALinkCapsuleHidesTheBandBehindIt) {
  // A vertical link of radius 2 cm at depth 0.5 hides |x| < (0.02 / 0.5) · 1 = 4 cm at the rod
  // (to first order; the tangent rays give 0.02 / √(0.5² − 0.02²) · 1).
  DepthOccluders occluders;
  occluders.links = {CapsuleObstacle{{0.0, -0.3, 0.5}, {0.0, 0.3, 0.5}, 0.02}};
  DepthCamera camera(exact_camera(), 1);
  const CloudFrame cloud = camera.observe(straight_rod(), kRadius, occluders);
  int beside = 0;
  for (const Eigen::Vector3d& p : cloud.points) {
    EXPECT_GT(std::abs(p.x()), 0.0395);
    if (std::abs(p.x()) < 0.06) ++beside;
  }
  EXPECT_GT(beside, 0);
}

TEST(DepthCamera, ThePandasLinkCapsulesStandWhereTheArmDoes) {
  PlanArm arm{samples::panda(), {}};
  const Eigen::VectorXd q = samples::panda_ready_pose();
  const std::vector<CapsuleObstacle> at_origin = arm_link_capsules(arm, q);
  ASSERT_EQ(at_origin.size(), arm.model.link_capsules().size());
  ASSERT_FALSE(at_origin.empty());
  arm.placement.world_T_base.position = Eigen::Vector3d(0.4, -0.2, 0.1);
  const std::vector<CapsuleObstacle> moved = arm_link_capsules(arm, q);
  for (std::size_t c = 0; c < moved.size(); ++c) {
    EXPECT_LT((moved[c].from - at_origin[c].from - Eigen::Vector3d(0.4, -0.2, 0.1)).norm(), 1e-12);
    EXPECT_DOUBLE_EQ(moved[c].radius, at_origin[c].radius);
  }
}

TEST(DepthCamera, FlyingPixelsLieBehindTheSilhouette) {
  DepthSensorModel model = exact_camera();
  model.points = 200;
  model.outliers = 0.25;
  DepthCamera camera(model, 5);
  const CloudFrame cloud = camera.observe(straight_rod(), kRadius);
  ASSERT_EQ(cloud.points.size(), 200u);
  int off_surface = 0;
  for (const Eigen::Vector3d& p : cloud.points)
    if (std::abs(to_axis(p) - kRadius) > 1e-9) {
      ++off_surface;
      EXPECT_LT(p.z(), kDepth + DepthCamera::kFlyingDepth + 1e-12);
    }
  // 50 flying pixels; one drawn within 1e-9 m of the surface has probability ~1e-8.
  EXPECT_EQ(off_surface, 50);
}

TEST(DepthCamera, DepthsOutsideTheRangeAreNotReported) {
  DepthSensorModel model = exact_camera();
  model.min_range = kDepth + 0.02;  // the whole rod is nearer
  DepthCamera camera(model, 1);
  EXPECT_TRUE(camera.observe(straight_rod(), kRadius).points.empty());
  EXPECT_EQ(camera.visible_pixels(), 0);
}

TEST(DepthCamera, TheSameSeedGivesTheSameCloud) {
  DepthSensorModel model;  // Kinect defaults
  model.camera = Pose{};
  model.outliers = 0.1;
  DepthCamera a(model, 11), b(model, 11), c(model, 12);
  const CloudFrame first = a.observe(straight_rod(), kRadius);
  const CloudFrame second = b.observe(straight_rod(), kRadius);
  ASSERT_EQ(first.points.size(), second.points.size());
  for (std::size_t k = 0; k < first.points.size(); ++k)
    EXPECT_EQ(first.points[k], second.points[k]);  // bit for bit
  EXPECT_NE(c.observe(straight_rod(), kRadius).points.front(), first.points.front());
}

TEST(DepthCamera, BadModelAndRadiusAreNamed) {
  DepthSensorModel model;
  model.points = 0;
  EXPECT_EQ(testing::input_error_message([&] {
              (void)DepthCamera(model, 1);
            }).rfind("DepthSensorModel.points = 0 must be in [1, 100000]", 0),
            0u);
  model.points = 500;
  model.width = DepthSensorModel::kMaxResolution + 1;
  EXPECT_NE(testing::input_error_message([&] {
              (void)DepthCamera(model, 1);
            }).find("DepthSensorModel.width"),
            std::string::npos);
  DepthCamera camera(DepthSensorModel{}, 1);
  EXPECT_NE(testing::input_error_message([&] {
              camera.observe(straight_rod(), 0.0);
            }).find("Scene.rod_radius"),
            std::string::npos);
}

}  // namespace
}  // namespace test_depth_camera
}  // namespace rodshape
