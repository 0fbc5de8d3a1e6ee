// quasi_static_plant.cpp: the quasi-static plant: drive_plant() behind the Plant seam.
#include "rodshape/sim/quasi_static_plant.hpp"

#include <utility>

namespace rodshape {

QuasiStaticPlant::QuasiStaticPlant(PlantSetup setup) : setup_(std::move(setup)) {}

void QuasiStaticPlant::reset(const PlantStart& start) {
  guess_ = start.guess;
  last_ = PlantFrame{};
}

PlantRun QuasiStaticPlant::drive(const PlantDrive& request, const PlantFrameSink& on_frame) {
  PlantRun run = drive_plant(setup_.rod, setup_.grasp, setup_.grasp_offset, request.path,
                             request.base, guess_, request.frame_times, on_frame, setup_.options);
  guess_ = run.last.base_wrench;
  last_ = run.last;
  return run;
}

PlantRun QuasiStaticPlant::hold(double t_end,
                                const std::vector<double>& frame_times,
                                const PlantFrameSink& on_frame) {
  last_.tip_twist.setZero();
  for (Eigen::Vector3d& v : last_.node_velocities) v.setZero();
  PlantRun run;
  PlantFrame still = last_;
  for (const double t : frame_times) {
    still.t = t;
    if (on_frame) on_frame(still);
    ++run.frames;
  }
  last_.t = t_end;
  run.last = last_;
  return run;
}

}  // namespace rodshape
