// validation_files.cpp: validation.csv and the files `rodshape validate` writes
// (validation_output.hpp).
#include <filesystem>
#include <iomanip>
#include <optional>
#include <sstream>

#include "rodshape/error.hpp"
#include "rodshape/io/atomic_file.hpp"
#include "rodshape/io/output_files.hpp"
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
  static const std::vector<std::string> names = {"validation.json", "validation.csv",
                                                 "validation.svg", "validation.html"};
  return names;
}

std::vector<std::string> write_validation(const std::string& directory,
                                          const ValidationResult& result,
                                          const PlanResult& plan,
                                          const PlanTask& task,
                                          const FigureFiles& figures) {
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
  const std::optional<PageLibrary> library = figures.html ? load_page_library() : std::nullopt;
  if (library)
    write("validation.html",
          validation_html(result, plan, task.problem, figure_caption(task), *library));
  else
    remove_earlier_outputs(directory, {"validation.html"});
  return written;
}

}  // namespace rodshape
