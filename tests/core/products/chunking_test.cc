#include "core/products/chunking.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "core/util/sha256.h"

namespace avc::products {
namespace {

Product MakeProduct(size_t size, const std::string& id = "src/1/1", uint32_t seed = 1) {
  Product product;
  product.product_id = id;
  product.name = "images/view_0001.png";
  product.content_type = "avc.image_t";
  product.payload.resize(size);
  std::mt19937 rng(seed);
  for (auto& byte : product.payload) byte = static_cast<uint8_t>(rng());
  product.sha256 = Sha256Hex(product.payload);
  return product;
}

constexpr size_t kCap = 64 * 1024;

TEST(Chunking, EveryEncodedChunkFitsTheCapWithRoomForTheHeader) {
  const Product product = MakeProduct(1'000'000);
  const auto chunks = SplitIntoChunks(product, kCap);
  ASSERT_GT(chunks.size(), 10u);
  for (auto chunk : chunks) {
    chunk.header.source = std::string(200, 's');
    chunk.header.cell = std::string(16, 'c');
    EXPECT_LE(static_cast<size_t>(chunk.getEncodedSize()), kCap);
  }
}

TEST(Chunking, SizesCoverThePayloadExactly) {
  for (size_t size :
       {size_t{0}, size_t{1}, size_t{5000}, ChunkPayloadBytes(kCap, MakeProduct(1)) * 3}) {
    const Product product = MakeProduct(size);
    const auto chunks = SplitIntoChunks(product, kCap);
    int64_t covered = 0;
    for (const auto& chunk : chunks) {
      EXPECT_EQ(chunk.offset, covered);
      covered += chunk.size;
      EXPECT_EQ(chunk.chunk_count, static_cast<int32_t>(chunks.size()));
    }
    EXPECT_EQ(covered, static_cast<int64_t>(size)) << size;
  }
}

TEST(Reassembler, OutOfOrderChunksGiveTheProductOnce) {
  const Product product = MakeProduct(300'000);
  auto chunks = SplitIntoChunks(product, kCap);
  std::reverse(chunks.begin(), chunks.end());
  Reassembler reassembler;
  for (size_t i = 0; i + 1 < chunks.size(); ++i) {
    const auto outcome = reassembler.Add(chunks[i]);
    EXPECT_EQ(outcome.status, Reassembler::Status::kIncomplete);
    EXPECT_EQ(reassembler.Missing(product.product_id).size(), chunks.size() - i - 1);
  }
  const auto done = reassembler.Add(chunks.back());
  ASSERT_EQ(done.status, Reassembler::Status::kComplete);
  EXPECT_EQ(done.product->payload, product.payload);
  EXPECT_EQ(done.product->name, product.name);
  for (const auto& chunk : chunks) {
    EXPECT_EQ(reassembler.Add(chunk).status, Reassembler::Status::kDuplicate);
  }
  EXPECT_EQ(reassembler.pending_products(), 0u);
}

TEST(Reassembler, DuplicateChunksWhileIncompleteAreHarmless) {
  const Product product = MakeProduct(200'000);
  const auto chunks = SplitIntoChunks(product, kCap);
  Reassembler reassembler;
  reassembler.Add(chunks[0]);
  const auto again = reassembler.Add(chunks[0]);
  EXPECT_EQ(again.status, Reassembler::Status::kIncomplete);
  EXPECT_EQ(reassembler.Missing(product.product_id).front(), 1);
  for (size_t i = 1; i < chunks.size(); ++i) reassembler.Add(chunks[i]);
  EXPECT_TRUE(reassembler.IsCompleted(product.product_id));
}

TEST(Reassembler, CorruptDataIsDetectedAndCanBeResent) {
  const Product product = MakeProduct(200'000);
  auto chunks = SplitIntoChunks(product, kCap);
  auto bad = chunks;
  bad[1].data[17] ^= 0x40;
  Reassembler reassembler;
  Reassembler::Outcome outcome;
  for (const auto& chunk : bad) outcome = reassembler.Add(chunk);
  EXPECT_EQ(outcome.status, Reassembler::Status::kCorrupt);
  EXPECT_NE(outcome.error.find("sha256"), std::string::npos);
  for (const auto& chunk : chunks) outcome = reassembler.Add(chunk);
  ASSERT_EQ(outcome.status, Reassembler::Status::kComplete);
  EXPECT_EQ(outcome.product->payload, product.payload);
}

TEST(Reassembler, SelfContradictingChunksAreRejectedWithReasons) {
  const Product product = MakeProduct(200'000);
  const auto chunks = SplitIntoChunks(product, kCap);
  Reassembler reassembler;
  auto expect_invalid = [&](avc::product_chunk_t chunk, const std::string& words) {
    const auto outcome = reassembler.Add(chunk);
    EXPECT_EQ(outcome.status, Reassembler::Status::kInvalid) << words;
    EXPECT_NE(outcome.error.find(words), std::string::npos) << outcome.error;
  };
  auto c = chunks[0];
  c.chunk_index = c.chunk_count;
  expect_invalid(c, "index outside");
  c = chunks[0];
  c.size += 1;
  expect_invalid(c, "size field");
  c = chunks[0];
  c.offset = c.total_size;
  expect_invalid(c, "outside the");
  c = chunks[0];
  c.sha256 = "xyz";
  expect_invalid(c, "sha256");
  c = chunks[0];
  c.product_id.clear();
  expect_invalid(c, "empty product id");
  c = chunks[0];
  c.chunk_count = static_cast<int32_t>(c.total_size) + 1;
  expect_invalid(c, "chunks for a");
  reassembler.Add(chunks[0]);
  c = chunks[1];
  c.total_size += 10;
  expect_invalid(c, "disagrees with earlier chunks");
}

TEST(Reassembler, OversizedProductIsRefusedAndPendingBytesAreBounded) {
  Reassembler reassembler(/*remember_completed=*/16, /*max_pending_bytes=*/500'000);
  auto huge = SplitIntoChunks(MakeProduct(600'000), kCap);
  EXPECT_EQ(reassembler.Add(huge[0]).status, Reassembler::Status::kInvalid);
  // Two incomplete 300 kB products cannot both be held: the older is evicted.
  auto first = SplitIntoChunks(MakeProduct(300'000, "p/1/1", 1), kCap);
  auto second = SplitIntoChunks(MakeProduct(300'000, "p/1/2", 2), kCap);
  reassembler.Add(first[0]);
  reassembler.Add(second[0]);
  EXPECT_EQ(reassembler.pending_products(), 1u);
  EXPECT_TRUE(reassembler.Missing("p/1/1").empty());
  EXPECT_FALSE(reassembler.Missing("p/1/2").empty());
}

TEST(Reassembler, RemembersABoundedNumberOfCompletedIds) {
  Reassembler reassembler(/*remember_completed=*/3);
  for (int i = 0; i < 5; ++i) {
    const auto chunks = SplitIntoChunks(MakeProduct(10, "p/1/" + std::to_string(i)), kCap);
    ASSERT_EQ(reassembler.Add(chunks[0]).status, Reassembler::Status::kComplete);
  }
  EXPECT_FALSE(reassembler.IsCompleted("p/1/0"));
  EXPECT_FALSE(reassembler.IsCompleted("p/1/1"));
  EXPECT_TRUE(reassembler.IsCompleted("p/1/4"));
}

}  // namespace
}  // namespace avc::products
