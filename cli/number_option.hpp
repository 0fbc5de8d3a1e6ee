// number_option.hpp: a numeric command-line option taken as text and read here, so that a bad value
// (negative, not a number, NaN, infinite, beyond its bound) is one line naming the option, exit 2
// (issue 43; CLI11's checks let NaN through and its conversion errors are its own).
#pragma once

#include <string>

namespace rodshape::cli {

/// `text` (the value of `option`) as a whole number in [low, high], written without a sign, a
/// fraction or an exponent; InputError "<option> = <text> must be a whole number in [low, high]".
int whole_option(const std::string& option, const std::string& text, int low, int high);

/// `text` (the value of `option`) as a finite number in (0, high]; InputError "<option> = <text>
/// must be a number in (0, <high>]" (also for NaN and infinity).
double positive_option(const std::string& option, const std::string& text, double high);

}  // namespace rodshape::cli
