#pragma once

// How every command-taking service answers on ACK: it publishes the ack and remembers the last
// answer per request id, so a repeated request (the sender did not hear us) gets the same answer
// again and never repeats the work. The memory is bounded (oldest request ids forgotten first).

#include <avc/ack_t.hpp>
#include <deque>
#include <map>
#include <string>

#include "core/bus/bus.h"

namespace avc::bus {

class AckBook {
 public:
  AckBook(Bus& bus, std::string service, size_t remembered = 1024);

  // Publishes the ack on ACK and remembers it as the request's latest answer.
  void Send(const std::string& request_id, int8_t status, const std::string& reason);
  // Publishes the ack without remembering it: the answer to a message that is not a genuine
  // request (e.g. one failing authentication), which must not become the request id's answer.
  void SendUnremembered(const std::string& request_id, int8_t status, const std::string& reason);
  // NOT_READY, not remembered: the same request id sent again once we are READY is taken as new.
  void SendNotReady(const std::string& request_id, const std::string& reason) {
    SendUnremembered(request_id, avc::ack_t::STATUS_NOT_READY, reason);
  }
  // A request seen before gets its latest answer again: returns true after re-sending it.
  bool Repeat(const std::string& request_id);
  bool Knows(const std::string& request_id) const { return last_.count(request_id) != 0; }

 private:
  Bus& bus_;
  avc::ack_t Publish(const std::string& request_id, int8_t status, const std::string& reason);

  std::string service_;
  size_t remembered_;
  std::map<std::string, avc::ack_t> last_;
  std::deque<std::string> order_;  // oldest first; bounds last_
};

}  // namespace avc::bus
