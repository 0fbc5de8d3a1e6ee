// task_text.hpp: a task-file text and edits of it, for the bad-input tests.
#pragma once

#include <gtest/gtest.h>

#include <string>

namespace rodshape::testing {

/// An equilibrium task: the paper's rubber band (tests/support/solver_fixtures.hpp) with its tip
/// held at a pose. Tests (tests/io/test_task_reader.cpp, tests/cli/test_cli.cpp) refer to its line
/// numbers (1 "rod:", 2 "length", 3 "section", 4 "material", 5 "stiffness", 6 "tip:",
/// 7 "position", 8 "rotation"; an appended line is 9): edit it with replaced_first or append to it,
/// and update those tests when changing it.
inline const std::string kBandTask = R"(rod:
  length: 0.29
  section: {shape: rectangle, width: 0.02, height: 0.02}
  material: {young_modulus: 3.2e6, poisson_ratio: 0.5, density: 1392}
  stiffness: {EIx: 0.04, EIy: 0.04, GJ: 0.028}
tip:
  position: [0.12, 0.0, 0.22]
  rotation: [0.7071067811865476, 0, 0.7071067811865476, 0]
)";

/// `text` with the first occurrence of `from` replaced by `to`; a test failure when `from` is not
/// there (the edit would silently test the unedited text).
inline std::string replaced_first(std::string text,
                                  const std::string& from,
                                  const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "not in the task text: " << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

}  // namespace rodshape::testing
