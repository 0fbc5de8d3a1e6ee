// panda_dh.hpp: the Franka Panda written out by hand from Franka's modified Denavit–Hartenberg
// table (https://frankaemika.github.io/docs/control_parameters.html), the oracle the robot tests
// hold data/robots/panda.urdf against, and the Panda's ready pose.
#pragma once

#include <Eigen/Geometry>
#include <numbers>
#include <string>
#include <vector>

#include "rodshape/samples/panda.hpp"

namespace rodshape::testing {

inline const std::string kPandaUrdf = std::string(RODSHAPE_SOURCE_DIR) + "/data/robots/panda.urdf";

/// One row: a_{i-1}, d_i, α_{i-1}.
struct DhRow {
  double a, d, alpha;
};

/// Joints 1 … 7, then the flange (θ = 0).
inline const std::vector<DhRow>& panda_dh_table() {
  constexpr double pi = std::numbers::pi;
  static const std::vector<DhRow> table = {
      {0.0, 0.333, 0.0},         {0.0, 0.0, -pi / 2}, {0.0, 0.316, pi / 2}, {0.0825, 0.0, pi / 2},
      {-0.0825, 0.384, -pi / 2}, {0.0, 0.0, pi / 2},  {0.088, 0.0, pi / 2}, {0.0, 0.107, 0.0},
  };
  return table;
}

/// The frames of the table's rows at q, each T_i = RotX(α_{i-1}) TransX(a_{i-1}) RotZ(θ_i)
/// TransZ(d_i) multiplied from the base: frame i (0-based, i < 7) has joint i + 1's axis as its z
/// axis through its origin; the last is the flange.
inline std::vector<Eigen::Isometry3d> panda_dh_frames(const Eigen::VectorXd& q) {
  std::vector<Eigen::Isometry3d> frames;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  const std::vector<DhRow>& table = panda_dh_table();
  for (std::size_t i = 0; i < table.size(); ++i) {
    const DhRow& row = table[i];
    const double theta = i < 7 ? q(static_cast<Eigen::Index>(i)) : 0.0;
    T = T * Eigen::AngleAxisd(row.alpha, Eigen::Vector3d::UnitX()) *
        Eigen::Translation3d(row.a, 0.0, 0.0) * Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ()) *
        Eigen::Translation3d(0.0, 0.0, row.d);
    frames.push_back(T);
  }
  return frames;
}

/// base_T_flange at q.
inline Eigen::Isometry3d panda_dh(const Eigen::VectorXd& q) { return panda_dh_frames(q).back(); }

/// The ready pose (0, -π/4, 0, -3π/4, 0, π/2, π/4): the library's sample.
inline Eigen::VectorXd panda_ready_pose() { return samples::panda_ready_pose(); }

}  // namespace rodshape::testing
