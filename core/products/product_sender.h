#pragma once

// Sends products reliably: chunks under the bus cap on the bulk URL, paced, with a window of
// unacknowledged bytes; resends what receivers report missing, and everything unacknowledged
// after a timeout that doubles per attempt; gives up after max_attempts with a clear error.

#include <atomic>
#include <avc/product_ack_t.hpp>
#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include "core/bus/bus.h"
#include "core/bus/event_loop.h"
#include "core/products/product.h"

namespace avc::products {

struct SenderOptions {
  // Receivers that must acknowledge each product. Empty: the first COMPLETE ack from anyone.
  std::vector<std::string> required_receivers;
  std::chrono::milliseconds initial_timeout{250};  // before the first retransmission
  std::chrono::milliseconds max_timeout{4000};     // the timeout doubles per attempt up to this
  int max_attempts = 12;                           // transmissions before giving up
  double max_bytes_per_second = 200e6;             // pacing: a flat-out sender overruns receivers
  size_t max_in_flight_bytes = 48'000'000;         // unacknowledged bytes before Send() queues
  // Largest chunk message; 0: the bus's cap. Smaller chunks fit receive buffers smaller than a
  // product (a lost fragment then costs one chunk) and keep a recorded log playable.
  size_t max_chunk_bytes = 0;

  std::string Validate() const;
};

struct SendResult {
  std::string product_id;
  std::string name;
  bool ok = false;
  int attempts = 0;        // transmissions of the product (1 = no retransmission)
  int64_t latency_us = 0;  // Send() to the last required ack
  std::string error;       // why it failed, naming the product and the silent receivers
};

struct SenderStats {
  int64_t products_sent = 0;
  int64_t products_acknowledged = 0;
  int64_t products_failed = 0;
  int64_t chunks_sent = 0;
  int64_t chunks_retransmitted = 0;
};

class ProductSender {
 public:
  using DoneCallback = std::function<void(const SendResult&)>;

  // Must be used from loop's thread (Send may be called from others: it posts to the loop).
  ProductSender(bus::Bus& bus, bus::EventLoop& loop, SenderOptions options = {});
  ~ProductSender();
  ProductSender(const ProductSender&) = delete;
  ProductSender& operator=(const ProductSender&) = delete;

  // Queues a product for channel (e.g. channels::kProductImage). Returns its product id.
  // done runs on the loop thread once every required receiver acknowledged, or on failure.
  std::string Send(std::string_view channel, std::string name, std::string content_type,
                   std::vector<uint8_t> payload, DoneCallback done = {});

  // Encodes msg (an AVC LCM message) and sends it as a product.
  template <class T>
  std::string SendMessage(std::string_view channel, std::string name, const T& msg,
                          DoneCallback done = {}) {
    std::vector<uint8_t> payload(static_cast<size_t>(msg.getEncodedSize()));
    msg.encode(payload.data(), 0, static_cast<int>(payload.size()));
    return Send(channel, std::move(name), ContentTypeOf<T>(), std::move(payload), std::move(done));
  }

  // Products queued or awaiting acknowledgement. Safe from any thread.
  size_t pending() const { return pending_.load(); }
  // Loop thread only.
  const SenderStats& stats() const { return stats_; }

 private:
  struct Outgoing;
  void Pump();
  void Admit();
  void TransmitQueued();
  void OnAck(const avc::product_ack_t& ack);
  void CheckTimeouts();
  void StartRound(Outgoing& outgoing, const std::vector<int32_t>& chunks);
  std::vector<int32_t> ChunksStillNeeded(const Outgoing& outgoing) const;
  bool IsSatisfied(const Outgoing& outgoing) const;
  void Finish(const std::string& product_id, bool ok, std::string error);

  bus::Bus& bus_;
  bus::EventLoop& loop_;
  SenderOptions options_;
  std::string incarnation_;
  uint64_t next_number_ = 1;
  size_t chunk_payload_bytes_ = 0;

  mutable std::mutex queue_mutex_;
  std::deque<std::unique_ptr<Outgoing>> queue_;  // guarded by queue_mutex_ (Send may be off-loop)
  std::atomic<size_t> pending_{0};

  // Loop thread only from here on.
  std::map<std::string, std::unique_ptr<Outgoing>> in_flight_;
  size_t in_flight_bytes_ = 0;
  std::deque<std::pair<std::string, int32_t>> transmit_queue_;  // (product id, chunk index)
  double tokens_ = 0;  // pacing budget in bytes; may go negative after a large chunk
  int64_t last_refill_us_ = 0;
  bool pump_scheduled_ = false;
  bus::EventLoop::TimerId pump_timer_ = 0;
  bus::EventLoop::TimerId timeout_timer_ = 0;
  bus::Bus::SubscriptionId ack_subscription_ = 0;
  // Work posted to the loop checks this is still alive before touching the sender.
  std::shared_ptr<int> alive_ = std::make_shared<int>(0);
  SenderStats stats_;
};

}  // namespace avc::products
