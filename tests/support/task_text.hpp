// task_text.hpp: edits of task-file texts for the bad-input tests.
#pragma once

#include <gtest/gtest.h>

#include <string>

namespace rodshape::testing {

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
