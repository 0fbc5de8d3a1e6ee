// plan_svg.cpp (figures): plan.svg, a picture of the plan that any browser shows: three
// orthographic projections (x–z, y–z, x–y) side by side at one common scale (a metre is as long in
// every panel and along both axes), so that lengths and angles can be compared between views. Plain
// SVG 1.1, written by hand: no dependency, no script, no external font or style sheet.
#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "figures/svg_drawing.hpp"
#include "overloaded.hpp"
#include "rodshape/figures/figures.hpp"

namespace rodshape {

namespace {

using figures::escaped;
using figures::step_colour;
using figures::tick_label;
using figures::tick_spacing;

/// A number as SVG wants it: fixed, two decimals (0.01 px).
std::string px(double value) { return figures::fixed(value, 2); }

// Layout, px.
constexpr double kPanel = 330.0;      // side of a panel's square plot area
constexpr double kLeft = 70.0;        // left margin (tick labels of the first panel)
constexpr double kGap = 85.0;         // between panels (the next panel's tick labels)
constexpr double kCaptionGap = 26.0;  // from the title's last line to a panel's top (caption)
constexpr double kLegendHeight = 96.0;
constexpr double kWidth = kLeft + 3 * kPanel + 2 * kGap + 45.0;
constexpr double kBelowPanels = 45.0 + kLegendHeight;

const char* const kInitialColour = "#9a9a9a";
const char* const kBasePathColour = "#3b3b3b";  // the base gripper's path (a moving base)
const char* const kTargetColour = "#d62728";

/// One projection: world axes (h, v) onto a panel's plot area.
struct Panel {
  int h = 0, v = 2;          // world axis drawn across and up
  double left = 0, top = 0;  // plot area's corner, px
  const char* caption = "";
};

/// The common view: per world axis the lower end of its range; one scale for all.
struct View {
  Eigen::Vector3d lower = Eigen::Vector3d::Zero();
  double range = 1.0;  // m, the same along every axis
  double scale() const { return kPanel / range; }
};

View fit_view(const std::vector<Eigen::Vector3d>& points) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (const Eigen::Vector3d& p : points) {
    if (!p.allFinite()) continue;
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  if (!(lo.array() <= hi.array()).all()) lo = hi = Eigen::Vector3d::Zero();
  const double span = std::max((hi - lo).maxCoeff(), 1e-3);
  View view;
  view.range = 1.12 * span;  // 6% margin on each side of the widest axis
  view.lower = 0.5 * (lo + hi) - Eigen::Vector3d::Constant(0.5 * view.range);
  return view;
}

class Canvas {
 public:
  explicit Canvas(const View& view) : view_(view) {}

  double x(const Panel& panel, const Eigen::Vector3d& p) const {
    return panel.left + (p[panel.h] - view_.lower[panel.h]) * view_.scale();
  }
  double y(const Panel& panel, const Eigen::Vector3d& p) const {
    return panel.top + kPanel - (p[panel.v] - view_.lower[panel.v]) * view_.scale();
  }

  void frame(const Panel& panel, int index) {
    static const char* const kAxisNames[3] = {"x", "y", "z"};
    const double spacing = tick_spacing(view_.range, 8);
    out_ << "<g font-family=\"sans-serif\" font-size=\"11\" fill=\"#333\">\n";
    out_ << "<text x=\"" << px(panel.left + kPanel / 2) << "\" y=\"" << px(panel.top - 10)
         << "\" text-anchor=\"middle\" font-size=\"13\" font-weight=\"bold\">" << panel.caption
         << "</text>\n";
    out_ << "<rect x=\"" << px(panel.left) << "\" y=\"" << px(panel.top) << "\" width=\""
         << px(kPanel) << "\" height=\"" << px(kPanel)
         << "\" fill=\"#fcfcfc\" stroke=\"#444\" stroke-width=\"1\"/>\n";
    for (const int axis : {panel.h, panel.v}) {
      const double lower = view_.lower[axis];
      for (double tick = std::ceil(lower / spacing) * spacing; tick <= lower + view_.range;
           tick += spacing) {
        const double offset = (tick - lower) * view_.scale();
        const std::string label = tick_label(tick, spacing);
        if (axis == panel.h) {
          const double at = panel.left + offset;
          out_ << "<line x1=\"" << px(at) << "\" y1=\"" << px(panel.top) << "\" x2=\"" << px(at)
               << "\" y2=\"" << px(panel.top + kPanel) << "\" stroke=\"#e2e2e2\"/>\n";
          out_ << "<text x=\"" << px(at) << "\" y=\"" << px(panel.top + kPanel + 15)
               << "\" text-anchor=\"middle\">" << label << "</text>\n";
        } else {
          const double at = panel.top + kPanel - offset;
          out_ << "<line x1=\"" << px(panel.left) << "\" y1=\"" << px(at) << "\" x2=\""
               << px(panel.left + kPanel) << "\" y2=\"" << px(at) << "\" stroke=\"#e2e2e2\"/>\n";
          out_ << "<text x=\"" << px(panel.left - 5) << "\" y=\"" << px(at + 4)
               << "\" text-anchor=\"end\">" << label << "</text>\n";
        }
      }
    }
    out_ << "<text x=\"" << px(panel.left + kPanel / 2) << "\" y=\"" << px(panel.top + kPanel + 32)
         << "\" text-anchor=\"middle\">" << kAxisNames[panel.h] << " [m]</text>\n";
    const double label_x = panel.left - 48, label_y = panel.top + kPanel / 2;
    out_ << "<text x=\"" << px(label_x) << "\" y=\"" << px(label_y)
         << "\" text-anchor=\"middle\" transform=\"rotate(-90 " << px(label_x) << ' ' << px(label_y)
         << ")\">" << kAxisNames[panel.v] << " [m]</text>\n";
    out_ << "</g>\n";
    out_ << "<clipPath id=\"panel" << index << "\"><rect x=\"" << px(panel.left) << "\" y=\""
         << px(panel.top) << "\" width=\"" << px(kPanel) << "\" height=\"" << px(kPanel)
         << "\"/></clipPath>\n";
  }

  void polyline(const Panel& panel,
                const std::vector<Eigen::Vector3d>& points,
                const std::string& colour,
                double width,
                const char* extra = "") {
    if (points.empty()) return;
    out_ << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"" << width
         << "\" stroke-linejoin=\"round\" stroke-linecap=\"round\"" << extra << " points=\"";
    for (const Eigen::Vector3d& p : points)
      out_ << px(x(panel, p)) << ',' << px(y(panel, p)) << ' ';
    out_ << "\"/>\n";
  }

  void dots(const Panel& panel,
            const std::vector<Eigen::Vector3d>& points,
            const std::string& colour,
            double radius) {
    for (const Eigen::Vector3d& p : points) {
      out_ << "<circle cx=\"" << px(x(panel, p)) << "\" cy=\"" << px(y(panel, p)) << "\" r=\""
           << radius << "\" fill=\"" << colour << "\"/>\n";
    }
  }

  void crosses(const Panel& panel, const std::vector<Eigen::Vector3d>& points) {
    for (const Eigen::Vector3d& p : points) cross(x(panel, p), y(panel, p));
  }

  void cross(double cx, double cy) {
    constexpr double r = 4.5;
    out_ << "<path d=\"M" << px(cx - r) << ',' << px(cy - r) << "L" << px(cx + r) << ','
         << px(cy + r) << "M" << px(cx - r) << ',' << px(cy + r) << "L" << px(cx + r) << ','
         << px(cy - r) << "\" stroke=\"" << kTargetColour << "\" stroke-width=\"2\"/>\n";
  }

  void clamp(const Panel& panel, const Eigen::Vector3d& p) { square(x(panel, p), y(panel, p)); }

  void square(double cx, double cy) {
    out_ << "<rect x=\"" << px(cx - 4) << "\" y=\"" << px(cy - 4)
         << "\" width=\"8\" height=\"8\" fill=\"#222\"/>\n";
  }

  /// A moving base's pose at a step: a small square in the step's colour, outlined.
  void base_mark(const Panel& panel, const Eigen::Vector3d& p, const std::string& colour) {
    const double cx = x(panel, p), cy = y(panel, p);
    out_ << "<rect x=\"" << px(cx - 3) << "\" y=\"" << px(cy - 3)
         << "\" width=\"6\" height=\"6\" fill=\"" << colour
         << "\" stroke=\"#222\" stroke-width=\"0.8\"/>\n";
  }

  /// An obstacle's orthographic projection, grey: a disc, a stadium (a capsule: a line as thick as
  /// its diameter, round caps), a box's six faces, or a half-space's solid side where its plane is
  /// seen edge-on (a tilted plane covers the whole panel: not drawn).
  void obstacle(const Panel& panel, const Obstacle& obstacle) {
    const double scale = view_.scale();
    std::visit(detail::Overloaded{[&](const SphereObstacle& s) {
                                    out_ << "<circle cx=\"" << px(x(panel, s.center)) << "\" cy=\""
                                         << px(y(panel, s.center)) << "\" r=\""
                                         << px(s.radius * scale) << "\"" << kObstacleStyle
                                         << "/>\n";
                                  },
                                  [&](const CapsuleObstacle& c) {
                                    out_ << "<line x1=\"" << px(x(panel, c.from)) << "\" y1=\""
                                         << px(y(panel, c.from)) << "\" x2=\"" << px(x(panel, c.to))
                                         << "\" y2=\"" << px(y(panel, c.to)) << "\" stroke=\""
                                         << kObstacleColour << "\" stroke-opacity=\"0.45\" "
                                         << "stroke-linecap=\"round\" stroke-width=\""
                                         << px(2 * c.radius * scale) << "\"/>\n";
                                  },
                                  [&](const BoxObstacle& b) { box(panel, b); },
                                  [&](const HalfSpaceObstacle& h) { half_space(panel, h); }},
               obstacle.shape);
  }

  std::ostringstream& out() { return out_; }

 private:
  static constexpr const char* kObstacleColour = "#8a8f98";
  static constexpr const char* kObstacleStyle =
      " fill=\"#8a8f98\" fill-opacity=\"0.35\" stroke=\"#5d626b\" stroke-width=\"1\"";

  void polygon(const std::vector<Eigen::Vector2d>& corners) {
    out_ << "<polygon points=\"";
    for (const Eigen::Vector2d& c : corners) out_ << px(c.x()) << ',' << px(c.y()) << ' ';
    out_ << "\"" << kObstacleStyle << "/>\n";
  }

  void box(const Panel& panel, const BoxObstacle& b) {
    // Face k = ±1 along axis a: its four corners, the other two axes' signs in cyclic order.
    for (int a = 0; a < 3; ++a) {
      for (const double side : {-1.0, 1.0}) {
        std::vector<Eigen::Vector2d> corners;
        const int u = (a + 1) % 3, v = (a + 2) % 3;
        for (const auto& [su, sv] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}}) {
          Eigen::Vector3d local = Eigen::Vector3d::Zero();
          local[a] = side;
          local[u] = su;
          local[v] = sv;
          const Eigen::Vector3d p = b.center + b.rotation * (0.5 * b.size.cwiseProduct(local));
          corners.emplace_back(x(panel, p), y(panel, p));
        }
        polygon(corners);
      }
    }
  }

  void half_space(const Panel& panel, const HalfSpaceObstacle& h) {
    const int view_axis = 3 - panel.h - panel.v;
    if (std::abs(h.normal[view_axis]) > 1e-9 * h.normal.norm()) return;
    // The panel's square in world coordinates, clipped to the solid side nᵀp ≥ offset.
    const double lo_h = view_.lower[panel.h], lo_v = view_.lower[panel.v], r = view_.range;
    const std::vector<Eigen::Vector2d> square{
        {lo_h, lo_v}, {lo_h + r, lo_v}, {lo_h + r, lo_v + r}, {lo_h, lo_v + r}};
    const auto solid = [&](const Eigen::Vector2d& q) {
      return h.normal[panel.h] * q.x() + h.normal[panel.v] * q.y() - h.offset;
    };
    std::vector<Eigen::Vector2d> clipped;
    for (std::size_t i = 0; i < square.size(); ++i) {
      const Eigen::Vector2d& a = square[i];
      const Eigen::Vector2d& b = square[(i + 1) % square.size()];
      const double fa = solid(a), fb = solid(b);
      if (fa >= 0.0) clipped.push_back(a);
      if ((fa >= 0.0) != (fb >= 0.0)) clipped.push_back(a + (fa / (fa - fb)) * (b - a));
    }
    if (clipped.size() < 3) return;
    std::vector<Eigen::Vector2d> corners;
    for (const Eigen::Vector2d& q : clipped) {
      Eigen::Vector3d p = Eigen::Vector3d::Zero();
      p[panel.h] = q.x();
      p[panel.v] = q.y();
      corners.emplace_back(x(panel, p), y(panel, p));
    }
    polygon(corners);
  }

  View view_;
  std::ostringstream out_;
};

std::string millimetres(double metres) {
  std::ostringstream out;
  out << std::setprecision(3) << metres * 1e3 << " mm";
  return out.str();
}

/// The base gripper's path (a moving base, issue 21): the timed path's positions, or, before it
/// is timed (a partial plan), the start and each step's base gripper. Empty with a fixed clamp.
std::vector<Eigen::Vector3d> base_path_points(const PlanResult& plan, const PlanProblem& request) {
  std::vector<Eigen::Vector3d> points;
  if (!request.base_moves()) return points;
  if (!plan.base_end_effector_path.empty()) {
    for (const TimedPose& sample : plan.base_end_effector_path)
      points.push_back(sample.pose.position);
    return points;
  }
  if (plan.initial_configuration.nodes() > 0)
    points.push_back(compose(Pose{plan.initial_configuration.p[0], plan.initial_configuration.R[0]},
                             request.moving_base->grasp.tip_to_end_effector)
                         .position);
  for (const PlanStep& step : plan.steps) points.push_back(step.base_end_effector.position);
  return points;
}

/// Everything drawn decides the view.
std::vector<Eigen::Vector3d> drawn_points(const PlanResult& plan, const PlanProblem& request) {
  std::vector<Eigen::Vector3d> all = request.target.points;
  const std::vector<Eigen::Vector3d> base_path = base_path_points(plan, request);
  all.insert(all.end(), base_path.begin(), base_path.end());
  all.push_back(request.rod.clamp.position);
  all.insert(all.end(), plan.initial_configuration.p.begin(), plan.initial_configuration.p.end());
  for (const PlanStep& step : plan.steps) {
    all.insert(all.end(), step.solution.configuration.p.begin(),
               step.solution.configuration.p.end());
    all.insert(all.end(), step.objective_points.begin(), step.objective_points.end());
  }
  return all;
}

/// Title: what, and how it went, wrapped to the figure's width. Returns the y of its last line.
double draw_title(std::ostringstream& out, const PlanResult& plan, const FigureCaption& caption) {
  const int n = static_cast<int>(plan.steps.size());
  std::ostringstream title, details;
  title << "rodshape plan: " << caption.source << " \u2014 " << to_string(plan.status) << ", " << n
        << " steps (" << caption.steps_requested << " requested";
  if (plan.tracking.refinements > 0) title << ", " << plan.tracking.refinements << " inserted";
  const auto detours = std::count_if(plan.steps.begin(), plan.steps.end(),
                                     [](const PlanStep& step) { return step.detour; });
  if (detours > 0) title << ", " << detours << " on a detour";
  title << ")";
  if (n > 0) {
    const ShapeResult& last = plan.steps.back().solution;
    details << "final max distance " << millimetres(last.cost.max_distance) << ", energy "
            << std::setprecision(3) << last.cost.energy << " J";
  }
  if (plan.tracking.performed)
    details << "; tracked peak energy " << std::setprecision(3) << plan.tracking.peak_energy
            << " J";
  if (plan.scene && std::isfinite(plan.scene->min_gap))
    details << "; least gap to the scene " << millimetres(plan.scene->min_gap) << " (obstacle "
            << plan.scene->obstacle_label << ", clearance " << millimetres(plan.scene->clearance)
            << ")";
  const double left = kLeft - 40, width = kWidth - left - 20;
  double y = 22;
  const auto lines = [&](const std::string& text, double size, const char* style) {
    for (const std::string& line : figures::wrapped(text, figures::characters_in(width, size))) {
      out << "<text x=\"" << px(left) << "\" y=\"" << px(y) << "\" font-family=\"sans-serif\" "
          << "font-size=\"" << size << "\" " << style << ">" << escaped(line) << "</text>\n";
      y += size + 4;
    }
  };
  lines(title.str(), 15, "font-weight=\"bold\" fill=\"#111\"");
  lines(details.str(), 12, "fill=\"#333\"");
  if (plan.status != PlanStatus::Complete)
    lines(plan.message, 12, (std::string("fill=\"") + kTargetColour + "\"").c_str());
  return y;
}

/// Three orthographic projections: the initial rod, every step's rod and objective points, the
/// target points and the clamp (with a moving base: where the base starts, the base gripper's
/// path and the base at each step).
void draw_panels(Canvas& canvas, const PlanResult& plan, const PlanProblem& request, double top) {
  std::ostringstream& out = canvas.out();
  const int n = static_cast<int>(plan.steps.size());
  const std::vector<Eigen::Vector3d> base_path = base_path_points(plan, request);
  const std::array<Panel, 3> panels = {{
      {0, 2, kLeft, top, "front: x\u2013z"},
      {1, 2, kLeft + kPanel + kGap, top, "side: y\u2013z"},
      {0, 1, kLeft + 2 * (kPanel + kGap), top, "top: x\u2013y"},
  }};
  for (std::size_t k = 0; k < panels.size(); ++k) {
    const Panel& panel = panels[k];
    canvas.frame(panel, static_cast<int>(k));
    out << "<g clip-path=\"url(#panel" << k << ")\">\n";
    for (const Obstacle& obstacle : request.scene.obstacles) canvas.obstacle(panel, obstacle);
    canvas.polyline(panel, plan.initial_configuration.p, kInitialColour, 2.0,
                    " stroke-dasharray=\"6 3\"");
    for (int i = 0; i < n; ++i) {
      const bool last = i == n - 1;
      canvas.polyline(panel, plan.steps[i].solution.configuration.p, step_colour(i, n),
                      last ? 3.5 : 1.3, last ? "" : " stroke-opacity=\"0.85\"");
    }
    for (int i = 0; i + 1 < n; ++i)
      canvas.dots(panel, plan.steps[i].objective_points, step_colour(i, n), 1.8);
    canvas.crosses(panel, request.target.points);
    canvas.clamp(panel, request.rod.clamp.position);
    if (request.base_moves()) {
      canvas.polyline(panel, base_path, kBasePathColour, 1.5, " stroke-dasharray=\"2 3\"");
      for (int i = 0; i < n; ++i)
        canvas.base_mark(panel, plan.steps[i].solution.configuration.p.front(), step_colour(i, n));
    }
    out << "</g>\n";
  }
}

void draw_legend(Canvas& canvas, int n, bool scene, bool base_moves, double panels_top) {
  std::ostringstream& out = canvas.out();
  const double top = panels_top + kPanel + 52;
  const double left = kLeft;
  out << "<g font-family=\"sans-serif\" font-size=\"12\" fill=\"#222\">\n";
  out << "<line x1=\"" << px(left) << "\" y1=\"" << px(top) << "\" x2=\"" << px(left + 30)
      << "\" y2=\"" << px(top) << "\" stroke=\"" << kInitialColour
      << "\" stroke-width=\"2\" stroke-dasharray=\"6 3\"/>\n";
  out << "<text x=\"" << px(left + 38) << "\" y=\"" << px(top + 4) << "\">initial rod</text>\n";
  const double ramp_left = left + 170;
  for (int i = 0; i < n; ++i) {
    out << "<rect x=\"" << px(ramp_left + i * 14) << "\" y=\"" << px(top - 5)
        << "\" width=\"14\" height=\"10\" fill=\"" << step_colour(i, n) << "\"/>\n";
  }
  if (n > 0) {
    out << "<text x=\"" << px(ramp_left + n * 14 + 8) << "\" y=\"" << px(top + 4)
        << "\">rod at steps 1 \u2026 " << n
        << " (thin), with their objective points (dots)</text>\n";
  } else {
    out << "<text x=\"" << px(ramp_left) << "\" y=\"" << px(top + 4)
        << "\">no step succeeded</text>\n";
  }
  const double row2 = top + 24;
  if (n > 0) {
    out << "<line x1=\"" << px(left) << "\" y1=\"" << px(row2) << "\" x2=\"" << px(left + 30)
        << "\" y2=\"" << px(row2) << "\" stroke=\"" << step_colour(n - 1, n)
        << "\" stroke-width=\"3.5\"/>\n";
    out << "<text x=\"" << px(left + 38) << "\" y=\"" << px(row2 + 4) << "\">final rod (step " << n
        << ")</text>\n";
  }
  canvas.cross(ramp_left + 7, row2);
  out << "<text x=\"" << px(ramp_left + 20) << "\" y=\"" << px(row2 + 4)
      << "\">target points p_obj</text>\n";
  canvas.square(ramp_left + 187, row2);
  out << "<text x=\"" << px(ramp_left + 200) << "\" y=\"" << px(row2 + 4) << "\">"
      << (base_moves ? "base p(0) at the start" : "clamp p(0)") << "</text>\n";
  if (base_moves) {
    const double base_left = ramp_left + 360;
    out << "<line x1=\"" << px(base_left) << "\" y1=\"" << px(row2) << "\" x2=\""
        << px(base_left + 30) << "\" y2=\"" << px(row2) << "\" stroke=\"" << kBasePathColour
        << "\" stroke-width=\"1.5\" stroke-dasharray=\"2 3\"/>\n";
    out << "<text x=\"" << px(base_left + 38) << "\" y=\"" << px(row2 + 4)
        << "\">base gripper's path; the base p(0) at each step (small squares)</text>\n";
  }
  const double row3 = row2 + 24;
  out << "<text x=\"" << px(left) << "\" y=\"" << px(row3 + 4) << "\" fill=\"#555\">"
      << "Orthographic projections, one scale in all panels; grid and labels in metres"
      << (scene ? "; the scene's obstacles in grey (a half-space where its plane is seen edge-on)"
                : "")
      << ".</text>\n";
  out << "</g>\n";
}

}  // namespace

std::string plan_svg(const PlanResult& plan,
                     const PlanProblem& problem,
                     const FigureCaption& caption) {
  Canvas canvas(fit_view(drawn_points(plan, problem)));
  std::ostringstream title;
  const double top = draw_title(title, plan, caption) + kCaptionGap;
  const double height = top + kPanel + kBelowPanels;
  std::ostringstream& out = canvas.out();
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" << svg_signature_comment() << '\n';
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" << px(kWidth)
      << "\" height=\"" << px(height) << "\" viewBox=\"0 0 " << px(kWidth) << ' ' << px(height)
      << "\">\n";
  out << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  out << title.str();
  draw_panels(canvas, plan, problem, top);
  draw_legend(canvas, static_cast<int>(plan.steps.size()), !problem.scene.empty(),
              problem.base_moves(), top);
  out << "</svg>\n";
  return out.str();
}

}  // namespace rodshape
