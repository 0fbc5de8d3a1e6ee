// validation_files.cpp: validation.csv, validation.svg and the files `rodshape validate` writes
// (validation_output.hpp).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>

#include "rodshape/error.hpp"
#include "rodshape/io/atomic_file.hpp"
#include "rodshape/io/output_files.hpp"
#include "rodshape/io/validation_output.hpp"

namespace rodshape {

namespace {

// Layout of the figure, px.
constexpr double kWidth = 760.0, kHeight = 420.0;
constexpr double kLeft = 70.0, kRight = 20.0, kTop = 40.0, kBottom = 50.0;
const char* const kColours[3] = {"#1f77b4", "#ff7f0e", "#2ca02c"};  // 3D, 2D, true

std::string fixed(double value, int digits) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(digits) << value;
  return out.str();
}

/// The plot's scale: time (s) across, error (mm) up, from 0 to the largest value.
struct Axes {
  double t_max = 1.0, e_max = 1.0;
  double x(double t) const { return kLeft + (kWidth - kLeft - kRight) * t / t_max; }
  double y(double e_mm) const {
    return kHeight - kBottom - (kHeight - kTop - kBottom) * e_mm / e_max;
  }
};

Axes fit_axes(const ValidationResult& result) {
  Axes axes;
  for (const ValidationRun& run : result.runs) {
    if (!run.time.empty()) axes.t_max = std::max(axes.t_max, run.time.back());
    for (const auto* series : {&run.error_3d, &run.error_2d, &run.true_error})
      for (double e : *series)
        if (std::isfinite(e)) axes.e_max = std::max(axes.e_max, 1e3 * e);
  }
  axes.e_max *= 1.05;
  return axes;
}

void draw_grid(std::ostringstream& out, const Axes& axes) {
  for (int k = 0; k <= 5; ++k) {
    const double t = axes.t_max * k / 5, e = axes.e_max * k / 5;
    out << "<line x1=\"" << fixed(axes.x(t), 2) << "\" y1=\"" << fixed(axes.y(0), 2) << "\" x2=\""
        << fixed(axes.x(t), 2) << "\" y2=\"" << fixed(axes.y(axes.e_max), 2)
        << "\" stroke=\"#ddd\"/>\n<text x=\"" << fixed(axes.x(t), 2) << "\" y=\""
        << fixed(kHeight - kBottom + 18, 2) << "\" text-anchor=\"middle\">" << fixed(t, 1)
        << "</text>\n";
    out << "<line x1=\"" << fixed(axes.x(0), 2) << "\" y1=\"" << fixed(axes.y(e), 2) << "\" x2=\""
        << fixed(axes.x(axes.t_max), 2) << "\" y2=\"" << fixed(axes.y(e), 2)
        << "\" stroke=\"#ddd\"/>\n<text x=\"" << fixed(kLeft - 8, 2) << "\" y=\""
        << fixed(axes.y(e) + 4, 2) << "\" text-anchor=\"end\">" << fixed(e, 1) << "</text>\n";
  }
  out << "<text x=\"" << fixed(kWidth / 2, 2) << "\" y=\"" << fixed(kHeight - 12, 2)
      << "\" text-anchor=\"middle\">time (s)</text>\n<text x=\"16\" y=\"" << fixed(kHeight / 2, 2)
      << "\" transform=\"rotate(-90 16 " << fixed(kHeight / 2, 2)
      << ")\" text-anchor=\"middle\">error (mm)</text>\n";
}

void draw_series(std::ostringstream& out,
                 const Axes& axes,
                 const std::vector<double>& t,
                 const std::vector<double>& e,
                 const char* colour) {
  out << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"1.2\" points=\"";
  for (std::size_t k = 0; k < t.size(); ++k)
    if (std::isfinite(e[k]))
      out << fixed(axes.x(t[k]), 2) << ',' << fixed(axes.y(1e3 * e[k]), 2) << ' ';
  out << "\"/>\n";
}

}  // namespace

std::string validation_csv(const ValidationResult& result) {
  std::ostringstream out;
  out << "run,seed,t,error_3d,error_2d,true_error,visible_markers\n" << std::setprecision(17);
  for (std::size_t r = 0; r < result.runs.size(); ++r) {
    const ValidationRun& run = result.runs[r];
    for (std::size_t k = 0; k < run.time.size(); ++k)
      out << r + 1 << ',' << run.seed << ',' << run.time[k] << ',' << run.error_3d[k] << ','
          << run.error_2d[k] << ',' << run.true_error[k] << ',' << run.visible_markers[k] << '\n';
  }
  return out.str();
}

std::string validation_svg(const ValidationResult& result) {
  const Axes axes = fit_axes(result);
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << svg_signature_comment()
      << "\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
         "version=\"1.1\" width=\""
      << kWidth << "\" height=\"" << kHeight << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<text x=\"" << kLeft
      << "\" y=\"22\" font-size=\"14\">Mean distance to the objective points: 3D (blue), 2D in "
         "the image plane (orange), true (green); "
      << result.runs.size() << (result.runs.size() == 1 ? " run" : " runs") << "</text>\n";
  draw_grid(out, axes);
  for (const ValidationRun& run : result.runs) {
    draw_series(out, axes, run.time, run.error_3d, kColours[0]);
    draw_series(out, axes, run.time, run.error_2d, kColours[1]);
  }
  if (!result.runs.empty())
    draw_series(out, axes, result.runs.front().time, result.runs.front().true_error, kColours[2]);
  out << "</svg>\n";
  return out.str();
}

const std::vector<std::string>& validation_file_names() {
  static const std::vector<std::string> names = {"validation.json", "validation.csv",
                                                 "validation.svg"};
  return names;
}

std::vector<std::string> write_validation(const std::string& directory,
                                          const ValidationResult& result,
                                          const PlanResult& plan,
                                          const PlanTask& task) {
  namespace fs = std::filesystem;
  std::error_code error;
  fs::create_directories(directory, error);
  if (error || !fs::is_directory(directory, error))
    throw InputError(directory + ": cannot create the output directory");
  std::vector<std::string> written;
  const auto write = [&](const char* name, const std::string& content) {
    write_file_atomically((fs::path(directory) / name).string(), content);
    written.push_back(name);
  };
  write("validation.json", validation_json(result, plan, task));
  write("validation.csv", validation_csv(result));
  write("validation.svg", validation_svg(result));
  return written;
}

}  // namespace rodshape
