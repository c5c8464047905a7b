#pragma once

// Receives products: reassembles chunks, verifies sha256, acknowledges on PRODUCT_ACK (COMPLETE,
// PARTIAL with the missing chunks, or CORRUPT) and hands each product to the handler exactly
// once, however often the producer retransmits.

#include <functional>
#include <string>

#include "core/bus/bus.h"
#include "core/products/chunking.h"
#include "core/products/product.h"

namespace avc::products {

struct ReceiverStats {
  int64_t chunks = 0;
  int64_t delivered = 0;
  int64_t duplicates = 0;  // chunks of products already delivered
  int64_t corrupt = 0;
  int64_t invalid = 0;
};

class ProductReceiver {
 public:
  using Handler = std::function<void(const Product&, const bus::RxInfo&)>;

  // receiver_name identifies this receiver in acks (producers can require it).
  // channel_pattern is a regex after the cell prefix, e.g. "PRODUCT/IMAGE" or "PRODUCT/.*".
  ProductReceiver(bus::Bus& bus, std::string receiver_name, const std::string& channel_pattern,
                  Handler handler);
  ~ProductReceiver();
  ProductReceiver(const ProductReceiver&) = delete;
  ProductReceiver& operator=(const ProductReceiver&) = delete;

  const ReceiverStats& stats() const { return stats_; }

 private:
  void OnChunk(const avc::product_chunk_t& chunk, const bus::RxInfo& info);
  void Ack(const std::string& product_id, int8_t status, const std::vector<int32_t>& missing);

  bus::Bus& bus_;
  bus::Bus::SubscriptionId subscription_ = 0;
  std::string receiver_name_;
  Handler handler_;
  Reassembler reassembler_;
  ReceiverStats stats_;
};

}  // namespace avc::products
