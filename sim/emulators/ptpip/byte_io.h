#pragma once

// Little-endian writer and bounds-checked reader for PTP and PTP/IP payloads, including PTP
// strings (uint8 count of UTF-16 units with the terminating NUL, then the units) and arrays
// (uint32 count, then elements). Reading past the end throws PtpDecodeError naming the payload
// and the field instead of touching memory it does not own.

#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace avc::sim::ptp {

class PtpDecodeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ByteWriter {
 public:
  void U8(uint8_t v);
  void U16(uint16_t v);
  void U32(uint32_t v);
  void U64(uint64_t v);
  void Bytes(std::span<const uint8_t> bytes);
  // PTP string from UTF-8 (code points beyond the BMP become '?'); at most 254 units, else
  // std::invalid_argument. The empty string is the single byte 0.
  void PtpString(std::string_view utf8);
  // NUL-terminated UTF-16LE without a count (PTP/IP host and camera names).
  void Utf16Z(std::string_view utf8);
  void U16Array(std::span<const uint16_t> values);
  void U32Array(std::span<const uint32_t> values);

  const std::vector<uint8_t>& bytes() const { return bytes_; }
  std::vector<uint8_t> Take() { return std::move(bytes_); }

 private:
  std::vector<uint8_t> bytes_;
};

class ByteReader {
 public:
  // `what` names the payload in error messages, e.g. "PTP ObjectInfo".
  ByteReader(std::span<const uint8_t> data, std::string what);

  uint8_t U8(std::string_view field);
  uint16_t U16(std::string_view field);
  uint32_t U32(std::string_view field);
  uint64_t U64(std::string_view field);
  std::vector<uint8_t> Bytes(size_t count, std::string_view field);
  std::string PtpString(std::string_view field);
  std::string Utf16Z(std::string_view field);
  std::vector<uint16_t> U16Array(std::string_view field);
  std::vector<uint32_t> U32Array(std::string_view field);
  std::vector<uint8_t> Rest();

  size_t remaining() const { return data_.size() - offset_; }
  // Throws unless every byte was consumed (a longer payload than the format means a bug).
  void ExpectEnd() const;

 private:
  void Need(size_t count, std::string_view field) const;

  std::span<const uint8_t> data_;
  std::string what_;
  size_t offset_ = 0;
};

}  // namespace avc::sim::ptp
