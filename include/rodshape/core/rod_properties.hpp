// rod_properties.hpp: the constants of the constitutive law (paper, "Constitutive Equations"):
//   n = R K_tra (v - ṽ),  m = R K_rot (u - ũ),
//   K_tra = diag(GA, GA, EA),  K_rot = diag(E Ix, E Iy, G J).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "rodshape/core/cross_section.hpp"
#include "rodshape/core/material.hpp"
#include "rodshape/enum_names.hpp"

namespace rodshape {

/// `cosserat`: shear and extension (the paper's model). `kirchhoff`: inextensible, unshearable (v =
/// ṽ).
enum class ConstitutiveModel { Cosserat, Kirchhoff };
/// The names of ConstitutiveModel (to_string, and the task file's rod.model).
inline constexpr EnumNames<ConstitutiveModel, 2> kConstitutiveModelNames = {{
    {ConstitutiveModel::Cosserat, "cosserat"},
    {ConstitutiveModel::Kirchhoff, "kirchhoff"},
}};
std::string to_string(ConstitutiveModel model);
/// Throws InputError naming `field` for anything but "cosserat" or "kirchhoff".
ConstitutiveModel constitutive_model_from_string(const std::string& name,
                                                 const std::string& field = "RodDescription.model");

/// The constants the integrator uses. Build it with make_rod_properties() from a RodDescription,
/// or fill it directly and call validate().
struct RodProperties {
  double length = 0.0;  // L, m
  ConstitutiveModel model = ConstitutiveModel::Cosserat;
  Eigen::Vector3d K_tra = Eigen::Vector3d::Ones();    // diag(GA, GA, EA), N
  Eigen::Vector3d K_rot = Eigen::Vector3d::Ones();    // diag(EIx, EIy, GJ), N·m²
  Eigen::Vector3d v_rest = Eigen::Vector3d::UnitZ();  // ṽ: straight, unstretched
  Eigen::Vector3d u_rest = Eigen::Vector3d::Zero();   // ũ: constant precurvature, 1/m
  double mass_per_length = 0.0;                       // ρA, kg/m (0 when unknown)
  /// The section the stiffnesses came from, when known: the rod's surface about its centreline
  /// (a depth camera sees it: feedback/cloud_estimator.hpp).
  std::optional<CrossSection> section;

  /// Throws InputError naming the field ("rod.length", "rod.stiffness.EIx", ...).
  void validate() const;

  /// The bending units of a base wrench, (EI/L² ×3, EI/L ×3) with EI the mean of EIx and EIy: the
  /// forces and moments that bend the rod by about 1 rad. The solvers measure the unknown in them.
  Eigen::Matrix<double, 6, 1> bending_wrench_units() const {
    const double EI = 0.5 * (K_rot.x() + K_rot.y());
    Eigen::Matrix<double, 6, 1> units;
    units << Eigen::Vector3d::Constant(EI / (length * length)),
        Eigen::Vector3d::Constant(EI / length);
    return units;
  }
};

/// Stiffness given directly; each one given replaces the value the section and material imply.
struct StiffnessOverrides {
  std::optional<double> EA, GA, EIx, EIy, GJ;
};

/// How a user describes a rod: geometry and material, or stiffness directly, or both.
struct RodDescription {
  double length = 0.0;
  ConstitutiveModel model = ConstitutiveModel::Cosserat;
  std::optional<CrossSection> section;
  std::optional<Material> material;
  StiffnessOverrides stiffness;
  Eigen::Vector3d rest_curvature = Eigen::Vector3d::Zero();  // ũ
};

/// A = section area, I = second moments, G = E/(2(1+ν)); overrides win. Throws InputError naming
/// the missing field when a stiffness the model needs has neither an override nor a section and
/// material. mass_per_length = ρA when both density and section are known, else 0.
RodProperties make_rod_properties(const RodDescription& description);

}  // namespace rodshape
