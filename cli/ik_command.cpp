// ik_command.cpp: joint positions that put the tip link at a pose, for users who check an arm
// model.
//   URDF -> ArmModel (robot) -> solve_ik -> {"q": [...], "status": ..., ...}
#include "ik_command.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "exit_code.hpp"
#include "fk_command.hpp"
#include "rodshape/error.hpp"
#include "rodshape/robot/arm_model.hpp"
#include "rodshape/robot/inverse_kinematics.hpp"
#include "rodshape/trajectory/joint_trajectory.hpp"

namespace rodshape::cli {

namespace {

/// A JSON string: quotes, backslashes and control characters escaped.
std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      out += ' ';
    } else {
      out += c;
    }
  }
  return out + "\"";
}

/// A rotation from [w, x, y, z]; a quaternion off unit length by more than 1e-3 is bad input
/// (it is probably mistyped), a smaller error is normalised away.
Eigen::Matrix3d rotation_from_wxyz(const std::vector<double>& wxyz) {
  const Eigen::Quaterniond q(wxyz[0], wxyz[1], wxyz[2], wxyz[3]);
  const double norm = q.norm();
  if (!std::isfinite(norm) || std::abs(norm - 1.0) > 1e-3) {
    throw InputError("the quaternion [qw, qx, qy, qz] = " +
                     json_numbers(Eigen::Vector4d(wxyz[0], wxyz[1], wxyz[2], wxyz[3])) +
                     " has norm " + json_number(norm) + "; expected a unit quaternion");
  }
  return q.normalized().toRotationMatrix();
}

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
    for (int i = 0; i < 3; ++i) {
      if (!std::isfinite(pose_[i]))
        throw InputError("the target position [x, y, z] must be finite");
    }
    target.rotation = rotation_from_wxyz({pose_[3], pose_[4], pose_[5], pose_[6]});

    const IkResult result = solve_ik(arm, target, seed);
    std::cout << "{\"q\": " << json_numbers(result.q) << ", \"status\": \""
              << to_string(result.status) << "\", \"message\": " << json_string(result.message)
              << ", \"iterations\": " << result.iterations << ", \"restarts\": " << result.restarts
              << ", \"position_error\": " << json_number(result.position_error)
              << ", \"rotation_error\": " << json_number(result.rotation_error) << "}\n"
              << std::flush;
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
