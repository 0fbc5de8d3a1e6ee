#include "rodshape/solvers/solve_status.hpp"

namespace rodshape {

std::string to_string(SolveStatus status) {
  return std::string(name_of(kSolveStatusNames, status));
}

}  // namespace rodshape
