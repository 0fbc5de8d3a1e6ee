// ipopt_derivative_test.hpp (private): IPOPT's derivative checker on a ShapeProblem, for the tests.
// No IPOPT header here, so a test can include it without compiling against IPOPT.
#pragma once

#include <string>

#include "rodshape/core/wrench.hpp"
#include "rodshape/optimisation/shape_problem.hpp"

namespace rodshape::detail {

struct DerivativeTestReport {
  int error_count = 0;          // entries IPOPT flagged with '*'; -1 when IPOPT did not start
  bool no_errors_line = false;  // IPOPT printed "No errors detected by derivative checker."
  std::string log;              // everything IPOPT printed at level J_WARNING and below
};

/// IPOPT's first-order derivative checker (derivative_test = first-order, max_iter = 0) on the
/// problem at `w` itself (point_perturbation_radius = 0), through the same ShapeNlp and options as
/// optimise_shape(). Each entry of ∇F and dg/dw is compared with the forward difference
/// (f(w + h e_j) - f(w)) / h, h = perturbation · max(1, |w_j|), and flagged when
/// |difference - exact| / max(|difference|, 1) ≥ tolerance.
DerivativeTestReport run_derivative_test(ShapeProblem& problem,
                                         const Vector6d& w,
                                         double tolerance,
                                         double perturbation);

}  // namespace rodshape::detail
