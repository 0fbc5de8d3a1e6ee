// replan_gentleness.cpp: the shape controller's gentleness test of a re-plan
// (replan_gentleness.hpp).
#include "replan_gentleness.hpp"

#include <algorithm>
#include <sstream>

namespace rodshape::feedback_detail {

std::string not_gentle(const std::vector<PlanStep>& steps,
                       double start_energy,
                       const std::vector<PlannedWaypoint>& replaced,
                       double ratio) {
  for (std::size_t k = 0; k < steps.size() && k < replaced.size(); ++k) {
    const double energy = steps[k].solution.configuration.energy;
    const double reference = std::max(replaced[k].energy, start_energy);
    if (energy <= ratio * reference) continue;
    std::ostringstream out;
    out.precision(3);
    out << "the re-planned step " << k + 1 << " is not gentle: energy " << energy << " J, above "
        << ratio << " x " << reference << " J (the step it replaces, or the state it starts from)";
    return out.str();
  }
  return {};
}

}  // namespace rodshape::feedback_detail
