// 03_plan_rubber_band: the paper's trajectory generation. The band, straight at rest, is to pass
// through ten points of an S (examples/plan_s_curve.yaml's target); plan() makes n_inter = 7
// optimal shapes from the initial one to the target, times the end-effector path through their tip
// poses and follows the held rod along it to check that it does not jump. Same as
// 03_plan_rubber_band.py. Usage: 03_plan_rubber_band [OUTDIR]  (writes OUTDIR/path.csv)
#include <cstdio>
#include <fstream>

#include "rodshape/samples/rubber_band.hpp"
#include "rodshape/trajectory/plan.hpp"

int main(int argc, char** argv) {
  using namespace rodshape;
  PlanProblem problem;
  problem.rod = samples::rubber_band();
  problem.target.points = {{0.004, 0.0, 0.027}, {0.016, 0.0, 0.054}, {0.032, 0.0, 0.078},
                           {0.051, 0.0, 0.100}, {0.071, 0.0, 0.121}, {0.091, 0.0, 0.142},
                           {0.111, 0.0, 0.163}, {0.128, 0.0, 0.187}, {0.142, 0.0, 0.212},
                           {0.149, 0.0, 0.240}};
  problem.target.energy_weight = 1e-3;   // W1: the tie-breaker between shapes through the points
  problem.target.distance_weight = 1.0;  // W2
  problem.initial = InitialState::rest();
  PlanOptions options;
  options.steps = 7;

  const PlanResult result = plan(problem, options);
  std::printf("%s\n", result.brief().c_str());
  for (const PlanStep& step : result.steps)
    std::printf("  step at %.3f: max distance %.3f mm, energy %.4f J\n", step.fraction,
                step.solution.cost.max_distance * 1e3, step.solution.cost.energy);
  if (argc > 1) {  // the end-effector path: t, x, y, z
    std::ofstream csv(std::string(argv[1]) + "/path.csv");
    csv.precision(17);
    csv << "t,x,y,z\n";
    for (const TimedPose& sample : result.end_effector_path)
      csv << sample.t << ',' << sample.pose.position.x() << ',' << sample.pose.position.y() << ','
          << sample.pose.position.z() << '\n';
  }
  return result.complete() ? 0 : 3;
}
