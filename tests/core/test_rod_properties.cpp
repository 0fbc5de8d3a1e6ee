// test_rod_properties.cpp: cross-sections, materials, make_rod_properties (section + material +
// overrides) and the validation of rods: bad input throws InputError naming the field.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <string>

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/rod_properties.hpp"
#include "rodshape/core/so3.hpp"
#include "rodshape/error.hpp"
#include "support/analytic_rods.hpp"
#include "support/eigen_compare.hpp"

namespace rodshape {
namespace test_rod_properties {
namespace {

using testing::CompareMatrices;
using testing::CompareScalars;
using testing::kEps;

constexpr double kPi = std::numbers::pi;
const double kNaN = std::numeric_limits<double>::quiet_NaN();

// Closed forms below are products of a few factors: each side rounds ≤ ~6 times, so they agree to
// 8ε relative.
constexpr double kFormulaRelTol = 8.0 * kEps;

/// `call` must throw InputError whose what() contains every one of `needles`.
::testing::AssertionResult ThrowsInputErrorNaming(const std::function<void()>& call,
                                                  std::initializer_list<std::string> needles) {
  try {
    call();
  } catch (const InputError& error) {
    const std::string message = error.what();
    for (const std::string& needle : needles) {
      if (message.find(needle) == std::string::npos)
        return ::testing::AssertionFailure()
               << "InputError \"" << message << "\" does not name \"" << needle << "\"";
    }
    return ::testing::AssertionSuccess() << message;
  } catch (const std::exception& other) {
    return ::testing::AssertionFailure() << "threw something else: " << other.what();
  }
  return ::testing::AssertionFailure() << "did not throw";
}

// ---- sections and materials ---------------------------------------------------------------------

TEST(CrossSection, RectangleHasAreaAndSecondMomentsAboutEachAxis) {
  const double w = 0.03, h = 0.01;  // width along local x, height along local y
  const CrossSection section = CrossSection::rectangle(w, h);
  EXPECT_TRUE(CompareScalars(section.area(), w * h, kFormulaRelTol * w * h));
  // Ix: bending in the y–z plane, the height is the lever arm: w h³/12 (and Iy = h w³/12).
  EXPECT_TRUE(
      CompareScalars(section.second_moment_x(), w * h * h * h / 12.0, kFormulaRelTol * 2.5e-9));
  EXPECT_TRUE(
      CompareScalars(section.second_moment_y(), h * w * w * w / 12.0, kFormulaRelTol * 2.25e-8));
  // Turning the section a quarter turn swaps the two moments and keeps J.
  const CrossSection turned = CrossSection::rectangle(h, w);
  EXPECT_DOUBLE_EQ(turned.second_moment_x(), section.second_moment_y());
  EXPECT_DOUBLE_EQ(turned.second_moment_y(), section.second_moment_x());
  EXPECT_DOUBLE_EQ(turned.torsion_constant(), section.torsion_constant());
}

TEST(CrossSection, RectangleTorsionConstantIsSaintVenantsSeries) {
  // J = a b³ (1/3 - 0.21 (b/a)(1 - b⁴/(12 a⁴))), a the long side (header's formula).
  const double a = 0.03, b = 0.01, r = b / a;
  const double expected = a * b * b * b * (1.0 / 3.0 - 0.21 * r * (1.0 - std::pow(r, 4) / 12.0));
  EXPECT_TRUE(CompareScalars(CrossSection::rectangle(a, b).torsion_constant(), expected,
                             kFormulaRelTol * expected));
}

TEST(CrossSection, RectangleTorsionConstantIsWithinHalfAPercentOfTheExactSolution) {
  // J = k₁ a b³ with the exact k₁ from Saint-Venant's series solution, tabulated in Timoshenko and
  // Goodier, "Theory of Elasticity", 3rd ed. (1970), §109 (torsion of rectangular bars), to 3
  // digits. The header promises 0.5%; the table's rounding adds up to 0.0005/k₁.
  struct Row {
    double aspect, k1;
  };
  for (const Row row : {Row{1.0, 0.141}, Row{1.5, 0.196}, Row{2.0, 0.229}, Row{2.5, 0.249},
                        Row{3.0, 0.263}, Row{4.0, 0.281}, Row{5.0, 0.291}, Row{10.0, 0.312}}) {
    const double b = 0.004, a = row.aspect * b;
    const double exact = row.k1 * a * b * b * b;
    const double J = CrossSection::rectangle(a, b).torsion_constant();
    EXPECT_LE(std::abs(J / exact - 1.0), 0.005 + 0.0005 / row.k1) << "a/b = " << row.aspect;
  }
}

TEST(CrossSection, CircleHasAreaSecondMomentsAndPolarTorsionConstant) {
  const double r = 0.002;
  const CrossSection section = CrossSection::circle(r);
  const double I = kPi * std::pow(r, 4) / 4.0;
  EXPECT_TRUE(CompareScalars(section.area(), kPi * r * r, kFormulaRelTol * kPi * r * r));
  EXPECT_TRUE(CompareScalars(section.second_moment_x(), I, kFormulaRelTol * I));
  EXPECT_TRUE(CompareScalars(section.second_moment_y(), I, kFormulaRelTol * I));
  EXPECT_TRUE(CompareScalars(section.torsion_constant(), 2.0 * I, kFormulaRelTol * 2.0 * I));
}

TEST(Material, ShearModulusIsYoungOverTwoOnePlusPoisson) {
  Material rubber{3.2e6, 0.5, 1392.0};
  EXPECT_TRUE(CompareScalars(rubber.shear_modulus(), 3.2e6 / 3.0, kFormulaRelTol * 3.2e6 / 3.0));
  Material steel{210e9, 0.3, 7850.0};
  EXPECT_TRUE(CompareScalars(steel.shear_modulus(), 210e9 / 2.6, kFormulaRelTol * 210e9 / 2.6));
}

// ---- make_rod_properties ------------------------------------------------------------------------

RodDescription steel_strip() {
  RodDescription d;
  d.length = 0.5;
  d.section = CrossSection::rectangle(0.02, 0.001);
  d.material = Material{210e9, 0.3, 7850.0};
  return d;
}

TEST(RodProperties, StiffnessFollowsFromSectionAndMaterial) {
  RodDescription d = steel_strip();
  d.rest_curvature = Eigen::Vector3d(0.1, -0.2, 0.3);
  const RodProperties p = make_rod_properties(d);
  const CrossSection& s = *d.section;
  const double E = 210e9, G = E / 2.6;
  EXPECT_EQ(p.length, 0.5);
  EXPECT_EQ(p.model, ConstitutiveModel::Cosserat);
  // K_tra = diag(GA, GA, EA), K_rot = diag(E Ix, E Iy, G J).
  const Eigen::Vector3d K_tra(G * s.area(), G * s.area(), E * s.area());
  const Eigen::Vector3d K_rot(E * s.second_moment_x(), E * s.second_moment_y(),
                              G * s.torsion_constant());
  EXPECT_TRUE(
      CompareMatrices(p.K_tra, K_tra, kFormulaRelTol, testing::MatrixCompareType::relative));
  EXPECT_TRUE(
      CompareMatrices(p.K_rot.cwiseQuotient(K_rot), Eigen::Vector3d::Ones(), kFormulaRelTol));
  EXPECT_TRUE(CompareMatrices(p.v_rest, Eigen::Vector3d::UnitZ(), 0.0));
  EXPECT_TRUE(CompareMatrices(p.u_rest, d.rest_curvature, 0.0));
  EXPECT_TRUE(CompareScalars(p.mass_per_length, 7850.0 * s.area(), kFormulaRelTol * 0.157));
}

TEST(RodProperties, EachStiffnessOverrideWinsOverTheSection) {
  const RodProperties base = make_rod_properties(steel_strip());
  struct Case {
    std::optional<double> StiffnessOverrides::*field;
    bool rotational;
    int index;
  };
  const Case cases[] = {{&StiffnessOverrides::EA, false, 2},
                        {&StiffnessOverrides::EIx, true, 0},
                        {&StiffnessOverrides::EIy, true, 1},
                        {&StiffnessOverrides::GJ, true, 2}};
  for (const Case& c : cases) {
    RodDescription d = steel_strip();
    d.stiffness.*c.field = 123.0;
    const RodProperties p = make_rod_properties(d);
    Eigen::Vector3d K_tra = base.K_tra, K_rot = base.K_rot;
    (c.rotational ? K_rot : K_tra)(c.index) = 123.0;
    EXPECT_TRUE(CompareMatrices(p.K_tra, K_tra, 0.0));  // the others untouched, exactly
    EXPECT_TRUE(CompareMatrices(p.K_rot, K_rot, 0.0));
  }
  RodDescription d = steel_strip();
  d.stiffness.GA = 77.0;  // shear stiffness in both directions
  const RodProperties p = make_rod_properties(d);
  EXPECT_EQ(p.K_tra.x(), 77.0);
  EXPECT_EQ(p.K_tra.y(), 77.0);
  EXPECT_EQ(p.K_tra.z(), base.K_tra.z());
}

// The rubber band of the paper: E = 3.2 MPa, ν = 0.5, ρ = 1392 kg/m³, L = 0.29 m, 0.02 × 0.02 m
// section, with measured bending and torsion stiffness given directly (EIx = EIy = 0.04, GJ =
// 0.028).
TEST(RodProperties, PapersRubberBandUsesMeasuredStiffnessAndSectionForTheRest) {
  RodDescription d;
  d.length = 0.29;
  d.section = CrossSection::rectangle(0.02, 0.02);
  d.material = Material{3.2e6, 0.5, 1392.0};
  d.stiffness.EIx = 0.04;
  d.stiffness.EIy = 0.04;
  d.stiffness.GJ = 0.028;
  const RodProperties p = make_rod_properties(d);
  const double A = 4e-4, G = 3.2e6 / 3.0;
  EXPECT_TRUE(CompareMatrices(p.K_rot, Eigen::Vector3d(0.04, 0.04, 0.028), 0.0));
  EXPECT_TRUE(CompareMatrices(p.K_tra, Eigen::Vector3d(G * A, G * A, 3.2e6 * A), kFormulaRelTol,
                              testing::MatrixCompareType::relative));  // (426.7, 426.7, 1280) N
  EXPECT_TRUE(
      CompareScalars(p.mass_per_length, 1392.0 * A, kFormulaRelTol * 0.5568));  // 0.5568 kg/m
  EXPECT_EQ(p.length, 0.29);
}

TEST(RodProperties, KirchhoffRodNeedsNoAxialOrShearStiffness) {
  RodDescription d;
  d.length = 1.0;
  d.model = ConstitutiveModel::Kirchhoff;
  d.stiffness.EIx = 2.0;
  d.stiffness.EIy = 3.0;
  d.stiffness.GJ = 1.5;
  RodProperties p;
  ASSERT_NO_THROW(p = make_rod_properties(d));
  EXPECT_TRUE(CompareMatrices(p.K_rot, Eigen::Vector3d(2.0, 3.0, 1.5), 0.0));
  EXPECT_EQ(p.mass_per_length, 0.0);  // no section: unknown
  // The same description for a Cosserat rod lacks GA and EA.
  d.model = ConstitutiveModel::Cosserat;
  EXPECT_TRUE(
      ThrowsInputErrorNaming([&] { make_rod_properties(d); }, {"RodDescription.stiffness."}));
}

TEST(RodProperties, ModelNamesRoundTrip) {
  for (ConstitutiveModel model : {ConstitutiveModel::Cosserat, ConstitutiveModel::Kirchhoff})
    EXPECT_EQ(constitutive_model_from_string(to_string(model)), model);
  EXPECT_EQ(to_string(ConstitutiveModel::Cosserat), "cosserat");
  EXPECT_EQ(to_string(ConstitutiveModel::Kirchhoff), "kirchhoff");
  EXPECT_TRUE(ThrowsInputErrorNaming([] { constitutive_model_from_string("elastic"); },
                                     {"RodDescription.model", "elastic"}));
  EXPECT_TRUE(ThrowsInputErrorNaming(
      [] { constitutive_model_from_string("Cosserat", "task.rod.kind"); }, {"task.rod.kind"}));
}

// ---- bad input ----------------------------------------------------------------------------------

TEST(RodPropertiesInput, NegativeLengthIsRejectedNamingFieldAndValue) {
  RodDescription d = steel_strip();
  d.length = -0.3;
  EXPECT_TRUE(
      ThrowsInputErrorNaming([&] { make_rod_properties(d); }, {"RodDescription.length", "-0.3"}));
  RodProperties p = make_rod_properties(steel_strip());
  p.length = -0.3;
  EXPECT_TRUE(ThrowsInputErrorNaming([&] { p.validate(); }, {"RodProperties.length", "-0.3"}));
  p.length = 0.0;
  EXPECT_TRUE(ThrowsInputErrorNaming([&] { p.validate(); }, {"RodProperties.length"}));
}

TEST(RodPropertiesInput, ZeroOrNaNStiffnessIsRejectedNamingTheStiffness) {
  {
    RodDescription d = steel_strip();
    d.stiffness.EIx = 0.0;
    EXPECT_TRUE(ThrowsInputErrorNaming([&] { make_rod_properties(d); }, {"EIx"}));
  }
  {
    RodDescription d = steel_strip();
    d.stiffness.GJ = kNaN;
    EXPECT_TRUE(ThrowsInputErrorNaming([&] { make_rod_properties(d); }, {"GJ"}));
  }
  {
    RodDescription d = steel_strip();
    d.stiffness.EA = -5.0;
    EXPECT_TRUE(ThrowsInputErrorNaming([&] { make_rod_properties(d); }, {"EA"}));
  }
  const RodProperties good = make_rod_properties(steel_strip());
  EXPECT_NO_THROW(good.validate());
  const char* const rot_names[] = {"K_rot[0]", "K_rot[1]", "K_rot[2]"};
  for (int i = 0; i < 3; ++i) {
    RodProperties p = good;
    p.K_rot(i) = 0.0;
    EXPECT_TRUE(ThrowsInputErrorNaming([&] { p.validate(); }, {rot_names[i]}));
    p.K_rot(i) = kNaN;
    EXPECT_TRUE(ThrowsInputErrorNaming([&] { p.validate(); }, {rot_names[i]}));
  }
  const char* const tra_names[] = {"K_tra[0]", "K_tra[1]", "K_tra[2]"};
  for (int i = 0; i < 3; ++i) {
    RodProperties p = good;
    p.K_tra(i) = 0.0;
    EXPECT_TRUE(ThrowsInputErrorNaming([&] { p.validate(); }, {tra_names[i]}));
    p.K_tra(i) = kNaN;
    EXPECT_TRUE(ThrowsInputErrorNaming([&] { p.validate(); }, {tra_names[i]}));
  }
}

TEST(RodPropertiesInput, SectionWithoutMaterialIsRejectedNamingTheMaterial) {
  RodDescription d = steel_strip();
  d.material.reset();
  EXPECT_TRUE(ThrowsInputErrorNaming([&] { make_rod_properties(d); }, {"material"}));
  RodDescription no_section = steel_strip();
  no_section.section.reset();
  EXPECT_TRUE(ThrowsInputErrorNaming([&] { make_rod_properties(no_section); }, {"section"}));
}

TEST(RodPropertiesInput, BadSectionAndMaterialValuesAreRejectedNamingTheField) {
  {
    RodDescription d = steel_strip();
    d.section = CrossSection::rectangle(0.0, 0.001);
    EXPECT_TRUE(ThrowsInputErrorNaming([&] { make_rod_properties(d); }, {"width"}));
  }
  {
    RodDescription d = steel_strip();
    d.section = CrossSection::circle(kNaN);
    EXPECT_TRUE(ThrowsInputErrorNaming([&] { make_rod_properties(d); }, {"radius"}));
  }
  {
    RodDescription d = steel_strip();
    d.material->poisson_ratio = 0.7;  // outside (-1, 0.5]
    EXPECT_TRUE(ThrowsInputErrorNaming([&] { make_rod_properties(d); }, {"poisson_ratio"}));
  }
  {
    RodDescription d = steel_strip();
    d.material->young_modulus = -1.0;
    EXPECT_TRUE(ThrowsInputErrorNaming([&] { make_rod_properties(d); }, {"young_modulus"}));
  }
}

ClampedRod good_clamped_rod() {
  ClampedRod rod;
  rod.properties = make_rod_properties(steel_strip());
  rod.clamp.rotation = exp_so3(Eigen::Vector3d(0.2, -0.4, 1.0));
  rod.intervals = 10;
  return rod;
}

TEST(ClampedRodInput, NonOrthonormalClampRotationIsRejectedNamingTheRotation) {
  EXPECT_NO_THROW(good_clamped_rod().validate());
  ClampedRod rod = good_clamped_rod();
  rod.clamp.rotation *= 1.001;  // RᵀR = 1.002 I: beyond the 1e-6 the header allows
  EXPECT_TRUE(ThrowsInputErrorNaming([&] { rod.validate(); }, {"rotation"}));
  rod.clamp.rotation = Eigen::Vector3d(1.0, 1.0, -1.0).asDiagonal();  // a reflection
  EXPECT_TRUE(ThrowsInputErrorNaming([&] { rod.validate(); }, {"rotation"}));
  ClampedRod nearly = good_clamped_rod();
  nearly.clamp.rotation(0, 0) += 1e-9;  // within 1e-6: accepted
  EXPECT_NO_THROW(nearly.validate());
}

TEST(ClampedRodInput, FewerThanOneIntervalIsRejectedNamingTheDiscretisation) {
  ClampedRod rod = good_clamped_rod();
  rod.intervals = 1;
  EXPECT_NO_THROW(rod.validate());
  for (int intervals : {0, -3}) {
    rod.intervals = intervals;
    // The field is `intervals` in C++ and the node count N + 1 in task files: either name will do.
    try {
      rod.validate();
      ADD_FAILURE() << "intervals = " << intervals << " accepted";
    } catch (const InputError& error) {
      const std::string message = error.what();
      EXPECT_TRUE(message.find("intervals") != std::string::npos ||
                  message.find("nodes") != std::string::npos)
          << message;
    }
  }
}

TEST(ClampedRodInput, NonFiniteLoadOrRodIsRejected) {
  ClampedRod rod = good_clamped_rod();
  rod.load.force.y() = kNaN;
  EXPECT_THROW(rod.validate(), InputError);
  rod = good_clamped_rod();
  rod.load.moment.z() = std::numeric_limits<double>::infinity();
  EXPECT_THROW(rod.validate(), InputError);
  rod = good_clamped_rod();
  rod.properties.length = -1.0;
  EXPECT_TRUE(ThrowsInputErrorNaming([&] { rod.validate(); }, {"RodProperties.length"}));
  rod = good_clamped_rod();
  rod.clamp.position.x() = kNaN;
  EXPECT_THROW(rod.validate(), InputError);
}

}  // namespace
}  // namespace test_rod_properties
}  // namespace rodshape
