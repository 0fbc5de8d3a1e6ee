#include "rodshape/solvers/tip_condition.hpp"

namespace rodshape {

const char* tip_condition_name(const TipCondition& condition) {
  static const char* const names[] = {"free", "clamped", "grasped"};
  return names[condition.index()];
}

}  // namespace rodshape
