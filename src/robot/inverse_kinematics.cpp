// inverse_kinematics.cpp: damped least squares with joint limits and null-space limit avoidance
// (the update is written out in inverse_kinematics.hpp).
#include "rodshape/robot/inverse_kinematics.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <sstream>

#include "robot/random_joint_positions.hpp"
#include "rodshape/core/so3.hpp"
#include "rodshape/error.hpp"
#include "validation.hpp"

namespace rodshape {

void IkOptions::validate() const {
  detail::require_positive("IkOptions.position_tolerance", position_tolerance);
  detail::require_positive("IkOptions.rotation_tolerance", rotation_tolerance);
  detail::require_count("IkOptions.max_iterations", max_iterations, 1, kMaxIterations);
  detail::require_count("IkOptions.max_restarts", max_restarts, 0, kMaxRestarts);
  detail::require_non_negative("IkOptions.limit_avoidance_gain", limit_avoidance_gain);
}

namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Jacobian = Eigen::Matrix<double, 6, Eigen::Dynamic>;

// Levenberg–Marquardt damping μ: start, floor, and the value beyond which no step can help.
constexpr double kInitialDamping = 1e-4;
constexpr double kMinDamping = 1e-12;
constexpr double kMaxDamping = 1e10;
// The largest joint motion of one step (rad or m): keeps a step from jumping to another branch.
constexpr double kMaxStep = 0.5;
// Null-space motion fades as the pose error |e| falls below this (m or rad), so that it stops
// before the end and the last iterations converge quadratically.
constexpr double kNullSpaceFade = 1e-2;
// Progress: when |e| fell by less than kSlowFactor over the last kSlowIterations iterations, the
// solve has stalled (at a local minimum of |e|, or at the edge of the reachable set).
constexpr int kSlowIterations = 20;
constexpr double kSlowFactor = 1e-2;

/// e = [p* - p; log(R* Rᵀ)]: the twist (base frame) that moves the tip onto the target.
Vector6 pose_error(const Pose& target, const Pose& pose) {
  Vector6 e;
  e.head<3>() = target.position - pose.position;
  e.tail<3>() = log_so3(target.rotation * pose.rotation.transpose());
  return e;
}

struct Attempt {
  Eigen::VectorXd q;
  Vector6 error = Vector6::Zero();
  int iterations = 0;
  bool converged = false;
  bool stalled = false;
};

class Solver {
 public:
  Solver(const ArmModel& arm, const Pose& target, const IkOptions& options)
      : arm_(arm),
        target_(target),
        options_(options),
        lower_(arm.lower_limits()),
        upper_(arm.upper_limits()),
        n_(arm.joints()) {
    mid_.resize(n_);
    range_.resize(n_);
    for (int i = 0; i < n_; ++i) {
      const bool finite = std::isfinite(lower_(i)) && std::isfinite(upper_(i));
      mid_(i) = finite ? 0.5 * (lower_(i) + upper_(i)) : 0.0;
      range_(i) = finite && upper_(i) > lower_(i) ? upper_(i) - lower_(i) : 0.0;
    }
  }

  /// The null-space clearance steps (inverse_kinematics.hpp) from the converged `attempt`, which
  /// stays converged; returns the number of steps taken.
  int improve_clearance(Attempt& attempt, const IkClearance& clearance) const {
    std::vector<LinkGapRow> rows;
    const auto shortfall = [&](const Eigen::VectorXd& q) {
      clearance.clearance->near_pairs(q, clearance.rods, clearance.influence, rows,
                                      clearance.others);
      double sum = 0.0;
      for (const LinkGapRow& row : rows) sum += row.shortfall * row.shortfall;
      return sum;
    };
    int steps = 0;
    double current = shortfall(attempt.q);
    for (int iteration = 0; iteration < clearance.max_iterations && current > 0.0; ++iteration) {
      // rows hold the pairs at attempt.q
      Pose pose;
      Jacobian J(6, n_);
      arm_.forward_kinematics(attempt.q, pose, J);
      const Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeFullV);
      const Eigen::VectorXd& sigma = svd.singularValues();
      const double threshold = 1e-9 * std::max(1.0, sigma(0));
      Eigen::Index rank = 0;
      while (rank < sigma.size() && sigma(rank) > threshold) ++rank;
      const Eigen::MatrixXd N = svd.matrixV().rightCols(n_ - rank);
      if (N.cols() == 0) break;
      Eigen::MatrixXd A(static_cast<Eigen::Index>(rows.size()), n_);
      Eigen::VectorXd s(static_cast<Eigen::Index>(rows.size()));
      for (std::size_t k = 0; k < rows.size(); ++k) {
        A.row(static_cast<Eigen::Index>(k)) = rows[k].gradient.transpose();
        s(static_cast<Eigen::Index>(k)) = rows[k].shortfall;
      }
      const Eigen::MatrixXd AN = A * N;
      const Eigen::MatrixXd H =
          AN.transpose() * AN + 1e-6 * Eigen::MatrixXd::Identity(N.cols(), N.cols());
      Eigen::VectorXd dq = N * H.ldlt().solve(AN.transpose() * s);
      const double largest = dq.cwiseAbs().maxCoeff();
      if (!(largest > 1e-12)) break;
      if (largest > kMaxStep) dq *= kMaxStep / largest;
      bool accepted = false;
      for (int halving = 0; halving < 7 && !accepted; ++halving, dq *= 0.5) {
        Attempt trial = run(clamp(attempt.q + dq));
        if (!trial.converged) continue;
        const double value = shortfall(trial.q);
        if (value < current) {
          trial.iterations += attempt.iterations;
          attempt = std::move(trial);
          current = value;
          accepted = true;
        }
      }
      if (!accepted) break;
      ++steps;
      shortfall(attempt.q);  // the rows at the new q
    }
    return steps;
  }

  bool within_tolerance(const Vector6& e) const {
    return e.head<3>().norm() <= options_.position_tolerance &&
           e.tail<3>().norm() <= options_.rotation_tolerance;
  }

  Attempt run(const Eigen::VectorXd& seed) const {
    Attempt attempt;
    attempt.q = seed;
    Pose pose;
    Jacobian J(6, n_);
    arm_.forward_kinematics(attempt.q, pose, J);
    attempt.error = pose_error(target_, pose);
    double damping = kInitialDamping;
    std::vector<double> history{attempt.error.norm()};  // |e| after each iteration
    while (!within_tolerance(attempt.error)) {
      if (attempt.iterations >= options_.max_iterations) return attempt;
      const bool slow =
          history.size() > kSlowIterations &&
          history.back() > (1.0 - kSlowFactor) * history[history.size() - 1 - kSlowIterations];
      if (damping > kMaxDamping || slow) {
        attempt.stalled = true;
        return attempt;
      }
      ++attempt.iterations;
      const double error_norm = attempt.error.norm();
      const Eigen::VectorXd q_new = clamp(attempt.q + step(attempt.q, J, attempt.error, damping));
      Pose pose_new;
      Jacobian J_new(6, n_);
      arm_.forward_kinematics(q_new, pose_new, J_new);
      const Vector6 error_new = pose_error(target_, pose_new);
      const double new_norm = error_new.norm();
      if (std::isfinite(new_norm) && new_norm < error_norm) {
        attempt.q = q_new;
        attempt.error = error_new;
        J = J_new;
        damping = std::max(damping / 10.0, kMinDamping);
      } else {
        damping *= 10.0;
      }
      history.push_back(attempt.error.norm());
    }
    attempt.converged = true;
    return attempt;
  }

 private:
  Eigen::VectorXd clamp(const Eigen::VectorXd& q) const {
    return q.cwiseMax(lower_).cwiseMin(upper_);
  }

  /// Δq for one iteration; joints on a limit that the step would push further are blocked.
  Eigen::VectorXd step(const Eigen::VectorXd& q,
                       const Jacobian& J,
                       const Vector6& e,
                       double damping) const {
    std::vector<bool> blocked(n_, false);
    Eigen::VectorXd dq(n_);
    for (int pass = 0; pass <= n_; ++pass) {
      Jacobian J_A = J;
      for (int i = 0; i < n_; ++i)
        if (blocked[i]) J_A.col(i).setZero();
      const Matrix6 A = J_A * J_A.transpose() + damping * Matrix6::Identity();
      dq = J_A.transpose() * A.ldlt().solve(e);
      if (n_ > 6 && options_.limit_avoidance_gain > 0.0)
        dq += null_space_step(q, J_A, blocked, e.norm());
      bool changed = false;
      for (int i = 0; i < n_; ++i) {
        if (blocked[i]) continue;
        const bool at_lower = q(i) <= lower_(i) && dq(i) < 0.0;
        const bool at_upper = q(i) >= upper_(i) && dq(i) > 0.0;
        if (at_lower || at_upper) blocked[i] = changed = true;
      }
      if (!changed) break;
    }
    const double largest = dq.cwiseAbs().maxCoeff();
    if (largest > kMaxStep) dq *= kMaxStep / largest;
    return dq;
  }

  /// N (-k ∇H): the descent of H(q) = ½ Σ ((q_i - mid_i) / range_i)² projected on the null space
  /// of J_A, fading with the pose error. The row space of J_A is spanned by v_k = J_Aᵀ u_k / σ_k
  /// with J_A J_Aᵀ = Σ σ_k² u_k u_kᵀ (a 6 × 6 eigenproblem, not the n × n SVD); directions with
  /// σ_k² ≤ kWeakDirection σ_max² (beyond the eigenvalues' rounding) count as null.
  Eigen::VectorXd null_space_step(const Eigen::VectorXd& q,
                                  const Jacobian& J_A,
                                  const std::vector<bool>& blocked,
                                  double error_norm) const {
    constexpr double kWeakDirection = 1e-12;
    Eigen::VectorXd gradient = Eigen::VectorXd::Zero(n_);
    for (int i = 0; i < n_; ++i) {
      if (range_(i) > 0.0 && !blocked[i]) gradient(i) = (q(i) - mid_(i)) / (range_(i) * range_(i));
    }
    const Eigen::SelfAdjointEigenSolver<Matrix6> eigen(J_A * J_A.transpose());
    const Vector6& lambda = eigen.eigenvalues();  // σ_k², ascending
    const double threshold = kWeakDirection * std::max(1.0, lambda(5));
    Eigen::VectorXd step = -options_.limit_avoidance_gain * gradient;
    // Σ_k v_k v_kᵀ step = J_Aᵀ Σ_k u_k (u_kᵀ J_A step) / σ_k², over the kept k.
    Vector6 c = eigen.eigenvectors().transpose() * (J_A * step);
    for (int k = 0; k < 6; ++k) c(k) = lambda(k) > threshold ? c(k) / lambda(k) : 0.0;
    step.noalias() -= J_A.transpose() * (eigen.eigenvectors() * c);
    for (int i = 0; i < n_; ++i)
      if (blocked[i]) step(i) = 0.0;
    return std::min(1.0, error_norm / kNullSpaceFade) * step;
  }

  const ArmModel& arm_;
  const Pose& target_;
  const IkOptions& options_;
  Eigen::VectorXd lower_, upper_, mid_, range_;
  int n_;
};

std::string format_length(double value) {
  std::ostringstream out;
  out.precision(3);
  out << value;
  return out.str();
}

}  // namespace

IkResult solve_ik(const ArmModel& arm,
                  const Pose& target,
                  const Eigen::VectorXd& seed,
                  const IkOptions& options) {
  return solve_ik(arm, target, seed, options, IkClearance{});
}

IkResult solve_ik(const ArmModel& arm,
                  const Pose& target,
                  const Eigen::VectorXd& seed,
                  const IkOptions& options,
                  const IkClearance& clearance) {
  options.validate();
  arm.check_joint_positions(seed, "seed");
  detail::require_finite("target.position", target.position);
  detail::require_finite("target.rotation", target.rotation);
  if (!is_rotation(target.rotation, 1e-6))
    throw InputError("target.rotation is not a rotation matrix (RᵀR ≠ I or det R ≠ 1)");
  Pose unit_target = target;  // the nearest exact rotation, so the error can reach zero
  unit_target.rotation = Eigen::Quaterniond(target.rotation).normalized().toRotationMatrix();

  IkResult result;
  result.q = arm.clamp_to_limits(seed);
  const double distance = unit_target.position.norm();
  if (distance > arm.reach()) {
    const Pose pose = arm.forward_kinematics(result.q);
    const Vector6 e = pose_error(unit_target, pose);
    result.status = SolveStatus::OutOfReach;
    result.position_error = e.head<3>().norm();
    result.rotation_error = e.tail<3>().norm();
    result.message = "out of reach: the target is " + format_length(distance) + " m from " +
                     arm.base_link() + ", beyond the arm's reach of " + format_length(arm.reach()) +
                     " m";
    return result;
  }

  const Solver solver(arm, unit_target, options);
  std::mt19937 rng(options.random_seed);
  Attempt best;
  bool all_stalled = true;
  for (int attempt_index = 0; attempt_index <= options.max_restarts; ++attempt_index) {
    const Eigen::VectorXd start =
        attempt_index == 0 ? result.q : detail::random_joint_positions(arm, rng);
    Attempt attempt = solver.run(start);
    result.iterations += attempt.iterations;
    result.restarts = attempt_index;
    all_stalled = all_stalled && attempt.stalled;
    if (attempt_index == 0 || attempt.error.norm() < best.error.norm()) best = std::move(attempt);
    if (best.converged) break;
  }

  if (best.converged && clearance.clearance != nullptr && arm.joints() > 6)
    result.clearance_steps = solver.improve_clearance(best, clearance);
  result.q = best.q;
  result.position_error = best.error.head<3>().norm();
  result.rotation_error = best.error.tail<3>().norm();
  if (best.converged) {
    result.status = SolveStatus::Converged;
  } else if (all_stalled) {
    result.status = SolveStatus::OutOfReach;
    result.message = "out of reach: no joint positions within the limits reach the target from " +
                     std::to_string(result.restarts + 1) + " starts; the closest pose found is " +
                     format_length(result.position_error) + " m and " +
                     format_length(result.rotation_error) + " rad away";
  } else {
    result.status = SolveStatus::IterationLimit;
    result.message = "no convergence within " + std::to_string(options.max_iterations) +
                     " iterations from each of " + std::to_string(result.restarts + 1) +
                     " starts; the closest pose found is " + format_length(result.position_error) +
                     " m and " + format_length(result.rotation_error) + " rad away";
  }
  return result;
}

Eigen::VectorXd default_seed(const ArmModel& arm) {
  if (arm.joints() == 7) {
    constexpr double pi = std::numbers::pi;
    Eigen::VectorXd q(7);
    q << 0.0, -pi / 4.0, 0.0, -3.0 * pi / 4.0, 0.0, pi / 2.0, pi / 4.0;
    return arm.clamp_to_limits(q);
  }
  return arm.clamp_to_limits(Eigen::VectorXd::Zero(arm.joints()));
}

std::string IkResult::brief() const {
  if (!converged()) return to_string(status) + ": " + message;
  std::ostringstream out;
  out.precision(3);
  out << "converged in " << iterations << " iterations (" << restarts
      << " restarts), |Δp| = " << position_error << " m, angle " << rotation_error << " rad";
  return out.str();
}

}  // namespace rodshape
