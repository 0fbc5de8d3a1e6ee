// arm_reach.cpp: shoulder and wrist points from the joint axes, the range of |w - c| by sampling
// and projected gradient refinement, and the shell in the rod's tip frame.
//
// Nearest point of line a (a₀ + s â) to line b (b₀ + t b̂), unit directions, c = â·b̂,
// d = â·(a₀ - b₀), e = b̂·(a₀ - b₀):  s = (c e - d) / (1 - c²); parallel lines: s = -d (the foot of
// b₀ on a).
// Gradient of r(q) = |w(q) - c|: the wrist point moves with the flange, ẇ = v + ω × (R w_flange)
// (v, ω the flange's twist, KDL's Jacobian), so  ∂r/∂q = êᵀ (J_v - [R w_flange]ₓ J_ω),
// ê = (w - c) / r.
#include "rodshape/robot/arm_reach.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <list>
#include <mutex>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "robot/arm_reach_cache.hpp"
#include "robot/random_joint_positions.hpp"
#include "rodshape/core/so3.hpp"
#include "rodshape/error.hpp"
#include "validation.hpp"

namespace rodshape {

namespace {

Eigen::Vector3d nearest_point_on(const JointAxis& a, const JointAxis& b) {
  const Eigen::Vector3d ab = a.origin - b.origin;
  const double c = a.direction.dot(b.direction);
  const double d = a.direction.dot(ab);
  const double e = b.direction.dot(ab);
  const double denominator = 1.0 - c * c;
  const double s = denominator > 1e-12 ? (c * e - d) / denominator : -d;
  return a.origin + s * a.direction;
}

/// The joint positions the axes are read at: zero, clamped into the limits.
Eigen::VectorXd reference_positions(const ArmModel& arm) {
  return arm.clamp_to_limits(Eigen::VectorXd::Zero(arm.joints()));
}

struct DistanceAt {
  double r = 0.0;
  Eigen::VectorXd gradient;  // ∂r/∂q
};

DistanceAt distance_and_gradient(const ArmModel& arm,
                                 const ArmReach& reach,
                                 const Eigen::VectorXd& q) {
  Pose base_T_flange;
  Eigen::Matrix<double, 6, Eigen::Dynamic> J;
  arm.forward_kinematics(q, base_T_flange, J);
  const Eigen::Vector3d arm_vector = base_T_flange.rotation * reach.wrist_in_tip_link;
  const Eigen::Vector3d d = base_T_flange.position + arm_vector - reach.shoulder;
  DistanceAt result;
  result.r = d.norm();
  result.gradient = Eigen::VectorXd::Zero(arm.joints());
  if (result.r > 1e-12) {
    const Eigen::Matrix<double, 3, Eigen::Dynamic> dw_dq =
        J.topRows<3>() - hat(arm_vector) * J.bottomRows<3>();
    result.gradient = (d / result.r).transpose() * dw_dq;
  }
  return result;
}

/// From `q`, projected gradient steps that increase (sign +1) or decrease (sign -1) r within the
/// limits, with a step that doubles after a success and halves after a failure.
void refine(const ArmModel& arm,
            const ArmReach& reach,
            double sign,
            int steps,
            Eigen::VectorXd& q,
            double& r) {
  const Eigen::VectorXd lower = arm.lower_limits(), upper = arm.upper_limits();
  DistanceAt at = distance_and_gradient(arm, reach, q);
  double step = 0.05;  // rad (or m) for the largest component
  for (int k = 0; k < steps && step > 1e-12; ++k) {
    Eigen::VectorXd direction = sign * at.gradient;
    for (int i = 0; i < q.size(); ++i)  // a joint on a limit that the step pushes further stays
      if ((q(i) <= lower(i) && direction(i) < 0.0) || (q(i) >= upper(i) && direction(i) > 0.0))
        direction(i) = 0.0;
    const double largest = direction.cwiseAbs().maxCoeff();
    if (!(largest > 0.0)) break;
    const Eigen::VectorXd trial =
        (q + (step / largest) * direction).cwiseMax(lower).cwiseMin(upper);
    const DistanceAt there = distance_and_gradient(arm, reach, trial);
    if (sign * (there.r - at.r) > 0.0) {
      q = trial;
      at = there;
      step *= 2.0;
    } else {
      step *= 0.5;
    }
  }
  r = at.r;
}

}  // namespace

void ArmReachOptions::validate() const {
  detail::require_count("ArmReachOptions.samples", samples, 1, kMaxSamples);
  detail::require_count("ArmReachOptions.refinement_steps", refinement_steps, 0,
                        kMaxRefinementSteps);
}

double ArmReach::wrist_distance(const Pose& base_T_flange) const {
  return (base_T_flange.position + base_T_flange.rotation * wrist_in_tip_link - shoulder).norm();
}

ArmReach compute_arm_reach(const ArmModel& arm, const ArmReachOptions& options) {
  options.validate();
  const int n = arm.joints();
  ArmReach reach;
  const Eigen::VectorXd q0 = reference_positions(arm);
  const std::vector<JointAxis> axes = arm.joint_axes(q0);
  reach.shoulder = n >= 2 ? nearest_point_on(axes[0], axes[1]) : axes[0].origin;
  const Eigen::Vector3d wrist_in_base =
      n >= 2 ? nearest_point_on(axes[n - 1], axes[n - 2]) : axes[n - 1].origin;
  const Pose base_T_flange = arm.forward_kinematics(q0);
  reach.wrist_in_tip_link =
      base_T_flange.rotation.transpose() * (wrist_in_base - base_T_flange.position);

  std::mt19937 random(options.random_seed);
  reach.min_distance = std::numeric_limits<double>::infinity();
  reach.max_distance = -1.0;
  for (int k = 0; k < options.samples; ++k) {
    const Eigen::VectorXd q = detail::random_joint_positions(arm, random);
    const double r = reach.wrist_distance(arm.forward_kinematics(q));
    if (r < reach.min_distance) {
      reach.min_distance = r;
      reach.q_min_distance = q;
    }
    if (r > reach.max_distance) {
      reach.max_distance = r;
      reach.q_max_distance = q;
    }
  }
  refine(arm, reach, +1.0, options.refinement_steps, reach.q_max_distance, reach.max_distance);
  refine(arm, reach, -1.0, options.refinement_steps, reach.q_min_distance, reach.min_distance);
  return reach;
}

Workspace::ReachShell reach_shell(const ArmReach& reach,
                                  const ArmPlacement& placement,
                                  const Pose& tip_T_ee,
                                  double margin) {
  detail::require_non_negative("margin", margin);
  Workspace::ReachShell shell;
  shell.center = placement.world_T_base.position + placement.world_T_base.rotation * reach.shoulder;
  const Pose tip_T_flange = compose(tip_T_ee, inverse(placement.flange_T_ee));
  shell.tip_point = tip_T_flange.position + tip_T_flange.rotation * reach.wrist_in_tip_link;
  shell.inner_radius = reach.min_distance + margin;
  shell.outer_radius = reach.max_distance - margin;
  if (!(shell.outer_radius > shell.inner_radius)) {
    throw InputError("margin",
                     " = " + detail::format_value(margin) + " leaves no shell: the wrist reaches " +
                         detail::format_value(reach.min_distance) + " to " +
                         detail::format_value(reach.max_distance) + " m from the shoulder");
  }
  return shell;
}

namespace detail {

namespace {

/// The cache's key (arm_reach_cache.hpp): names, then numbers as their bits.
struct ReachKey {
  std::vector<std::string> names;
  std::vector<std::uint64_t> bits;
  bool operator==(const ReachKey&) const = default;
};

ReachKey reach_key(const ArmModel& arm, const ArmReachOptions& options) {
  ReachKey key;
  const auto number = [&](double x) { key.bits.push_back(std::bit_cast<std::uint64_t>(x)); };
  const auto vector = [&](const Eigen::Vector3d& v) {
    for (int i = 0; i < 3; ++i) number(v(i));
  };
  key.names = {arm.robot_name(), arm.base_link(), arm.tip_link()};
  key.names.insert(key.names.end(), arm.frame_links().begin(), arm.frame_links().end());
  for (const JointInfo& joint : arm.joint_info()) {
    key.names.push_back(joint.name);
    number(joint.prismatic ? 1.0 : 0.0);
    number(joint.lower);
    number(joint.upper);
  }
  LinkFrames frames;
  for (const double q : {0.0, 0.5}) {
    arm.link_frames(Eigen::VectorXd::Constant(arm.joints(), q), frames);
    for (const Pose& frame : frames.frames) {
      vector(frame.position);
      for (int c = 0; c < 3; ++c) vector(frame.rotation.col(c));
    }
    for (const JointAxis& axis : frames.axes) {
      vector(axis.origin);
      vector(axis.direction);
    }
  }
  key.bits.push_back(static_cast<std::uint64_t>(options.samples));
  key.bits.push_back(static_cast<std::uint64_t>(options.refinement_steps));
  key.bits.push_back(options.random_seed);
  return key;
}

}  // namespace

ArmReach cached_arm_reach(const ArmModel& arm, const ArmReachOptions& options) {
  options.validate();
  constexpr std::size_t kKept = 8;
  static std::mutex mutex;
  static std::list<std::pair<ReachKey, ArmReach>> kept;  // most recently used first
  ReachKey key = reach_key(arm, options);
  {
    const std::lock_guard<std::mutex> lock(mutex);
    for (auto it = kept.begin(); it != kept.end(); ++it) {
      if (!(it->first == key)) continue;
      kept.splice(kept.begin(), kept, it);
      return kept.front().second;
    }
  }
  ArmReach reach = compute_arm_reach(arm, options);  // outside the lock: other chains go on
  const std::lock_guard<std::mutex> lock(mutex);
  kept.emplace_front(std::move(key), reach);
  if (kept.size() > kKept) kept.pop_back();
  return reach;
}

}  // namespace detail

}  // namespace rodshape
