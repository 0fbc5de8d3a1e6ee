// mcap_writer.hpp: a small MCAP writer (the file format Foxglove, Rerun and rosbag2 read;
// specification: github.com/foxglove/mcap, specification/README.md, format version "0"). The file
// is built in memory, as rodshape's other outputs are, and written as a set with them:
//   magic, Header, the Schema and Channel records, Chunks (each followed by one Message Index
//   record per channel in it), Data End (with the data section's CRC-32), the summary section
//   (Schemas, Channels, Statistics, Chunk Indexes), one Summary Offset record per group, Footer
//   (with the summary's CRC-32), magic.
// Records are an opcode (uint8), a content length (uint64) and the content, all little endian;
// strings and byte arrays are preceded by a uint32 length, maps and arrays by their uint32 length
// in bytes. Chunks are uncompressed or zstd-compressed (libzstd).
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "rodshape/enum_names.hpp"

namespace rodshape {

/// The 8 bytes an MCAP file begins and ends with: 0x89 "MCAP" '0' "\r\n".
inline constexpr std::string_view kMcapMagic = {"\x89MCAP0\r\n", 8};

/// The record opcodes (specification, "Records").
enum class McapOpcode : std::uint8_t {
  Header = 0x01,
  Footer = 0x02,
  Schema = 0x03,
  Channel = 0x04,
  Message = 0x05,
  Chunk = 0x06,
  MessageIndex = 0x07,
  ChunkIndex = 0x08,
  Statistics = 0x0B,
  SummaryOffset = 0x0E,
  DataEnd = 0x0F,
};

enum class McapCompression { None, Zstd };
/// The names of McapCompression (`--mcap-compression`); a chunk's compression field is "" for
/// None and "zstd" for Zstd.
inline constexpr EnumNames<McapCompression, 2> kMcapCompressionNames = {{
    {McapCompression::None, "none"},
    {McapCompression::Zstd, "zstd"},
}};

struct McapOptions {
  McapCompression compression = McapCompression::Zstd;
  /// A chunk is closed once its uncompressed records reach this size (bytes).
  std::size_t chunk_size = std::size_t{1} << 20;
};

/// CRC-32 (ISO-HDLC: polynomial 0x04C11DB7 reflected, initial and final XOR 0xFFFFFFFF), the CRC
/// MCAP uses; `crc` continues an earlier call's result.
std::uint32_t mcap_crc32(std::string_view bytes, std::uint32_t crc = 0);

class McapWriter {
 public:
  /// `profile` ("ros2") and `library` (rodshape's signature) go into the Header record.
  McapWriter(std::string_view profile, std::string_view library, McapOptions options = {});

  /// A schema (e.g. name "sensor_msgs/msg/JointState", encoding "ros2msg", the .msg text);
  /// returns its id (1, 2, ...).
  std::uint16_t add_schema(std::string_view name, std::string_view encoding, std::string_view data);
  /// A channel (a topic) of messages of `schema_id` in `message_encoding` ("cdr"); returns its id
  /// (0, 1, ...).
  std::uint16_t add_channel(std::uint16_t schema_id,
                            std::string_view topic,
                            std::string_view message_encoding);
  /// A message at `log_time` (ns) on `channel`; published at the same time. Messages are indexed
  /// by log time and should come in its order.
  void add_message(std::uint16_t channel, std::uint64_t log_time, std::string_view data);

  /// Closes the last chunk, writes the summary and the footer and returns the whole file. The
  /// writer is left empty.
  std::string finish();

 private:
  struct Entry {
    std::uint64_t log_time;
    std::uint64_t offset;
  };
  struct ChunkIndex {
    std::uint64_t start_time, end_time, offset, length;
    std::map<std::uint16_t, std::uint64_t> message_index_offsets;
    std::uint64_t message_index_length;
    std::uint64_t compressed_size, uncompressed_size;
  };
  void flush_chunk();

  McapOptions options_;
  std::string file_;
  std::vector<std::string> schemas_;   // their records, for the summary
  std::vector<std::string> channels_;  // "
  std::string chunk_;                  // the open chunk's records, uncompressed
  std::map<std::uint16_t, std::vector<Entry>> chunk_entries_;
  std::uint64_t chunk_start_ = 0, chunk_end_ = 0;
  std::vector<ChunkIndex> chunk_indexes_;
  std::map<std::uint16_t, std::uint64_t> message_counts_;
  std::vector<std::uint32_t> sequences_;
  std::uint64_t message_count_ = 0, start_time_ = 0, end_time_ = 0;
};

}  // namespace rodshape
