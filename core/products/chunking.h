#pragma once

// Splitting a payload into product_chunk_t messages and putting them back together. Pure logic:
// no bus, no clock, so it is unit-tested on its own.

#include <avc/product_chunk_t.hpp>
#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <unordered_set>
#include <vector>

#include "core/products/product.h"

namespace avc::products {

// Bytes of payload per chunk so that the encoded chunk (payload + strings + fixed fields) stays
// within max_message_bytes.
size_t ChunkPayloadBytes(size_t max_message_bytes, const Product& product);

// The chunks of product, in order, with attempt 0. Headers are left for the bus to stamp.
std::vector<avc::product_chunk_t> SplitIntoChunks(const Product& product, size_t max_message_bytes);

// Collects chunks per product id, checks them, and reports each product complete exactly once.
class Reassembler {
 public:
  enum class Status {
    kIncomplete,  // chunk stored, more to come (Missing() lists what is still needed)
    kComplete,    // all chunks arrived and sha256 matched: product is set
    kDuplicate,   // the product was already completed earlier: acknowledge again, deliver nothing
    kCorrupt,     // all chunks arrived but sha256 differs: the partial data was dropped
    kInvalid,     // the chunk contradicts itself or earlier chunks: error says how
  };
  struct Outcome {
    Status status = Status::kInvalid;
    std::optional<Product> product;
    std::string error;
  };

  // remember_completed: how many completed ids are kept for deduplication.
  explicit Reassembler(size_t remember_completed = 8192, size_t max_pending_bytes = 1ull << 30);

  Outcome Add(const avc::product_chunk_t& chunk);
  // Chunk indices not yet received for a pending product (empty if unknown or complete). Linear
  // in the product's chunk count, so a receiver asks only when it acknowledges, not per chunk.
  std::vector<int32_t> Missing(const std::string& product_id) const;
  bool IsCompleted(const std::string& product_id) const;
  // Forgets that a product was completed, so a retransmission delivers it again (used when the
  // consumer failed to store it).
  void ForgetCompleted(const std::string& product_id);
  size_t pending_products() const { return pending_.size(); }

 private:
  struct Pending {
    Product product;
    int32_t chunk_count = 0;
    std::vector<bool> have;
    int32_t received = 0;
    uint64_t arrival = 0;  // for evicting the oldest when over max_pending_bytes
  };
  void RememberCompleted(const std::string& product_id);
  void EvictOldestPending();

  size_t remember_completed_;
  size_t max_pending_bytes_;
  size_t pending_bytes_ = 0;
  uint64_t arrivals_ = 0;
  std::map<std::string, Pending> pending_;
  std::unordered_set<std::string> completed_;
  std::deque<std::string> completed_order_;
};

}  // namespace avc::products
