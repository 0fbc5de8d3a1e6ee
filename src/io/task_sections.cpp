// task_sections.cpp: the readers of the task file's sections. Numbers are checked for being numbers
// and finite here; their ranges are checked by the library's validate() functions where those exist
// (CrossSection, Material, RodProperties, ClampedRod, ShootingOptions), located in the file.
#include "io/task_sections.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "rodshape/core/physical_bounds.hpp"
#include "rodshape/core/so3.hpp"
#include "validation.hpp"

namespace rodshape::io_detail {

namespace {

constexpr double kRotationTolerance = kRotationInputTolerance;

/// Keys that users put directly under `rod` but that belong elsewhere.
const std::vector<KeyHint>& rod_key_hints() {
  static const std::vector<KeyHint> hints = {
      {"gravity", "gravity is a top-level section, not part of rod"},
      {"distributed_load", "distributed_load is a top-level section, not part of rod"},
      {"base", "base is a top-level section, not part of rod"},
      {"tip", "tip is a top-level section, not part of rod"},
      {"density", "density belongs in rod.material"},
      {"young_modulus", "young_modulus belongs in rod.material"},
      {"poisson_ratio", "poisson_ratio belongs in rod.material"},
      {"EA", "EA belongs in rod.stiffness"},
      {"GA", "GA belongs in rod.stiffness"},
      {"EIx", "EIx belongs in rod.stiffness"},
      {"EIy", "EIy belongs in rod.stiffness"},
      {"GJ", "GJ belongs in rod.stiffness"},
      {"shape", "shape belongs in rod.section"},
      {"width", "width belongs in rod.section"},
      {"height", "height belongs in rod.section"},
      {"radius", "radius belongs in rod.section"},
  };
  return hints;
}

CrossSection read_cross_section(const YamlField& section) {
  section.expect_mapping({"shape", "width", "height", "radius"});
  const std::string shape = section.require("shape").choice({"rectangle", "circle"});
  CrossSection result;
  if (shape == "rectangle") {
    if (section.has("radius")) section.get("radius").fail_value("does not apply to a rectangle");
    result = CrossSection::rectangle(section.require("width").number(),
                                     section.require("height").number());
  } else {
    for (const char* key : {"width", "height"}) {
      if (section.has(key)) section.get(key).fail_value("does not apply to a circle");
    }
    result = CrossSection::circle(section.require("radius").number());
  }
  section.located([&] { result.validate(section.path()); });
  return result;
}

/// Reads rod.material into `rod`: the elastic constants only when both are given (a rod given by
/// its stiffness needs neither), the density on its own (a weight needs only it and the section).
void read_material(const YamlField& material, RodSection& rod) {
  material.expect_mapping({"young_modulus", "poisson_ratio", "density"});
  const YamlField young_modulus = material.get("young_modulus");
  const YamlField poisson_ratio = material.get("poisson_ratio");
  const YamlField density = material.get("density");
  if (density.present()) rod.density = density.number();
  if (young_modulus.present() != poisson_ratio.present()) {
    const YamlField& given = young_modulus.present() ? young_modulus : poisson_ratio;
    const YamlField& missing = young_modulus.present() ? poisson_ratio : young_modulus;
    given.fail(missing.path() + " is required with " + given.path());
  }
  if (young_modulus.present()) {
    Material elastic;
    elastic.young_modulus = young_modulus.number();
    elastic.poisson_ratio = poisson_ratio.number();
    elastic.density = rod.density.value_or(0.0);
    material.located([&] { elastic.validate(material.path()); });
    rod.description.material = elastic;
  } else if (rod.density && !(*rod.density >= 0.0)) {
    density.fail_value("must be >= 0");
  }
}

StiffnessOverrides read_stiffness(const YamlField& stiffness) {
  stiffness.expect_mapping({"EA", "GA", "EIx", "EIy", "GJ"});
  StiffnessOverrides overrides;
  const auto read = [&](std::string_view key, std::optional<double>& value) {
    if (const YamlField field = stiffness.get(key); field.present())
      value = field.positive_number();
  };
  read("EA", overrides.EA);
  read("GA", overrides.GA);
  read("EIx", overrides.EIx);
  read("EIy", overrides.EIy);
  read("GJ", overrides.GJ);
  return overrides;
}

}  // namespace

// ---- rod ----------------------------------------------------------------------------------------

RodSection read_rod_section(const YamlField& rod) {
  rod.expect_mapping(
      {"length", "nodes", "model", "section", "material", "stiffness", "rest_curvature"},
      rod_key_hints());
  RodSection result;
  RodDescription& description = result.description;
  description.length = rod.require("length").number();
  if (const YamlField nodes = rod.get("nodes"); nodes.present()) {
    result.nodes = nodes.integer();
    if (result.nodes < 2) nodes.fail_value("must be >= 2 (both ends are nodes)");
    if (result.nodes > kMaxNodes) nodes.fail_value("must be <= " + std::to_string(kMaxNodes));
  }
  if (const YamlField model = rod.get("model"); model.present()) {
    const std::string name = model.choice(names_of(kConstitutiveModelNames));
    description.model =
        model.located([&] { return constitutive_model_from_string(name, model.path()); });
  }
  if (const YamlField section = rod.get("section"); section.present()) {
    description.section = read_cross_section(section);
  }
  if (const YamlField material = rod.get("material"); material.present()) {
    read_material(material, result);
  }
  if (const YamlField stiffness = rod.get("stiffness"); stiffness.present()) {
    description.stiffness = read_stiffness(stiffness);
  }
  if (const YamlField curvature = rod.get("rest_curvature"); curvature.present()) {
    description.rest_curvature = curvature.vector3();
  }
  return result;
}

RodProperties build_rod_properties(const RodSection& rod, const YamlField& rod_field) {
  RodProperties properties =
      rod_field.located([&] { return make_rod_properties(rod.description); });
  if (rod.density && rod.description.section) {
    properties.mass_per_length = *rod.density * rod.description.section->area();
  }
  return properties;
}

// ---- loads --------------------------------------------------------------------------------------

DistributedLoad read_distributed_load(const YamlField& root, const RodSection& rod) {
  DistributedLoad load;
  if (const YamlField gravity = root.get("gravity"); gravity.present()) {
    const Eigen::Vector3d g = gravity.vector3();
    gravity.located([&] { require_magnitude_at_most("gravity", g, bounds::kMaxGravity, "m/s^2"); });
    if (!g.isZero(0.0)) {
      // Weight: f = ρ A g.
      const std::string needs = gravity.path() + " is not zero, so the weight rho*A*g needs ";
      if (!rod.density) gravity.fail(needs + "rod.material.density, which is missing");
      if (!rod.description.section) gravity.fail(needs + "rod.section, which is missing");
      load.force += *rod.density * rod.description.section->area() * g;
    }
  }
  if (const YamlField distributed = root.get("distributed_load"); distributed.present()) {
    distributed.expect_mapping({"force", "moment"});
    if (const YamlField force = distributed.get("force"); force.present()) {
      load.force += force.vector3();
    }
    if (const YamlField moment = distributed.get("moment"); moment.present()) {
      load.moment += moment.vector3();
    }
  }
  return load;
}

// ---- poses and wrenches -------------------------------------------------------------------------

Eigen::Matrix3d read_rotation(const YamlField& rotation) {
  const std::string expected = rotation.path() +
                               ": expected a quaternion [w, x, y, z] or a 3x3 matrix given as "
                               "3 rows [[..], [..], [..]]";
  if (!rotation.is_sequence()) rotation.fail(expected);
  const std::vector<YamlField> elements = rotation.elements();
  if (elements.size() == 4) {
    const Eigen::Vector4d wxyz(elements[0].number(), elements[1].number(), elements[2].number(),
                               elements[3].number());
    return rotation.located([&] { return rotation_from_wxyz(wxyz, rotation.path()); });
  }
  if (elements.size() != 3) rotation.fail(expected);
  Eigen::Matrix3d R;
  for (int row = 0; row < 3; ++row) {
    const YamlField& row_field = elements[static_cast<std::size_t>(row)];
    if (!row_field.is_sequence()) rotation.fail(expected);
    R.row(row) = row_field.vector3().transpose();
  }
  if (!is_rotation(R, kRotationTolerance)) {
    const double determinant = R.determinant();
    if (determinant < 0.0) {
      rotation.fail(rotation.path() + ": the matrix has determinant " +
                    detail::format_value(determinant) + "; a rotation has determinant +1");
    }
    const double orthogonality =
        (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
    rotation.fail(rotation.path() + ": the matrix is not a rotation: max |R^T R - I| = " +
                  detail::format_value(orthogonality) +
                  ", det = " + detail::format_value(determinant) + " (tolerance 1e-6)");
  }
  // Within 1e-6 of SO(3): project so that the pose is orthonormal to round-off, unless it already
  // is (an exact matrix such as [[0, 0, 1], [0, 1, 0], [-1, 0, 0]] stays exact).
  if (is_rotation(R, 1e-15)) return R;
  return Eigen::Quaterniond(R).normalized().toRotationMatrix();
}

/// `value` (read from `field`) when |value| ≤ `max`; else fails naming the field, "has magnitude
/// 1e+300 m; at most 10000 m (docs/limits.md)" (as require_magnitude_at_most()).
Eigen::Vector3d at_most(const YamlField& field,
                        const Eigen::Vector3d& value,
                        double max,
                        const char* unit) {
  if (value.stableNorm() > max)  // stableNorm: |[1e300, 0, 0]| is 1e300, not inf
    field.fail_value("has magnitude " + detail::format_value(value.stableNorm()) + " " + unit +
                     "; at most " + detail::format_value(max) + " " + unit + " (docs/limits.md)");
  return value;
}

Pose read_pose_fields(const YamlField& pose) {
  Pose result;
  const YamlField position = pose.require("position");
  result.position = at_most(position, position.vector3(), bounds::kMaxPosition, "m");
  if (const YamlField rotation = pose.get("rotation"); rotation.present()) {
    result.rotation = read_rotation(rotation);
  }
  return result;
}

Pose read_pose(const YamlField& pose) {
  pose.expect_mapping({"position", "rotation"});
  return read_pose_fields(pose);
}

Wrench read_wrench(const YamlField& wrench) {
  wrench.expect_mapping({"force", "moment"});
  Wrench result;
  if (const YamlField force = wrench.get("force"); force.present()) result.force = force.vector3();
  if (const YamlField moment = wrench.get("moment"); moment.present()) {
    result.moment = moment.vector3();
  }
  return result;
}

// ---- tip ----------------------------------------------------------------------------------------

std::array<bool, 6> read_wrench_axes(const YamlField& axes) {
  // Order of GraspedTip::released and Grasp::released: force x, y, z, then moment x, y, z.
  static const std::vector<std::string_view> kAxes = {"fx", "fy", "fz", "mx", "my", "mz"};
  std::array<bool, 6> result{};
  for (const YamlField& element : axes.elements()) {
    const std::string name = element.choice(kAxes);
    std::size_t axis = 0;
    while (kAxes[axis] != name) ++axis;
    if (result[axis]) element.fail_value("is listed twice");
    result[axis] = true;
  }
  return result;
}

TipCondition read_tip_condition(const YamlField& tip) {
  tip.expect_mapping({"position", "rotation", "released", "wrench"});
  const bool held = tip.has("position") || tip.has("rotation") || tip.has("released");
  if (tip.has("wrench")) {
    if (held) {
      tip.fail(tip.path() +
               ": give either a pose (position, rotation, released) for a held tip or a wrench "
               "for a free tip, not both");
    }
    return FreeTip{read_wrench(tip.get("wrench"))};
  }
  if (!held) {
    tip.fail(tip.path() +
             ": expected position (and rotation) for a clamped tip, position and released for a "
             "grasped tip, or wrench for a free tip");
  }
  const Pose pose = read_pose_fields(tip);
  if (const YamlField released = tip.get("released"); released.present()) {
    const std::array<bool, 6> axes = read_wrench_axes(released);
    if (std::all_of(axes.begin(), axes.end(), [](bool axis) { return axis; }))
      released.fail(released.path() +
                    " releases all six axes: the grasp would hold nothing; a tip held by nothing "
                    "is a free tip (tip: {wrench: {}})");
    return GraspedTip{pose, axes};
  }
  return ClampedTip{pose};
}

// ---- solver -------------------------------------------------------------------------------------

/// solver.tolerance (m, rad, N, N·m) and integration_tolerance (relative) at most: beyond, a
/// tip a metre or a radian off would be "converged" (.inf, which turns the library's accuracy
/// check off, is out of range in a task file).
constexpr double kMaxTolerance = 1.0;

void read_solver_section(const YamlField& solver,
                         ShootingOptions& options,
                         BaseWrench& initial_wrench) {
  solver.expect_mapping({"max_iterations", "tolerance", "continuation", "max_continuation_steps",
                         "initial_wrench", "integration_tolerance", "max_substeps",
                         "max_axial_strain", "max_shear_strain"});
  if (const YamlField field = solver.get("max_iterations"); field.present()) {
    options.max_iterations = field.integer_in(1, ShootingOptions::kMaxIterations);
  }
  if (const YamlField field = solver.get("tolerance"); field.present()) {
    options.residual_tolerance = field.positive_number_at_most(kMaxTolerance);
  }
  if (const YamlField field = solver.get("continuation"); field.present()) {
    options.continuation = field.boolean();
  }
  if (const YamlField field = solver.get("max_continuation_steps"); field.present()) {
    options.max_continuation_steps = field.integer_in(1, ShootingOptions::kMaxContinuationSteps);
  }
  if (const YamlField field = solver.get("initial_wrench"); field.present()) {
    initial_wrench = read_wrench(field);  // the guess: as a wrench, at most kMaxForce
    at_most(field.get("force"), initial_wrench.force, bounds::kMaxForce, "N");
    at_most(field.get("moment"), initial_wrench.moment, bounds::kMaxForce, "N*m");
  }
  if (const YamlField field = solver.get("integration_tolerance"); field.present()) {
    options.integration_tolerance = field.positive_number_at_most(kMaxTolerance);
  }
  if (const YamlField field = solver.get("max_substeps"); field.present()) {
    options.max_substeps = field.integer();
    if (options.max_substeps < 1 || options.max_substeps > ClampedRod::kMaxSubsteps)
      field.fail_value("must be in [1, " + std::to_string(ClampedRod::kMaxSubsteps) + "]");
  }
  if (const YamlField field = solver.get("max_axial_strain"); field.present()) {
    options.strain_limits.max_axial_strain = field.positive_number();
  }
  if (const YamlField field = solver.get("max_shear_strain"); field.present()) {
    options.strain_limits.max_shear_strain = field.positive_number();
  }
}

}  // namespace rodshape::io_detail
