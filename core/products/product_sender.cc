#include "core/products/product_sender.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <limits>

#include "core/bus/channels.h"
#include "core/products/chunking.h"
#include "core/util/log.h"
#include "core/util/sha256.h"

namespace avc::products {
namespace {

constexpr int64_t kNever = std::numeric_limits<int64_t>::max();
constexpr auto kTimeoutCheckPeriod = std::chrono::milliseconds(20);

}  // namespace

struct ProductSender::Outgoing {
  Product product;
  std::string channel;  // without the cell prefix
  DoneCallback done;
  int32_t chunk_count = 0;
  int64_t start_us = 0;
  int attempts = 0;  // transmission rounds started
  std::chrono::microseconds timeout{};
  int64_t deadline_us = kNever;  // set when the round's last chunk has been published
  int queued_chunks = 0;
  std::vector<bool> queued;  // per chunk: waiting in transmit_queue_
  std::set<std::string> complete_receivers;
  std::map<std::string, std::vector<int32_t>> missing_by_receiver;  // from PARTIAL acks
};

std::string SenderOptions::Validate() const {
  if (initial_timeout.count() <= 0) return "initial_timeout must be positive";
  if (max_timeout < initial_timeout) return "max_timeout must be >= initial_timeout";
  if (max_attempts < 1) return "max_attempts must be >= 1";
  if (max_bytes_per_second <= 0) return "max_bytes_per_second must be positive";
  if (max_in_flight_bytes == 0) return "max_in_flight_bytes must be positive";
  if (max_chunk_bytes != 0 && max_chunk_bytes < 4096) return "max_chunk_bytes must be >= 4096";
  return "";
}

ProductSender::ProductSender(bus::Bus& bus, bus::EventLoop& loop, SenderOptions options)
    : bus_(bus), loop_(loop), options_(std::move(options)) {
  if (const std::string error = options_.Validate(); !error.empty()) {
    throw std::invalid_argument("ProductSender: " + error);
  }
  // Ids must not repeat across restarts of the producer, or receivers would take a new product
  // for a duplicate of an old one.
  incarnation_ = fmt::format("{}-{:x}", getpid(), MonotonicMicros());
  ack_subscription_ = bus_.Subscribe<avc::product_ack_t>(
      channels::kProductAck,
      [this](const avc::product_ack_t& ack, const bus::RxInfo&) { OnAck(ack); });
  timeout_timer_ = loop_.AddTimer(
      kTimeoutCheckPeriod, [this] { CheckTimeouts(); }, true);
  last_refill_us_ = MonotonicMicros();
  tokens_ = static_cast<double>(bus_.options().max_message_bytes);
}

ProductSender::~ProductSender() {
  loop_.CancelTimer(timeout_timer_);
  if (pump_scheduled_) loop_.CancelTimer(pump_timer_);
  bus_.Unsubscribe(ack_subscription_);
  if (pending() > 0) {
    log::Warn("product sender stopped with {} products not acknowledged", pending());
  }
}

std::string ProductSender::Send(std::string_view channel, std::string name,
                                std::string content_type, std::vector<uint8_t> payload,
                                DoneCallback done) {
  auto outgoing = std::make_unique<Outgoing>();
  Product& product = outgoing->product;
  product.name = std::move(name);
  product.content_type = std::move(content_type);
  product.sha256 = Sha256Hex(payload);
  product.source = bus_.options().source;
  product.payload = std::move(payload);
  outgoing->channel = std::string(channel);
  outgoing->done = std::move(done);
  outgoing->start_us = MonotonicMicros();
  outgoing->timeout = options_.initial_timeout;
  {
    std::lock_guard lock(queue_mutex_);
    product.product_id =
        fmt::format("{}/{}/{}", bus_.options().source, incarnation_, next_number_++);
    if (chunk_payload_bytes_ == 0) {
      const size_t cap = bus_.options().max_message_bytes;
      chunk_payload_bytes_ = ChunkPayloadBytes(
          options_.max_chunk_bytes == 0 ? cap : std::min(cap, options_.max_chunk_bytes), product);
    }
    const size_t size = product.payload.size();
    outgoing->chunk_count = static_cast<int32_t>(
        std::max<size_t>(1, (size + chunk_payload_bytes_ - 1) / chunk_payload_bytes_));
    outgoing->queued.assign(static_cast<size_t>(outgoing->chunk_count), false);
    std::string id = product.product_id;
    queue_.push_back(std::move(outgoing));
    ++pending_;
    loop_.Post([this, alive = std::weak_ptr<int>(alive_)] {
      if (alive.lock()) Pump();
    });
    return id;
  }
}

void ProductSender::Pump() {
  pump_scheduled_ = false;
  Admit();
  TransmitQueued();
}

void ProductSender::Admit() {
  std::lock_guard lock(queue_mutex_);
  while (!queue_.empty()) {
    const size_t size = queue_.front()->product.payload.size();
    // A window of unacknowledged bytes: back-pressure from slow receivers instead of loss.
    if (!in_flight_.empty() && in_flight_bytes_ + size > options_.max_in_flight_bytes) break;
    std::unique_ptr<Outgoing> outgoing = std::move(queue_.front());
    queue_.pop_front();
    in_flight_bytes_ += size;
    Outgoing& ref = *outgoing;
    in_flight_.emplace(ref.product.product_id, std::move(outgoing));
    ++stats_.products_sent;
    std::vector<int32_t> all(static_cast<size_t>(ref.chunk_count));
    for (int32_t i = 0; i < ref.chunk_count; ++i) all[static_cast<size_t>(i)] = i;
    StartRound(ref, all);
  }
}

void ProductSender::StartRound(Outgoing& outgoing, const std::vector<int32_t>& chunks) {
  ++outgoing.attempts;
  outgoing.deadline_us = kNever;
  for (int32_t index : chunks) {
    if (index < 0 || index >= outgoing.chunk_count) continue;
    if (outgoing.queued[static_cast<size_t>(index)]) continue;
    outgoing.queued[static_cast<size_t>(index)] = true;
    ++outgoing.queued_chunks;
    transmit_queue_.emplace_back(outgoing.product.product_id, index);
  }
  if (outgoing.queued_chunks == 0) {
    outgoing.deadline_us = MonotonicMicros() + outgoing.timeout.count();
  }
}

void ProductSender::TransmitQueued() {
  const double rate = options_.max_bytes_per_second;
  while (!transmit_queue_.empty()) {
    const int64_t now = MonotonicMicros();
    const double burst = static_cast<double>(bus_.options().max_message_bytes);
    tokens_ = std::min(burst, tokens_ + static_cast<double>(now - last_refill_us_) * rate / 1e6);
    last_refill_us_ = now;
    if (tokens_ < 0) {
      if (!pump_scheduled_) {
        pump_scheduled_ = true;
        const auto wait =
            std::chrono::microseconds(static_cast<int64_t>(-tokens_ / rate * 1e6) + 1);
        pump_timer_ = loop_.AddTimer(wait, [this] { Pump(); });
      }
      return;
    }
    auto [product_id, index] = transmit_queue_.front();
    transmit_queue_.pop_front();
    auto it = in_flight_.find(product_id);
    if (it == in_flight_.end()) continue;  // finished while queued
    Outgoing& outgoing = *it->second;
    outgoing.queued[static_cast<size_t>(index)] = false;
    --outgoing.queued_chunks;

    const Product& product = outgoing.product;
    avc::product_chunk_t chunk{};
    chunk.product_id = product.product_id;
    chunk.name = product.name;
    chunk.content_type = product.content_type;
    chunk.sha256 = product.sha256;
    chunk.total_size = static_cast<int64_t>(product.payload.size());
    chunk.chunk_index = index;
    chunk.chunk_count = outgoing.chunk_count;
    const size_t begin = static_cast<size_t>(index) * chunk_payload_bytes_;
    const size_t end = std::min(product.payload.size(), begin + chunk_payload_bytes_);
    chunk.offset = static_cast<int64_t>(begin);
    chunk.attempt = outgoing.attempts - 1;
    chunk.data.assign(product.payload.begin() + static_cast<std::ptrdiff_t>(begin),
                      product.payload.begin() + static_cast<std::ptrdiff_t>(end));
    chunk.size = static_cast<int32_t>(chunk.data.size());
    try {
      bus_.Publish(outgoing.channel, chunk, bus::Link::kBulk);
    } catch (const bus::BusError& e) {
      // A refused publish is retried by the timeout like a lost one.
      log::Warn("product '{}' chunk {}: {}", product.name, index, e.what());
    }
    ++stats_.chunks_sent;
    if (outgoing.attempts > 1) ++stats_.chunks_retransmitted;
    tokens_ -= static_cast<double>(chunk.data.size());
    if (outgoing.queued_chunks == 0) {
      outgoing.deadline_us = MonotonicMicros() + outgoing.timeout.count();
    }
  }
}

void ProductSender::OnAck(const avc::product_ack_t& ack) {
  auto it = in_flight_.find(ack.product_id);
  if (it == in_flight_.end()) return;  // another producer's, or already finished
  Outgoing& outgoing = *it->second;
  const auto& required = options_.required_receivers;
  const bool counts = required.empty() ||
                      std::find(required.begin(), required.end(), ack.receiver) != required.end();
  if (!counts) return;
  switch (ack.status) {
    case avc::product_ack_t::STATUS_COMPLETE:
      outgoing.complete_receivers.insert(ack.receiver);
      outgoing.missing_by_receiver.erase(ack.receiver);
      if (IsSatisfied(outgoing)) Finish(ack.product_id, true, "");
      return;
    case avc::product_ack_t::STATUS_PARTIAL:
      if (outgoing.complete_receivers.contains(ack.receiver)) return;
      outgoing.missing_by_receiver[ack.receiver] = ack.missing;
      // Resend the gaps at once rather than waiting for the timeout, unless a round is still
      // going out (its own last chunk will bring a fresh report).
      if (outgoing.queued_chunks == 0) {
        if (outgoing.attempts >= options_.max_attempts) return;  // the timeout reports failure
        StartRound(outgoing, ack.missing);
        TransmitQueued();
      }
      return;
    case avc::product_ack_t::STATUS_CORRUPT: {
      outgoing.missing_by_receiver.erase(ack.receiver);
      if (outgoing.queued_chunks == 0 && outgoing.attempts < options_.max_attempts) {
        StartRound(outgoing, ChunksStillNeeded(outgoing));
        TransmitQueued();
      }
      return;
    }
    default:
      return;
  }
}

bool ProductSender::IsSatisfied(const Outgoing& outgoing) const {
  if (options_.required_receivers.empty()) return !outgoing.complete_receivers.empty();
  for (const std::string& receiver : options_.required_receivers) {
    if (!outgoing.complete_receivers.contains(receiver)) return false;
  }
  return true;
}

std::vector<int32_t> ProductSender::ChunksStillNeeded(const Outgoing& outgoing) const {
  std::set<int32_t> needed;
  auto add_all = [&] {
    for (int32_t i = 0; i < outgoing.chunk_count; ++i) needed.insert(i);
  };
  if (options_.required_receivers.empty()) {
    if (outgoing.missing_by_receiver.empty()) {
      add_all();
    } else {
      for (const auto& [receiver, missing] : outgoing.missing_by_receiver) {
        needed.insert(missing.begin(), missing.end());
      }
    }
  } else {
    for (const std::string& receiver : options_.required_receivers) {
      if (outgoing.complete_receivers.contains(receiver)) continue;
      auto it = outgoing.missing_by_receiver.find(receiver);
      if (it == outgoing.missing_by_receiver.end()) {
        add_all();
        break;
      }
      needed.insert(it->second.begin(), it->second.end());
    }
  }
  return {needed.begin(), needed.end()};
}

void ProductSender::CheckTimeouts() {
  const int64_t now = MonotonicMicros();
  std::vector<std::string> failed;
  for (auto& [id, outgoing] : in_flight_) {
    if (outgoing->queued_chunks > 0 || now < outgoing->deadline_us) continue;
    if (outgoing->attempts >= options_.max_attempts) {
      failed.push_back(id);
      continue;
    }
    outgoing->timeout =
        std::min<std::chrono::microseconds>(2 * outgoing->timeout, options_.max_timeout);
    StartRound(*outgoing, ChunksStillNeeded(*outgoing));
  }
  for (const std::string& id : failed) {
    const Outgoing& outgoing = *in_flight_.at(id);
    std::string silent;
    if (options_.required_receivers.empty()) {
      silent = "any receiver";
    } else {
      for (const std::string& receiver : options_.required_receivers) {
        if (outgoing.complete_receivers.contains(receiver)) continue;
        silent += (silent.empty() ? "" : ", ") + receiver;
      }
    }
    Finish(id, false,
           fmt::format("product '{}' on {} was not acknowledged by {} after {} transmissions over "
                       "{:.1f} s: is the receiver running on cell '{}' and reachable on {}?",
                       outgoing.product.name, outgoing.channel, silent, outgoing.attempts,
                       static_cast<double>(now - outgoing.start_us) / 1e6, bus_.cell(),
                       bus_.options().bulk_url.empty() ? bus_.options().control_url
                                                       : bus_.options().bulk_url));
  }
  if (!transmit_queue_.empty() && !pump_scheduled_) TransmitQueued();
  if (!failed.empty()) Pump();
}

void ProductSender::Finish(const std::string& product_id, bool ok, std::string error) {
  auto node = in_flight_.extract(product_id);
  if (node.empty()) return;
  std::unique_ptr<Outgoing> outgoing = std::move(node.mapped());
  in_flight_bytes_ -= outgoing->product.payload.size();
  --pending_;
  SendResult result;
  result.product_id = product_id;
  result.name = outgoing->product.name;
  result.ok = ok;
  result.attempts = outgoing->attempts;
  result.latency_us = MonotonicMicros() - outgoing->start_us;
  result.error = std::move(error);
  if (ok) {
    ++stats_.products_acknowledged;
  } else {
    ++stats_.products_failed;
    log::Error("{}", result.error);
  }
  if (outgoing->done) outgoing->done(result);
  // Room in the window for queued products.
  loop_.Post([this, alive = std::weak_ptr<int>(alive_)] {
    if (alive.lock()) Pump();
  });
}

}  // namespace avc::products
