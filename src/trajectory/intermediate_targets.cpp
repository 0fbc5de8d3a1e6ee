#include "rodshape/trajectory/intermediate_targets.hpp"

#include <Eigen/Geometry>
#include <algorithm>

#include "rodshape/core/pose_between_nodes.hpp"
#include "rodshape/error.hpp"
#include "rodshape/optimisation/curve_distance.hpp"

namespace rodshape {

PointSet points_at_arc_lengths(const ClampedRod& rod,
                               const RodConfiguration& initial,
                               const std::vector<double>& arc_lengths) {
  if (initial.derivatives != Derivatives::AllNodes || initial.nodes() != rod.nodes())
    throw InputError(
        "points_at_arc_lengths needs the rod's configuration with Derivatives::AllNodes");
  const int N = initial.nodes() - 1;
  PointSet points;
  points.reserve(arc_lengths.size());
  for (const double s : arc_lengths) {
    const double at = std::clamp(s, 0.0, initial.s[N]);
    const auto after = std::upper_bound(initial.s.begin(), initial.s.end(), at);
    const int i = std::clamp(static_cast<int>(after - initial.s.begin()) - 1, 0, N);
    points.push_back(at == initial.s[i] ? initial.p[i]
                                        : pose_between_nodes(rod, initial, i, at).pose.position);
  }
  return points;
}

PointSet project_onto_initial_shape(const RodConfiguration& initial, const PointSet& objective) {
  PointSet projected;
  projected.reserve(objective.size());
  for (const Eigen::Vector3d& p : objective)
    projected.push_back(project_onto_curve(initial, p).closest);
  return projected;
}

PointSet objective_set(const PointSet& initial, const PointSet& objective, double fraction) {
  if (initial.size() != objective.size())
    throw InputError("objective_set: " + std::to_string(initial.size()) + " initial points for " +
                     std::to_string(objective.size()) + " objective points");
  if (fraction == 1.0) return objective;  // exactly p_obj, not p_obj up to round-off
  PointSet set(objective.size());
  for (std::size_t k = 0; k < objective.size(); ++k)
    set[k] = initial[k] + fraction * (objective[k] - initial[k]);
  return set;
}

PointSet turned_objective_set(const Eigen::Vector3d& clamp,
                              const PointSet& initial,
                              const PointSet& objective,
                              double fraction) {
  if (initial.size() != objective.size())
    throw InputError("turned_objective_set: " + std::to_string(initial.size()) +
                     " initial points for " + std::to_string(objective.size()) +
                     " objective points");
  if (fraction == 1.0) return objective;
  PointSet set(objective.size());
  Eigen::Vector3d joint = clamp;  // the chain's joint before link k
  for (std::size_t k = 0; k < objective.size(); ++k) {
    const Eigen::Vector3d a = initial[k] - (k == 0 ? clamp : initial[k - 1]);
    const Eigen::Vector3d b = objective[k] - (k == 0 ? clamp : objective[k - 1]);
    const double la = a.norm(), lb = b.norm();
    Eigen::Vector3d link = a + fraction * (b - a);
    if (la > 0.0 && lb > 0.0) {
      const Eigen::Quaterniond turn = Eigen::Quaterniond::FromTwoVectors(a / la, b / lb);
      link = (la + fraction * (lb - la)) *
             (Eigen::Quaterniond::Identity().slerp(fraction, turn) * (a / la));
    }
    joint += link;
    set[k] = joint;
  }
  return set;
}

std::vector<PointSet> intermediate_targets(const PointSet& initial,
                                           const PointSet& objective,
                                           int n_inter) {
  if (n_inter < 1) throw InputError("n_inter", " = " + std::to_string(n_inter) + " must be >= 1");
  std::vector<PointSet> steps;
  steps.reserve(n_inter);
  for (int i = 1; i <= n_inter; ++i)  // p^i = p_init + i (p_obj - p_init) / n_inter
    steps.push_back(
        objective_set(initial, objective, static_cast<double>(i) / n_inter));  // i = n: 1
  return steps;
}

}  // namespace rodshape
