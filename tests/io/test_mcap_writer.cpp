// test_mcap_writer.cpp: the MCAP file's layout (mcap_writer.hpp; github.com/foxglove/mcap,
// specification/README.md) read back record by record: magic at both ends, the Header's profile
// and library, Schemas and Channels before the chunks, each Chunk's CRC-32 of its uncompressed
// records (zstd: decompressed here with libzstd), Message Index offsets that land on the messages
// in the chunk, Data End's CRC of the data section, the Footer's summary and summary-offset
// positions and the summary's CRC-32, Chunk Indexes and Statistics that agree with the chunks; the
// CRC's check value; an MCAP file told as rodshape's by its Header's library.
#include <gtest/gtest.h>
#include <unistd.h>
#include <zstd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "rodshape/io/mcap_writer.hpp"
#include "rodshape/io/output_files.hpp"

namespace rodshape {
namespace test_mcap_writer {
namespace {

/// A little-endian reader of the file's fields.
struct Cursor {
  std::string_view data;
  std::size_t at = 0;
  template <typename T>
  T get() {
    T value{};
    EXPECT_LE(at + sizeof(T), data.size());
    if (at + sizeof(T) > data.size()) return value;
    std::memcpy(&value, data.data() + at, sizeof(T));
    at += sizeof(T);
    return value;
  }
  std::string string() {
    const auto size = get<std::uint32_t>();
    std::string s(data.substr(at, size));
    at += size;
    return s;
  }
};

struct Record {
  std::uint8_t opcode;
  std::size_t start;  // of the opcode
  std::string_view content;
};

/// The records of `data` from `at` to `end`.
std::vector<Record> records_of(std::string_view data, std::size_t at, std::size_t end) {
  std::vector<Record> records;
  while (at < end) {
    Cursor c{data, at};
    const auto opcode = c.get<std::uint8_t>();
    const auto length = c.get<std::uint64_t>();
    EXPECT_LE(c.at + length, end) << "a record runs past its section";
    if (c.at + length > end) break;
    records.push_back({opcode, at, data.substr(c.at, length)});
    at = c.at + length;
  }
  return records;
}

constexpr auto op = [](McapOpcode code) { return static_cast<std::uint8_t>(code); };

/// Two channels, `messages` messages alternating between them at t = 10, 20, ... ns.
std::string sample_file(McapCompression compression, int messages, std::size_t chunk_size) {
  McapWriter writer("ros2", "rodshape test", {compression, chunk_size});
  const std::uint16_t schema = writer.add_schema("pkg/msg/A", "ros2msg", "int32 a\n");
  const std::uint16_t first = writer.add_channel(schema, "/a", "cdr");
  const std::uint16_t second = writer.add_channel(schema, "/b", "cdr");
  for (int i = 0; i < messages; ++i)
    writer.add_message(i % 2 ? second : first, 10U * static_cast<std::uint64_t>(i + 1),
                       std::string(40, static_cast<char>('a' + i % 26)));
  return writer.finish();
}

TEST(McapCrc, IsTheIsoHdlcCrc32) {
  EXPECT_EQ(mcap_crc32("123456789"), 0xCBF43926U);  // the CRC-32 check value
  EXPECT_EQ(mcap_crc32(""), 0U);
  EXPECT_EQ(mcap_crc32("56789", mcap_crc32("1234")), 0xCBF43926U);  // continued
}

class McapLayout : public ::testing::TestWithParam<McapCompression> {};

TEST_P(McapLayout, EveryRecordIsWhereTheSummaryAndIndexesSay) {
  const int messages = 25;
  const std::string file = sample_file(GetParam(), messages, 300);  // several chunks
  const std::string_view data = file;
  ASSERT_GT(data.size(), 2 * kMcapMagic.size());
  EXPECT_EQ(data.substr(0, 8), kMcapMagic);
  EXPECT_EQ(data.substr(data.size() - 8), kMcapMagic);

  // The footer: the last record before the closing magic, 20 bytes of content.
  const std::size_t footer = data.size() - 8 - (1 + 8 + 20);
  Cursor f{data, footer};
  ASSERT_EQ(f.get<std::uint8_t>(), op(McapOpcode::Footer));
  ASSERT_EQ(f.get<std::uint64_t>(), 20U);
  const auto summary_start = f.get<std::uint64_t>();
  const auto summary_offset_start = f.get<std::uint64_t>();
  const auto summary_crc = f.get<std::uint32_t>();
  ASSERT_LT(summary_start, summary_offset_start);
  ASSERT_LT(summary_offset_start, footer);
  // The summary's CRC: from the summary's start through the footer's summary_offset_start field.
  EXPECT_EQ(summary_crc,
            mcap_crc32(data.substr(summary_start, footer + 1 + 8 + 16 - summary_start)));

  // The data section: Header, Schema, 2 Channels, then Chunks each followed by Message Indexes,
  // then Data End (its CRC: every byte before it, the magic included).
  const std::vector<Record> records = records_of(data, 8, summary_start);
  ASSERT_GE(records.size(), 6U);
  EXPECT_EQ(records[0].opcode, op(McapOpcode::Header));
  Cursor header{records[0].content};
  EXPECT_EQ(header.string(), "ros2");
  EXPECT_EQ(header.string(), "rodshape test");
  EXPECT_EQ(records[1].opcode, op(McapOpcode::Schema));
  EXPECT_EQ(records[2].opcode, op(McapOpcode::Channel));
  EXPECT_EQ(records[3].opcode, op(McapOpcode::Channel));
  const Record& data_end = records.back();
  ASSERT_EQ(data_end.opcode, op(McapOpcode::DataEnd));
  EXPECT_EQ(Cursor{data_end.content}.get<std::uint32_t>(),
            mcap_crc32(data.substr(0, data_end.start)));

  struct ChunkSeen {
    std::size_t start, length;
    std::uint64_t first, last;
    std::map<std::uint16_t, std::size_t> index_offsets;
    std::size_t index_length = 0;
  };
  std::vector<ChunkSeen> chunks;
  int messages_seen = 0;
  std::map<std::uint16_t, std::uint64_t> per_channel;
  std::string chunk_records;  // the last chunk's, decompressed
  for (std::size_t r = 4; r + 1 < records.size(); ++r) {
    const Record& record = records[r];
    if (record.opcode == op(McapOpcode::Chunk)) {
      Cursor c{record.content};
      const auto first = c.get<std::uint64_t>();
      const auto last = c.get<std::uint64_t>();
      const auto uncompressed_size = c.get<std::uint64_t>();
      const auto crc = c.get<std::uint32_t>();
      const std::string compression = c.string();
      const auto size = c.get<std::uint64_t>();
      const std::string_view stored = record.content.substr(c.at, size);
      EXPECT_EQ(c.at + size, record.content.size());
      if (GetParam() == McapCompression::Zstd) {
        EXPECT_EQ(compression, "zstd");
        chunk_records.assign(uncompressed_size, '\0');
        const std::size_t got = ZSTD_decompress(chunk_records.data(), chunk_records.size(),
                                                stored.data(), stored.size());
        ASSERT_FALSE(ZSTD_isError(got));
        ASSERT_EQ(got, uncompressed_size);
      } else {
        EXPECT_EQ(compression, "");
        chunk_records.assign(stored);
        EXPECT_EQ(chunk_records.size(), uncompressed_size);
      }
      EXPECT_EQ(crc, mcap_crc32(chunk_records));
      for (const Record& m : records_of(chunk_records, 0, chunk_records.size())) {
        ASSERT_EQ(m.opcode, op(McapOpcode::Message));
        ++messages_seen;
      }
      chunks.push_back({record.start, record.content.size() + 9, first, last, {}, 0});
    } else {
      ASSERT_EQ(record.opcode, op(McapOpcode::MessageIndex));
      ASSERT_FALSE(chunks.empty());
      Cursor c{record.content};
      const auto channel = c.get<std::uint16_t>();
      chunks.back().index_offsets[channel] = record.start;
      chunks.back().index_length += record.content.size() + 9;
      const auto bytes = c.get<std::uint32_t>();
      EXPECT_EQ(bytes % 16, 0U);
      for (std::uint32_t k = 0; k < bytes / 16; ++k) {
        const auto time = c.get<std::uint64_t>();
        const auto offset = c.get<std::uint64_t>();
        // The offset lands on a Message record of this channel at this time, in the chunk.
        Cursor m{chunk_records, offset};
        ASSERT_EQ(m.get<std::uint8_t>(), op(McapOpcode::Message));
        m.get<std::uint64_t>();
        EXPECT_EQ(m.get<std::uint16_t>(), channel);
        m.get<std::uint32_t>();  // sequence
        EXPECT_EQ(m.get<std::uint64_t>(), time);
        EXPECT_GE(time, chunks.back().first);
        EXPECT_LE(time, chunks.back().last);
        ++per_channel[channel];
      }
    }
  }
  EXPECT_GE(chunks.size(), 3U);
  EXPECT_EQ(messages_seen, messages);
  EXPECT_EQ(per_channel[0], 13U);
  EXPECT_EQ(per_channel[1], 12U);

  // The summary: Schema, Channels, Statistics, Chunk Indexes; then one Summary Offset per group.
  const std::vector<Record> summary = records_of(data, summary_start, summary_offset_start);
  ASSERT_EQ(summary.size(), 1 + 2 + 1 + chunks.size());
  EXPECT_EQ(summary[0].opcode, op(McapOpcode::Schema));
  EXPECT_EQ(summary[0].content, records[1].content);
  EXPECT_EQ(summary[1].content, records[2].content);
  ASSERT_EQ(summary[3].opcode, op(McapOpcode::Statistics));
  Cursor s{summary[3].content};
  EXPECT_EQ(s.get<std::uint64_t>(), std::uint64_t(messages));
  EXPECT_EQ(s.get<std::uint16_t>(), 1U);              // schemas
  EXPECT_EQ(s.get<std::uint32_t>(), 2U);              // channels
  EXPECT_EQ(s.get<std::uint32_t>(), 0U);              // attachments
  EXPECT_EQ(s.get<std::uint32_t>(), 0U);              // metadata
  EXPECT_EQ(s.get<std::uint32_t>(), chunks.size());   // chunks
  EXPECT_EQ(s.get<std::uint64_t>(), 10U);             // message_start_time
  EXPECT_EQ(s.get<std::uint64_t>(), 10U * messages);  // message_end_time
  EXPECT_EQ(s.get<std::uint32_t>(), 20U);             // the map's bytes: 2 × (2 + 8)
  EXPECT_EQ(s.get<std::uint16_t>(), 0U);
  EXPECT_EQ(s.get<std::uint64_t>(), 13U);
  for (std::size_t k = 0; k < chunks.size(); ++k) {
    const Record& index = summary[4 + k];
    ASSERT_EQ(index.opcode, op(McapOpcode::ChunkIndex));
    Cursor c{index.content};
    EXPECT_EQ(c.get<std::uint64_t>(), chunks[k].first);
    EXPECT_EQ(c.get<std::uint64_t>(), chunks[k].last);
    EXPECT_EQ(c.get<std::uint64_t>(), chunks[k].start);
    EXPECT_EQ(c.get<std::uint64_t>(), chunks[k].length);
    const auto map_bytes = c.get<std::uint32_t>();
    EXPECT_EQ(map_bytes, 10U * chunks[k].index_offsets.size());
    for (std::uint32_t e = 0; e < map_bytes / 10; ++e) {
      const auto channel = c.get<std::uint16_t>();
      EXPECT_EQ(c.get<std::uint64_t>(), chunks[k].index_offsets[channel]);
    }
    EXPECT_EQ(c.get<std::uint64_t>(), chunks[k].index_length);
  }
  const std::vector<Record> offsets = records_of(data, summary_offset_start, footer);
  ASSERT_EQ(offsets.size(), 4U);  // schemas, channels, statistics, chunk indexes
  const std::uint8_t groups[] = {op(McapOpcode::Schema), op(McapOpcode::Channel),
                                 op(McapOpcode::Statistics), op(McapOpcode::ChunkIndex)};
  for (std::size_t g = 0; g < offsets.size(); ++g) {
    EXPECT_EQ(offsets[g].opcode, op(McapOpcode::SummaryOffset));
    Cursor c{offsets[g].content};
    EXPECT_EQ(c.get<std::uint8_t>(), groups[g]);
    const auto start = c.get<std::uint64_t>();
    const auto length = c.get<std::uint64_t>();
    const std::vector<Record> group = records_of(data, start, start + length);
    ASSERT_FALSE(group.empty());
    for (const Record& r : group) EXPECT_EQ(r.opcode, groups[g]);
  }
}

INSTANTIATE_TEST_SUITE_P(Compressions,
                         McapLayout,
                         ::testing::Values(McapCompression::None, McapCompression::Zstd));

TEST(McapWithoutMessages, HasNoChunkButAWholeSummary) {
  McapWriter writer("ros2", "rodshape test");
  writer.add_channel(writer.add_schema("pkg/msg/A", "ros2msg", "int32 a\n"), "/a", "cdr");
  const std::string file = writer.finish();
  const std::size_t footer = file.size() - 8 - 29;
  Cursor f{file, footer + 9};
  const auto summary_start = f.get<std::uint64_t>();
  const std::vector<Record> data = records_of(file, 8, summary_start);
  ASSERT_EQ(data.size(), 4U);  // Header, Schema, Channel, Data End
  EXPECT_EQ(data[3].opcode, op(McapOpcode::DataEnd));
}

TEST(McapSignature, AnMcapFileIsRodshapesWhenItsHeaderNamesRodshape) {
  namespace fs = std::filesystem;
  const fs::path directory =
      fs::temp_directory_path() / ("rodshape_mcap_signature_" + std::to_string(::getpid()));
  fs::create_directories(directory);
  const auto write = [&](const std::string& name, const std::string& content) {
    std::ofstream(directory / name, std::ios::binary) << content;
    return (directory / name).string();
  };
  EXPECT_TRUE(is_rodshape_output(write("plan.mcap", McapWriter("ros2", "rodshape 1.2").finish())));
  EXPECT_FALSE(is_rodshape_output(write("other.mcap", McapWriter("ros2", "rosbag2").finish())));
  std::string cut = McapWriter("ros2", "rodshape 1.2").finish().substr(0, 20);
  EXPECT_FALSE(is_rodshape_output(write("cut.mcap", cut)));
  EXPECT_FALSE(is_rodshape_output(write("text.mcap", "rodshape 1.2\n")));
  fs::remove_all(directory);
}

}  // namespace
}  // namespace test_mcap_writer
}  // namespace rodshape
