#pragma once

// Big-endian (network order) writing and bounds-checked reading of the fixed-width fields every
// UR binary interface (RTDE, primary/secondary) uses.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace avc::robot {

class BigEndianWriter {
 public:
  void U8(uint8_t value) { bytes_.push_back(value); }
  void U16(uint16_t value);
  void U32(uint32_t value);
  void U64(uint64_t value);
  void I32(int32_t value) { U32(static_cast<uint32_t>(value)); }
  void F32(float value);
  void F64(double value);
  void Bytes(std::string_view text) { bytes_.insert(bytes_.end(), text.begin(), text.end()); }

  const std::vector<uint8_t>& bytes() const { return bytes_; }
  std::vector<uint8_t>& bytes() { return bytes_; }

 private:
  std::vector<uint8_t> bytes_;
};

// Reads fields from a byte span; running past the end throws std::runtime_error naming `what`
// (the packet being decoded) and the offset.
class BigEndianReader {
 public:
  BigEndianReader(const uint8_t* data, size_t size, std::string what)
      : data_(data), size_(size), what_(std::move(what)) {}

  uint8_t U8();
  uint16_t U16();
  uint32_t U32();
  uint64_t U64();
  int32_t I32() { return static_cast<int32_t>(U32()); }
  float F32();
  double F64();
  std::string Bytes(size_t count);
  std::string Rest() { return Bytes(Remaining()); }

  size_t Remaining() const { return size_ - offset_; }
  size_t offset() const { return offset_; }

 private:
  void Need(size_t count) const;

  const uint8_t* data_;
  size_t size_;
  std::string what_;
  size_t offset_ = 0;
};

}  // namespace avc::robot
