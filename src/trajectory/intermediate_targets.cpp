#include "rodshape/trajectory/intermediate_targets.hpp"

#include "rodshape/error.hpp"
#include "rodshape/optimisation/curve_distance.hpp"

namespace rodshape {

PointSet project_onto_initial_shape(const RodConfiguration& initial, const PointSet& objective) {
  PointSet projected;
  projected.reserve(objective.size());
  for (const Eigen::Vector3d& p : objective)
    projected.push_back(project_onto_curve(initial, p).closest);
  return projected;
}

std::vector<PointSet> intermediate_targets(const PointSet& initial,
                                           const PointSet& objective,
                                           int n_inter) {
  if (n_inter < 1)
    throw InputError("trajectory.steps = " + std::to_string(n_inter) + " must be >= 1");
  if (initial.size() != objective.size())
    throw InputError("intermediate_targets: " + std::to_string(initial.size()) +
                     " initial points for " + std::to_string(objective.size()) +
                     " objective points");
  std::vector<PointSet> steps(n_inter, PointSet(objective.size()));
  for (int i = 1; i <= n_inter; ++i) {
    const double fraction =
        static_cast<double>(i) / n_inter;  // p^i = p_init + i (p_obj - p_init)/n
    for (std::size_t k = 0; k < objective.size(); ++k)
      steps[i - 1][k] = initial[k] + fraction * (objective[k] - initial[k]);
    if (i == n_inter) steps[i - 1] = objective;  // exactly p_obj, not p_obj up to round-off
  }
  return steps;
}

}  // namespace rodshape
