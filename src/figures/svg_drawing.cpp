// svg_drawing.cpp: the SVG figures' shared helpers (svg_drawing.hpp).
#include "figures/svg_drawing.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "rodshape/figures/figures.hpp"
#include "rodshape/version.hpp"

namespace rodshape::figures {

std::string fixed(double value, int digits) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(digits) << value;
  return out.str();
}

std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string step_colour(int k, int n) {
  static constexpr std::array<std::array<double, 3>, 4> kRamp = {
      {{13, 8, 135}, {126, 3, 168}, {204, 71, 120}, {240, 130, 50}}};
  const double t = n > 1 ? static_cast<double>(k) / (n - 1) : 1.0;
  const double x = t * (kRamp.size() - 1);
  const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(x), kRamp.size() - 2);
  const double f = x - static_cast<double>(i);
  std::ostringstream out;
  out << '#' << std::hex << std::setfill('0');
  for (int c = 0; c < 3; ++c) {
    const double value = (1.0 - f) * kRamp[i][c] + f * kRamp[i + 1][c];
    out << std::setw(2) << static_cast<int>(std::lround(value));
  }
  return out.str();
}

double tick_spacing(double range, int count) {
  const double raw = range / count;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double factor : {1.0, 2.0, 5.0}) {
    if (factor * decade >= raw) return factor * decade;
  }
  return 10.0 * decade;
}

std::string tick_label(double value, double spacing) {
  const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(spacing) + 1e-9)));
  return fixed(std::abs(value) < 0.5 * spacing ? 0.0 : value, decimals);
}

std::size_t characters_in(double width, double font_size) {
  return static_cast<std::size_t>(std::max(8.0, width / (0.55 * font_size)));
}

std::vector<std::string> wrapped(const std::string& text, std::size_t max_characters) {
  // Counted in code points: a UTF-8 continuation byte adds no width.
  const auto width = [](const std::string& s) {
    return static_cast<std::size_t>(
        std::count_if(s.begin(), s.end(), [](char c) { return (c & 0xC0) != 0x80; }));
  };
  std::vector<std::string> lines;
  std::string line;
  std::istringstream words(text);
  std::string word;
  while (words >> word) {
    while (width(word) > max_characters) {  // a word longer than a line: cut it
      if (!line.empty()) lines.push_back(std::move(line)), line.clear();
      std::size_t cut = 0, count = 0;
      while (cut < word.size() && count < max_characters) {
        ++cut;
        while (cut < word.size() && (word[cut] & 0xC0) == 0x80) ++cut;
        ++count;
      }
      lines.push_back(word.substr(0, cut));
      word = word.substr(cut);
    }
    if (word.empty()) continue;
    if (!line.empty() && width(line) + 1 + width(word) > max_characters) {
      lines.push_back(std::move(line));
      line.clear();
    }
    if (!line.empty()) line += ' ';
    line += word;
  }
  if (!line.empty()) lines.push_back(std::move(line));
  return lines;
}

}  // namespace rodshape::figures

namespace rodshape {

std::string svg_signature_comment() { return "<!-- generator: rodshape " + version() + " -->"; }

}  // namespace rodshape
