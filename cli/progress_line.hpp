// progress_line.hpp: long work's progress on one updating line of standard error ("validate: 3/10
// runs, 12 s, about 28 s left"), drawn only when standard error is a terminal and the command is
// not quiet; the line is cleared when the work ends.
#pragma once

#include <chrono>
#include <string>

namespace rodshape::cli {

class ProgressLine {
 public:
  /// Draws nothing unless `enabled` and standard error is a terminal.
  ProgressLine(std::string what, std::string unit, bool enabled);
  ~ProgressLine();  // clears the line if one was drawn
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  bool active() const { return active_; }
  /// `done` of `total` units: redrawn at most five times a second, and at done = total.
  void update(int done, int total);

 private:
  std::string what_, unit_;
  bool active_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace rodshape::cli
