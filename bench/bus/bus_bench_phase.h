#pragma once

// One phase of `avc bench bus` on the sending side: count products of payload_bytes each, at a
// fixed rate or all at once, through a fresh ProductSender, waiting for every result.

#include <chrono>
#include <string>
#include <vector>

#include "bench/summary.h"
#include "core/bus/bus.h"
#include "core/bus/event_loop.h"
#include "core/products/product_sender.h"

namespace avc::bench {

struct PhaseSpec {
  std::string name;  // product names are "<name>/<index>"
  int count = 0;
  double rate_hz = 0;  // 0: queue every product at once (a burst)
  size_t payload_bytes = 0;
};

struct PhaseResult {
  std::string name;
  int sent = 0;
  int acknowledged = 0;
  int failed = 0;
  int max_attempts =
      0;  // most transmissions any product needed (SenderOptions::max_attempts caps it)
  int64_t chunks_sent = 0;
  int64_t chunks_retransmitted = 0;
  Summary latency_ms;               // Send() to acknowledgement, acknowledged products only
  double seconds = 0;               // first Send() to last result
  double megabytes_per_second = 0;  // acknowledged payload over seconds
  std::string first_error;
};

// Runs on loop's thread; returns once every product is acknowledged or has failed.
PhaseResult RunPhase(bus::Bus& bus, bus::EventLoop& loop, const PhaseSpec& spec,
                     const products::SenderOptions& sender_options);

}  // namespace avc::bench
