// cdr_writer.hpp: ROS 2 messages serialised as the OMG's CDR (version 1, little endian), the
// encoding ROS 2's middleware (Fast DDS's Fast-CDR) puts on the wire and rosbag2 stores in MCAP
// (message encoding "cdr", docs/ros.md). A buffer begins with the 4-byte encapsulation header
// {0x00, 0x01, 0x00, 0x00} (CDR_LE); every primitive of n bytes (1, 2, 4 or 8) is aligned to a
// multiple of n counted from the end of that header (CDR, OMG DDS-XTypes 1.3, 7.4.1: PLAIN_CDR).
// A string is a uint32 length counting its terminating NUL, its bytes and the NUL; a sequence a
// uint32 element count and its elements (an empty sequence of primitives adds no padding, as
// Fast-CDR writes it); a fixed array its elements only.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace rodshape {

class CdrWriter {
 public:
  /// The encapsulation header, CDR_LE (OMG RTPS 2.5, 10.5: representation identifier 0x0001).
  static constexpr std::size_t kHeaderSize = 4;

  CdrWriter();

  void write_bool(bool value);
  void write_uint8(std::uint8_t value);
  void write_int32(std::int32_t value);
  void write_uint32(std::uint32_t value);
  void write_float32(float value);
  void write_float64(double value);
  void write_string(std::string_view value);
  /// A sequence's length (element count), before its elements.
  void write_length(std::size_t count);
  /// sequence<float64>: the count, then (when not empty) padding to 8 and the values.
  void write_float64_sequence(std::span<const double> values);
  /// sequence<uint8>: the count and the bytes.
  void write_uint8_sequence(std::string_view bytes);

  /// The bytes written so far, header included.
  const std::string& bytes() const { return buffer_; }
  std::string take() { return std::move(buffer_); }
  /// The offset the next value would start at before its padding, counted from the header's end.
  std::size_t offset() const { return buffer_.size() - kHeaderSize; }

 private:
  void align(std::size_t size);
  void append(const void* data, std::size_t size);
  std::string buffer_;
};

}  // namespace rodshape
