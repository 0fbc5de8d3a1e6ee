// arm_reach_cache.hpp: compute_arm_reach() once per kinematic chain and options in the process.
//
// Two arms of one plan are often the same robot (two Pandas, each its own ArmModel read from the
// same URDF), and a program plans many times with the same arms: the reach (4096 forward
// kinematics and 400 refinement steps, about 5 ms for a Panda) is the same every time. The key is
// the chain as the public ArmModel shows it, compared bit for bit: the robot's and the links'
// names, every joint's name, kind and limits, and every link frame and joint axis at two joint
// positions (zero and 0.5 in every joint); and the options. Equal keys mean the same URDF chain
// between the same links, so the same computation and the same reach.
#pragma once

#include "rodshape/robot/arm_model.hpp"
#include "rodshape/robot/arm_reach.hpp"

namespace rodshape::detail {

/// compute_arm_reach(arm, options), from a process-wide cache (thread-safe; the last few chains).
ArmReach cached_arm_reach(const ArmModel& arm, const ArmReachOptions& options);

}  // namespace rodshape::detail
