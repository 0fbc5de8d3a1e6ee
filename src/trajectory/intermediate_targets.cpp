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
