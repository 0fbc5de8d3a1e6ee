// 04_validate: the plan carried out in simulation, as the paper's experiment was on the robot. The
// C-arc task (examples/plan_c_arc.yaml) is planned; the simulated band, 15 % softer than the
// planner's, with its weight and a grasp 2 mm off, follows the end-effector path and ten markers
// are seen by a noisy camera. Open loop, then closed loop (at each waypoint the state is estimated
// from the markers and the rest re-planned). Same as 04_validate.py.
// Usage: 04_validate [OUTDIR]  (run from the source tree; writes the closed loop's plan.json,
// validation.json, ... into OUTDIR, as `rodshape validate` does)
#include <cstdio>
#include <string>

#include "rodshape/error.hpp"
#include "rodshape/io/plan_output.hpp"
#include "rodshape/io/task_reader.hpp"
#include "rodshape/io/validation_output.hpp"
#include "rodshape/sim/plan_validation.hpp"
#include "rodshape/trajectory/plan.hpp"

int main(int argc, char** argv) {
  using namespace rodshape;
  try {
    PlanTask task = read_plan_task("examples/plan_c_arc.yaml");
    task.plant.stiffness_scale = 0.85;
    task.plant.gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
    task.plant.grasp_offset.position = {0.002, 0.0, 0.0};

    const PlanResult planned = plan(task.problem, task.options);
    std::printf("%s\n", planned.brief().c_str());
    if (!planned.complete()) return 3;
    for (bool closed_loop : {false, true}) {
      ValidationOptions options;
      options.runs = 2;
      options.seed = 7;
      options.closed_loop = closed_loop;
      options.loop = task.closed_loop;
      options.planning = task.options;
      const ValidationResult v =
          validate_plan(task.problem, planned, task.plant, task.sensor_model(), options);
      std::printf("%s loop: %s\n", closed_loop ? "closed" : "open", v.brief().c_str());
      for (const ValidationRun& run : v.runs)
        std::printf("  seed %llu: final true error %.3f mm\n",
                    static_cast<unsigned long long>(run.seed), run.final.true_error * 1e3);
      if (v.status != ValidationStatus::Complete) return 3;
      if (closed_loop && argc > 1) {
        write_plan(argv[1], planned, task);
        write_validation(argv[1], v, planned, task);
      }
    }
  } catch (const InputError& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return 2;
  }
  return 0;
}
