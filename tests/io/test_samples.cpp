// The sample models are the bundled files: the rubber band is examples/rubber_band.yaml's rod, and
// the compiled-in Panda is data/robots/panda.urdf.
#include <gtest/gtest.h>

#include <random>

#include "rodshape/io/task_reader.hpp"
#include "rodshape/robot/arm_model.hpp"
#include "rodshape/samples/panda.hpp"
#include "rodshape/samples/rubber_band.hpp"
#include "support/panda_dh.hpp"

namespace rodshape {
namespace test_samples {
namespace {

const std::string kSource = RODSHAPE_SOURCE_DIR;

TEST(Samples, RubberBandIsTheBundledExamplesRod) {
  const EquilibriumTask task = read_equilibrium_task(kSource + "/examples/rubber_band.yaml");
  const ClampedRod band = samples::rubber_band();
  // The same numbers through the same make_rod_properties: equal to the last bit.
  EXPECT_EQ(band.properties.length, task.rod.properties.length);
  EXPECT_EQ(band.properties.K_rot, task.rod.properties.K_rot);
  EXPECT_EQ(band.properties.K_tra, task.rod.properties.K_tra);
  EXPECT_EQ(band.properties.mass_per_length, task.rod.properties.mass_per_length);
  EXPECT_EQ(band.properties.model, task.rod.properties.model);
  EXPECT_EQ(band.intervals, task.rod.intervals);
  EXPECT_TRUE(band.clamp.position.isZero());
  EXPECT_TRUE(band.clamp.rotation.isIdentity());
}

TEST(Samples, RubberBandTakesModelAndIntervals) {
  const ClampedRod band = samples::rubber_band(ConstitutiveModel::Kirchhoff, 20);
  EXPECT_EQ(band.properties.model, ConstitutiveModel::Kirchhoff);
  EXPECT_EQ(band.intervals, 20);
  EXPECT_THROW(samples::rubber_band(ConstitutiveModel::Cosserat, 0), InputError);
}

TEST(Samples, PandaIsTheBundledUrdf) {
  const ArmModel sample = samples::panda();
  const ArmModel file = ArmModel::from_urdf_file(testing::kPandaUrdf, "panda_link0", "panda_link8");
  ASSERT_EQ(sample.joints(), 7);
  ASSERT_EQ(file.joints(), 7);
  EXPECT_EQ(sample.tip_link(), "panda_link8");
  std::mt19937 rng(8);
  for (int k = 0; k < 20; ++k) {
    Eigen::VectorXd q = sample.lower_limits();
    for (int j = 0; j < 7; ++j)
      q(j) += std::uniform_real_distribution<double>(0.0, 1.0)(rng) *
              (sample.upper_limits()(j) - sample.lower_limits()(j));
    const Pose a = sample.forward_kinematics(q), b = file.forward_kinematics(q);
    EXPECT_EQ(a.position, b.position);  // the same text, parsed the same way
    EXPECT_EQ(a.rotation, b.rotation);
  }
  const Eigen::VectorXd ready = samples::panda_ready_pose();
  EXPECT_TRUE((ready.array() >= sample.lower_limits().array()).all());
  EXPECT_TRUE((ready.array() <= sample.upper_limits().array()).all());
}

}  // namespace
}  // namespace test_samples
}  // namespace rodshape
