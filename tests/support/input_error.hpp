// input_error.hpp: the message of the rodshape::InputError an action throws, for the bad-input
// tests. Callers check the message for the field it must name (find(), rfind(..., 0), EXPECT_EQ),
// so the "" returned when nothing is thrown fails those checks too; check EXPECT_NE(message, "")
// where the message itself is not inspected.
#pragma once

#include <gtest/gtest.h>

#include <exception>
#include <functional>
#include <string>
#include <typeinfo>

#include "rodshape/error.hpp"

namespace rodshape::testing {

/// The what() of the InputError `action` throws; "" when it throws nothing. Any other
/// std::exception is a test failure naming it (and gives "").
inline std::string input_error_message(const std::function<void()>& action) {
  try {
    action();
  } catch (const InputError& error) {
    return error.what();
  } catch (const std::exception& error) {
    ADD_FAILURE() << "threw " << typeid(error).name()
                  << " instead of rodshape::InputError: " << error.what();
  }
  return "";
}

}  // namespace rodshape::testing
