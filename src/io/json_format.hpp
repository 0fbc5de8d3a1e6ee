// json_format.hpp (private to the io area): the JSON pieces the result documents share, so that
// `equilibrium` and `plan` write a rod configuration the same way. nlohmann::json stays private.
#pragma once

#include <nlohmann/json.hpp>

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "rodshape/core/pose.hpp"
#include "rodshape/core/rod_configuration.hpp"
#include "rodshape/core/rod_properties.hpp"
#include "rodshape/core/wrench.hpp"
#include "rodshape/solvers/stability.hpp"

namespace rodshape::io_detail {

/// Keys keep the order in which they are set.
using Json = nlohmann::ordered_json;

/// A number, or null when it is not finite (JSON has no NaN or infinity).
Json json_number(double value);
/// [x, y, z].
Json json_vector(const Eigen::Vector3d& v);
/// A list of [x, y, z].
Json json_vectors(const std::vector<Eigen::Vector3d>& values);
/// [w, x, y, z] with w ≥ 0 (Pose::quaternion_wxyz).
Json json_quaternion(const Eigen::Matrix3d& R);
/// {force, moment}.
Json json_wrench(const Wrench& w);
/// {position, rotation}.
Json json_pose(const Pose& pose);

/// A rod configuration as both result documents write it (docs/task-file.md): model, energy,
/// stable, stability, base_wrench, tip_wrench, tip, nodes. `stability` absent: "stable" and
/// "stability" are null. A configuration without nodes (a solve that never integrated) has null
/// energy, tip and tip_wrench.
Json configuration_json(const RodConfiguration& configuration,
                        const BaseWrench& base_wrench,
                        const std::optional<StabilityResult>& stability,
                        ConstitutiveModel model);

/// Pretty-printed with two-space indentation, except that a list of scalars stays on one line (so
/// each node's position is one line of the file), ending with a newline.
std::string format_json(const Json& value);

}  // namespace rodshape::io_detail
