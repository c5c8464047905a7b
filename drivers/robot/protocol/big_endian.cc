#include "drivers/robot/protocol/big_endian.h"

#include <fmt/format.h>

#include <bit>
#include <stdexcept>

namespace avc::robot {

void BigEndianWriter::U16(uint16_t value) {
  U8(static_cast<uint8_t>(value >> 8));
  U8(static_cast<uint8_t>(value));
}

void BigEndianWriter::U32(uint32_t value) {
  U16(static_cast<uint16_t>(value >> 16));
  U16(static_cast<uint16_t>(value));
}

void BigEndianWriter::U64(uint64_t value) {
  U32(static_cast<uint32_t>(value >> 32));
  U32(static_cast<uint32_t>(value));
}

void BigEndianWriter::F32(float value) { U32(std::bit_cast<uint32_t>(value)); }

void BigEndianWriter::F64(double value) { U64(std::bit_cast<uint64_t>(value)); }

void BigEndianReader::Need(size_t count) const {
  if (count > size_ - offset_) {
    throw std::runtime_error(fmt::format("{}: truncated, needs {} more byte(s) at offset {} of {}",
                                         what_, count, offset_, size_));
  }
}

uint8_t BigEndianReader::U8() {
  Need(1);
  return data_[offset_++];
}

uint16_t BigEndianReader::U16() {
  const uint16_t high = U8();
  return static_cast<uint16_t>((high << 8) | U8());
}

uint32_t BigEndianReader::U32() {
  const uint32_t high = U16();
  return (high << 16) | U16();
}

uint64_t BigEndianReader::U64() {
  const uint64_t high = U32();
  return (high << 32) | U32();
}

float BigEndianReader::F32() { return std::bit_cast<float>(U32()); }

double BigEndianReader::F64() { return std::bit_cast<double>(U64()); }

std::string BigEndianReader::Bytes(size_t count) {
  Need(count);
  std::string text(reinterpret_cast<const char*>(data_ + offset_), count);
  offset_ += count;
  return text;
}

}  // namespace avc::robot
