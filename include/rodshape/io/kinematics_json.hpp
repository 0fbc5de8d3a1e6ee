// kinematics_json.hpp: the answers of `rodshape fk` and `rodshape ik` as one line of JSON (schemas
// in docs/robot.md). Non-finite numbers are written as null.
#pragma once

#include <string>

#include "rodshape/core/pose.hpp"
#include "rodshape/robot/inverse_kinematics.hpp"

namespace rodshape {

/// {"position": [x, y, z], "rotation": [w, x, y, z]} (unit quaternion, w ≥ 0) and a newline.
std::string pose_json(const Pose& pose);

/// {"q": [...], "status": ..., "message": ..., "iterations": ..., "restarts": ...,
///  "position_error": ..., "rotation_error": ...} and a newline.
std::string ik_result_json(const IkResult& result);

}  // namespace rodshape
