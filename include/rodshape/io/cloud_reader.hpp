// cloud_reader.hpp: a depth camera's point cloud from a file (`rodshape estimate --cloud`,
// docs/estimate.md): PLY (ascii, binary_little_endian, binary_big_endian; the vertex element's
// x, y, z as float or double, its other properties skipped, other elements skipped), PCD (DATA
// ascii or binary; binary_compressed is refused; x, y, z of TYPE F, SIZE 4 or 8) or CSV (x,y,z per
// line, an optional header line, blank lines skipped). The points are as the file gives them: in
// the camera's frame. Points with a non-finite coordinate (a camera's invalid pixels, NaN in an
// organised PCD) are skipped. Caps: the file at most kMaxCloudFileBytes, the cloud at most
// kMaxCloudPoints (cloud_estimator.hpp, 10⁶) points; a malformed file, or one beyond a cap, is an
// InputError naming the file and what is wrong (and the line, or the field).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace rodshape {

/// 64 MiB: a million points as binary doubles are 24 MB, as text about 40 MB.
inline constexpr std::size_t kMaxCloudFileBytes = std::size_t{64} << 20;

enum class CloudFormat { Ply, Pcd, Csv };

/// The format named by `path`'s extension (.ply, .pcd, .csv, any case); InputError otherwise.
CloudFormat cloud_format_of(const std::string& path);

/// The points of the cloud file at `path` (its format by the extension), camera frame.
std::vector<Eigen::Vector3d> read_cloud(const std::string& path);

/// The points of `bytes`, a whole file in `format`; `name` is what the messages call it.
std::vector<Eigen::Vector3d> parse_cloud(std::string_view bytes,
                                         CloudFormat format,
                                         const std::string& name);

}  // namespace rodshape
