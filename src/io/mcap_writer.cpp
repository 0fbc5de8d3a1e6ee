// mcap_writer.cpp: the MCAP records (mcap_writer.hpp; the field lists are the specification's,
// github.com/foxglove/mcap specification/README.md, "Records").
#include "rodshape/io/mcap_writer.hpp"

#include <zstd.h>

#include <algorithm>
#include <array>
#include <bit>
#include <limits>

#include "rodshape/error.hpp"

namespace rodshape {

static_assert(
    std::endian::native == std::endian::little,
    "the MCAP writer copies integers in the host's byte order, which must be little endian");

namespace {

/// The table of the reflected polynomial 0xEDB88320, one entry per byte value.
constexpr std::array<std::uint32_t, 256> mcap_crc_table() {
  std::array<std::uint32_t, 256> table{};
  for (std::uint32_t i = 0; i < 256; ++i) {
    std::uint32_t c = i;
    for (int k = 0; k < 8; ++k) c = (c & 1U) ? 0xEDB88320U ^ (c >> 1) : c >> 1;
    table[i] = c;
  }
  return table;
}
constexpr std::array<std::uint32_t, 256> kMcapCrcTable = mcap_crc_table();

template <typename Integer>
void mcap_put(std::string& out, Integer value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof(value));
}

void put_mcap_string(std::string& out, std::string_view value) {
  mcap_put(out, static_cast<std::uint32_t>(value.size()));
  out.append(value);
}

/// A record: opcode, content length, content.
void put_mcap_record(std::string& out, McapOpcode opcode, std::string_view content) {
  mcap_put(out, static_cast<std::uint8_t>(opcode));
  mcap_put(out, static_cast<std::uint64_t>(content.size()));
  out.append(content);
}

std::string_view mcap_compression_field(McapCompression compression) {
  return compression == McapCompression::Zstd ? "zstd" : "";
}

std::string zstd_compressed(std::string_view data) {
  std::string out(ZSTD_compressBound(data.size()), '\0');
  const std::size_t size =
      ZSTD_compress(out.data(), out.size(), data.data(), data.size(), ZSTD_CLEVEL_DEFAULT);
  if (ZSTD_isError(size))
    throw std::runtime_error(std::string("MCAP: zstd compression failed: ") +
                             ZSTD_getErrorName(size));
  out.resize(size);
  return out;
}

}  // namespace

std::uint32_t mcap_crc32(std::string_view bytes, std::uint32_t crc) {
  crc = ~crc;
  for (const char byte : bytes)
    crc = kMcapCrcTable[(crc ^ static_cast<unsigned char>(byte)) & 0xFFU] ^ (crc >> 8);
  return ~crc;
}

McapWriter::McapWriter(std::string_view profile, std::string_view library, McapOptions options)
    : options_(options) {
  file_.append(kMcapMagic);
  std::string header;
  put_mcap_string(header, profile);
  put_mcap_string(header, library);
  put_mcap_record(file_, McapOpcode::Header, header);
}

std::uint16_t McapWriter::add_schema(std::string_view name,
                                     std::string_view encoding,
                                     std::string_view data) {
  if (schemas_.size() >= std::numeric_limits<std::uint16_t>::max())
    throw InputError("MCAP: too many schemas");
  const auto id = static_cast<std::uint16_t>(schemas_.size() + 1);  // 0 means "no schema"
  std::string content;
  mcap_put(content, id);
  put_mcap_string(content, name);
  put_mcap_string(content, encoding);
  put_mcap_string(content, data);  // uint32 length and bytes, as a string
  std::string record;
  put_mcap_record(record, McapOpcode::Schema, content);
  file_.append(record);  // in the data section, before any message may need it
  schemas_.push_back(std::move(record));
  return id;
}

std::uint16_t McapWriter::add_channel(std::uint16_t schema_id,
                                      std::string_view topic,
                                      std::string_view message_encoding) {
  if (channels_.size() >= std::numeric_limits<std::uint16_t>::max())
    throw InputError("MCAP: too many channels");
  const auto id = static_cast<std::uint16_t>(channels_.size());
  std::string content;
  mcap_put(content, id);
  mcap_put(content, schema_id);
  put_mcap_string(content, topic);
  put_mcap_string(content, message_encoding);
  mcap_put(content, std::uint32_t{0});  // metadata: an empty map
  std::string record;
  put_mcap_record(record, McapOpcode::Channel, content);
  file_.append(record);
  channels_.push_back(std::move(record));
  sequences_.push_back(0);
  message_counts_[id] = 0;
  return id;
}

void McapWriter::add_message(std::uint16_t channel, std::uint64_t log_time, std::string_view data) {
  if (channel >= channels_.size()) throw InputError("MCAP: a message on an unknown channel");
  if (chunk_.empty()) chunk_start_ = chunk_end_ = log_time;
  chunk_start_ = std::min(chunk_start_, log_time);
  chunk_end_ = std::max(chunk_end_, log_time);
  if (message_count_ == 0) start_time_ = end_time_ = log_time;
  start_time_ = std::min(start_time_, log_time);
  end_time_ = std::max(end_time_, log_time);
  ++message_count_;
  ++message_counts_[channel];
  chunk_entries_[channel].push_back({log_time, chunk_.size()});  // offset in the chunk's records
  std::string content;
  mcap_put(content, channel);
  mcap_put(content, sequences_[channel]++);
  mcap_put(content, log_time);
  mcap_put(content, log_time);  // publish_time
  content.append(data);
  put_mcap_record(chunk_, McapOpcode::Message, content);
  if (chunk_.size() >= options_.chunk_size) flush_chunk();
}

void McapWriter::flush_chunk() {
  if (chunk_.empty()) return;
  const std::string compressed =
      options_.compression == McapCompression::Zstd ? zstd_compressed(chunk_) : std::string();
  const std::string_view records = options_.compression == McapCompression::Zstd
                                       ? std::string_view(compressed)
                                       : std::string_view(chunk_);
  ChunkIndex index{};
  index.start_time = chunk_start_;
  index.end_time = chunk_end_;
  index.offset = file_.size();
  index.compressed_size = records.size();
  index.uncompressed_size = chunk_.size();
  std::string content;
  mcap_put(content, chunk_start_);
  mcap_put(content, chunk_end_);
  mcap_put(content, static_cast<std::uint64_t>(chunk_.size()));
  mcap_put(content, mcap_crc32(chunk_));  // of the uncompressed records
  put_mcap_string(content, mcap_compression_field(options_.compression));
  mcap_put(content, static_cast<std::uint64_t>(records.size()));
  content.append(records);
  put_mcap_record(file_, McapOpcode::Chunk, content);
  index.length = file_.size() - index.offset;
  const std::uint64_t indexes_start = file_.size();
  for (const auto& [channel, entries] : chunk_entries_) {  // by channel id
    index.message_index_offsets[channel] = file_.size();
    std::string message_index;
    mcap_put(message_index, channel);
    mcap_put(message_index, static_cast<std::uint32_t>(entries.size() * 16));
    for (const Entry& entry : entries) {
      mcap_put(message_index, entry.log_time);
      mcap_put(message_index, entry.offset);
    }
    put_mcap_record(file_, McapOpcode::MessageIndex, message_index);
  }
  index.message_index_length = file_.size() - indexes_start;
  chunk_indexes_.push_back(std::move(index));
  chunk_.clear();
  chunk_entries_.clear();
}

std::string McapWriter::finish() {
  flush_chunk();
  std::string data_end;
  mcap_put(data_end, mcap_crc32(file_));  // every byte before the Data End record, magic included
  put_mcap_record(file_, McapOpcode::DataEnd, data_end);

  const std::uint64_t summary_start = file_.size();
  struct Group {
    McapOpcode opcode;
    std::uint64_t start, length;
  };
  std::vector<Group> groups;
  const auto group = [&](McapOpcode opcode, const auto& write) {
    const std::uint64_t start = file_.size();
    write();
    if (file_.size() > start) groups.push_back({opcode, start, file_.size() - start});
  };
  group(McapOpcode::Schema, [&] {
    for (const std::string& record : schemas_) file_.append(record);
  });
  group(McapOpcode::Channel, [&] {
    for (const std::string& record : channels_) file_.append(record);
  });
  group(McapOpcode::Statistics, [&] {
    std::string content;
    mcap_put(content, message_count_);
    mcap_put(content, static_cast<std::uint16_t>(schemas_.size()));
    mcap_put(content, static_cast<std::uint32_t>(channels_.size()));
    mcap_put(content, std::uint32_t{0});  // attachments
    mcap_put(content, std::uint32_t{0});  // metadata
    mcap_put(content, static_cast<std::uint32_t>(chunk_indexes_.size()));
    mcap_put(content, start_time_);
    mcap_put(content, end_time_);
    mcap_put(content, static_cast<std::uint32_t>(message_counts_.size() * 10));
    for (const auto& [channel, count] : message_counts_) {
      mcap_put(content, channel);
      mcap_put(content, count);
    }
    put_mcap_record(file_, McapOpcode::Statistics, content);
  });
  group(McapOpcode::ChunkIndex, [&] {
    for (const ChunkIndex& index : chunk_indexes_) {
      std::string content;
      mcap_put(content, index.start_time);
      mcap_put(content, index.end_time);
      mcap_put(content, index.offset);
      mcap_put(content, index.length);
      mcap_put(content, static_cast<std::uint32_t>(index.message_index_offsets.size() * 10));
      for (const auto& [channel, offset] : index.message_index_offsets) {
        mcap_put(content, channel);
        mcap_put(content, offset);
      }
      mcap_put(content, index.message_index_length);
      put_mcap_string(content, mcap_compression_field(options_.compression));
      mcap_put(content, index.compressed_size);
      mcap_put(content, index.uncompressed_size);
      put_mcap_record(file_, McapOpcode::ChunkIndex, content);
    }
  });
  const std::uint64_t summary_offset_start = file_.size();
  for (const Group& g : groups) {
    std::string content;
    mcap_put(content, static_cast<std::uint8_t>(g.opcode));
    mcap_put(content, g.start);
    mcap_put(content, g.length);
    put_mcap_record(file_, McapOpcode::SummaryOffset, content);
  }
  // Footer: its CRC covers the summary section, the summary offsets and the footer up to the CRC.
  mcap_put(file_, static_cast<std::uint8_t>(McapOpcode::Footer));
  mcap_put(file_, std::uint64_t{20});
  mcap_put(file_, summary_start);
  mcap_put(file_, summary_offset_start);
  mcap_put(file_, mcap_crc32(std::string_view(file_).substr(summary_start)));
  file_.append(kMcapMagic);
  std::string out = std::move(file_);
  file_.clear();
  return out;
}

}  // namespace rodshape
