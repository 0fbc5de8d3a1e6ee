// cloud_text.hpp (private to the io area): what the cloud readers share (cloud_reader.hpp): lines
// of a header with their numbers, numbers from text, binary scalars of either byte order, the
// point cap and the error that names the file.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace rodshape::io_detail {

/// Throws InputError "<name>: <what>".
[[noreturn]] void cloud_error(const std::string& name, const std::string& what);

/// Lines of a text (or a text header before binary data), counted from 1.
class LineCursor {
 public:
  explicit LineCursor(std::string_view text) : text_(text) {}
  /// The next line without its "\n" or "\r\n"; false at the end.
  bool next(std::string_view& line);
  int number() const { return number_; }          // the line last returned
  std::size_t offset() const { return offset_; }  // bytes consumed: where binary data starts

 private:
  std::string_view text_;
  std::size_t offset_ = 0;
  int number_ = 0;
};

/// The whitespace-separated tokens of `line`.
std::vector<std::string_view> split_words(std::string_view line);

/// `token` as a finite-or-not double (std::from_chars: "nan", "inf" accepted); false if it is not
/// a number or has trailing characters.
bool parse_double(std::string_view token, double& value);
/// `token` as a non-negative count ≤ limit; false otherwise.
bool parse_count(std::string_view token, std::size_t limit, std::size_t& value);

/// A scalar of `size` bytes (1, 2, 4, 8) at `data`, integer (signed or not) or IEEE float, in
/// `big_endian` or little-endian order, as a double.
enum class ScalarKind { Signed, Unsigned, Float };
double read_scalar(const unsigned char* data, int size, ScalarKind kind, bool big_endian);

/// Adds (x, y, z) to `points` when finite; throws when `points` already holds the cap.
void add_point(
    std::vector<Eigen::Vector3d>& points, double x, double y, double z, const std::string& name);

/// Throws when a header declares more than the cap.
void check_declared(std::size_t declared, const std::string& name);

std::vector<Eigen::Vector3d> parse_ply(std::string_view bytes, const std::string& name);
std::vector<Eigen::Vector3d> parse_pcd(std::string_view bytes, const std::string& name);
std::vector<Eigen::Vector3d> parse_csv(std::string_view bytes, const std::string& name);

}  // namespace rodshape::io_detail
