// pcd_cloud.cpp: a cloud as PCD (Point Cloud Library's format, v0.7; cloud_reader.hpp): the header
// (FIELDS, SIZE, TYPE, COUNT, WIDTH, HEIGHT, POINTS, DATA), then the points, DATA ascii (a line per
// point) or binary (point-major, little-endian); binary_compressed is refused.
#include <array>
#include <string>

#include "io/cloud_text.hpp"

namespace rodshape::io_detail {

namespace {

struct PcdField {
  std::string name;
  int size = 4;
  char type = 'F';
  std::size_t count = 1;
};

struct PcdHeader {
  std::vector<PcdField> fields;
  std::size_t points = 0;
  bool binary = false;
  std::size_t data_offset = 0;
  int data_line = 0;  // the DATA line
};

/// Each word of `words` after the keyword, through `each`, which returns false for a bad one.
template <typename Each>
void per_field(PcdHeader& header,
               const std::vector<std::string_view>& words,
               const std::string& where,
               const std::string& name,
               Each each) {
  if (words.size() != header.fields.size() + 1)
    cloud_error(name, where + ": " + std::string(words[0]) + " has " +
                          std::to_string(words.size() - 1) + " entries, FIELDS has " +
                          std::to_string(header.fields.size()));
  for (std::size_t k = 0; k < header.fields.size(); ++k)
    if (!each(header.fields[k], words[k + 1]))
      cloud_error(name, where + ": bad " + std::string(words[0]) + " entry '" +
                            std::string(words[k + 1]) + "'");
}

PcdHeader read_pcd_header(std::string_view bytes, const std::string& name) {
  LineCursor lines(bytes);
  std::string_view line;
  PcdHeader header;
  bool have_fields = false, have_points = false;
  while (true) {
    if (!lines.next(line)) cloud_error(name, "the header has no DATA line");
    const std::string where = "line " + std::to_string(lines.number());
    const std::vector<std::string_view> words = split_words(line);
    if (words.empty() || words[0].front() == '#') continue;
    const std::string_view key = words[0];
    if (key == "VERSION" || key == "VIEWPOINT") continue;
    if (key == "FIELDS") {
      if (words.size() < 2 || words.size() > 1001)
        cloud_error(name, where + ": FIELDS needs 1 to 1000 names");
      header.fields.clear();
      for (std::size_t k = 1; k < words.size(); ++k)
        header.fields.push_back({std::string(words[k])});
      have_fields = true;
    } else if (!have_fields && (key == "SIZE" || key == "TYPE" || key == "COUNT")) {
      cloud_error(name, where + ": " + std::string(key) + " before FIELDS");
    } else if (key == "SIZE") {
      per_field(header, words, where, name, [](PcdField& f, std::string_view w) {
        std::size_t size = 0;
        if (!parse_count(w, 8, size) || (size != 1 && size != 2 && size != 4 && size != 8))
          return false;
        f.size = static_cast<int>(size);
        return true;
      });
    } else if (key == "TYPE") {
      per_field(header, words, where, name, [](PcdField& f, std::string_view w) {
        if (w != "F" && w != "I" && w != "U") return false;
        f.type = w.front();
        return true;
      });
    } else if (key == "COUNT") {
      per_field(header, words, where, name, [](PcdField& f, std::string_view w) {
        return parse_count(w, 1 << 20, f.count) && f.count >= 1;
      });
    } else if (key == "WIDTH" || key == "HEIGHT") {
      std::size_t ignored = 0;
      if (words.size() != 2 || !parse_count(words[1], SIZE_MAX, ignored))
        cloud_error(name, where + ": " + std::string(key) + " must be a count");
    } else if (key == "POINTS") {
      if (words.size() != 2 || !parse_count(words[1], SIZE_MAX, header.points))
        cloud_error(name, where + ": POINTS must be a count");
      have_points = true;
    } else if (key == "DATA") {
      if (words.size() != 2) cloud_error(name, where + ": expected 'DATA ascii|binary'");
      if (words[1] == "binary_compressed")
        cloud_error(name, where +
                              ": DATA binary_compressed is not supported; save the cloud as "
                              "ascii or binary (pcl_convert_pcd_ascii_binary)");
      if (words[1] != "ascii" && words[1] != "binary")
        cloud_error(name, where + ": unknown DATA '" + std::string(words[1]) + "'");
      header.binary = words[1] == "binary";
      header.data_line = lines.number();
      header.data_offset = lines.offset();
      break;
    } else {
      cloud_error(name, where + ": unknown header keyword '" + std::string(key) + "'");
    }
  }
  if (!have_fields) cloud_error(name, "the header has no FIELDS line");
  if (!have_points) cloud_error(name, "the header has no POINTS line");
  check_declared(header.points, name);
  return header;
}

/// The index of each of x, y, z among the fields (TYPE F, SIZE 4 or 8, COUNT 1).
std::array<std::size_t, 3> xyz_fields(const PcdHeader& header, const std::string& name) {
  std::array<std::size_t, 3> at{};
  const std::array<std::string_view, 3> axes = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    bool found = false;
    for (std::size_t f = 0; f < header.fields.size() && !found; ++f) {
      const PcdField& field = header.fields[f];
      if (field.name != axes[k]) continue;
      if (field.type != 'F' || (field.size != 4 && field.size != 8) || field.count != 1)
        cloud_error(name, "field " + field.name + " must be TYPE F, SIZE 4 or 8, COUNT 1");
      at[k] = f;
      found = true;
    }
    if (!found) cloud_error(name, "FIELDS has no " + std::string(axes[k]));
  }
  return at;
}

std::vector<Eigen::Vector3d> read_pcd_ascii(std::string_view bytes,
                                            const PcdHeader& header,
                                            const std::array<std::size_t, 3>& xyz,
                                            const std::string& name) {
  // Each field's first value's position among a line's values.
  std::vector<std::size_t> first;
  std::size_t values = 0;
  for (const PcdField& field : header.fields) {
    first.push_back(values);
    values += field.count;
  }
  LineCursor lines(bytes.substr(header.data_offset));
  std::vector<Eigen::Vector3d> points;
  std::string_view line;
  std::size_t read = 0;
  while (read < header.points) {
    if (!lines.next(line))
      cloud_error(name, "the file ends after " + std::to_string(read) + " of " +
                            std::to_string(header.points) + " points");
    const std::vector<std::string_view> words = split_words(line);
    if (words.empty()) continue;
    const std::string where = "line " + std::to_string(header.data_line + lines.number());
    if (words.size() != values)
      cloud_error(name, where + ": " + std::to_string(words.size()) + " values, expected " +
                            std::to_string(values));
    double p[3];
    for (int k = 0; k < 3; ++k)
      if (!parse_double(words[first[xyz[k]]], p[k]))
        cloud_error(name, where + ": " + header.fields[xyz[k]].name + " is not a number");
    add_point(points, p[0], p[1], p[2], name);
    ++read;
  }
  return points;
}

std::vector<Eigen::Vector3d> read_pcd_binary(std::string_view bytes,
                                             const PcdHeader& header,
                                             const std::array<std::size_t, 3>& xyz,
                                             const std::string& name) {
  std::vector<std::size_t> at;
  std::size_t stride = 0;
  for (const PcdField& field : header.fields) {
    at.push_back(stride);
    stride += static_cast<std::size_t>(field.size) * field.count;
  }
  const std::size_t available = bytes.size() - std::min(header.data_offset, bytes.size());
  if (header.points > available / stride)
    cloud_error(name, "the file ends within the points: " + std::to_string(header.points) +
                          " points of " + std::to_string(stride) + " bytes need " +
                          std::to_string(header.points * stride) + ", " +
                          std::to_string(available) + " are left");
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data()) + header.data_offset;
  std::vector<Eigen::Vector3d> points;
  points.reserve(header.points);
  for (std::size_t i = 0; i < header.points; ++i, data += stride) {
    double p[3];
    for (int k = 0; k < 3; ++k)
      p[k] = read_scalar(data + at[xyz[k]], header.fields[xyz[k]].size, ScalarKind::Float, false);
    add_point(points, p[0], p[1], p[2], name);
  }
  return points;
}

}  // namespace

std::vector<Eigen::Vector3d> parse_pcd(std::string_view bytes, const std::string& name) {
  const PcdHeader header = read_pcd_header(bytes, name);
  const std::array<std::size_t, 3> xyz = xyz_fields(header, name);
  if (header.binary) return read_pcd_binary(bytes, header, xyz, name);
  return read_pcd_ascii(bytes, header, xyz, name);
}

}  // namespace rodshape::io_detail
