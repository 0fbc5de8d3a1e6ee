// fk_command.cpp: the tip link's pose at given joint positions, for users who check an arm model.
//   URDF -> ArmModel (robot) -> forward_kinematics -> pose_json (io)
#include "fk_command.hpp"

#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "exit_code.hpp"
#include "rodshape/error.hpp"
#include "rodshape/io/kinematics_json.hpp"
#include "rodshape/robot/arm_model.hpp"
#include "rodshape/samples/bundled_arms.hpp"

namespace rodshape::cli {

ArmModel ArmArguments::load() const {
  if (samples::is_bundled_arm(urdf_path))
    return *samples::bundled_arm(urdf_path, base_link, tip_link);
  if (urdf_path.find_first_of("/.") == std::string::npos && !std::filesystem::exists(urdf_path))
    throw InputError("'" + urdf_path + "' is neither a bundled arm (" +
                     samples::bundled_arm_names() + ") nor a URDF file");
  return ArmModel::from_urdf_file(urdf_path, base_link, tip_link);
}

void ArmArguments::add_to(CLI::App& command) {
  command
      .add_option("urdf", urdf_path,
                  "The arm's URDF file, e.g. data/robots/panda.urdf, or a bundled arm: fr3, panda")
      ->required()
      ->type_name("URDF");
  command.add_option("--base", base_link, "Base link of the chain (default: the URDF's root)")
      ->type_name("LINK");
  command
      .add_option("--tip", tip_link,
                  "Tip link of the chain (default: the last link below the base)")
      ->type_name("LINK");
}

namespace {

class FkCommand final : public Command {
 public:
  CLI::App* add_to(CLI::App& app) override {
    CLI::App* command = app.add_subcommand(
        "fk",
        "Forward kinematics: print the tip link's pose in the base link's frame as JSON "
        "{\"position\": [x, y, z], \"rotation\": [w, x, y, z]} (m; unit quaternion, w >= 0). "
        "The joint positions (rad or m) must lie within the URDF's limits. Docs: docs/robot.md.");
    arm_.add_to(*command);
    command->add_option("q", q_, "One position per moving joint of the chain, base to tip")
        ->required()
        ->type_name("Q");
    return command;
  }

  int run() override {
    const ArmModel arm = arm_.load();
    const Eigen::VectorXd q =
        Eigen::Map<const Eigen::VectorXd>(q_.data(), static_cast<Eigen::Index>(q_.size()));
    arm.check_joint_positions(q, "q");
    const Pose base_T_tip = arm.forward_kinematics(q);
    std::cout << pose_json(base_T_tip) << std::flush;
    return kSuccess;
  }

 private:
  ArmArguments arm_;
  std::vector<double> q_;
};

}  // namespace

std::unique_ptr<Command> make_fk_command() { return std::make_unique<FkCommand>(); }

}  // namespace rodshape::cli
