// json_format.cpp: the shared JSON pieces of the result documents (see json_format.hpp).
#include "io/json_format.hpp"

#include "rodshape/core/strain_extremes.hpp"

#include <cmath>
#include <utility>

namespace rodshape::io_detail {

namespace {

Json stability_object(const std::optional<StabilityResult>& stability) {
  if (!stability) return nullptr;
  return {
      {"stable", stability->stable},
      {"conjugate_point_s",
       stability->conjugate_point_s ? json_number(*stability->conjugate_point_s) : Json(nullptr)},
      {"min_singular_value", json_number(stability->min_singular_value)},
      {"tip_singular_value", json_number(stability->tip_singular_value)},
      {"degenerate", stability->degenerate},
      {"tip_stiffness_eigenvalue", stability->tip_stiffness_eigenvalue
                                       ? json_number(*stability->tip_stiffness_eigenvalue)
                                       : Json(nullptr)},
  };
}

/// The largest strains, to judge the shape against the linear law's range (null when not finite).
Json strain_object(const RodProperties& properties, const RodConfiguration& c) {
  const StrainExtremes e = strain_extremes(properties, c);
  return {{"max_axial", json_number(e.max_axial)},
          {"max_shear", json_number(e.max_shear)},
          {"max_curvature", json_number(e.max_curvature)}};
}

Json nodes_object(const RodConfiguration& c) {
  Json s = Json::array();
  for (const double value : c.s) s.push_back(json_number(value));
  Json rotation = Json::array();
  for (const Eigen::Matrix3d& R : c.R) rotation.push_back(json_quaternion(R));
  return {
      {"s", std::move(s)},
      {"position", json_vectors(c.p)},
      {"rotation", std::move(rotation)},
      {"force", json_vectors(c.n)},
      {"moment", json_vectors(c.m)},
      {"u", json_vectors(c.u)},
      {"v", json_vectors(c.v)},
  };
}

bool is_flat(const Json& list) {
  for (const Json& element : list) {
    if (element.is_structured()) return false;
  }
  return true;
}

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

void format_line(const Json& value, std::string& out) {
  if (value.is_object()) {
    out += "{";
    bool first = true;
    for (const auto& [key, element] : value.items()) {
      out += (first ? "" : ", ") + Json(key).dump() + ": ";
      first = false;
      format_line(element, out);
    }
    out += "}";
  } else if (value.is_array()) {
    out += "[";
    bool first = true;
    for (const Json& element : value) {
      out += first ? "" : ", ";
      first = false;
      format_line(element, out);
    }
    out += "]";
  } else {
    out += value.dump();
  }
}

}  // namespace

std::string format_json_line(const Json& value) {
  std::string out;
  format_line(value, out);
  return out + "\n";
}

Json json_number(double value) { return std::isfinite(value) ? Json(value) : Json(nullptr); }

Json json_vector(const Eigen::Vector3d& v) {
  return Json::array({json_number(v.x()), json_number(v.y()), json_number(v.z())});
}

Json json_vectors(const std::vector<Eigen::Vector3d>& values) {
  Json list = Json::array();
  for (const Eigen::Vector3d& v : values) list.push_back(json_vector(v));
  return list;
}

Json json_quaternion(const Eigen::Matrix3d& R) {
  const Eigen::Vector4d q = Pose{Eigen::Vector3d::Zero(), R}.quaternion_wxyz();
  return Json::array({json_number(q[0]), json_number(q[1]), json_number(q[2]), json_number(q[3])});
}

Json json_wrench(const Wrench& w) {
  return {{"force", json_vector(w.force)}, {"moment", json_vector(w.moment)}};
}

Json json_pose(const Pose& pose) {
  return {{"position", json_vector(pose.position)}, {"rotation", json_quaternion(pose.rotation)}};
}

Json configuration_json(const RodConfiguration& configuration,
                        const BaseWrench& base_wrench,
                        const std::optional<StabilityResult>& stability,
                        const RodProperties& properties) {
  const bool has_shape = configuration.nodes() > 0;
  Json result;
  result["model"] = to_string(properties.model);
  result["energy"] = has_shape ? json_number(configuration.energy) : Json(nullptr);
  result["stable"] = stability ? Json(stability->stable) : Json(nullptr);
  result["stability"] = stability_object(stability);
  result["strain"] = has_shape ? strain_object(properties, configuration) : Json(nullptr);
  result["base_wrench"] = json_wrench(base_wrench);
  if (has_shape) {
    result["tip_wrench"] = json_wrench(configuration.tip_wrench());
    result["tip"] = json_pose(configuration.tip());
  } else {
    result["tip_wrench"] = nullptr;
    result["tip"] = nullptr;
  }
  result["nodes"] = nodes_object(configuration);
  return result;
}

std::string format_json(const Json& value) {
  std::string out;
  format(value, 0, out);
  out += "\n";
  return out;
}

}  // namespace rodshape::io_detail
