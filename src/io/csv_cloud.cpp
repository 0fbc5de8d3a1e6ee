// csv_cloud.cpp: a cloud as CSV: x,y,z per line, an optional header line (the first line, when it
// is not three numbers), blank lines skipped, a NaN or infinite value refused: unlike a camera's
// organised PLY or PCD, a CSV has no invalid pixels to skip (cloud_reader.hpp).
#include <cmath>
#include <string>

#include "io/cloud_text.hpp"

namespace rodshape::io_detail {

namespace {

/// The comma-separated fields of `line`, spaces around them trimmed.
std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    std::string_view field = line.substr(
        start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
    while (!field.empty() && (field.front() == ' ' || field.front() == '\t'))
      field.remove_prefix(1);
    while (!field.empty() && (field.back() == ' ' || field.back() == '\t')) field.remove_suffix(1);
    fields.push_back(field);
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

}  // namespace

std::vector<Eigen::Vector3d> parse_csv(std::string_view bytes, const std::string& name) {
  std::vector<Eigen::Vector3d> points;
  LineCursor lines(bytes);
  std::string_view line;
  bool first = true;
  while (lines.next(line)) {
    if (split_words(line).empty()) continue;
    const std::vector<std::string_view> fields = split_fields(line);
    double xyz[3];
    bool numbers = fields.size() == 3;
    for (std::size_t k = 0; numbers && k < 3; ++k) numbers = parse_double(fields[k], xyz[k]);
    const bool header = first && !numbers;
    first = false;
    if (header) continue;
    const std::string where = "line " + std::to_string(lines.number());
    if (fields.size() != 3)
      cloud_error(name,
                  where + ": " + std::to_string(fields.size()) + " fields, expected 3 (x,y,z)");
    if (!numbers) {
      for (std::size_t k = 0; k < 3; ++k)
        if (!parse_double(fields[k], xyz[k]))
          cloud_error(name, where + ": field " + std::to_string(k + 1) + " (" + "xyz"[k] +
                                ") is not a number");
    }
    for (std::size_t k = 0; k < 3; ++k)
      if (!std::isfinite(xyz[k]))
        cloud_error(name, where + ": field " + std::to_string(k + 1) + " (" + "xyz"[k] + ") is " +
                              std::string(fields[k]) + ", not a finite number");
    add_point(points, xyz[0], xyz[1], xyz[2], name);
  }
  return points;
}

}  // namespace rodshape::io_detail
