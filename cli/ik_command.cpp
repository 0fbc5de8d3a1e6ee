// ik_command.cpp: joint positions that put the tip link at a pose, for users who check an arm
// model.
//   URDF -> ArmModel (robot) -> solve_ik -> ik_result_json (io)
#include "ik_command.hpp"

#include <iostream>
#include <string>
#include <vector>

#include "exit_code.hpp"
#include "fk_command.hpp"
#include "rodshape/core/so3.hpp"
#include "rodshape/error.hpp"
#include "rodshape/io/kinematics_json.hpp"
#include "rodshape/robot/arm_model.hpp"
#include "rodshape/robot/inverse_kinematics.hpp"
#include "rodshape/trajectory/joint_trajectory.hpp"

namespace rodshape::cli {

namespace {

class IkCommand final : public Command {
 public:
  CLI::App* add_to(CLI::App& app) override {
    CLI::App* command = app.add_subcommand(
        "ik",
        "Inverse kinematics: print joint positions that put the tip link at the pose (x y z in m, "
        "qw qx qy qz a unit quaternion, in the base link's frame), within the joint limits, as "
        "JSON {\"q\": [...], \"status\": ..., ...}. Exit 3 when the pose is out of reach. Docs: "
        "docs/robot.md.");
    arm_.add_to(*command);
    command->add_option("pose", pose_, "Target pose: x y z qw qx qy qz")
        ->required()
        ->expected(7)
        ->type_name("X Y Z QW QX QY QZ");
    command
        ->add_option("--seed", seed_,
                     "Start from these joint positions (default: the Panda ready pose "
                     "0 -pi/4 0 -3pi/4 0 pi/2 pi/4 for a 7-joint chain, else zeros clamped into "
                     "the limits)")
        ->expected(1, -1)
        ->type_name("Q");
    return command;
  }

  int run() override {
    const ArmModel arm = arm_.load();
    const Eigen::VectorXd seed = seed_.empty()
                                     ? default_seed(arm)
                                     : Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(
                                           seed_.data(), static_cast<Eigen::Index>(seed_.size())));
    arm.check_joint_positions(seed, "--seed");

    Pose target;
    target.position = Eigen::Vector3d(pose_[0], pose_[1], pose_[2]);
    if (!target.position.allFinite())
      throw InputError("the target position [x, y, z] must be finite");
    target.rotation =
        rotation_from_wxyz({pose_[3], pose_[4], pose_[5], pose_[6]}, "the target's rotation");

    const IkResult result = solve_ik(arm, target, seed);
    std::cout << ik_result_json(result) << std::flush;
    if (!result.converged()) {
      std::cerr << "error: " << arm_.urdf_path << ": ik: " << result.message << "\n";
      return kNotConverged;
    }
    return kSuccess;
  }

 private:
  ArmArguments arm_;
  std::vector<double> pose_;
  std::vector<double> seed_;
};

}  // namespace

std::unique_ptr<Command> make_ik_command() { return std::make_unique<IkCommand>(); }

}  // namespace rodshape::cli
