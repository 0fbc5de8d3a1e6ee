// cloud_reader.cpp: a cloud file read whole within its cap, parsed by its format
// (cloud_reader.hpp).
#include "rodshape/io/cloud_reader.hpp"

#include <algorithm>
#include <cctype>

#include "capped_file.hpp"
#include "io/cloud_text.hpp"
#include "rodshape/error.hpp"

namespace rodshape {

CloudFormat cloud_format_of(const std::string& path) {
  const std::size_t dot = path.rfind('.');
  std::string extension = dot == std::string::npos ? "" : path.substr(dot + 1);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == "ply") return CloudFormat::Ply;
  if (extension == "pcd") return CloudFormat::Pcd;
  if (extension == "csv") return CloudFormat::Csv;
  throw InputError(path + ": unknown cloud format; the file must end in .ply, .pcd or .csv");
}

std::vector<Eigen::Vector3d> parse_cloud(std::string_view bytes,
                                         CloudFormat format,
                                         const std::string& name) {
  switch (format) {
    case CloudFormat::Ply:
      return io_detail::parse_ply(bytes, name);
    case CloudFormat::Pcd:
      return io_detail::parse_pcd(bytes, name);
    case CloudFormat::Csv:
      break;
  }
  return io_detail::parse_csv(bytes, name);
}

std::vector<Eigen::Vector3d> read_cloud(const std::string& path) {
  constexpr detail::FileCap kCap{kMaxCloudFileBytes, "a cloud file", "cannot read"};
  // Read first: a directory, a missing file or one beyond the cap says so, whatever its name.
  const std::string bytes = detail::read_capped_file(path, kCap);
  return parse_cloud(bytes, cloud_format_of(path), path);
}

}  // namespace rodshape
