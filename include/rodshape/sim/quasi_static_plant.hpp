// quasi_static_plant.hpp: today's plant behind the plant seam: each drive is one drive_plant()
// call (plant.hpp: the held equilibrium solved sample by sample), from the last drive's base
// wrench; a hold repeats the last frame, at rest.
#pragma once

#include <string>
#include <vector>

#include "rodshape/sim/plant_interface.hpp"

namespace rodshape {

class QuasiStaticPlant final : public Plant {
 public:
  explicit QuasiStaticPlant(PlantSetup setup);

  std::string name() const override { return "quasi_static"; }
  const PlantSetup& setup() const override { return setup_; }
  void reset(const PlantStart& start) override;
  /// drive_plant() along the request, its start equilibrium solved (with continuation) from the
  /// base wrench of the last drive's last frame (the first: PlantStart::guess).
  PlantRun drive(const PlantDrive& request, const PlantFrameSink& on_frame) override;
  /// The last drive's last frame at each frame time, its velocities zero.
  PlantRun hold(double t_end,
                const std::vector<double>& frame_times,
                const PlantFrameSink& on_frame) override;

 private:
  PlantSetup setup_;
  BaseWrench guess_;  // the next drive's start guess
  PlantFrame last_;   // where the last drive left the rod
};

}  // namespace rodshape
