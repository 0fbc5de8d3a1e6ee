// number_option.cpp: numeric command-line options read from their text (number_option.hpp).
#include "number_option.hpp"

#include <charconv>
#include <cmath>
#include <sstream>

#include "rodshape/error.hpp"

namespace rodshape::cli {

namespace {

/// `value` as written in a message: "1000000" for 1e6, "0.5" for 0.5.
std::string number_text(double value) {
  std::ostringstream out;
  out.precision(15);
  out << value;
  return out.str();
}

}  // namespace

int whole_option(const std::string& option, const std::string& text, int low, int high) {
  int value = 0;
  const char* end = text.data() + text.size();
  const bool digits = !text.empty() && text.front() >= '0' && text.front() <= '9';
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (!digits || error != std::errc() || stop != end || value < low || value > high)
    throw InputError(option + " = " + text + " must be a whole number in [" + std::to_string(low) +
                     ", " + std::to_string(high) + "]");
  return value;
}

double positive_option(const std::string& option, const std::string& text, double high) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || stop != end || !std::isfinite(value) ||
      !(value > 0.0) || value > high)
    throw InputError(option + " = " + text + " must be a number in (0, " + number_text(high) + "]");
  return value;
}

}  // namespace rodshape::cli
