// svg_drawing.hpp: what the SVG figures (plan_svg.cpp, validation_svg.cpp) share: numbers as SVG
// wants them, escaped text, round tick spacings, the step colour ramp and a title wrapped to a
// width.
#pragma once

#include <string>
#include <vector>

namespace rodshape::figures {

/// A number, fixed, with `digits` decimals (2: 0.01 px).
std::string fixed(double value, int digits = 2);
/// `text` with &, <, > and " escaped for SVG or HTML.
std::string escaped(const std::string& text);
/// The colour "#rrggbb" of step k of n on a ramp from dark blue through purple and pink to orange
/// (the first four fifths of matplotlib's "plasma": every colour stays readable on white).
std::string step_colour(int k, int n);
/// A round tick spacing, 1, 2 or 5 × 10^k, giving about `count` intervals over `range`.
double tick_spacing(double range, int count);
/// `value` with as many decimals as `spacing` needs (0 for a value within half a spacing of 0).
std::string tick_label(double value, double spacing);
/// `text` cut into lines of at most `max_characters` (at spaces where it can; a word longer than a
/// line is cut), about what fits in a width at a font size: a character of sans-serif is about
/// 0.55 of the font size wide.
std::vector<std::string> wrapped(const std::string& text, std::size_t max_characters);
/// The characters that fit in `width` px at `font_size` px of sans-serif.
std::size_t characters_in(double width, double font_size);

}  // namespace rodshape::figures
