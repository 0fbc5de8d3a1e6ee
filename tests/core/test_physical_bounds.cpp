// test_physical_bounds.cpp: every physical size a user sets has a documented range (issue 24,
// item 5; docs/limits.md, "Physical sizes"): `rod.length: 1e300` or `1e-300` ended in a "singular"
// solve, now it is an InputError naming the field. And a Cosserat rod stiffer in extension than
// double precision resolves (EA·L²/EI > 1e16, item 8) is refused, suggesting the Kirchhoff model.
#include <gtest/gtest.h>

#include <limits>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/physical_bounds.hpp"
#include "rodshape/samples/rubber_band.hpp"
#include "support/input_error.hpp"

namespace rodshape {
namespace test_physical_bounds {
namespace {

using testing::input_error_message;

bool names(const std::string& message, const std::string& field) {
  return message.rfind(field, 0) == 0;
}

TEST(PhysicalBounds, LengthsBeyondTheRangeAreRefusedNamingTheLength) {
  for (const double length : {1e300, 1e-300, 1e5, 1e-5}) {
    SCOPED_TRACE(length);
    RodDescription band = samples::rubber_band_description();
    band.length = length;
    const std::string message = input_error_message([&] { make_rod_properties(band); });
    EXPECT_TRUE(names(message, "RodDescription.length = ")) << message;
    EXPECT_NE(message.find("must be in [0.0001, 10000] m"), std::string::npos) << message;
    RodProperties p = samples::rubber_band().properties;
    p.length = length;
    EXPECT_TRUE(names(input_error_message([&] { p.validate(); }), "RodProperties.length"));
  }
  // The ends of the range are accepted.
  for (const double length : {bounds::kLength.min, bounds::kLength.max}) {
    RodProperties p = samples::rubber_band(ConstitutiveModel::Kirchhoff).properties;
    p.length = length;
    EXPECT_NO_THROW(p.validate()) << length;
  }
}

TEST(PhysicalBounds, SectionMaterialAndStiffnessBeyondTheRangeAreRefusedNamingThem) {
  const auto message_of = [](auto edit) {
    RodDescription band = samples::rubber_band_description();
    edit(band);
    return input_error_message([&] { make_rod_properties(band); });
  };
  EXPECT_TRUE(names(message_of([](RodDescription& d) { d.section->width = 1e300; }),
                    "RodDescription.section.width"));
  EXPECT_TRUE(names(message_of([](RodDescription& d) { d.section->height = 1e-300; }),
                    "RodDescription.section.height"));
  EXPECT_TRUE(names(message_of([](RodDescription& d) { d.material->young_modulus = 1e300; }),
                    "RodDescription.material.young_modulus"));
  EXPECT_TRUE(names(message_of([](RodDescription& d) { d.material->young_modulus = 1e-300; }),
                    "RodDescription.material.young_modulus"));
  EXPECT_TRUE(names(message_of([](RodDescription& d) { d.material->density = 1e300; }),
                    "RodDescription.material.density"));
  EXPECT_TRUE(names(message_of([](RodDescription& d) { d.stiffness.EIx = 1e300; }),
                    "RodDescription.stiffness.EIx"));
  EXPECT_TRUE(names(message_of([](RodDescription& d) { d.stiffness.GJ = 1e-300; }),
                    "RodDescription.stiffness.GJ"));
}

TEST(PhysicalBounds, LoadsClampAndRestCurvatureBeyondTheRangeAreRefusedNamingThem) {
  {
    ClampedRod rod = samples::rubber_band();
    rod.load.force = {0.0, 0.0, -1e300};
    EXPECT_TRUE(names(input_error_message([&] { rod.validate(); }), "ClampedRod.load.force"));
  }
  {
    ClampedRod rod = samples::rubber_band();
    rod.clamp.position = {1e300, 0.0, 0.0};
    EXPECT_TRUE(names(input_error_message([&] { rod.validate(); }), "ClampedRod.clamp.position"));
  }
  {
    ClampedRod rod = samples::rubber_band();
    rod.properties.u_rest = {1e300, 0.0, 0.0};
    EXPECT_TRUE(names(input_error_message([&] { rod.validate(); }), "RodProperties.u_rest"));
  }
}

// Issue 24, item 8: the band with EIx, EIy, GJ given and E = 1e20 has EA·L²/EI ≈ 8.4e16 (EA = E
// · 4e-4 m², L = 0.29 m, EI = 0.04 N·m²): refused naming EA and suggesting the Kirchhoff model;
// at E = 1e19 (8.4e15) accepted; the Kirchhoff rod does not use EA and is accepted at any E.
TEST(PhysicalBounds, CosseratRodBeyondTheResolvableStretchToBendRatioIsRefused) {
  RodDescription band = samples::rubber_band_description();
  band.material->young_modulus = 1e20;
  const std::string message = input_error_message([&] { make_rod_properties(band); });
  // Named as the user gave it: Young's modulus, whose E A is EA.
  EXPECT_EQ(message,
            "RodDescription.material.young_modulus = 1e+20 Pa makes EA = E A = 4e+16 N, with "
            "EI = 0.04 N*m^2 and L = 0.29 m, gives EA*L^2/EI = 8.41e+16, beyond 1e+16: a Cosserat "
            "rod that stiff in extension is a Kirchhoff rod to double precision; use "
            "RodProperties.model = kirchhoff");
  {
    RodDescription given = samples::rubber_band_description();
    given.stiffness.EA = 4e16;
    EXPECT_TRUE(names(input_error_message([&] { make_rod_properties(given); }),
                      "RodDescription.stiffness.EA = 4e+16 N, with EI"));
  }
  band.model = ConstitutiveModel::Kirchhoff;
  EXPECT_NO_THROW(make_rod_properties(band));
  band.model = ConstitutiveModel::Cosserat;
  band.material->young_modulus = 1e19;
  EXPECT_NO_THROW(make_rod_properties(band));
  // Given directly, the same.
  RodProperties p = samples::rubber_band().properties;
  p.K_tra.z() = 1e20 * 4e-4;
  EXPECT_TRUE(names(input_error_message([&] { p.validate(); }), "RodProperties.K_tra[2]"));
  p.K_tra = {1e20 * 4e-4, 1e20 * 4e-4, 1280.0};  // shear as stiff: GA named
  EXPECT_TRUE(names(input_error_message([&] { p.validate(); }), "RodProperties.K_tra[0]"));
}

}  // namespace
}  // namespace test_physical_bounds
}  // namespace rodshape
