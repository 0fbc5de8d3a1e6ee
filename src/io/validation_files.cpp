// validation_files.cpp: validation.csv and the files `rodshape validate` writes
// (validation_output.hpp).
#include <iomanip>
#include <optional>
#include <sstream>

#include "rodshape/io/output_files.hpp"
#include "rodshape/io/plan_mcap.hpp"
#include "rodshape/io/validation_output.hpp"

namespace rodshape {

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

const std::vector<std::string>& validation_file_names() {
  static const std::vector<std::string> names = {
      "validation.json", "validation.csv", "validation.svg", "validation.html", "validation.mcap"};
  return names;
}

OutputSet validation_outputs(const ValidationResult& result,
                             const PlanResult& plan,
                             const PlanTask& task,
                             const FigureFiles& figures) {
  OutputSet set;
  set.files.emplace_back("validation.json", validation_json(result, plan, task));
  set.files.emplace_back("validation.csv", validation_csv(result));
  set.files.emplace_back("validation.svg", validation_svg(result));
  const std::optional<PageLibrary> library = figures.html ? load_page_library() : std::nullopt;
  if (library)
    set.files.emplace_back("validation.html", validation_html(result, plan, task.problem,
                                                              figure_caption(task), *library));
  else
    set.stale.emplace_back("validation.html");
  if (figures.mcap)
    set.files.emplace_back("validation.mcap",
                           validation_mcap(result, plan, task.problem, *figures.mcap));
  else
    set.stale.emplace_back("validation.mcap");
  return set;
}

std::vector<std::string> write_validation(const std::string& directory,
                                          const ValidationResult& result,
                                          const PlanResult& plan,
                                          const PlanTask& task,
                                          const FigureFiles& figures) {
  return write_output_set(directory, validation_outputs(result, plan, task, figures));
}

}  // namespace rodshape
