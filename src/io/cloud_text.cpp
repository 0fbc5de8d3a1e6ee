// cloud_text.cpp: what the cloud readers share (cloud_text.hpp).
#include "io/cloud_text.hpp"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>

#include "rodshape/error.hpp"
#include "rodshape/feedback/cloud_estimator.hpp"

namespace rodshape::io_detail {

void cloud_error(const std::string& name, const std::string& what) {
  throw InputError(name + ": " + what);
}

bool LineCursor::next(std::string_view& line) {
  if (offset_ >= text_.size()) return false;
  const std::size_t end = text_.find('\n', offset_);
  const std::size_t stop = end == std::string_view::npos ? text_.size() : end;
  line = text_.substr(offset_, stop - offset_);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  offset_ = end == std::string_view::npos ? text_.size() : end + 1;
  ++number_;
  return true;
}

std::vector<std::string_view> split_words(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

bool parse_double(std::string_view token, double& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  return !token.empty() && ec == std::errc() && ptr == end;
}

bool parse_count(std::string_view token, std::size_t limit, std::size_t& value) {
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  return !token.empty() && ec == std::errc() && ptr == end && value <= limit;
}

double read_scalar(const unsigned char* data, int size, ScalarKind kind, bool big_endian) {
  unsigned char bytes[8];
  std::memcpy(bytes, data, static_cast<std::size_t>(size));
  if (big_endian != (std::endian::native == std::endian::big)) std::reverse(bytes, bytes + size);
  switch (size) {
    case 1:
      return kind == ScalarKind::Signed ? static_cast<double>(static_cast<std::int8_t>(bytes[0]))
                                        : static_cast<double>(bytes[0]);
    case 2: {
      std::uint16_t u;
      std::memcpy(&u, bytes, 2);
      return kind == ScalarKind::Signed ? static_cast<double>(static_cast<std::int16_t>(u))
                                        : static_cast<double>(u);
    }
    case 4: {
      if (kind == ScalarKind::Float) {
        float f;
        std::memcpy(&f, bytes, 4);
        return static_cast<double>(f);
      }
      std::uint32_t u;
      std::memcpy(&u, bytes, 4);
      return kind == ScalarKind::Signed ? static_cast<double>(static_cast<std::int32_t>(u))
                                        : static_cast<double>(u);
    }
    default: {
      if (kind == ScalarKind::Float) {
        double d;
        std::memcpy(&d, bytes, 8);
        return d;
      }
      std::uint64_t u;
      std::memcpy(&u, bytes, 8);
      return kind == ScalarKind::Signed ? static_cast<double>(static_cast<std::int64_t>(u))
                                        : static_cast<double>(u);
    }
  }
}

void add_point(
    std::vector<Eigen::Vector3d>& points, double x, double y, double z, const std::string& name) {
  if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) return;
  if (points.size() >= static_cast<std::size_t>(kMaxCloudPoints))
    cloud_error(name, "more than " + std::to_string(kMaxCloudPoints) + " points, the cap");
  points.emplace_back(x, y, z);
}

void check_declared(std::size_t declared, const std::string& name) {
  if (declared > static_cast<std::size_t>(kMaxCloudPoints))
    cloud_error(name, "the header declares " + std::to_string(declared) + " points, more than " +
                          std::to_string(kMaxCloudPoints) + ", the cap");
}

}  // namespace rodshape::io_detail
