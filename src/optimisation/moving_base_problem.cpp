// moving_base_problem.cpp: ShapeProblem with a moving base (base_motion.hpp). One integration with
// the wrench's derivatives and the base pose's (base_pose_derivatives), then, with B =
// blockdiag(R(0), R(0)) (w = B w_b) and J = blockdiag(I, J_l(δφ)) (exp([δφ + ε]×) ≈
// exp([J_l(δφ) ε]×) exp([δφ]×): the world-frame turn of a change ε of δφ),
//   ∇_x F = (Bᵀ ∇_w F, Jᵀ ∇_ξ F + ∇ motion term),   dg/dx = (dg/dw B, dg/dξ J).
// Every block is linear in the configuration's derivative arrays (the chain rule), so evaluated on
// the configuration of base_pose_derivatives it gives dg/dξ.
#include <Eigen/Cholesky>
#include <cmath>
#include <limits>

#include "optimisation/blocks/constraint_blocks.hpp"
#include "rodshape/core/base_pose_derivatives.hpp"
#include "rodshape/core/rod_integrator.hpp"
#include "rodshape/core/so3.hpp"
#include "rodshape/optimisation/shape_problem.hpp"
#include "validation.hpp"

namespace rodshape {

void BaseMotion::validate() const {
  detail::require_pose("BaseMotion.reference", reference);
  workspace.validate();
  detail::require_non_negative("BaseMotion.motion_weight", motion_weight);
  for (int k = 0; k < 6; ++k)
    if (std::isnan(wrench_bounds.lower(k)) || std::isnan(wrench_bounds.upper(k)) ||
        wrench_bounds.lower(k) > wrench_bounds.upper(k))
      throw InputError("BaseMotion.wrench_bounds",
                       ": component " + std::to_string(k) + " has lower above upper, or NaN");
}

void ShapeProblem::move_base(BaseMotion motion) {
  motion.validate();
  base_motion_ = std::move(motion);
  rod_.clamp = base_motion_->reference;
  blocks_.push_back(blocks::base_workspace(base_motion_->workspace));
  rows_.base = blocks_.back()->rows();
  const int old_count = constraint_count_;
  constraint_count_ += rows_.base;
  g_lower_.conservativeResize(constraint_count_);
  g_upper_.conservativeResize(constraint_count_);
  blocks_.back()->bounds(g_lower_.segment(old_count, rows_.base),
                         g_upper_.segment(old_count, rows_.base));
  g_ = Eigen::VectorXd::Zero(constraint_count_);
  dg_dw_ = Eigen::MatrixXd::Zero(constraint_count_, 6);
  dg_dxi_ = Eigen::MatrixXd::Zero(constraint_count_, 6);
  dg_dx_ = Eigen::MatrixXd::Zero(constraint_count_, 12);
  gradient_x_ = Eigen::VectorXd::Zero(12);
  pose_tangent_.resize(rod_.nodes(), Derivatives::AllNodes);
  evaluated_ = false;
}

void ShapeProblem::set_base_reference(const Pose& reference) {
  detail::require_pose("BaseMotion.reference", reference);
  base_motion_->reference = reference;
  rod_.clamp = reference;
  evaluated_ = false;
}

Pose ShapeProblem::base_pose(const Vector12d& x) const {
  const Pose& reference = base_motion_->reference;
  return {reference.position + x.segment<3>(6), exp_so3(x.segment<3>(9)) * reference.rotation};
}

BaseWrench ShapeProblem::world_wrench(const Vector12d& x) const {
  const Eigen::Matrix3d R0 = base_pose(x).rotation;
  return {R0 * x.segment<3>(0), R0 * x.segment<3>(3)};
}

Vector12d ShapeProblem::variables_at_reference(const BaseWrench& w) const {
  const Eigen::Matrix3d& R0 = base_motion_->reference.rotation;
  Vector12d x = Vector12d::Zero();
  x << R0.transpose() * w.force, R0.transpose() * w.moment, Eigen::Vector3d::Zero(),
      Eigen::Vector3d::Zero();
  return x;
}

Vector12d ShapeProblem::variable_lower() const {
  Vector12d lower;
  const BaseMotion& motion = *base_motion_;
  for (int k = 0; k < 6; ++k) lower[k] = motion.released[k] ? 0.0 : motion.wrench_bounds.lower(k);
  lower.segment<3>(6).setConstant(-std::numeric_limits<double>::infinity());
  lower.segment<3>(9).setConstant(-BaseMotion::kMaxTurn);
  return lower;
}

Vector12d ShapeProblem::variable_upper() const {
  Vector12d upper;
  const BaseMotion& motion = *base_motion_;
  for (int k = 0; k < 6; ++k) upper[k] = motion.released[k] ? 0.0 : motion.wrench_bounds.upper(k);
  upper.segment<3>(6).setConstant(std::numeric_limits<double>::infinity());
  upper.segment<3>(9).setConstant(BaseMotion::kMaxTurn);
  return upper;
}

void ShapeProblem::set_clamp(const Vector12d& x) { rod_.clamp = base_pose(x); }

Vector6d ShapeProblem::distance_gradient_sum(const RodConfiguration& derivatives) const {
  Vector6d sum = Vector6d::Zero();
  if (target_.distance_weight == 0.0) return sum;
  for (std::size_t k = 0; k < target_.points.size(); ++k) {
    const double d = breakdown_.distances[k];
    sum += distance_term_slope(d) *
           distance_gradient(rod_, derivatives, projections_[k], target_.points[k]).transpose();
  }
  return sum;
}

void ShapeProblem::evaluate_with_base(const Vector12d& x) {
  if (evaluated_ && x == x_) return;
  x_ = x;
  set_clamp(x);
  const Eigen::Matrix3d& R0 = rod_.clamp.rotation;
  const BaseWrench w{R0 * x.segment<3>(0), R0 * x.segment<3>(3)};  // world_wrench(x), R0 once
  integrate(rod_, w, configuration_, Derivatives::AllNodes);
  ++integrations_;
  base_pose_derivatives(rod_, configuration_, pose_tangent_);
  evaluate_cost();  // F, ∇_w F (world wrench), the projections
  evaluate_moving_constraints();
  const double L = rod_.properties.length;
  const double W1 = target_.energy_weight;
  gradient_xi_ =
      (W1 / L) * pose_tangent_.denergy_dw.transpose() + distance_gradient_sum(pose_tangent_);
  breakdown_.cost += motion_cost(x);
  const double Wb = base_motion_->motion_weight * target_.distance_weight;
  const Eigen::Vector3d dt = x.segment<3>(6), dphi = x.segment<3>(9);
  const Eigen::Matrix3d J = left_jacobian_so3(dphi);
  gradient_x_.segment<3>(0) = R0.transpose() * cost_gradient_.head<3>();
  gradient_x_.segment<3>(3) = R0.transpose() * cost_gradient_.tail<3>();
  gradient_x_.segment<3>(6) = gradient_xi_.head<3>() + (2.0 * Wb / L) * dt;
  gradient_x_.segment<3>(9) = J.transpose() * gradient_xi_.tail<3>() + (2.0 * Wb * L) * dphi;
  w_ = w.to_vector();
  evaluated_ = true;
}

double ShapeProblem::motion_cost(const Vector12d& x) const {
  const double L = rod_.properties.length;
  const double Wb = base_motion_->motion_weight * target_.distance_weight;
  return Wb * (x.segment<3>(6).squaredNorm() + L * L * x.segment<3>(9).squaredNorm()) / L;
}

void ShapeProblem::evaluate_aligned(const Vector12d& x) {
  x_ = x;
  set_clamp(x);  // the rod's clamp is the evaluated base pose
  const Pose& base = rod_.clamp;
  for (std::size_t k = 0; k < target_.points.size(); ++k)  // q = R0ᵀ (p - p0)
    body_points_[k] = base.rotation.transpose() * (target_.points[k] - base.position);
  evaluate_cost(body_, body_points_, &align_intervals_);  // ∇ in the body-frame wrench w_b
  breakdown_.cost += motion_cost(x);
  gradient_x_.head<6>() = cost_gradient_;
  gradient_x_.tail<6>().setZero();  // ∂F/∂ξ = 0 at ξ*
  w_ = world_wrench(x).to_vector();
  evaluated_ = false;
}

void ShapeProblem::evaluate_moving_constraints() {
  const Eigen::Matrix3d& R0 = rod_.clamp.rotation;
  const Eigen::Matrix3d J = left_jacobian_so3(x_.segment<3>(9));
  int row = 0;
  for (const auto& block : blocks_) {
    const int rows = block->rows();
    if (rows > 0) {
      block->evaluate(configuration_, g_.segment(row, rows), dg_dw_.middleRows(row, rows));
      block->evaluate(pose_tangent_, g_.segment(row, rows), dg_dxi_.middleRows(row, rows));
    }
    row += rows;
  }
  dg_dx_.leftCols<3>().noalias() = dg_dw_.leftCols<3>() * R0;
  dg_dx_.middleCols<3>(3).noalias() = dg_dw_.middleCols<3>(3) * R0;
  dg_dx_.middleCols<3>(6) = dg_dxi_.leftCols<3>();
  dg_dx_.rightCols<3>().noalias() = dg_dxi_.rightCols<3>() * J;
}

bool ShapeProblem::rigid_alignment_applies() const {
  return base_motion_ && rod_.load.force.isZero(0.0) && rod_.load.moment.isZero(0.0) &&
         target_.distance_weight > 0.0 &&
         (target_.squared_distances || target_.distance_smoothing > 0.0);
}

namespace {
/// align_base() stops at |∂F/∂ξ̃|∞ below this (ξ̃ = (δt / L, δφ)).
constexpr double kAlignedGradient = 1e-12;
/// align_base()'s projections start on the last closest point's interval alone.
constexpr int kAlignReach = 0;
/// A Newton step of align_base() this short in ξ̃ is the last (its error is its square).
constexpr double kNegligibleStep = 1e-8;
}  // namespace

namespace {
/// dΓ/ds and d²Γ/ds² of the body-frame curve at a projection: the derivatives of the Hermite
/// interpolant (curve_distance.cpp) of interval i at t.
struct CurveDerivatives {
  Eigen::Vector3d first, second;
};
CurveDerivatives curve_derivatives(const RodConfiguration& body,
                                   const CurveProjection& projection) {
  const int i = projection.interval;
  const double t = projection.t, h = body.s[i + 1] - body.s[i];
  const Eigen::Vector3d d0 = body.R[i] * body.v[i], d1 = body.R[i + 1] * body.v[i + 1];
  return {(6.0 * t * t - 6.0 * t) / h * (body.p[i] - body.p[i + 1]) +
              (3.0 * t * t - 4.0 * t + 1.0) * d0 + (3.0 * t * t - 2.0 * t) * d1,
          (12.0 * t - 6.0) / (h * h) * (body.p[i] - body.p[i + 1]) + (6.0 * t - 4.0) / h * d0 +
              (6.0 * t - 2.0) / h * d1};
}

/// |Γ'|² - r·Γ'' (r = q - Γ, q the point), how fast (q - Γ)·Γ' falls as s grows: the closest
/// point slides by (Γ'·δq)/this as the point moves. |Γ'|² where it is not positive.
double slide_denominator(const CurveDerivatives& curve, const Eigen::Vector3d& r) {
  const double speed = curve.first.squaredNorm(), denominator = speed - r.dot(curve.second);
  return std::isfinite(denominator) && denominator > 0.0 ? denominator : speed;
}

/// At an end of the rod the closest point is the end itself, whatever the point's motion.
bool at_rod_end(const RodConfiguration& body, const CurveProjection& projection) {
  return (projection.interval == 0 && projection.t == 0.0) ||
         (projection.interval == body.nodes() - 2 && projection.t == 1.0);
}

/// W2 ρ''(d) (along the normal) and W2 ρ'(d)/d (across it) of the distance term.
struct DistanceWeights {
  double along = 0.0, across = 0.0;
};
DistanceWeights distance_weights(double d, const ShapeTarget& target) {
  const double W2 = target.distance_weight, delta = target.distance_smoothing;
  if (target.squared_distances) return {2.0 * W2, 2.0 * W2};
  if (delta > 0.0) {
    const double root = std::sqrt(d * d + delta * delta);
    return {W2 * delta * delta / (root * root * root), W2 / root};
  }
  return {0.0, d > 0.0 ? W2 / d : 0.0};
}

/// The Hessian of one point's distance term in the world point, W2 ρ''(d) along the normal n̂ and
/// W2 ρ'(d)/d across it in the normal plane of the curve (body_ is the shape in the base's frame,
/// q the point there, R0 the base's rotation). Along the curve's unit tangent the distance curves
/// by (1 - |Γ'|²/(|Γ'|² - r·Γ''))/d, r = q - Γ (the closest point slides as the point moves). At
/// an end of the rod the closest point is the end itself: the distance to a point, curved along
/// the tangent too.
Eigen::Matrix3d distance_curvature(const RodConfiguration& body,
                                   const CurveProjection& projection,
                                   const Eigen::Vector3d& q,
                                   const Eigen::Matrix3d& R0,
                                   const Eigen::Vector3d& normal,
                                   double d,
                                   const ShapeTarget& target) {
  const CurveDerivatives curve = curve_derivatives(body, projection);
  const Eigen::Vector3d tangent = (R0 * curve.first).normalized();
  const double slide = curve.first.squaredNorm() / slide_denominator(curve, q - projection.closest);
  const DistanceWeights weight = distance_weights(d, target);
  const Eigen::Matrix3d across_plane =
      Eigen::Matrix3d::Identity() - normal * normal.transpose() -
      (at_rod_end(body, projection) ? Eigen::Matrix3d::Zero()
                                    : Eigen::Matrix3d(slide * tangent * tangent.transpose()));
  return weight.along * normal * normal.transpose() + weight.across * across_plane;
}

/// ∂(W2 ρ'(d) n̂)/∂w_b in the base's frame (n̂ = r/d, r = q - Γ(s*)) as the curve moves under the
/// fixed point q: -(W2 ρ'' n̂n̂ᵀ + W2 ρ'/d (I - n̂n̂ᵀ)) (G + Γ' ∂s*/∂w), G = ∂Γ/∂w at s*, with
/// ∂s*/∂w = (-Γ'ᵀ G + rᵀ ∂Γ'/∂w) / (|Γ'|² - r·Γ'') from (q - Γ)·Γ' = 0 (0 at the rod's ends).
Matrix36d normal_slope_jacobian(const ClampedRod& rod,
                                const RodConfiguration& body,
                                const CurveProjection& projection,
                                const Eigen::Vector3d& q,
                                const ShapeTarget& target) {
  const double d = projection.distance;
  const Eigen::Vector3d r = q - projection.closest, normal = r / d;
  Matrix36d moved = curve_point_jacobian(rod, body, projection.s);
  if (!at_rod_end(body, projection)) {
    const CurveDerivatives curve = curve_derivatives(body, projection);
    const Eigen::Matrix<double, 1, 6> slide =
        (r.transpose() * curve_tangent_jacobian(rod, body, projection.s) -
         curve.first.transpose() * moved) /
        slide_denominator(curve, r);
    moved += curve.first * slide;
  }
  const DistanceWeights weight = distance_weights(d, target);
  const Eigen::Matrix3d nn = normal * normal.transpose();
  return -(weight.along * nn + weight.across * (Eigen::Matrix3d::Identity() - nn)) * moved;
}
}  // namespace

double ShapeProblem::aligned_cost(const Vector6d& xi_scaled,
                                  Vector6d* gradient,
                                  Matrix6d* hessian,
                                  bool global,
                                  std::vector<int>& intervals,
                                  Matrix6d* mixed) {
  intervals.resize(target_.points.size());
  std::size_t k = 0;
  const double L = rod_.properties.length;
  const Pose& reference = base_motion_->reference;
  const Eigen::Vector3d dt = L * xi_scaled.head<3>(), dphi = xi_scaled.tail<3>();
  const Eigen::Matrix3d R0 = exp_so3(dphi) * reference.rotation;
  const Eigen::Matrix3d Jl = left_jacobian_so3(dphi);
  const Eigen::Vector3d p0 = reference.position + dt;
  const double Wb = base_motion_->motion_weight * target_.distance_weight;
  const double W2 = target_.distance_weight;
  double cost = Wb * (dt.squaredNorm() + L * L * dphi.squaredNorm()) / L;
  Vector6d g = Vector6d::Zero();
  g << 2.0 * Wb * dt, (2.0 * Wb * L) * dphi;  // in ξ̃ = (δt / L, δφ)
  Matrix6d H = (2.0 * Wb * L) * Matrix6d::Identity();
  Eigen::Vector3d pull = Eigen::Vector3d::Zero();  // Σ W2 ρ'(d) (p - p0) × n̂
  if (mixed != nullptr) mixed->setZero();
  for (const Eigen::Vector3d& point : target_.points) {
    // The point in the base's frame, q = R0ᵀ (p - p0), and its distance to the body-frame curve.
    const Eigen::Vector3d q = R0.transpose() * (point - p0);
    const CurveProjection projection =
        global ? project_onto_curve(body_, q, body_balls_)
               : project_from_interval(body_, q, align_intervals_[k], kAlignReach);
    intervals[k++] = projection.interval;
    const double d = projection.distance;
    cost += W2 * distance_penalty(d);
    if (gradient == nullptr) continue;
    // The point seen from the base, q = R0ᵀ y with y = p - p0 (world), moves by dq = R0ᵀ J ξ̃,
    // J = [-L I, [y]× J_l] (dR0 = [J_l dδφ]× R0); d dist = n̂ · R0 dq with n̂ the unit normal from
    // the closest point c to p (world).
    const Eigen::Vector3d y = point - p0;
    Eigen::Matrix<double, 3, 6> J;
    J << -L * Eigen::Matrix3d::Identity(), hat(y) * Jl;
    const double slope = distance_term_slope(d);  // W2 ρ'(d)
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    if (d > 0.0) {
      normal = R0 * (q - projection.closest) / d;
      g += slope * (J.transpose() * normal);
      // H_ξ̃w: ∂(W2 ρ' Jᵀ R0 n̂_b)/∂w_b, J and R0 fixed as the curve moves.
      if (mixed != nullptr)
        mixed->noalias() +=
            (J.transpose() * R0) * normal_slope_jacobian(rod_, body_, projection, q, target_);
    }
    if (hessian == nullptr) continue;
    // Newton: W2 ρ'' along n̂, W2 ρ'/d across it in the normal plane of the curve.
    const Eigen::Matrix3d M = distance_curvature(body_, projection, q, R0, normal, d, target_);
    H.noalias() += J.transpose() * M * J;
    // q's own second derivatives times W2 ρ'(d) n̂: ∂²q/∂a_j∂δφ = -L R0ᵀ [e_j]× J_l gives
    // L W2 ρ' [n̂]× J_l; ∂²q/∂δφ² gives W2 ρ' J_lᵀ (n̂ yᵀ - (n̂ · y) I) J_l (symmetrised below
    // with the J_l-derivative term, their sum being symmetric).
    const Eigen::Matrix3d cross = (slope * L) * hat(normal) * Jl;
    H.topRightCorner<3, 3>() += cross;
    H.bottomLeftCorner<3, 3>() += cross.transpose();
    const Eigen::Matrix3d turn =
        normal * y.transpose() - normal.dot(y) * Eigen::Matrix3d::Identity();
    H.bottomRightCorner<3, 3>().noalias() += slope * (Jl.transpose() * turn * Jl);
    pull += slope * y.cross(normal);
  }
  if (hessian != nullptr) {
    // The curvature of the parametrisation: ∂q/∂δφ = R0ᵀ [y]× J_l(δφ), J_l's own derivative
    // (central differences) times the points' pull.
    for (int b = 0; b < 3; ++b) {
      constexpr double kStep = 1e-6;
      const Eigen::Vector3d e = kStep * Eigen::Vector3d::Unit(b);
      const Eigen::Matrix3d dJl =
          (left_jacobian_so3(dphi + e) - left_jacobian_so3(dphi - e)) / (2.0 * kStep);
      H.block<3, 1>(3, 3 + b).noalias() -= dJl.transpose() * pull;
    }
  }
  if (gradient != nullptr) *gradient = g;
  if (hessian != nullptr) *hessian = 0.5 * (H + H.transpose());
  return cost;
}

void ShapeProblem::integrate_body(const Vector6d& w_b) {
  // The rod in its base's frame: the clamp at the identity for this integration only (rod_ itself,
  // not a copy, so that the evaluation does not allocate), put back however the call ends.
  struct ClampRestored {
    ClampedRod& rod;
    Pose clamp;
    ~ClampRestored() { rod.clamp = clamp; }
  } restore{rod_, rod_.clamp};
  rod_.clamp = Pose{};
  integrate(rod_, BaseWrench::from_vector(w_b), body_, Derivatives::AllNodes);
  ++integrations_;
  interval_balls(body_, body_balls_);
}

double ShapeProblem::alignment_cost(const Vector6d& w_b,
                                    const Vector6d& xi,
                                    Vector6d* gradient,
                                    Matrix6d* hessian,
                                    Matrix6d* mixed) {
  integrate_body(w_b);
  Vector6d at;
  at << xi.head<3>() / rod_.properties.length, xi.tail<3>();
  std::vector<int> intervals;
  return aligned_cost(at, gradient, hessian, true, intervals, mixed);
}

namespace {
double top_of(const Matrix6d& hessian) {
  return std::max(1.0, hessian.diagonal().cwiseAbs().maxCoeff());
}
}  // namespace

bool ShapeProblem::align_base(const Vector6d& w_b, Vector6d& xi) {
  integrate_body(w_b);
  const double L = rod_.properties.length;
  using Matrix6 = Matrix6d;
  Vector6d at;
  at << xi.head<3>() / L, xi.tail<3>();
  Vector6d gradient;
  Matrix6 hessian, mixed;
  std::vector<int>& found = align_found_;  // swapped with align_intervals_: both keep capacity
  // The projections start from the last alignment's closest points (the whole curve the first
  // time); one global projection of every point at the end catches a closest point that jumped.
  const bool warm = align_intervals_.size() == target_.points.size();
  double cost = aligned_cost(at, &gradient, &hessian, !warm, found);
  align_intervals_.swap(found);
  if (!std::isfinite(cost) || !gradient.allFinite() || !hessian.allFinite()) return false;
  // Newton steps from the last ξ*, to a gradient at the rounding level of F's: ξ* enters
  // the reduced gradient through H_wξ δξ. Shifted towards a gradient step until it descends. Then
  // every point is projected onto the whole curve; where one comes closer elsewhere, again.
  for (int round = 0; round < 4; ++round) {
    for (int iteration = 0; iteration < 300; ++iteration) {
      if (gradient.lpNorm<Eigen::Infinity>() <= kAlignedGradient) break;
      // The Newton direction, the Hessian shifted until positive definite (no evaluation).
      Vector6d step;
      bool newton = true;
      for (double shift = 0.0;; shift = shift == 0.0 ? 1e-8 * top_of(hessian) : 10.0 * shift) {
        if (shift > 1e8 * top_of(hessian)) return false;
        const Eigen::LDLT<Matrix6> ldlt(hessian + shift * Matrix6::Identity());
        step = -ldlt.solve(gradient);
        if (ldlt.isPositive() && step.allFinite()) break;
        newton = false;
      }
      // The exact Hessian converges quadratically: a Newton step this short leaves an error of
      // its square, below rounding, so ξ* is found without trying it.
      if (newton && step.lpNorm<Eigen::Infinity>() <= kNegligibleStep) {
        at += step;
        break;
      }
      // Backtracking: Armijo, or, where F's differences are at its rounding, a gradient that falls.
      bool moved = false;
      const double length = step.lpNorm<Eigen::Infinity>();
      for (double alpha = 1.0; alpha * length > 1e-2 * kNegligibleStep && !moved; alpha *= 0.5) {
        Vector6d next_gradient;
        Matrix6 next_hessian;
        const double next_cost =
            aligned_cost(at + alpha * step, &next_gradient, &next_hessian, false, found);
        const bool descends =
            next_cost <= cost + 1e-4 * alpha * gradient.dot(step) ||
            (next_cost <= cost + 1e-14 * std::abs(cost) &&
             next_gradient.lpNorm<Eigen::Infinity>() < 0.5 * gradient.lpNorm<Eigen::Infinity>());
        if (std::isfinite(next_cost) && next_gradient.allFinite() && next_hessian.allFinite() &&
            descends) {
          at += alpha * step;
          cost = next_cost;
          gradient = next_gradient;
          hessian = next_hessian;
          align_intervals_.swap(found);
          moved = true;
        }
      }
      if (!moved) break;  // no descent left: at the minimiser to rounding
    }
    const double global_cost = aligned_cost(at, &gradient, &hessian, true, found, &mixed);
    if (!std::isfinite(global_cost) || !gradient.allFinite() || !hessian.allFinite()) return false;
    align_intervals_.swap(found);
    const bool jumped = global_cost < cost - 1e-13 * std::abs(cost);
    cost = global_cost;
    if (!jumped) break;
  }
  xi << L * at.head<3>(), at.tail<3>();
  // dξ̃*/dw_b = -H_ξ̃ξ̃⁻¹ H_ξ̃w at the minimiser: the next alignment's first-order start.
  const Eigen::LDLT<Matrix6> ldlt(hessian);
  xi_sensitivity_ = -ldlt.solve(mixed);
  predictor_ready_ = ldlt.isPositive() && xi_sensitivity_.allFinite();
  return gradient.lpNorm<Eigen::Infinity>() <= 1e-6;
}

Vector6d ShapeProblem::predicted_xi(const Vector6d& w_b) const {
  if (!predictor_ready_) return xi_star_;
  const double L = rod_.properties.length;
  // x_ = (w_b, ξ*) of the last eliminated evaluation, where the sensitivity was found.
  const Vector6d step = xi_sensitivity_ * (w_b - x_.head<6>());  // in ξ̃ = (δt / L, δφ)
  Vector6d xi = xi_star_;
  xi.head<3>() += L * step.head<3>();
  xi.tail<3>() += step.tail<3>();
  return xi;
}

void ShapeProblem::eliminate_base_pose(bool eliminated) {
  eliminated_ = eliminated;
  xi_star_.setZero();
  predictor_ready_ = false;
  align_intervals_.clear();
  evaluated_ = eliminated_evaluated_ = false;
}

void ShapeProblem::evaluate_eliminated(const Vector6d& w_scaled) {
  const Vector6d units = rod_.properties.bending_wrench_units();
  const Vector6d w_b = w_scaled.cwiseProduct(units);
  if (eliminated_evaluated_ && w_b == x_.head<6>()) return;
  eliminated_evaluated_ = false;
  evaluated_ = false;
  Vector6d xi = predicted_xi(w_b);
  if (!align_base(w_b, xi)) {
    predictor_ready_ = false;
    breakdown_.cost = std::numeric_limits<double>::quiet_NaN();
    cost_gradient_.setConstant(std::numeric_limits<double>::quiet_NaN());
    return;
  }
  xi_star_ = xi;
  Vector12d x;
  x << w_b, xi;
  evaluate_aligned(x);
  eliminated_evaluated_ = true;
  // ∂F/∂w̃ = D ∂F/∂w_b at ξ*: ∂F/∂ξ = 0 there.
  cost_gradient_ = gradient_x_.head<6>().cwiseProduct(units);
}

}  // namespace rodshape
