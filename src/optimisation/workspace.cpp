// workspace.cpp: the rows of g for the tip pose (p, R) ∈ Ws, in the order box (x, y, z), inside
// balls, outside balls, half-spaces, reach shell (one two-sided row). The balls are written
// squared, |p - c|² ≤ r² (≥ r² outside), so that g is a polynomial in p (smooth everywhere, also at
// the centre, where |p - c| is not). The reach shell's point q = p + R t moves with the tip's
// rotation:
//   δq = δp + R θ̂ t = δp - R t̂ θ,   so  d|q - c|²/dp = 2 (q - c)ᵀ,  d|q - c|²/dθ = -2 (q - c)ᵀ R t̂.
#include "rodshape/optimisation/workspace.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "rodshape/core/so3.hpp"
#include "validation.hpp"

namespace rodshape {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::string indexed(const char* name, std::size_t i) {
  return std::string("Workspace.") + name + "[" + std::to_string(i) + "]";
}

}  // namespace

int Workspace::constraint_count() const {
  return (box ? 3 : 0) + static_cast<int>(inside.size() + outside.size() + half_spaces.size()) +
         (reach ? 1 : 0);
}

bool Workspace::contains(const Pose& tip, double tolerance) const {
  const Eigen::Vector3d& p = tip.position;
  if (box) {
    if ((p.array() < box->lower.array() - tolerance).any()) return false;
    if ((p.array() > box->upper.array() + tolerance).any()) return false;
  }
  for (const Ball& ball : inside)
    if ((p - ball.center).norm() > ball.radius + tolerance) return false;
  for (const Ball& ball : outside)
    if ((p - ball.center).norm() < ball.radius - tolerance) return false;
  for (const HalfSpace& half : half_spaces)  // distance to the plane, not nᵀp - offset
    if (half.normal.dot(p) - half.offset > tolerance * half.normal.norm()) return false;
  if (reach) {
    const double r = reach->distance(tip);
    if (r > reach->outer_radius + tolerance || r < reach->inner_radius - tolerance) return false;
  }
  return true;
}

void Workspace::evaluate(const Pose& tip,
                         Eigen::Ref<Eigen::VectorXd> g,
                         Eigen::Ref<Eigen::MatrixXd> dg_dp,
                         Eigen::Ref<Eigen::MatrixXd> dg_dtheta) const {
  const Eigen::Vector3d& p = tip.position;
  dg_dtheta.setZero();
  int row = 0;
  if (box) {
    g.segment<3>(row) = p;  // lower ≤ p ≤ upper
    dg_dp.middleRows<3>(row).setIdentity();
    row += 3;
  }
  auto ball_row = [&](const Ball& ball) {
    const Eigen::Vector3d d = p - ball.center;
    g(row) = d.squaredNorm();  // |p - c|²
    dg_dp.row(row++) = 2.0 * d.transpose();
  };
  for (const Ball& ball : inside) ball_row(ball);
  for (const Ball& ball : outside) ball_row(ball);
  for (const HalfSpace& half : half_spaces) {
    g(row) = half.normal.dot(p);  // nᵀp ≤ offset
    dg_dp.row(row++) = half.normal.transpose();
  }
  if (reach) {
    const Eigen::Vector3d d = reach->point(tip) - reach->center;
    g(row) = d.squaredNorm();  // |q - c|²
    dg_dp.row(row) = 2.0 * d.transpose();
    dg_dtheta.row(row) = -2.0 * d.transpose() * tip.rotation * hat(reach->tip_point);
  }
}

void Workspace::bounds(Eigen::Ref<Eigen::VectorXd> lower, Eigen::Ref<Eigen::VectorXd> upper) const {
  int row = 0;
  if (box) {
    lower.segment<3>(row) = box->lower;
    upper.segment<3>(row) = box->upper;
    row += 3;
  }
  for (const Ball& ball : inside) {
    lower(row) = -kInf;
    upper(row++) = ball.radius * ball.radius;
  }
  for (const Ball& ball : outside) {
    lower(row) = ball.radius * ball.radius;
    upper(row++) = kInf;
  }
  for (const HalfSpace& half : half_spaces) {
    lower(row) = -kInf;
    upper(row++) = half.offset;
  }
  if (reach) {
    lower(row) = reach->inner_radius > 0.0 ? reach->inner_radius * reach->inner_radius : -kInf;
    upper(row) = reach->outer_radius * reach->outer_radius;
  }
}

void Workspace::validate() const {
  if (box) {
    detail::require_finite("Workspace.box.lower", box->lower);
    detail::require_finite("Workspace.box.upper", box->upper);
    for (int k = 0; k < 3; ++k) {
      if (box->lower(k) > box->upper(k)) {
        throw InputError("Workspace.box", ": lower[" + std::to_string(k) +
                                              "] = " + detail::format_value(box->lower(k)) +
                                              " is above upper[" + std::to_string(k) +
                                              "] = " + detail::format_value(box->upper(k)));
      }
    }
  }
  auto check_balls = [](const std::vector<Ball>& balls, const char* name) {
    for (std::size_t i = 0; i < balls.size(); ++i) {
      detail::require_finite(indexed(name, i) + ".center", balls[i].center);
      detail::require_positive(indexed(name, i) + ".radius", balls[i].radius);
    }
  };
  const auto check_count = [](std::size_t count, const char* name) {
    if (count > kMaxSets)
      throw InputError(
          std::string("Workspace.") + name,
          " has " + std::to_string(count) + " entries; at most " + std::to_string(kMaxSets));
  };
  check_count(inside.size(), "inside");
  check_count(outside.size(), "outside");
  check_count(half_spaces.size(), "half_spaces");
  check_balls(inside, "inside");
  check_balls(outside, "outside");
  for (std::size_t i = 0; i < half_spaces.size(); ++i) {
    const std::string field = indexed("half_spaces", i);
    detail::require_finite(field + ".normal", half_spaces[i].normal);
    if (half_spaces[i].normal.norm() == 0.0) throw InputError(field, ".normal must be non-zero");
    detail::require_finite(field + ".offset", half_spaces[i].offset);
  }
  if (reach) {
    detail::require_finite("Workspace.reach.center", reach->center);
    detail::require_finite("Workspace.reach.tip_point", reach->tip_point);
    detail::require_positive("Workspace.reach.outer_radius", reach->outer_radius);
    detail::require_non_negative("Workspace.reach.inner_radius", reach->inner_radius);
    if (reach->inner_radius >= reach->outer_radius)
      throw InputError("Workspace.reach",
                       ": inner_radius = " + detail::format_value(reach->inner_radius) +
                           " is not below outer_radius = " +
                           detail::format_value(reach->outer_radius) + " (an empty shell)");
  }
}

}  // namespace rodshape
