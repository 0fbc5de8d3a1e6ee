// inverse_kinematics.hpp: joint positions that put an arm's tip at a pose, within the joint limits.
//
// Damped least squares (Levenberg–Marquardt) on the pose error, started from a seed (the previous
// waypoint, so that a trajectory stays on one branch). One iteration at q:
//   e = [p* - p(q); log(R* R(q)ᵀ)]                        (base frame; m and rad)
//   Δq = J_Aᵀ (J_A J_Aᵀ + μ I)⁻¹ e + N (-k ∇H(q))          J_A: J with blocked joints' columns
//   zeroed q ← clamp(q + Δq, lower, upper)                        accepted only if |e| decreases
// μ shrinks ×10 after an accepted step (down to 1e-12, so the end is Gauss–Newton and converges
// quadratically) and grows ×10 after a rejected one. A joint is blocked while it sits on a limit
// and the step would push it further. For a redundant arm (n > 6) the null-space term
// N = I - J_A⁺ J_A moves the arm away from its limits without moving the tip:
//   H(q) = ½ Σ ((q_i - mid_i) / range_i)²,  mid and range from each joint's limits.
// When the seed's solve stalls, the solve restarts from seeds drawn (deterministically) within the
// limits; IkResult::restarts says so, since such a solution may lie on another branch.
//
// Clearance (IkClearance, a redundant arm): once the pose has converged, the links are pushed away
// from the scene and the rod through the null space. The pairs (link capsule, obstacle or rod)
// whose gap g_k is below its required gap plus the influence distance δ have shortfalls
// s_k = required_k + δ - g_k > 0 and gradients a_k = ∂g_k/∂q (arm_clearance.hpp); with N an
// orthonormal basis of the null space of J (from its SVD), the step is
//   Δq = N z,   z = argmin |A N z - s|² + λ |z|²   (A the rows a_kᵀ),
// which raises every short gap at first order without moving the tip; the pose is then converged
// again (the damped least squares above, from q + Δq) and the step is kept only if the sum of the
// squared shortfalls fell (halved up to 6 times, else the search stops).
#pragma once

#include <Eigen/Core>
#include <string>

#include "rodshape/core/pose.hpp"
#include "rodshape/robot/arm_clearance.hpp"
#include "rodshape/robot/arm_model.hpp"
#include "rodshape/solvers/solve_status.hpp"

namespace rodshape {

struct IkOptions {
  /// Upper bounds (docs/limits.md, "Sizes"): an iteration is one Jacobian and a 6×n solve; one IK
  /// runs at every sample of a joint trajectory.
  static constexpr int kMaxIterations = 10'000;
  static constexpr int kMaxRestarts = 1000;

  double position_tolerance = 1e-10;  // converged when |p* - p| ≤ this (m) ...
  double rotation_tolerance = 1e-10;  // ... and the angle of R* Rᵀ ≤ this (rad)
  int max_iterations = 200;           // per attempt (the seed and each restart)
  int max_restarts = 20;              // random seeds tried after the seed's solve stalls; 0: none
  double limit_avoidance_gain = 0.1;  // k above; 0 turns the null-space motion off
  unsigned random_seed = 1;           // for the restart seeds
  /// Throws InputError naming "ik.position_tolerance" etc.
  void validate() const;
};

/// The links kept clear through the redundancy (n > 6; ignored otherwise).
struct IkClearance {
  const ArmClearance* clearance = nullptr;  // null: off
  std::vector<const RodNodes*> rods;        // the rod's centreline(s) to keep the links off
  /// The other arm's link capsules (world_capsules(); null: none), kept off as the obstacles are.
  const std::vector<Obstacle>* others = nullptr;
  double influence = 0.03;  // δ, m: gaps below required + δ are pushed out
  int max_iterations = 20;  // null-space steps
};

struct IkResult {
  SolveStatus status = SolveStatus::NotRun;  // Converged, or OutOfReach ("out of reach: ..."), or
                                             // IterationLimit
  std::string message;                       // empty when converged
  Eigen::VectorXd q;                         // best joint positions found (within limits)
  int iterations = 0;                        // over all attempts
  int restarts = 0;                          // attempts after the first one
  double position_error = 0.0;               // |p* - p(q)|, m
  double rotation_error = 0.0;               // angle of R* R(q)ᵀ, rad
  int clearance_steps = 0;                   // null-space clearance steps taken (IkClearance)
  bool converged() const { return status == SolveStatus::Converged; }
  /// "converged in 5 iterations (0 restarts), |Δp| = 1.8e-15 m, angle 6.2e-16 rad" or
  /// "<status>: <message>".
  std::string brief() const;
};

/// Joint positions with forward_kinematics(q) = `target` (to the tolerances), starting from `seed`.
/// Throws InputError when `seed` has the wrong size, is not finite or lies outside the limits, when
/// `target` is not finite or its rotation is not a rotation, or when `options` are invalid. A
/// target the arm cannot reach is a status: OutOfReach with a message "out of reach: ...".
IkResult solve_ik(const ArmModel& arm,
                  const Pose& target,
                  const Eigen::VectorXd& seed,
                  const IkOptions& options = {});
/// The same, then the links pushed clear through the null space (see above); the pose stays
/// converged to the tolerances. `clearance.clearance` must be made for this arm.
IkResult solve_ik(const ArmModel& arm,
                  const Pose& target,
                  const Eigen::VectorXd& seed,
                  const IkOptions& options,
                  const IkClearance& clearance);

/// The default seed: the Panda "ready" pose (0, -π/4, 0, -3π/4, 0, π/2, π/4) for a 7-joint arm,
/// else zeros; clamped into the joint limits.
Eigen::VectorXd default_seed(const ArmModel& arm);

}  // namespace rodshape
