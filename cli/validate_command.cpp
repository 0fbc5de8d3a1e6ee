// validate_command.cpp: plan a task, carry the plan out on the simulated plant seen by the
// simulated sensors, and write the errors.
//   task file -> PlanTask (io) -> plan (trajectory) -> validate_plan (sim) -> validation.* (io)
#include "validate_command.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <thread>
#include <variant>
#include <vector>

#include "exit_code.hpp"
#include "mcap_option.hpp"
#include "number_option.hpp"
#include "progress_line.hpp"
#include "rodshape/io/field_names.hpp"
#include "rodshape/io/output_files.hpp"
#include "rodshape/io/plan_output.hpp"
#include "rodshape/io/task_reader.hpp"
#include "rodshape/io/validation_output.hpp"
#include "rodshape/sim/plan_validation.hpp"
#include "rodshape/trajectory/plan.hpp"

namespace rodshape::cli {

namespace {

/// --seed as written: a whole number in [0, 2^64 - 1], without a sign (CLI11 would take -1 as
/// 2^64 - 1 and wrap a larger number).
std::uint64_t parse_seed(const std::string& text) {
  std::uint64_t seed = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, seed);
  if (text.empty() || error != std::errc() || stop != end)
    throw InputError("--seed = " + text + " must be a whole number in [0, " +
                     std::to_string(std::numeric_limits<std::uint64_t>::max()) + "]");
  return seed;
}

// validate's time, estimated before any work (docs/limits.md, "Sizes of a validation"): one core's
// work, as the CPU seconds of the Release build (2 shared cores) on examples/plan_c_arc.yaml
// (100 intervals, 10 markers and points, 497 frames a run, 7 checkpoints; open loop 2/8/32 runs
// 0.37/0.51/1.16 s, closed loop 2/8 runs 0.67/2.50 s) and examples/validate_depth_camera.yaml
// (512 x 424 pixels, 500 points a frame; open loop 2/8 runs 1.34/4.17 s, closed loop 2/4 runs
// 3.61/7.21 s). Per run: open loop frames x (markers + points) x kMarkerSeconds or frames x
// pixels x kPixelSeconds; the plant's solve per frame, once open loop and per run closed loop,
// intervals x kPlantSeconds; closed loop, per checkpoint a re-plan (the plan's estimate per step,
// times the horizon) and, for a depth camera, the fit of the pooled cloud, intervals x points x
// kCloudFitSeconds. The sum is the fit times kMargin (--jobs is not counted: with 2 jobs on 2
// shared cores the closed loop took 0.9 x the time of 1 job).
constexpr double kPlantSeconds = 5.0e-6;      // per interval and frame (0.25 s for 497 x 100)
constexpr double kMarkerSeconds = 2.6e-6;     // per marker and target point, frame and run
constexpr double kPixelSeconds = 4.4e-9;      // per pixel, frame and run (the camera's rays)
constexpr double kCloudFitSeconds = 1.75e-7;  // per interval and pooled point, checkpoint and run
constexpr double kMargin = 1.5;
constexpr double kAnnouncedSeconds = 10.0;  // an estimate this long is said on standard error
constexpr double kMaxMaxSeconds = 1.0e6;    // --max-seconds' bound (docs/limits.md), 11.6 days

/// "0.42", "4.2", "683": two significant digits below 10 s, whole seconds above.
std::string seconds_text(double seconds) {
  if (seconds >= 10.0) return std::to_string(std::lround(seconds));
  std::ostringstream out;
  out.precision(2);
  out << seconds;
  return out.str();
}

/// The estimate of a validation's time, s, and what it comes from. `path_frames`: the frames of
/// the plan's path a run sees (0 before planning: a lower bound then).
struct ValidationCost {
  double seconds = 0.0;
  std::string from;
};

ValidationCost estimated_validation_cost(const PlanTask& task,
                                         const ValidationOptions& options,
                                         double steps,
                                         double path_frames) {
  const double intervals = task.problem.rod.intervals;
  const double runs = options.runs;
  const SensorModel sensor = task.sensor_model();
  const auto* depth = std::get_if<DepthSensorModel>(&sensor);
  const auto* markers = std::get_if<MarkerSensorModel>(&sensor);
  const double seeing =  // one frame seen in one run
      depth ? kPixelSeconds * depth->width * depth->height
            : kMarkerSeconds * ((markers ? markers->markers : 0) +
                                static_cast<double>(task.problem.target.points.size()));
  const double plant = kPlantSeconds * intervals;  // one frame driven
  const double plan = estimated_plan_seconds(task.problem, task.options);
  double seconds = plan;
  ValidationCost cost;
  std::ostringstream from;
  from << options.runs << (options.runs == 1 ? " run" : " runs") << ", "
       << (options.closed_loop ? "closed loop" : "open loop") << ", ";
  if (path_frames > 0.0)
    from << path_frames << " frames of the path a run";
  else
    from << "the path's frames not yet known";
  from << ", " << task.problem.rod.intervals + 1 << " rod nodes, "
       << (depth ? std::to_string(depth->width) + " x " + std::to_string(depth->height) +
                       " depth pixels"
                 : std::to_string(markers ? markers->markers : 0) + " markers");
  if (!options.closed_loop) {
    seconds += path_frames * (plant + runs * seeing);
  } else {
    const double checkpoint_frames = options.loop.checkpoint_frames;
    const double frames = path_frames + steps * (checkpoint_frames + 1.0);
    const double horizon = options.loop.horizon > 0 ? options.loop.horizon : 0.5 * steps;
    double checkpoint = plan / std::max(steps, 1.0) * std::min(horizon, steps);
    if (depth) checkpoint += kCloudFitSeconds * intervals * checkpoint_frames * depth->points;
    seconds += runs * (frames * (plant + seeing) + steps * checkpoint);
    from << ", " << steps << " checkpoints of " << options.loop.checkpoint_frames << " frames";
  }
  cost.seconds = kMargin * seconds;
  cost.from = from.str();
  return cost;
}

/// InputError when `cost` is beyond `max_seconds` (a lower bound when `at_least`).
void check_validation_cost(const std::string& task_path,
                           const ValidationCost& cost,
                           double max_seconds,
                           bool at_least) {
  if (cost.seconds <= max_seconds) return;
  throw InputError(task_path + ": validate would take " + (at_least ? "at least " : "") + "about " +
                   seconds_text(cost.seconds) + " s, estimated from " + cost.from + "; at most " +
                   seconds_text(max_seconds) +
                   " s (docs/limits.md): lower --runs, or raise --max-seconds");
}

/// The cores, within [1, ValidationOptions::kMaxJobs].
int default_jobs() {
  const auto cores = static_cast<int>(std::thread::hardware_concurrency());
  return std::clamp(cores, 1, ValidationOptions::kMaxJobs);
}

class ValidateCommand final : public Command {
 public:
  CLI::App* add_to(CLI::App& app) override {
    CLI::App* command = app.add_subcommand(
        "validate",
        "Plan the task, then carry the plan out in simulation: the real rod (the task's plant "
        "section) driven along the commanded path and seen by the sensors (its sensor section). "
        "Writes OUTDIR/validation.json, OUTDIR/validation.csv (the errors over time) and "
        "OUTDIR/validation.svg and the 3D page OUTDIR/validation.html, besides the plan's files.");
    command->add_option("task", task_path_, "Task file (YAML); format in docs/task-file.md")
        ->required()
        ->type_name("TASK.yaml");
    command
        ->add_option("-o,--output", output_directory_,
                     "Directory for the plan's files and validation.* (created if missing)")
        ->required()
        ->type_name("OUTDIR");
    command
        ->add_option(
            "--runs", runs_,
            "Repeats with the sensor's noise drawn anew (1 to 1000; the plant is the same)")
        ->type_name("N");
    command
        ->add_option("--seed", seed_,
                     "Seed of the first run (run k: seed + k - 1), a whole number in [0, 2^64 - "
                     "runs]")
        ->type_name("S");
    jobs_ = std::to_string(default_jobs());
    command
        ->add_option("--jobs", jobs_,
                     "Closed loop: runs carried out at once, 1 to 256 (default: the cores, here " +
                         std::to_string(default_jobs()) +
                         "); the results are the same for every value")
        ->type_name("N");
    command
        ->add_option("--max-seconds", max_seconds_text_,
                     "Refuse a validation estimated to take longer (default " +
                         seconds_text(kMaxEstimatedPlanSeconds) +
                         " s, as for plan; at most 1e6; docs/limits.md)")
        ->type_name("S");
    command->add_flag("--closed-loop", options_.closed_loop,
                      "Close the loop: at each waypoint, estimate the rod from the sensors and "
                      "re-plan the rest (the task's closed_loop section)");
    command->add_flag("-q,--quiet", quiet_,
                      "Do not print the one-line summary on standard output, nor the progress on "
                      "standard error (drawn only when it is a terminal)");
    command->add_flag("--no-html", no_html_,
                      "Do not write plan.html and validation.html (the 3D pages)");
    mcap_.add_to(command, "validation.mcap");
    command->footer(
        "Exit codes: 0 the plant followed the whole path; 2 bad input (task file, command line, "
        "output path, an infeasible target): nothing written or removed; 3 the plant snapped, was "
        "lost or "
        "would touch an obstacle of the scene, or the plan has no path to carry out (the files are "
        "still written); 1 internal "
        "error.");
    return command;
  }

  int run() override {
    ValidationOptions options = options_;
    options.runs = whole_option("--runs", runs_, 1, ValidationOptions::kMaxRuns);
    options.jobs = whole_option("--jobs", jobs_, 1, ValidationOptions::kMaxJobs);
    const double max_seconds =
        max_seconds_text_.empty()
            ? kMaxEstimatedPlanSeconds
            : positive_option("--max-seconds", max_seconds_text_, kMaxMaxSeconds);
    options.seed = parse_seed(seed_);
    try {
      options.validate();
    } catch (const InputError& error) {
      throw InputError(fields_in_task_names(error.what()));
    }
    const PlanTask task = read_plan_task(task_path_);
    // As for plan: bad input writes and removes nothing (plan_command.cpp).
    check_output_directory(output_directory_);
    std::vector<std::string> outputs = plan_file_names();
    for (const std::string& name : validation_file_names()) outputs.push_back(name);
    check_output_files(output_directory_, outputs, task.input_files);
    options.loop = task.closed_loop;
    options.planning = task.options;
    // Before planning, a lower bound (the path's frames are not known yet); after, the estimate.
    check_validation_cost(task_path_,
                          estimated_validation_cost(task, options, task.options.steps, 0.0),
                          max_seconds, true);
    PlanResult plan;
    ValidationResult result;
    try {
      plan = rodshape::plan(task.problem, task.options);
    } catch (const InputError& error) {
      throw InputError(task.locate(error));
    }
    if (plan.status == PlanStatus::Infeasible) throw task.infeasible_target(plan);
    if (plan.end_effector_path.empty()) {
      std::cerr << "error: " << task_path_
                << ": nothing to validate: " << fields_in_task_names(plan.brief()) << "\n";
      OutputSet set = plan_outputs(plan, task, {.html = !no_html_});
      for (const std::string& name : validation_file_names()) set.stale.push_back(name);
      write_output_set(output_directory_, std::move(set));
      return kPartialPlan;
    }
    const double duration = plan.end_effector_path.back().t - plan.end_effector_path.front().t;
    const double rate =
        std::visit([](const auto& model) { return model.frame_rate; }, task.sensor_model());
    const ValidationCost cost = estimated_validation_cost(
        task, options, static_cast<double>(plan.steps.size()), std::floor(duration * rate) + 2.0);
    check_validation_cost(task_path_, cost, max_seconds, false);
    if (!quiet_ && cost.seconds >= kAnnouncedSeconds)
      std::cerr << "validate: about " << seconds_text(cost.seconds) << " s estimated (" << cost.from
                << ")\n";
    {
      ProgressLine progress("validate", options.closed_loop ? "runs" : "frames", !quiet_);
      if (progress.active())
        options.progress = [&progress](int done, int total) { progress.update(done, total); };
      try {
        result = validate_plan(task.problem, plan, task.plant, task.sensor_model(), options);
      } catch (const InputError& error) {
        throw InputError(task.locate(error));
      }
    }
    warn_without_html(no_html_);
    // The plan's files and the validation's as one set: all checked, all written, then renamed.
    OutputSet set = plan_outputs(plan, task, {.html = !no_html_});
    set.append(
        validation_outputs(result, plan, task, {.html = !no_html_, .mcap = mcap_.options()}));
    const std::vector<std::string> written = write_output_set(output_directory_, std::move(set));
    if (!quiet_) {
      std::cout << task_path_ << ": " << fields_in_task_names(result.brief()) << "; wrote";
      for (const std::string& name : written)
        std::cout << " " << (std::filesystem::path(output_directory_) / name).string();
      std::cout << "\n" << std::flush;
    }
    if (result.status == ValidationStatus::Complete) return kSuccess;
    std::cerr << "error: " << task_path_ << ": " << to_string(result.status) << ": "
              << result.message << "\n";
    return kNotConverged;
  }

 private:
  std::string task_path_;
  std::string output_directory_;
  ValidationOptions options_;
  std::string seed_ = "1";
  std::string runs_ = "1", jobs_;  // read by whole_option() (number_option.hpp)
  std::string max_seconds_text_;   // "": kMaxEstimatedPlanSeconds
  bool quiet_ = false;
  bool no_html_ = false;
  McapOption mcap_;
};

}  // namespace

std::unique_ptr<Command> make_validate_command() { return std::make_unique<ValidateCommand>(); }

}  // namespace rodshape::cli
