#include "core/bus/ack_book.h"

#include <utility>

#include "core/bus/channels.h"

namespace avc::bus {

AckBook::AckBook(Bus& bus, std::string service, size_t remembered)
    : bus_(bus), service_(std::move(service)), remembered_(remembered) {}

avc::ack_t AckBook::Publish(const std::string& request_id, int8_t status,
                            const std::string& reason) {
  avc::ack_t ack{};
  ack.request_id = request_id;
  ack.service = service_;
  ack.status = status;
  ack.reason = reason;
  bus_.Publish(channels::kAck, ack);
  return ack;
}

void AckBook::SendUnremembered(const std::string& request_id, int8_t status,
                               const std::string& reason) {
  Publish(request_id, status, reason);
}

void AckBook::Send(const std::string& request_id, int8_t status, const std::string& reason) {
  const avc::ack_t ack = Publish(request_id, status, reason);
  if (request_id.empty()) return;
  if (last_.find(request_id) == last_.end()) {
    order_.push_back(request_id);
    if (order_.size() > remembered_) {
      last_.erase(order_.front());
      order_.pop_front();
    }
  }
  last_[request_id] = ack;
}

bool AckBook::Repeat(const std::string& request_id) {
  const auto it = last_.find(request_id);
  if (it == last_.end()) return false;
  avc::ack_t ack = it->second;
  bus_.Publish(channels::kAck, ack);
  return true;
}

}  // namespace avc::bus
