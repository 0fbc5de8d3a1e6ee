// The estimate's options (state_estimator.hpp): the sigma floors are stated, positive and bounded.
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "rodshape/error.hpp"
#include "rodshape/feedback/state_estimator.hpp"

namespace rodshape {
namespace test_estimation_options {
namespace {

/// The message of the InputError that `options.validate()` throws, or "" if none.
std::string refusal(const EstimationOptions& options) {
  try {
    options.validate();
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

TEST(EstimationOptions, TheSigmaFloorsArePositiveAndBounded) {
  const EstimationOptions defaults;
  EXPECT_EQ(refusal(defaults), "");
  EXPECT_EQ(defaults.min_marker_sigma, 1e-4);  // 0.1 mm, as docs/validation.md states
  for (const double bad : {0.0, -1e-4, 2.0, std::numeric_limits<double>::quiet_NaN()}) {
    EstimationOptions options;
    options.min_marker_sigma = bad;
    EXPECT_NE(refusal(options).find("EstimationOptions.min_marker_sigma"), std::string::npos)
        << bad << ": " << refusal(options);
    options = {};
    options.min_wrist_force_sigma = bad == 2.0 ? 1e21 : bad;  // 2 N is allowed; 1e21 is not
    EXPECT_NE(refusal(options).find("EstimationOptions.min_wrist_force_sigma"), std::string::npos)
        << bad << ": " << refusal(options);
    options = {};
    options.min_wrist_moment_sigma = bad == 2.0 ? 1e21 : bad;
    EXPECT_NE(refusal(options).find("EstimationOptions.min_wrist_moment_sigma"), std::string::npos)
        << bad << ": " << refusal(options);
  }
}

}  // namespace
}  // namespace test_estimation_options
}  // namespace rodshape
