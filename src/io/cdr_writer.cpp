// cdr_writer.cpp: CDR version 1, little endian (cdr_writer.hpp).
#include "rodshape/io/cdr_writer.hpp"

#include <bit>
#include <cstring>
#include <limits>

#include "rodshape/error.hpp"

namespace rodshape {

static_assert(std::endian::native == std::endian::little,
              "CdrWriter copies values in the host's byte order, which must be CDR_LE's");

CdrWriter::CdrWriter() : buffer_{'\x00', '\x01', '\x00', '\x00'} {}

void CdrWriter::align(std::size_t size) {
  const std::size_t padding = (size - offset() % size) % size;
  buffer_.append(padding, '\0');
}

void CdrWriter::append(const void* data, std::size_t size) {
  buffer_.append(static_cast<const char*>(data), size);
}

void CdrWriter::write_bool(bool value) { write_uint8(value ? 1 : 0); }

void CdrWriter::write_uint8(std::uint8_t value) { append(&value, 1); }

void CdrWriter::write_int32(std::int32_t value) {
  align(4);
  append(&value, 4);
}

void CdrWriter::write_uint32(std::uint32_t value) {
  align(4);
  append(&value, 4);
}

void CdrWriter::write_float32(float value) {
  align(4);
  append(&value, 4);
}

void CdrWriter::write_float64(double value) {
  align(8);
  append(&value, 8);
}

void CdrWriter::write_length(std::size_t count) {
  if (count > std::numeric_limits<std::uint32_t>::max())
    throw InputError("CDR: a sequence of " + std::to_string(count) +
                     " elements is longer than its uint32 length allows");
  write_uint32(static_cast<std::uint32_t>(count));
}

void CdrWriter::write_string(std::string_view value) {
  write_length(value.size() + 1);
  append(value.data(), value.size());
  buffer_.push_back('\0');
}

void CdrWriter::write_float64_sequence(std::span<const double> values) {
  write_length(values.size());
  if (values.empty()) return;
  align(8);
  append(values.data(), values.size() * sizeof(double));
}

void CdrWriter::write_uint8_sequence(std::string_view bytes) {
  write_length(bytes.size());
  append(bytes.data(), bytes.size());
}

}  // namespace rodshape
