// shape_problem.cpp: F(w), ∇F(w), g(w) and dg/dw from one integration with all-node derivatives.
//
// Rows of g: the constraint blocks in order (optimisation/blocks/: workspace on the tip pose,
// grasp, curvature, axial strain, clearance), each citing its rows' formula. Cost: F = W1 E / L +
// W2 Σ ρ(dist_k), ∇F = W1/L dE/dw + W2 Σ ρ'(dist_k) ∇dist_k, with ρ(d) = sqrt(d² + δ²) - δ (δ =
// ShapeTarget::distance_smoothing: the paper's sum of distances made smooth where a point is
// reached, which an interior-point method needs to certify an optimum), or ρ(d) = d (δ = 0: the
// exact form; ∇dist is taken as 0 at dist = 0, a subgradient), or ρ(d) = d² (squared_distances).
#include "rodshape/optimisation/shape_problem.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "optimisation/blocks/constraint_blocks.hpp"
#include "rodshape/core/rod_integrator.hpp"
#include "validation.hpp"

namespace rodshape {

namespace {

void validate_wrench_bounds(const WrenchBounds& bounds) {
  static const char* const kNames[6] = {"force.x",  "force.y",  "force.z",
                                        "moment.x", "moment.y", "moment.z"};
  for (int k = 0; k < 6; ++k) {
    const std::string field = std::string("WrenchBounds.") + kNames[k];
    if (std::isnan(bounds.lower(k)) || std::isnan(bounds.upper(k)))
      throw InputError(field, ": a bound is NaN");
    if (bounds.lower(k) > bounds.upper(k)) {
      throw InputError(field, ": lower = " + detail::format_value(bounds.lower(k)) +
                                  " is above upper = " + detail::format_value(bounds.upper(k)));
    }
  }
}

}  // namespace

void Clearance::validate() const {
  scene.validate();
  if (required.size() != scene.obstacles.size())
    throw InputError("Clearance.required",
                     " has " + std::to_string(required.size()) + " entries for " +
                         std::to_string(scene.obstacles.size()) + " obstacles");
  for (std::size_t j = 0; j < required.size(); ++j)
    detail::require_finite("Clearance.required[" + std::to_string(j) + "]", required[j]);
}

ShapeProblem::ShapeProblem(ClampedRod rod,
                           ShapeTarget target,
                           Workspace workspace,
                           Grasp grasp,
                           StrainLimits limits,
                           WrenchBounds wrench_bounds,
                           Clearance clearance)
    : rod_(std::move(rod)),
      target_(std::move(target)),
      workspace_(std::move(workspace)),
      grasp_(std::move(grasp)),
      limits_(std::move(limits)),
      wrench_bounds_(std::move(wrench_bounds)),
      clearance_(std::move(clearance)) {
  rod_.validate();
  target_.validate();
  workspace_.validate();
  limits_.validate();
  validate_wrench_bounds(wrench_bounds_);
  clearance_.validate();
  detail::require_pose("Grasp.tip_to_end_effector", grasp_.tip_to_end_effector);

  const int nodes = rod_.nodes();
  // The blocks, in the order of RowBlocks.
  blocks_.push_back(blocks::workspace(workspace_));
  rows_.workspace = blocks_.back()->rows();
  blocks_.push_back(blocks::grasp(grasp_));
  rows_.grasp = blocks_.back()->rows();
  if (limits_.max_curvature) {
    blocks_.push_back(blocks::curvature(rod_.properties, nodes, *limits_.max_curvature));
    rows_.curvature = blocks_.back()->rows();
  }
  if (limits_.max_axial_strain && rod_.properties.model == ConstitutiveModel::Cosserat) {
    blocks_.push_back(blocks::axial_strain(rod_.properties, nodes, *limits_.max_axial_strain));
    rows_.axial = blocks_.back()->rows();
  }
  if (!clearance_.empty()) {
    blocks_.push_back(blocks::clearance(clearance_, rod_.intervals));
    rows_.clearance = blocks_.back()->rows();
  }
  constraint_count_ = 0;
  for (const auto& block : blocks_) constraint_count_ += block->rows();

  g_lower_.resize(constraint_count_);
  g_upper_.resize(constraint_count_);
  int row = 0;
  for (const auto& block : blocks_) {
    block->bounds(g_lower_.segment(row, block->rows()), g_upper_.segment(row, block->rows()));
    row += block->rows();
  }

  // Every buffer evaluate() writes, sized once.
  configuration_.resize(nodes, Derivatives::AllNodes);
  const std::size_t points = target_.points.size();
  projections_.resize(points);
  body_points_.resize(points);
  balls_.resize(static_cast<std::size_t>(rod_.intervals));
  breakdown_.distances.assign(points, 0.0);
  g_ = Eigen::VectorXd::Zero(constraint_count_);
  dg_dw_ = Eigen::MatrixXd::Zero(constraint_count_, 6);
}

ShapeProblem::~ShapeProblem() = default;

void ShapeProblem::evaluate(const Vector6d& w) {
  if (eliminated_) return evaluate_eliminated(w);
  if (evaluated_ && w == w_) return;
  integrate(rod_, BaseWrench::from_vector(w), configuration_, Derivatives::AllNodes);
  ++integrations_;
  evaluate_cost();
  evaluate_constraints();
  w_ = w;
  evaluated_ = true;
}

double ShapeProblem::constraint_violation() const {
  double violation = 0.0;
  for (Eigen::Index i = 0; i < g_.size(); ++i) {
    if (!std::isfinite(g_(i))) return std::numeric_limits<double>::infinity();
    violation = std::max({violation, g_(i) - g_upper_(i), g_lower_(i) - g_(i)});
  }
  if (base_motion_) {
    const Vector12d lower = variable_lower(), upper = variable_upper();
    for (int j = 0; j < 12; ++j)
      violation = std::max({violation, x_(j) - upper(j), lower(j) - x_(j)});
    return violation;
  }
  for (int j = 0; j < 6; ++j)
    violation =
        std::max({violation, w_(j) - wrench_bounds_.upper(j), wrench_bounds_.lower(j) - w_(j)});
  return violation;
}

void ShapeProblem::evaluate_cost(const RodConfiguration& c,
                                 const std::vector<Eigen::Vector3d>& points,
                                 const std::vector<int>* near_intervals) {
  const double L = rod_.properties.length;
  const double W1 = target_.energy_weight, W2 = target_.distance_weight;
  breakdown_.energy = c.energy;
  breakdown_.energy_term = W1 * c.energy / L;
  cost_gradient_ = (W1 / L) * c.denergy_dw.transpose();
  double distance_term = 0.0;
  breakdown_.max_distance = 0.0;
  if (near_intervals == nullptr) interval_balls(c, balls_);  // once for all the points
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Eigen::Vector3d& point = points[k];
    projections_[k] = near_intervals == nullptr
                          ? project_onto_curve(c, point, balls_)
                          : project_from_interval(c, point, (*near_intervals)[k], 0);
    const double d = projections_[k].distance;
    breakdown_.distances[k] = d;
    breakdown_.max_distance = std::max(breakdown_.max_distance, d);
    if (W2 == 0.0) continue;
    const Eigen::Matrix<double, 1, 6> gradient = distance_gradient(rod_, c, projections_[k], point);
    distance_term += distance_penalty(d);
    cost_gradient_ += distance_term_slope(d) * gradient.transpose();
  }
  breakdown_.distance_term = W2 * distance_term;
  breakdown_.cost = breakdown_.energy_term + breakdown_.distance_term;
}

double ShapeProblem::distance_penalty(double d) const {
  if (target_.squared_distances) return d * d;
  const double delta = target_.distance_smoothing;
  if (delta > 0.0) return std::sqrt(d * d + delta * delta) - delta;  // pseudo-Huber
  return d;
}

double ShapeProblem::distance_term_slope(double d) const {
  const double W2 = target_.distance_weight;
  if (target_.squared_distances) return 2.0 * W2 * d;
  const double delta = target_.distance_smoothing;
  if (delta > 0.0) return W2 * d / std::sqrt(d * d + delta * delta);  // W2 ρ'(d)
  return W2;
}

void ShapeProblem::evaluate_constraints() {
  int row = 0;
  for (const auto& block : blocks_) {
    const int rows = block->rows();
    if (rows > 0)
      block->evaluate(configuration_, g_.segment(row, rows), dg_dw_.middleRows(row, rows));
    row += rows;
  }
}

}  // namespace rodshape
