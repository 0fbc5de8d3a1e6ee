// aligned_objective_set.cpp: the objective points' way from p_init to p_obj when the base moves
// (issue 21): a rigid motion and a bending in the moving frame (see intermediate_targets.hpp).
#include <Eigen/Geometry>
#include <Eigen/SVD>

#include "rodshape/core/so3.hpp"
#include "rodshape/error.hpp"
#include "rodshape/trajectory/intermediate_targets.hpp"

namespace rodshape {

namespace {

Eigen::Vector3d centroid(const PointSet& points) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points) sum += p;
  return sum / static_cast<double>(points.size());
}

}  // namespace

RigidAlignment best_rigid_alignment(const PointSet& from, const PointSet& to) {
  if (from.size() != to.size() || from.empty())
    throw InputError("objective points", ": the two sets differ in size or are empty");
  RigidAlignment alignment;
  alignment.from_centroid = centroid(from);
  alignment.to_centroid = centroid(to);
  // Kabsch: H = Σ (a_i - ā)(b_i - b̄)ᵀ = U S Vᵀ, R = V diag(1, 1, det(V Uᵀ)) Uᵀ.
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < from.size(); ++i)
    H += (from[i] - alignment.from_centroid) * (to[i] - alignment.to_centroid).transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Vector3d sigma = svd.singularValues();
  if (sigma(1) <= 1e-9 * sigma(0)) {
    // Rank ≤ 1 (one set on a line, e.g. the straight rod at rest): H = σ0 u vᵀ leaves the turn
    // about the line free, and Kabsch's pick of it is arbitrary (up to 180°). The least rotation
    // taking the line's direction u onto v is the one a rigid motion of the rod needs.
    alignment.rotation =
        Eigen::Quaterniond::FromTwoVectors(svd.matrixU().col(0), svd.matrixV().col(0))
            .toRotationMatrix();
    return alignment;
  }
  Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
  D(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  alignment.rotation = svd.matrixV() * D * svd.matrixU().transpose();
  return alignment;
}

PointSet aligned_objective_set(const Eigen::Vector3d& base,
                               const PointSet& initial,
                               const PointSet& objective,
                               double fraction) {
  const RigidAlignment a = best_rigid_alignment(initial, objective);
  // The target seen from the initial frame: a_i = Rᵀ (p_obj,i - c_obj) + c_init.
  PointSet aligned(objective.size());
  for (std::size_t i = 0; i < objective.size(); ++i)
    aligned[i] = a.rotation.transpose() * (objective[i] - a.to_centroid) + a.from_centroid;
  const PointSet bent = turned_objective_set(base, initial, aligned, fraction);
  // q_i(f) = c_init + f (c_obj - c_init) + R(f) (s_i(f) - c_init), R(f) = exp(f log R).
  const Eigen::Matrix3d turn = exp_so3(fraction * log_so3(a.rotation));
  const Eigen::Vector3d centre = a.from_centroid + fraction * (a.to_centroid - a.from_centroid);
  PointSet points(objective.size());
  for (std::size_t i = 0; i < objective.size(); ++i)
    points[i] = fraction == 1.0 ? objective[i] : centre + turn * (bent[i] - a.from_centroid);
  return points;
}

}  // namespace rodshape
