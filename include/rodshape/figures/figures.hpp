// figures.hpp: the pictures of a plan and of its validation, as whole texts: plan.svg and
// validation.svg (plain SVG 1.1, no script) and plan.html and validation.html (one self-contained
// page each: an orbitable 3D view made with three.js, inlined from Debian's libjs-three when the
// page is written; the page's own code is src/figures/page/rodshape_view.js). The figures area
// sits below io, whose writers (write_plan, write_validation) call it and write the files; it
// knows nothing of task files. docs/figures.md describes the pages.
#pragma once

#include <optional>
#include <string>

#include "rodshape/sim/plan_validation.hpp"
#include "rodshape/trajectory/plan_problem.hpp"
#include "rodshape/trajectory/plan_result.hpp"

namespace rodshape {

/// What a figure says of where the plan came from: the task file (or any name) and the number of
/// steps that were asked for (PlanOptions::steps).
struct FigureCaption {
  std::string source;
  int steps_requested = 0;
};

/// The comment every SVG and HTML page rodshape writes has near its start (after the XML
/// declaration, or the HTML doctype): "<!-- generator: rodshape <version> -->".
std::string svg_signature_comment();

/// A self-contained SVG picture of the plan: three projections (x–z, y–z, x–y) at one common
/// scale, with grids labelled in metres; the initial rod (grey), each step's rod (a colour ramp
/// from the first step to the last, the last drawn thick), each step's objective points (small dots
/// of the step's colour), the target points (red ×), the scene's obstacles and a legend. The title
/// and the summary are wrapped to the figure's width.
std::string plan_svg(const PlanResult& plan,
                     const PlanProblem& problem,
                     const FigureCaption& caption);

/// A self-contained SVG: the 3D, 2D and true errors (mm) over time (s) of every run, on a
/// logarithmic error axis (0.01 mm … the largest error), so that the final stretch reads.
std::string validation_svg(const ValidationResult& result);

/// three.js, as the page inlines it: the library (three.min.js) and its OrbitControls (a plain
/// script, examples/js/controls/OrbitControls.js), read from `directory`.
struct PageLibrary {
  std::string directory;
  std::string three;
  std::string orbit_controls;
};
/// Where the page's three.js is read from: $RODSHAPE_THREE_JS_DIR when set, else Debian's
/// libjs-three, /usr/share/javascript/three.
std::string page_library_directory();
/// The library read from page_library_directory(), or nullopt when a file is missing or cannot be
/// read; then `why` (when given) says which and what to install.
std::optional<PageLibrary> load_page_library(std::string* why = nullptr);

/// Caps on what a page holds, so that it stays a few MB at the largest plans (docs/limits.md):
/// keyframes of the rod's shape (the initial rod and the steps), samples of the arm's joint
/// trajectory and of the end-effector path, nodes per shape. Beyond a cap they are decimated
/// evenly, the first and the last kept.
inline constexpr int kPageMaxShapes = 300;
inline constexpr int kPageMaxArmSamples = 300;
inline constexpr int kPageMaxPathSamples = 1000;
inline constexpr int kPageMaxNodes = 200;

/// plan.html: the rod as a tube (the section's circumscribed radius) moving through its steps
/// along the timed end-effector path (the shape between two waypoints interpolated node by node
/// between the two steps' shapes), with a time slider and play/pause; the initial and final
/// shapes, every step's shape and objective points, the target points, the end-effector path, the
/// arm's links between its joint frames (computed here from the joint trajectory), the scene's
/// obstacles, the workspace box, the plan's summary and its energy along time. Test hooks:
/// window.rodshape.setTime(t), window.rodshape.state().
std::string plan_html(const PlanResult& plan,
                      const PlanProblem& problem,
                      const FigureCaption& caption,
                      const PageLibrary& library);

/// validation.html: plan.html's view and, for a run chosen in a selector, the plant's last
/// equilibrium beside the planned final shape, the markers the sensor saw at the last frame, the
/// errors over time (linked to the slider) and the checkpoints (closed loop) on the time axis.
std::string validation_html(const ValidationResult& result,
                            const PlanResult& plan,
                            const PlanProblem& problem,
                            const FigureCaption& caption,
                            const PageLibrary& library);

}  // namespace rodshape
