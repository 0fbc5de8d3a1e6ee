// test_figures.cpp: the figures area: the shared SVG helpers (wrapping, ticks), plan.svg's wrapped
// title, validation.svg's decade ticks, the HTML page (signature, data, caps, script-safe),
// three.js missing, and write_plan() with and without the page. The page in a browser:
// tests/figures/check_pages.py (.ci/run, step 3b).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>

#include "figures/svg_drawing.hpp"
#include "rodshape/figures/figures.hpp"
#include "rodshape/io/output_files.hpp"
#include "rodshape/io/plan_output.hpp"
#include "rodshape/io/task_reader.hpp"
#include "support/hand_made_plan.hpp"

namespace rodshape {
namespace test_figures {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

/// Sets an environment variable for a scope.
class ScopedEnvironment {
 public:
  ScopedEnvironment(const char* name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    ::setenv(name, value.c_str(), 1);
  }
  ~ScopedEnvironment() {
    if (old_)
      ::setenv(name_, old_->c_str(), 1);
    else
      ::unsetenv(name_);
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

fs::path fresh_directory(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("rodshape_figures_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The page's data: the JSON in <script id="rodshape-data">.
Json page_data(const std::string& html) {
  const std::string open = "<script type=\"application/json\" id=\"rodshape-data\">\n";
  const std::size_t from = html.find(open);
  EXPECT_NE(from, std::string::npos);
  const std::size_t to = html.find("\n</script>", from);
  std::string text = html.substr(from + open.size(), to - from - open.size());
  return Json::parse(std::regex_replace(text, std::regex("<\\\\/"), "</"));
}

/// A stand-in for libjs-three: two small scripts that define what the page uses.
fs::path fake_three(const std::string& name) {
  const fs::path d = fresh_directory(name);
  fs::create_directories(d / "examples/js/controls");
  std::ofstream(d / "three.min.js") << "window.THREE = {}; // </script> inside\n";
  std::ofstream(d / "examples/js/controls/OrbitControls.js") << "THREE.OrbitControls = 1;\n";
  return d;
}

TEST(SvgDrawing, WrapsAtSpacesAndCutsLongWords) {
  const auto lines = figures::wrapped("one two three four five", 9);
  EXPECT_EQ(lines, (std::vector<std::string>{"one two", "three", "four five"}));
  const auto cut = figures::wrapped("abcdefghijkl xy", 5);
  EXPECT_EQ(cut, (std::vector<std::string>{"abcde", "fghij", "kl xy"}));
  // Counted in characters, not bytes: "—" is one.
  EXPECT_EQ(figures::wrapped("a \u2014 b", 5).size(), 1u);
  EXPECT_TRUE(figures::wrapped("", 5).empty());
}

TEST(SvgDrawing, TicksAreRound) {
  EXPECT_DOUBLE_EQ(figures::tick_spacing(1.0, 5), 0.2);
  EXPECT_DOUBLE_EQ(figures::tick_spacing(7.3, 6), 2.0);
  EXPECT_EQ(figures::tick_label(0.30000000000000004, 0.1), "0.3");
  EXPECT_EQ(figures::tick_label(-1e-17, 0.1), "0.0");
}

TEST(PlanSvg, ALongTitleIsWrappedWithinTheFigure) {
  const PlanTask task = parse_plan_task(testing::kHandMadeTask, "plan.yaml");
  const PlanResult plan = testing::make_plan(task, 3);
  const FigureCaption caption{std::string(150, 'x') + " very/long/path/of/a/task.yaml", 3};
  const std::string svg = plan_svg(plan, task.problem, caption);
  // The width, and every text line within it at its font size.
  std::smatch width;
  ASSERT_TRUE(std::regex_search(svg, width, std::regex("width=\"([0-9.]+)\"")));
  const double figure_width = std::stod(width[1]);
  const std::regex text("<text x=\"([0-9.]+)\"[^>]*font-size=\"([0-9.]+)\"[^>]*>([^<]*)</text>");
  int title_lines = 0;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), text); it != std::sregex_iterator();
       ++it) {
    const double x = std::stod((*it)[1]), size = std::stod((*it)[2]);
    const std::string line = (*it)[3];
    if (size < 12) continue;  // tick labels
    EXPECT_LE(x + 0.55 * size * static_cast<double>(line.size()), figure_width + 1) << line;
    if (size == 15) ++title_lines;
  }
  EXPECT_GE(title_lines, 2);
}

TEST(ValidationSvg, ErrorsOnALogAxisWithDecadeTicks) {
  ValidationResult result;
  result.status = ValidationStatus::Complete;
  ValidationRun run;
  for (int k = 0; k <= 100; ++k) {
    run.time.push_back(0.073 * k);
    run.error_3d.push_back(0.02 * std::exp(-0.05 * k));  // 20 mm down to 0.13 mm
    run.error_2d.push_back(0.5 * run.error_3d.back());
    run.true_error.push_back(0.0003);
    run.visible_markers.push_back(5);
  }
  run.final = {run.error_3d.back(), run.error_2d.back(), 0.0003, 0.0004, 5};
  result.runs.push_back(run);
  const std::string svg = validation_svg(result);
  EXPECT_NE(svg.find("log scale"), std::string::npos);
  for (const char* label : {">0.1<", ">1<", ">10<", ">100<"})
    EXPECT_NE(svg.find(label), std::string::npos) << label;
  EXPECT_NE(svg.find("final 0.3 mm"), std::string::npos);  // the true error, in the legend
  // Time ticks are round: 0, 2, 4, 6 s over 7.3 s.
  EXPECT_NE(svg.find(">6<"), std::string::npos);
  EXPECT_EQ(svg.find(">1.5<"), std::string::npos);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
}

TEST(PlanHtml, OnePageWithTheSignatureAndTheData) {
  const PlanTask task = parse_plan_task(testing::kHandMadeTask, "a</script>b.yaml");
  const PlanResult plan = testing::make_plan(task, 3);
  const ScopedEnvironment three("RODSHAPE_THREE_JS_DIR", fake_three("page").string());
  std::string why;
  const std::optional<PageLibrary> library = load_page_library(&why);
  ASSERT_TRUE(library) << why;
  const std::string html = plan_html(plan, task.problem, figure_caption(task), *library);
  EXPECT_EQ(html.rfind("<!DOCTYPE html>\n" + svg_signature_comment() + "\n", 0), 0u);
  EXPECT_EQ(html.substr(html.size() - 8), "</html>\n");
  // No "</script>" but the elements' own: five scripts (three.js, controls, data, the view).
  std::size_t closes = 0;
  for (std::size_t at = html.find("</script>"); at != std::string::npos;
       at = html.find("</script>", at + 1))
    ++closes;
  EXPECT_EQ(closes, 4u);
  const Json data = page_data(html);
  EXPECT_EQ(data["kind"], "plan");
  EXPECT_EQ(data["source"], "a</script>b.yaml");
  EXPECT_EQ(data["steps"].size(), 3u);
  EXPECT_EQ(data["initial"].size(), 21u);
  // The steps' times: increasing, the last at the path's end.
  EXPECT_LT(data["steps"][0]["t"].get<double>(), data["steps"][2]["t"].get<double>());
  EXPECT_DOUBLE_EQ(data["steps"][2]["t"].get<double>(), plan.end_effector_path.back().t);
  EXPECT_DOUBLE_EQ(data["duration"].get<double>(), plan.end_effector_path.back().t);
  // The target's B-spline: from the clamp to the last target point, through the others.
  const Json& curve = data["target_curve"];
  ASSERT_EQ(curve.size(), 31u);
  const auto at = [](const Json& p) { return Eigen::Vector3d(p[0], p[1], p[2]); };
  EXPECT_LT((at(curve.front()) - task.problem.rod.clamp.position).norm(), 1e-6);
  EXPECT_LT((at(curve.back()) - task.problem.target.points.back()).norm(), 1e-6);
  for (const Eigen::Vector3d& p : task.problem.target.points) {
    double nearest = 1.0;
    for (const Json& q : curve) nearest = std::min(nearest, (at(q) - p).norm());
    EXPECT_LT(nearest, 0.02);  // a sample within a chord's tenth of each point
  }
  EXPECT_TRUE(data["arm"].is_null());
  EXPECT_TRUE(data["base_arm"].is_null());
  EXPECT_TRUE(data["base_path"].is_null());
  EXPECT_TRUE(data["validation"].is_null());
  EXPECT_NE(html.find("window.rodshape ="), std::string::npos);  // the view's code
}

TEST(PlanHtml, AMovingBaseHasItsPathAndItsArm) {
  const std::string panda = std::string(RODSHAPE_SOURCE_DIR) + "/data/robots/panda.urdf";
  const PlanTask task = parse_plan_task(testing::kHandMadeTask +
                                            "base:\n  position: [0, 0, 0]\n"
                                            "base_robot:\n  urdf: " +
                                            panda + "\n  base: {position: [-0.4, 0, -0.2]}\n",
                                        "plan.yaml");
  ASSERT_TRUE(task.problem.base_arm);
  PlanResult plan = testing::make_plan(task, 3);
  for (const TimedPose& sample : plan.end_effector_path)
    plan.base_end_effector_path.push_back(
        {sample.t, Pose{Eigen::Vector3d(0, -0.01 * sample.t, 0), Eigen::Matrix3d::Identity()}});
  ArmPlanResult& arm = plan.base_arm.emplace();
  arm.status = ArmPlanStatus::Reachable;
  arm.joints.status = JointTrajectoryStatus::Complete;
  const ArmModel& model = task.problem.base_arm->model;
  for (const TimedPose& sample : plan.base_end_effector_path) {
    arm.joints.t.push_back(sample.t);
    arm.joints.q.push_back(Eigen::VectorXd::Zero(model.joints()));
  }
  const ScopedEnvironment three("RODSHAPE_THREE_JS_DIR", fake_three("base").string());
  const Json data =
      page_data(plan_html(plan, task.problem, figure_caption(task), *load_page_library()));
  ASSERT_TRUE(data["base_path"].is_object());
  EXPECT_EQ(data["base_path"]["t"].size(),  // decimated as the tip's path
            std::min<std::size_t>(plan.base_end_effector_path.size(), kPageMaxPathSamples));
  EXPECT_DOUBLE_EQ(data["base_path"]["p"].back()[1].get<double>(),
                   std::round(plan.base_end_effector_path.back().pose.position.y() * 1e6) / 1e6);
  ASSERT_TRUE(data["base_arm"].is_object());
  EXPECT_EQ(data["base_arm"]["name"], "panda");
  EXPECT_EQ(data["base_arm"]["status"], "reachable");
  EXPECT_EQ(data["base_arm"]["frames"].size(),
            std::min<std::size_t>(plan.base_end_effector_path.size(), kPageMaxArmSamples));
  // The first joint frame is the base arm's base.
  EXPECT_NEAR(data["base_arm"]["frames"][0][0][0].get<double>(), -0.4, 1e-9);
  EXPECT_TRUE(data["arm"].is_null());  // no arm at the tip
}

TEST(PlanHtml, ManyStepsAreDecimatedToTheCap) {
  const PlanTask task = parse_plan_task(testing::kHandMadeTask, "plan.yaml");
  PlanResult plan = testing::make_plan(task, 3);
  while (plan.steps.size() < 1000) plan.steps.push_back(plan.steps.back());
  const ScopedEnvironment three("RODSHAPE_THREE_JS_DIR", fake_three("cap").string());
  const std::string html =
      plan_html(plan, task.problem, figure_caption(task), *load_page_library());
  const Json data = page_data(html);
  EXPECT_EQ(data["steps"].size(), static_cast<std::size_t>(kPageMaxShapes - 1));
  EXPECT_EQ(data["steps"].back()["index"], 1000);  // the last step is kept
  EXPECT_LT(html.size(), 5'000'000u);
}

TEST(PlanHtml, WithoutThreeJsNoPageAndAClearReason) {
  const fs::path empty = fresh_directory("no_three");
  const ScopedEnvironment three("RODSHAPE_THREE_JS_DIR", empty.string());
  std::string why;
  EXPECT_FALSE(load_page_library(&why));
  EXPECT_NE(why.find("three.min.js cannot be read"), std::string::npos) << why;
  EXPECT_NE(why.find("libjs-three"), std::string::npos) << why;
  EXPECT_EQ(html_unavailable(), why);
  // write_plan writes the SVG, not the page, and removes an earlier run's page.
  const PlanTask task = parse_plan_task(testing::kHandMadeTask, "plan.yaml");
  const PlanResult plan = testing::make_plan(task, 3);
  const fs::path out = fresh_directory("no_three_out");
  std::ofstream(out / "plan.html") << "<!DOCTYPE html>\n" << svg_signature_comment() << "\n";
  ASSERT_TRUE(is_rodshape_output((out / "plan.html").string()));
  const std::vector<std::string> written = write_plan(out.string(), plan, task);
  EXPECT_EQ(std::count(written.begin(), written.end(), "plan.svg"), 1);
  EXPECT_EQ(std::count(written.begin(), written.end(), "plan.html"), 0);
  EXPECT_FALSE(fs::exists(out / "plan.html"));
}

TEST(PlanHtml, WritePlanWritesThePageUnlessTurnedOff) {
  const ScopedEnvironment three("RODSHAPE_THREE_JS_DIR", fake_three("write").string());
  const PlanTask task = parse_plan_task(testing::kHandMadeTask, "plan.yaml");
  const PlanResult plan = testing::make_plan(task, 3);
  const fs::path out = fresh_directory("write_out");
  std::vector<std::string> written = write_plan(out.string(), plan, task);
  EXPECT_EQ(std::count(written.begin(), written.end(), "plan.html"), 1);
  EXPECT_TRUE(is_rodshape_output((out / "plan.html").string()));
  written = write_plan(out.string(), plan, task, {.html = false});
  EXPECT_EQ(std::count(written.begin(), written.end(), "plan.html"), 0);
  EXPECT_FALSE(fs::exists(out / "plan.html"));  // an earlier run's page would not match
  // A page that is not rodshape's is left alone (and check_output_files refuses it).
  std::ofstream(out / "plan.html") << "<html>mine</html>\n";
  EXPECT_THROW(check_output_files(out.string(), plan_file_names(), {}), InputError);
  write_plan(out.string(), plan, task, {.html = false});
  EXPECT_EQ(read_file(out / "plan.html"), "<html>mine</html>\n");
}

}  // namespace
}  // namespace test_figures
}  // namespace rodshape
