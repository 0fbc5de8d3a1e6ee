// error.hpp: the two kinds of exception rodshape throws. Numerical non-convergence is not one of
// them: it is a status in a result (see solvers/solve_status.hpp).
#pragma once

#include <stdexcept>
#include <string>

namespace rodshape {

/// Base class of every exception rodshape throws.
class RodshapeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Bad input: the message names the field and the value, e.g.
/// "PlanOptions.steps = 0 must be >= 1". The library names its own fields (C++ type and member);
/// io says them as the task file does ("trajectory.steps = 0 must be >= 1") from field() and
/// problem(), by a table (io/field_names.hpp), not by rewriting the text.
class InputError : public RodshapeError {
 public:
  /// A message that names no single field (or names it in its own words).
  explicit InputError(const std::string& message) : RodshapeError(message), problem_(message) {}
  /// what() is field + problem, e.g. "ClampedRod.intervals" + " = 0 must be >= 1".
  InputError(std::string field, std::string problem)
      : RodshapeError(field + problem), field_(std::move(field)), problem_(std::move(problem)) {}

  /// The field the message is about, in the library's names; empty when none is named apart.
  const std::string& field() const noexcept { return field_; }
  /// The rest of the message after the field (the whole message when field() is empty).
  const std::string& problem() const noexcept { return problem_; }

 private:
  std::string field_;
  std::string problem_;
};

}  // namespace rodshape
