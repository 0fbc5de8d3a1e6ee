// fk_command.hpp: `rodshape fk URDF q1 … qn [--base LINK] [--tip LINK]`, and the small JSON
// helpers that fk and ik share.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>

#include "command.hpp"

namespace rodshape::cli {

std::unique_ptr<Command> make_fk_command();

/// A number as JSON: the shortest text that reads back to the same double; null if not finite.
std::string json_number(double value);
/// [a, b, …] of json_number.
std::string json_numbers(const Eigen::VectorXd& values);

}  // namespace rodshape::cli
