// result_json.cpp: the equilibrium result document (schema in docs/task-file.md). Objects are
// indented; lists of numbers stay on one line, so each node's position is one line of the file.
#include "rodshape/io/result_json.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "rodshape/core/rod_properties.hpp"
#include "rodshape/solvers/solve_status.hpp"

namespace rodshape {

namespace {

using Json = nlohmann::ordered_json;

/// A number, or null when it is not finite (JSON has no NaN or infinity).
Json number(double value) { return std::isfinite(value) ? Json(value) : Json(nullptr); }

Json vector(const Eigen::Vector3d& v) {
  return Json::array({number(v.x()), number(v.y()), number(v.z())});
}

Json quaternion(const Eigen::Matrix3d& R) {
  // [w, x, y, z] with w >= 0 (Pose::quaternion_wxyz).
  const Eigen::Vector4d q = Pose{Eigen::Vector3d::Zero(), R}.quaternion_wxyz();
  return Json::array({number(q[0]), number(q[1]), number(q[2]), number(q[3])});
}

Json wrench(const Wrench& w) { return {{"force", vector(w.force)}, {"moment", vector(w.moment)}}; }

Json vectors(const std::vector<Eigen::Vector3d>& values) {
  Json list = Json::array();
  for (const Eigen::Vector3d& v : values) list.push_back(vector(v));
  return list;
}

Json stability_object(const std::optional<StabilityReport>& stability) {
  if (!stability) return nullptr;
  return {
      {"stable", stability->stable},
      {"conjugate_point_s",
       stability->conjugate_point_s ? number(*stability->conjugate_point_s) : Json(nullptr)},
      {"min_singular_value", number(stability->min_singular_value)},
      {"tip_singular_value", number(stability->tip_singular_value)},
      {"degenerate", stability->degenerate},
  };
}

Json nodes_object(const RodConfiguration& c) {
  Json s = Json::array();
  for (const double value : c.s) s.push_back(number(value));
  Json rotation = Json::array();
  for (const Eigen::Matrix3d& R : c.R) rotation.push_back(quaternion(R));
  return {
      {"s", std::move(s)},     {"position", vectors(c.p)}, {"rotation", std::move(rotation)},
      {"force", vectors(c.n)}, {"moment", vectors(c.m)},   {"u", vectors(c.u)},
      {"v", vectors(c.v)},
  };
}

bool is_flat(const Json& list) {
  for (const Json& element : list) {
    if (element.is_structured()) return false;
  }
  return true;
}

/// Pretty-prints with two-space indentation, except that a list of scalars stays on one line.
void format(const Json& value, int indent, std::string& out) {
  const std::string inner(static_cast<std::size_t>(indent + 2), ' ');
  const std::string outer(static_cast<std::size_t>(indent), ' ');
  if (value.is_object() && !value.empty()) {
    out += "{\n";
    bool first = true;
    for (const auto& [key, element] : value.items()) {
      if (!first) out += ",\n";
      first = false;
      out += inner + Json(key).dump() + ": ";
      format(element, indent + 2, out);
    }
    out += "\n" + outer + "}";
  } else if (value.is_array() && !value.empty() && !is_flat(value)) {
    out += "[\n";
    bool first = true;
    for (const Json& element : value) {
      if (!first) out += ",\n";
      first = false;
      out += inner;
      format(element, indent + 2, out);
    }
    out += "\n" + outer + "]";
  } else if (value.is_array()) {
    out += "[";
    bool first = true;
    for (const Json& element : value) {
      if (!first) out += ", ";
      first = false;
      out += element.dump();
    }
    out += "]";
  } else {
    out += value.dump();
  }
}

}  // namespace

std::string equilibrium_result_json(const ShootingSolution& solution,
                                    const std::optional<StabilityReport>& stability,
                                    const ClampedRod& rod) {
  const ShootingSummary& summary = solution.summary;
  const RodConfiguration& configuration = solution.configuration;
  const bool has_shape = configuration.nodes() > 0;

  Json result;
  result["status"] = to_string(summary.status);
  result["message"] = summary.message;
  result["residual"] = number(summary.residual_norm);
  result["iterations"] = summary.iterations;
  result["chord_steps"] = summary.chord_steps;
  result["integrations"] = summary.integrations;
  result["jacobian_evaluations"] = summary.jacobian_evaluations;
  result["continuation_steps"] = summary.continuation_steps;
  result["model"] = to_string(rod.properties.model);
  result["energy"] = has_shape ? number(configuration.energy) : Json(nullptr);
  result["stable"] = stability ? Json(stability->stable) : Json(nullptr);
  result["stability"] = stability_object(stability);
  result["base_wrench"] = wrench(solution.base_wrench);
  if (has_shape) {
    const Pose tip = configuration.tip();
    result["tip_wrench"] = wrench(configuration.tip_wrench());
    result["tip"] = {{"position", vector(tip.position)}, {"rotation", quaternion(tip.rotation)}};
  } else {
    result["tip_wrench"] = nullptr;
    result["tip"] = nullptr;
  }
  result["nodes"] = nodes_object(configuration);

  std::string out;
  format(result, 0, out);
  out += "\n";
  return out;
}

}  // namespace rodshape
