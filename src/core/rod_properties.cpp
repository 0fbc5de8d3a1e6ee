#include "rodshape/core/rod_properties.hpp"

#include <limits>

#include "validation.hpp"

namespace rodshape {

std::string to_string(ConstitutiveModel model) {
  return model == ConstitutiveModel::Cosserat ? "cosserat" : "kirchhoff";
}

ConstitutiveModel constitutive_model_from_string(const std::string& name,
                                                 const std::string& field) {
  if (name == "cosserat") return ConstitutiveModel::Cosserat;
  if (name == "kirchhoff") return ConstitutiveModel::Kirchhoff;
  throw InputError(field, " = '" + name + "' must be 'cosserat' or 'kirchhoff'");
}

void RodProperties::validate() const {
  detail::require_positive("RodProperties.length", length);
  static const char* const tra_names[] = {"RodProperties.K_tra[0]", "RodProperties.K_tra[1]",
                                          "RodProperties.K_tra[2]"};
  static const char* const rot_names[] = {"RodProperties.K_rot[0]", "RodProperties.K_rot[1]",
                                          "RodProperties.K_rot[2]"};
  for (int i = 0; i < 3; ++i) {
    // The Kirchhoff model never uses K_tra (v = ṽ): it may be +inf there ("not given").
    if (model == ConstitutiveModel::Kirchhoff &&
        K_tra(i) == std::numeric_limits<double>::infinity())
      continue;
    detail::require_positive(tra_names[i], K_tra(i));
    detail::require_positive(rot_names[i], K_rot(i));
  }
  detail::require_finite("RodProperties.v_rest", v_rest);
  if (!(v_rest.z() > 0.0))
    throw InputError("RodProperties.v_rest[2]",
                     " = " + detail::format_value(v_rest.z()) + " must be > 0");
  detail::require_finite("RodProperties.u_rest", u_rest);
  detail::require_non_negative("RodProperties.mass_per_length", mass_per_length);
}

namespace {

/// The override if given, else the section-and-material value, else an error naming what is
/// missing.
double stiffness_or(const std::optional<double>& override_value,
                    const RodDescription& d,
                    const char* name,
                    double (*from_section)(const CrossSection&, const Material&)) {
  const std::string field = std::string("RodDescription.stiffness.") + name;
  if (override_value) {
    detail::require_positive(field, *override_value);
    return *override_value;
  }
  if (!d.section)
    throw InputError(field, " is not given and RodDescription.section is missing to compute it");
  if (!d.material)
    throw InputError(field, " is not given and RodDescription.material is missing to compute it");
  return from_section(*d.section, *d.material);
}

}  // namespace

RodProperties make_rod_properties(const RodDescription& d) {
  detail::require_positive("RodDescription.length", d.length);
  if (d.section) d.section->validate("RodDescription.section");
  if (d.material) d.material->validate("RodDescription.material");

  RodProperties p;
  p.length = d.length;
  p.model = d.model;
  p.u_rest = d.rest_curvature;

  using S = const CrossSection&;
  using M = const Material&;
  // An inextensible, unshearable rod needs no K_tra: +inf when it cannot be computed.
  const bool needs_K_tra = d.model == ConstitutiveModel::Cosserat || (d.section && d.material);
  const double inf = std::numeric_limits<double>::infinity();
  const double GA =
      !needs_K_tra && !d.stiffness.GA ? inf : stiffness_or(d.stiffness.GA, d, "GA", [](S s, M m) {
        return m.shear_modulus() * s.area();
      });
  const double EA =
      !needs_K_tra && !d.stiffness.EA ? inf : stiffness_or(d.stiffness.EA, d, "EA", [](S s, M m) {
        return m.young_modulus * s.area();
      });
  const double EIx = stiffness_or(d.stiffness.EIx, d, "EIx",
                                  [](S s, M m) { return m.young_modulus * s.second_moment_x(); });
  const double EIy = stiffness_or(d.stiffness.EIy, d, "EIy",
                                  [](S s, M m) { return m.young_modulus * s.second_moment_y(); });
  const double GJ = stiffness_or(d.stiffness.GJ, d, "GJ",
                                 [](S s, M m) { return m.shear_modulus() * s.torsion_constant(); });
  p.K_tra = {GA, GA, EA};
  p.K_rot = {EIx, EIy, GJ};
  if (d.section && d.material) p.mass_per_length = d.material->density * d.section->area();
  p.validate();
  return p;
}

}  // namespace rodshape
