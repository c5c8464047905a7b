#include "core/util/sha256.h"

#include <gtest/gtest.h>

#include <vector>

namespace avc {
namespace {

// Reference digests from FIPS 180-2 examples.
TEST(Sha256, MatchesKnownDigests) {
  EXPECT_EQ(Sha256Hex(std::string_view("")),
            "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(Sha256Hex(std::string_view("abc")),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

TEST(Sha256, ChangesWithOneBit) {
  std::vector<uint8_t> bytes(1 << 20, 7);
  const std::string before = Sha256Hex(bytes);
  bytes[12345] ^= 1;
  EXPECT_NE(before, Sha256Hex(bytes));
}

}  // namespace
}  // namespace avc
