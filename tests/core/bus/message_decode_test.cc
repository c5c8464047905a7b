// Received bytes that claim more array elements than they carry, or a string length below one,
// are refused before anything is allocated or computed from them (cmake/AvcLcmBoundArrays.cmake
// over lcm-gen's decode), and bus::DecodeMessage turns the generated decode's exceptions into
// refusals: a few hostile bytes cost a receiver nothing.

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <avc/product_chunk_t.hpp>
#include <cstdint>
#include <vector>

#include "core/bus/decode.h"

namespace avc::bus {
namespace {

std::vector<uint8_t> Encode(const avc::product_chunk_t& chunk) {
  std::vector<uint8_t> bytes(static_cast<size_t>(chunk.getEncodedSize()));
  chunk.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

avc::product_chunk_t Chunk() {
  avc::product_chunk_t chunk{};
  chunk.product_id = "p";
  chunk.name = "n";
  chunk.content_type = "t";
  chunk.sha256 = "s";
  chunk.data = {1, 2, 3, 4};
  chunk.size = 4;
  return chunk;
}

TEST(MessageDecode, ValidBytesDecodeAsBefore) {
  avc::product_chunk_t decoded;
  const std::vector<uint8_t> bytes = Encode(Chunk());
  ASSERT_TRUE(DecodeMessage(bytes.data(), bytes.size(), &decoded));
  EXPECT_EQ(decoded.data, (std::vector<uint8_t>{1, 2, 3, 4}));
  EXPECT_FALSE(DecodeMessage(bytes.data(), bytes.size() - 1, &decoded));  // one byte short
}

TEST(MessageDecode, AHugeArrayCountIsRefusedWithoutAllocatingIt) {
  std::vector<uint8_t> bytes = Encode(Chunk());
  // The last field is data[size]: its int32 count (big-endian) sits just before its 4 bytes.
  const size_t count_at = bytes.size() - 4 - 4;
  ASSERT_EQ(bytes[count_at + 3], 4);
  for (const uint32_t claimed : {0x7fffffffu, 0x40000000u, 5u, 0xffffffffu}) {
    bytes[count_at] = static_cast<uint8_t>(claimed >> 24);
    bytes[count_at + 1] = static_cast<uint8_t>(claimed >> 16);
    bytes[count_at + 2] = static_cast<uint8_t>(claimed >> 8);
    bytes[count_at + 3] = static_cast<uint8_t>(claimed);
    // A decode that allocated first would need 1-2 GB: allow this process far less.
    rlimit before{};
    ASSERT_EQ(getrlimit(RLIMIT_AS, &before), 0);
    rlimit tight = before;
    tight.rlim_cur = 768ull << 20;
    ASSERT_EQ(setrlimit(RLIMIT_AS, &tight), 0);
    avc::product_chunk_t decoded;
    const int result = decoded.decode(bytes.data(), 0, static_cast<int>(bytes.size()));
    setrlimit(RLIMIT_AS, &before);
    EXPECT_LT(result, 0) << "claimed " << claimed;
    EXPECT_FALSE(DecodeMessage(bytes.data(), bytes.size(), &decoded));
  }
}

TEST(MessageDecode, AStringLengthOfZeroOrLessIsRefused) {
  std::vector<uint8_t> bytes = Encode(Chunk());
  // After the 8-byte type hash, header_t's utime and seq (8 bytes each), then source's length.
  const size_t length_at = 8 + 8 + 8;
  for (const uint32_t length : {0x80000000u, 0u, 0xffffffffu}) {
    for (int i = 0; i < 4; ++i) bytes[length_at + i] = static_cast<uint8_t>(length >> (24 - 8 * i));
    avc::product_chunk_t decoded;
    EXPECT_LT(decoded.decode(bytes.data(), 0, static_cast<int>(bytes.size())), 0) << length;
  }
}

}  // namespace
}  // namespace avc::bus
