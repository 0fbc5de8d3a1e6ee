// kinematics_json.cpp: fk and ik answers as JSON (see kinematics_json.hpp).
#include "rodshape/io/kinematics_json.hpp"

#include "io/json_format.hpp"

namespace rodshape {

using io_detail::Json;

std::string pose_json(const Pose& pose) {
  return io_detail::format_json_line(io_detail::json_pose(pose));
}

std::string ik_result_json(const IkResult& result) {
  Json q = Json::array();
  for (Eigen::Index i = 0; i < result.q.size(); ++i)
    q.push_back(io_detail::json_number(result.q(i)));
  Json json;
  json["q"] = std::move(q);
  json["status"] = to_string(result.status);
  json["message"] = result.message;
  json["iterations"] = result.iterations;
  json["restarts"] = result.restarts;
  json["position_error"] = io_detail::json_number(result.position_error);
  json["rotation_error"] = io_detail::json_number(result.rotation_error);
  return io_detail::format_json_line(json);
}

}  // namespace rodshape
