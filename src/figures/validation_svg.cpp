// validation_svg.cpp (figures): validation.svg, the errors of every run over time, as the paper's
// figure but on a logarithmic error axis: the difference that matters at the end (a millimetre
// open loop against a few tenths closed) reads beside the larger errors on the way.
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "figures/svg_drawing.hpp"
#include "rodshape/figures/figures.hpp"

namespace rodshape {

namespace {

using figures::escaped;
using figures::fixed;

// Layout of the figure, px.
constexpr double kFigureWidth = 760.0, kPlotHeight = 330.0;
constexpr double kAxisLeft = 70.0, kRight = 20.0, kBottom = 50.0, kLegend = 26.0;
const char* const kColours[3] = {"#1f77b4", "#ff7f0e", "#2ca02c"};  // 3D, 2D, true
const char* const kNames[3] = {"3D error", "2D error (image plane)", "true error"};
constexpr double kSmallest = 1e-3;  // mm: the axis never goes below a micrometre

/// The plot's scale: time (s) across from 0, error (mm) up on a log axis over whole decades.
struct Axes {
  double top = 60.0;
  double t_max = 1.0;
  double log_lo = -2.0, log_hi = 1.0;  // decades of mm
  double x(double t) const { return kAxisLeft + (kFigureWidth - kAxisLeft - kRight) * t / t_max; }
  double y(double e_mm) const {
    const double l = std::log10(std::max(e_mm, std::pow(10.0, log_lo)));
    return top + kPlotHeight - kPlotHeight * (l - log_lo) / (log_hi - log_lo);
  }
};

Axes fit_axes(const ValidationResult& result, double top) {
  Axes axes;
  axes.top = top;
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (const ValidationRun& run : result.runs) {
    if (!run.time.empty()) axes.t_max = std::max(axes.t_max, run.time.back());
    for (const auto* series : {&run.error_3d, &run.error_2d, &run.true_error})
      for (double e : *series)
        if (std::isfinite(e) && e > 0.0) {
          lo = std::min(lo, 1e3 * e);
          hi = std::max(hi, 1e3 * e);
        }
  }
  if (hi > 0.0) {
    axes.log_hi = std::ceil(std::log10(hi) + 1e-9);
    axes.log_lo = std::floor(std::log10(std::max(lo, kSmallest)));
    axes.log_lo = std::max(axes.log_lo, axes.log_hi - 5.0);  // five decades at most
    if (axes.log_hi - axes.log_lo < 2.0) axes.log_lo = axes.log_hi - 2.0;
  }
  return axes;
}

std::string decade_label(double decade) {
  const int d = static_cast<int>(std::lround(decade));
  return fixed(std::pow(10.0, d), std::max(0, -d));
}

void draw_grid(std::ostringstream& out, const Axes& axes) {
  const double bottom = axes.top + kPlotHeight;
  const double spacing = figures::tick_spacing(axes.t_max, 6);
  for (double t = 0.0; t <= axes.t_max * (1 + 1e-9); t += spacing) {
    out << "<line x1=\"" << fixed(axes.x(t)) << "\" y1=\"" << fixed(bottom) << "\" x2=\""
        << fixed(axes.x(t)) << "\" y2=\"" << fixed(axes.top) << "\" stroke=\"#ddd\"/>\n<text x=\""
        << fixed(axes.x(t)) << "\" y=\"" << fixed(bottom + 18) << "\" text-anchor=\"middle\">"
        << figures::tick_label(t, spacing) << "</text>\n";
  }
  for (double d = axes.log_lo; d <= axes.log_hi + 1e-9; d += 1.0) {
    const double e = std::pow(10.0, d);
    out << "<line x1=\"" << fixed(kAxisLeft) << "\" y1=\"" << fixed(axes.y(e)) << "\" x2=\""
        << fixed(kFigureWidth - kRight) << "\" y2=\"" << fixed(axes.y(e))
        << "\" stroke=\"#bbb\"/>\n<text x=\"" << fixed(kAxisLeft - 8) << "\" y=\""
        << fixed(axes.y(e) + 4) << "\" text-anchor=\"end\">" << decade_label(d) << "</text>\n";
    if (d + 1.0 <= axes.log_hi + 1e-9)
      for (const double m : {2.0, 5.0})
        out << "<line x1=\"" << fixed(kAxisLeft) << "\" y1=\"" << fixed(axes.y(m * e)) << "\" x2=\""
            << fixed(kFigureWidth - kRight) << "\" y2=\"" << fixed(axes.y(m * e))
            << "\" stroke=\"#eee\"/>\n";
  }
  out << "<rect x=\"" << fixed(kAxisLeft) << "\" y=\"" << fixed(axes.top) << "\" width=\""
      << fixed(kFigureWidth - kAxisLeft - kRight) << "\" height=\"" << fixed(kPlotHeight)
      << "\" fill=\"none\" stroke=\"#444\"/>\n";
  out << "<text x=\"" << fixed((kAxisLeft + kFigureWidth - kRight) / 2) << "\" y=\""
      << fixed(bottom + 38) << "\" text-anchor=\"middle\">time (s)</text>\n<text x=\"16\" y=\""
      << fixed(axes.top + kPlotHeight / 2) << "\" transform=\"rotate(-90 16 "
      << fixed(axes.top + kPlotHeight / 2)
      << ")\" text-anchor=\"middle\">error (mm, log scale)</text>\n";
}

void draw_series(std::ostringstream& out,
                 const Axes& axes,
                 const std::vector<double>& t,
                 const std::vector<double>& e,
                 const char* colour) {
  out << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"1.2\" points=\"";
  for (std::size_t k = 0; k < t.size(); ++k)
    if (std::isfinite(e[k])) out << fixed(axes.x(t[k])) << ',' << fixed(axes.y(1e3 * e[k])) << ' ';
  out << "\"/>\n";
}

std::string in_millimetres(double metres) {
  std::ostringstream out;
  out.precision(2);
  out << metres * 1e3 << " mm";
  return out.str();
}

constexpr double kCloudHeight = 260.0;  // px, the cloud's panel below the plot

/// A depth camera's run: its last frame's cloud (blue dots) over the real rod's centreline
/// (green), both projected on the world's x–z plane (the default camera's image plane), at one
/// scale on both axes.
void draw_cloud_panel(std::ostringstream& out, const ValidationRun& run, double top) {
  const std::vector<Eigen::Vector3d>& rod = run.plant_final.configuration.p;
  const std::vector<Eigen::Vector3d>& cloud = run.last_cloud.points;
  Eigen::Vector2d lo(std::numeric_limits<double>::infinity(),
                     std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = -lo;
  for (const auto* points : {&rod, &cloud})
    for (const Eigen::Vector3d& p : *points) {
      lo = lo.cwiseMin(Eigen::Vector2d(p.x(), p.z()));
      hi = hi.cwiseMax(Eigen::Vector2d(p.x(), p.z()));
    }
  const double inner = kCloudHeight - 40.0;
  const double scale =
      std::min((kFigureWidth - kAxisLeft - kRight) / std::max(hi.x() - lo.x(), 1e-6),
               inner / std::max(hi.y() - lo.y(), 1e-6));
  const auto x = [&](const Eigen::Vector3d& p) { return kAxisLeft + scale * (p.x() - lo.x()); };
  const auto y = [&](const Eigen::Vector3d& p) { return top + 30.0 + scale * (hi.y() - p.z()); };
  out << "<text x=\"" << fixed(kAxisLeft) << "\" y=\"" << fixed(top + 14)
      << "\">the depth camera's cloud at the last frame (" << cloud.size()
      << " points, blue) and the real rod (green), x–z, " << fixed(1e3 / scale, 2)
      << " mm per px</text>\n";
  out << "<polyline fill=\"none\" stroke=\"#2ca02c\" stroke-width=\"1.5\" points=\"";
  for (const Eigen::Vector3d& p : rod) out << fixed(x(p)) << ',' << fixed(y(p)) << ' ';
  out << "\"/>\n<g fill=\"#1f77b4\">\n";
  for (const Eigen::Vector3d& p : cloud)
    out << "<circle cx=\"" << fixed(x(p)) << "\" cy=\"" << fixed(y(p)) << "\" r=\"1.2\"/>\n";
  out << "</g>\n";
}

}  // namespace

std::string validation_svg(const ValidationResult& result) {
  std::ostringstream title;
  title << "rodshape validation: mean distance to the objective points over time, "
        << result.runs.size() << (result.runs.size() == 1 ? " run" : " runs") << " ("
        << to_string(result.status) << ")";
  const std::vector<std::string> lines =
      figures::wrapped(title.str(), figures::characters_in(kFigureWidth - kAxisLeft - kRight, 14));
  const double top = 22 + 18.0 * static_cast<double>(lines.size()) + kLegend;
  const Axes axes = fit_axes(result, top);
  const ValidationRun* first = result.runs.empty() ? nullptr : &result.runs.front();
  const bool cloud = first != nullptr && !first->last_cloud.points.empty();
  const double height = top + kPlotHeight + kBottom + (cloud ? kCloudHeight : 0.0);
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << svg_signature_comment()
      << "\n<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" << kFigureWidth
      << "\" height=\"" << fixed(height) << "\" viewBox=\"0 0 " << kFigureWidth << ' '
      << fixed(height) << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for (std::size_t k = 0; k < lines.size(); ++k)
    out << "<text x=\"" << fixed(kAxisLeft) << "\" y=\""
        << fixed(22 + 18.0 * static_cast<double>(k)) << "\" font-size=\"14\">" << escaped(lines[k])
        << "</text>\n";
  // The legend, with the first run's final errors: the numbers the figure is about.
  double x = kAxisLeft;
  const double y = top - 12;
  for (int c = 0; c < 3; ++c) {
    std::string label = kNames[c];
    if (first != nullptr) {
      const double final = c == 0 ? first->final.error_3d
                                  : (c == 1 ? first->final.error_2d : first->final.true_error);
      if (std::isfinite(final)) label += ", final " + in_millimetres(final);
    }
    out << "<line x1=\"" << fixed(x) << "\" y1=\"" << fixed(y - 4) << "\" x2=\"" << fixed(x + 22)
        << "\" y2=\"" << fixed(y - 4) << "\" stroke=\"" << kColours[c]
        << "\" stroke-width=\"2\"/>\n<text x=\"" << fixed(x + 27) << "\" y=\"" << fixed(y) << "\">"
        << escaped(label) << "</text>\n";
    x += 27 + 6.6 * static_cast<double>(label.size()) + 18;
  }
  draw_grid(out, axes);
  for (const ValidationRun& run : result.runs) {
    draw_series(out, axes, run.time, run.error_3d, kColours[0]);
    draw_series(out, axes, run.time, run.error_2d, kColours[1]);
  }
  if (first != nullptr) draw_series(out, axes, first->time, first->true_error, kColours[2]);
  if (cloud) draw_cloud_panel(out, *first, top + kPlotHeight + kBottom);
  out << "</svg>\n";
  return out.str();
}

}  // namespace rodshape
