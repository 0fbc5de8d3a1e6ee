#include "rodshape/core/rod_properties.hpp"

#include <algorithm>
#include <functional>
#include <limits>

#include "rodshape/core/physical_bounds.hpp"
#include "validation.hpp"

namespace rodshape {

std::string to_string(ConstitutiveModel model) {
  return std::string(name_of(kConstitutiveModelNames, model));
}

ConstitutiveModel constitutive_model_from_string(const std::string& name,
                                                 const std::string& field) {
  if (const auto model = value_of(kConstitutiveModelNames, name)) return *model;
  throw InputError(field, " = '" + name + "' must be 'cosserat' or 'kirchhoff'");
}

namespace {

/// Where a stiff K_tra came from, for messages: the field and " = <value> ...".
struct StiffSource {
  std::string field;
  std::string value;
};

/// A Cosserat rod's EA·L²/EI and GA·L²/EI within bounds::kMaxStretchToBendRatio (issue 24, item 8;
/// docs/task-file.md, rod.model): beyond, it is a Kirchhoff rod to double precision. `source`
/// names the field the stiffer of EA (axial) and GA came from.
void require_cosserat_resolvable(const RodProperties& p,
                                 const std::function<StiffSource(bool axial, double K)>& source) {
  if (p.model != ConstitutiveModel::Cosserat) return;
  const double EI = std::min(p.K_rot.x(), p.K_rot.y());
  const bool axial = p.K_tra.z() >= p.K_tra.x();
  const double K = axial ? p.K_tra.z() : p.K_tra.x();
  const double ratio = K * p.length * p.length / EI;
  if (ratio <= bounds::kMaxStretchToBendRatio) return;
  using detail::format_value;
  const StiffSource stiff = source(axial, K);
  throw InputError(stiff.field, stiff.value + ", with EI = " + format_value(EI) +
                                    " N*m^2 and L = " + format_value(p.length) + " m, gives " +
                                    (axial ? "EA" : "GA") + "*L^2/EI = " + format_value(ratio) +
                                    ", beyond " + format_value(bounds::kMaxStretchToBendRatio) +
                                    ": a Cosserat rod that stiff in extension is a Kirchhoff rod "
                                    "to double precision; use RodProperties.model = kirchhoff");
}

/// EA or GA given (RodDescription.stiffness), else Young's modulus times the section's area.
StiffSource description_source(const RodDescription& d, bool axial, double K) {
  const std::string K_text = detail::format_value(K) + " N";
  if (axial ? d.stiffness.EA.has_value() : d.stiffness.GA.has_value())
    return {std::string("RodDescription.stiffness.") + (axial ? "EA" : "GA"), " = " + K_text};
  return {"RodDescription.material.young_modulus",
          " = " + detail::format_value(d.material ? d.material->young_modulus : 0.0) +
              " Pa makes " + (axial ? "EA = E A = " : "GA = G A = ") + K_text};
}

}  // namespace

void RodProperties::validate() const {
  detail::require_positive("RodProperties.length", length);
  require_in_range("RodProperties.length", length, bounds::kLength);
  static const char* const tra_names[] = {"RodProperties.K_tra[0]", "RodProperties.K_tra[1]",
                                          "RodProperties.K_tra[2]"};
  static const char* const rot_names[] = {"RodProperties.K_rot[0]", "RodProperties.K_rot[1]",
                                          "RodProperties.K_rot[2]"};
  for (int i = 0; i < 3; ++i) {
    detail::require_positive(rot_names[i], K_rot(i));
    require_in_range(rot_names[i], K_rot(i), bounds::kStiffness);
    // The Kirchhoff model never uses K_tra (v = ṽ): it may be +inf there ("not given").
    if (model == ConstitutiveModel::Kirchhoff &&
        K_tra(i) == std::numeric_limits<double>::infinity())
      continue;
    detail::require_positive(tra_names[i], K_tra(i));
    require_in_range(tra_names[i], K_tra(i), bounds::kStiffness);
  }
  detail::require_finite("RodProperties.v_rest", v_rest);
  if (!(v_rest.z() > 0.0))
    throw InputError("RodProperties.v_rest[2]",
                     " = " + detail::format_value(v_rest.z()) + " must be > 0");
  detail::require_finite("RodProperties.u_rest", u_rest);
  require_magnitude_at_most("RodProperties.u_rest", u_rest, bounds::kMaxRestTurn / length, "1/m");
  detail::require_non_negative("RodProperties.mass_per_length", mass_per_length);
  require_in_range("RodProperties.mass_per_length", mass_per_length, bounds::kMassPerLength);
  if (section) section->validate("RodProperties.section");
  require_cosserat_resolvable(*this, [](bool axial, double K) {
    return StiffSource{axial ? "RodProperties.K_tra[2]" : "RodProperties.K_tra[0]",
                       " = " + detail::format_value(K) + " N"};
  });
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
    require_in_range(field, *override_value, bounds::kStiffness);
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
  require_in_range("RodDescription.length", d.length, bounds::kLength);
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
  p.section = d.section;
  require_cosserat_resolvable(  // named as the user gave it
      p, [&d](bool axial, double K) { return description_source(d, axial, K); });
  p.validate();
  return p;
}

}  // namespace rodshape
