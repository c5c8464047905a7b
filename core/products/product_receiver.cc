#include "core/products/product_receiver.h"

#include <avc/product_ack_t.hpp>

#include "core/bus/channels.h"
#include "core/bus/decode.h"
#include "core/util/log.h"

namespace avc::products {

ProductReceiver::ProductReceiver(bus::Bus& bus, std::string receiver_name,
                                 const std::string& channel_pattern, Handler handler)
    : bus_(bus), receiver_name_(std::move(receiver_name)), handler_(std::move(handler)) {
  subscription_ = bus_.SubscribeRegex(
      bus::Link::kBulk, bus_.cell() + "/" + channel_pattern,
      [this](const uint8_t* data, size_t size, const bus::RxInfo& info) {
        avc::product_chunk_t chunk{};
        if (!bus::DecodeMessage(data, size, &chunk)) {
          ++stats_.invalid;
          bus_.Reject(info, "does not decode as product_chunk_t");
          return;
        }
        OnChunk(chunk, info);
      },
      /*queue_capacity=*/0);
}

ProductReceiver::~ProductReceiver() { bus_.Unsubscribe(subscription_); }

void ProductReceiver::OnChunk(const avc::product_chunk_t& chunk, const bus::RxInfo& info) {
  ++stats_.chunks;
  Reassembler::Outcome outcome = reassembler_.Add(chunk);
  switch (outcome.status) {
    case Reassembler::Status::kIncomplete:
      // Report gaps once per transmission round (at its last chunk) and on every retransmitted
      // chunk, so the producer resends only what is missing without an ack per chunk.
      if (chunk.chunk_index == chunk.chunk_count - 1 || chunk.attempt > 0) {
        Ack(chunk.product_id, avc::product_ack_t::STATUS_PARTIAL,
            reassembler_.Missing(chunk.product_id));
      }
      return;
    case Reassembler::Status::kDuplicate:
      ++stats_.duplicates;
      Ack(chunk.product_id, avc::product_ack_t::STATUS_COMPLETE, {});
      return;
    case Reassembler::Status::kCorrupt:
      ++stats_.corrupt;
      log::Warn("{}: {}; asking for it again", receiver_name_, outcome.error);
      Ack(chunk.product_id, avc::product_ack_t::STATUS_CORRUPT, {});
      return;
    case Reassembler::Status::kInvalid:
      ++stats_.invalid;
      bus_.Reject(info, outcome.error);
      return;
    case Reassembler::Status::kComplete:
      break;
  }
  // Acknowledge only once the consumer has the product: if it fails (a full disk, say), the
  // producer keeps it and resends.
  try {
    handler_(*outcome.product, info);
  } catch (const std::exception& e) {
    reassembler_.ForgetCompleted(chunk.product_id);
    log::Error("{}: could not take product '{}': {}; not acknowledged, it will be resent",
               receiver_name_, outcome.product->name, e.what());
    return;
  }
  ++stats_.delivered;
  Ack(chunk.product_id, avc::product_ack_t::STATUS_COMPLETE, {});
}

void ProductReceiver::Ack(const std::string& product_id, int8_t status,
                          const std::vector<int32_t>& missing) {
  avc::product_ack_t ack{};
  ack.product_id = product_id;
  ack.receiver = receiver_name_;
  ack.status = status;
  ack.missing = missing;
  ack.num_missing = static_cast<int32_t>(missing.size());
  try {
    bus_.Publish(channels::kProductAck, ack);
  } catch (const bus::BusError& e) {
    log::Warn("{}: acknowledgement of {} not sent: {}", receiver_name_, product_id, e.what());
  }
}

}  // namespace avc::products
