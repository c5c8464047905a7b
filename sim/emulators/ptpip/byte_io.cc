#include "sim/emulators/ptpip/byte_io.h"

#include <fmt/format.h>

namespace avc::sim::ptp {
namespace {

// UTF-8 to UTF-16 code units; anything outside the BMP or malformed becomes '?'.
std::vector<uint16_t> ToUtf16(std::string_view utf8) {
  std::vector<uint16_t> units;
  size_t i = 0;
  while (i < utf8.size()) {
    const auto c = static_cast<uint8_t>(utf8[i]);
    uint32_t code = '?';
    size_t length = 1;
    if (c < 0x80) {
      code = c;
    } else if ((c & 0xE0) == 0xC0 && i + 1 < utf8.size()) {
      code = ((c & 0x1Fu) << 6) | (static_cast<uint8_t>(utf8[i + 1]) & 0x3Fu);
      length = 2;
    } else if ((c & 0xF0) == 0xE0 && i + 2 < utf8.size()) {
      code = ((c & 0x0Fu) << 12) | ((static_cast<uint8_t>(utf8[i + 1]) & 0x3Fu) << 6) |
             (static_cast<uint8_t>(utf8[i + 2]) & 0x3Fu);
      length = 3;
    } else if ((c & 0xF8) == 0xF0) {
      length = 4;  // beyond the BMP: stays '?'
    }
    units.push_back(static_cast<uint16_t>(code));
    i += length;
  }
  return units;
}

void AppendUtf8(uint16_t unit, std::string& out) {
  if (unit < 0x80) {
    out.push_back(static_cast<char>(unit));
  } else if (unit < 0x800) {
    out.push_back(static_cast<char>(0xC0 | (unit >> 6)));
    out.push_back(static_cast<char>(0x80 | (unit & 0x3F)));
  } else {
    out.push_back(static_cast<char>(0xE0 | (unit >> 12)));
    out.push_back(static_cast<char>(0x80 | ((unit >> 6) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | (unit & 0x3F)));
  }
}

}  // namespace

void ByteWriter::U8(uint8_t v) { bytes_.push_back(v); }

void ByteWriter::U16(uint16_t v) {
  bytes_.push_back(static_cast<uint8_t>(v));
  bytes_.push_back(static_cast<uint8_t>(v >> 8));
}

void ByteWriter::U32(uint32_t v) {
  for (int shift = 0; shift < 32; shift += 8) bytes_.push_back(static_cast<uint8_t>(v >> shift));
}

void ByteWriter::U64(uint64_t v) {
  for (int shift = 0; shift < 64; shift += 8) bytes_.push_back(static_cast<uint8_t>(v >> shift));
}

void ByteWriter::Bytes(std::span<const uint8_t> bytes) {
  bytes_.insert(bytes_.end(), bytes.begin(), bytes.end());
}

void ByteWriter::PtpString(std::string_view utf8) {
  if (utf8.empty()) {
    U8(0);
    return;
  }
  const std::vector<uint16_t> units = ToUtf16(utf8);
  if (units.size() > 254) {
    throw std::invalid_argument(
        fmt::format("PTP string of {} characters is longer than the 254 PTP allows", units.size()));
  }
  U8(static_cast<uint8_t>(units.size() + 1));
  for (uint16_t unit : units) U16(unit);
  U16(0);
}

void ByteWriter::Utf16Z(std::string_view utf8) {
  for (uint16_t unit : ToUtf16(utf8)) U16(unit);
  U16(0);
}

void ByteWriter::U16Array(std::span<const uint16_t> values) {
  U32(static_cast<uint32_t>(values.size()));
  for (uint16_t v : values) U16(v);
}

void ByteWriter::U32Array(std::span<const uint32_t> values) {
  U32(static_cast<uint32_t>(values.size()));
  for (uint32_t v : values) U32(v);
}

ByteReader::ByteReader(std::span<const uint8_t> data, std::string what)
    : data_(data), what_(std::move(what)) {}

void ByteReader::Need(size_t count, std::string_view field) const {
  if (count > remaining()) {
    throw PtpDecodeError(
        fmt::format("{}: truncated at field '{}' (needs {} bytes at offset {}, {} left)", what_,
                    field, count, offset_, remaining()));
  }
}

uint8_t ByteReader::U8(std::string_view field) {
  Need(1, field);
  return data_[offset_++];
}

uint16_t ByteReader::U16(std::string_view field) {
  Need(2, field);
  const uint16_t v = static_cast<uint16_t>(data_[offset_] | (data_[offset_ + 1] << 8));
  offset_ += 2;
  return v;
}

uint32_t ByteReader::U32(std::string_view field) {
  Need(4, field);
  uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | data_[offset_ + static_cast<size_t>(i)];
  offset_ += 4;
  return v;
}

uint64_t ByteReader::U64(std::string_view field) {
  Need(8, field);
  uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = (v << 8) | data_[offset_ + static_cast<size_t>(i)];
  offset_ += 8;
  return v;
}

std::vector<uint8_t> ByteReader::Bytes(size_t count, std::string_view field) {
  Need(count, field);
  std::vector<uint8_t> out(data_.begin() + static_cast<ptrdiff_t>(offset_),
                           data_.begin() + static_cast<ptrdiff_t>(offset_ + count));
  offset_ += count;
  return out;
}

std::string ByteReader::PtpString(std::string_view field) {
  const uint8_t count = U8(field);
  std::string out;
  if (count == 0) return out;
  Need(size_t{count} * 2, field);
  for (uint8_t i = 0; i < count; ++i) {
    const uint16_t unit = U16(field);
    if (unit == 0) {
      if (i + 1 != count) {
        throw PtpDecodeError(fmt::format("{}: field '{}' has a NUL at character {} of {}", what_,
                                         field, i + 1, count));
      }
      break;
    }
    AppendUtf8(unit, out);
  }
  return out;
}

std::string ByteReader::Utf16Z(std::string_view field) {
  std::string out;
  while (true) {
    const uint16_t unit = U16(field);
    if (unit == 0) return out;
    AppendUtf8(unit, out);
  }
}

std::vector<uint16_t> ByteReader::U16Array(std::string_view field) {
  const uint32_t count = U32(field);
  Need(size_t{count} * 2, field);
  std::vector<uint16_t> out(count);
  for (auto& v : out) v = U16(field);
  return out;
}

std::vector<uint32_t> ByteReader::U32Array(std::string_view field) {
  const uint32_t count = U32(field);
  Need(size_t{count} * 4, field);
  std::vector<uint32_t> out(count);
  for (auto& v : out) v = U32(field);
  return out;
}

std::vector<uint8_t> ByteReader::Rest() { return Bytes(remaining(), "rest"); }

void ByteReader::ExpectEnd() const {
  if (remaining() != 0) {
    throw PtpDecodeError(
        fmt::format("{}: {} unexpected trailing bytes at offset {}", what_, remaining(), offset_));
  }
}

}  // namespace avc::sim::ptp
