#include "bench/bus/bus_bench_phase.h"

#include <algorithm>
#include <cstring>
#include <random>

#include "core/bus/channels.h"
#include "core/util/clock.h"

namespace avc::bench {
namespace {

// Incompressible bytes, different per product (the index is written at the front) so a stale
// retransmission can never pass for another product.
std::vector<uint8_t> Payload(const std::vector<uint8_t>& base, int index) {
  std::vector<uint8_t> payload = base;
  std::memcpy(payload.data(), &index, std::min(sizeof(index), payload.size()));
  return payload;
}

std::vector<uint8_t> RandomBytes(size_t size) {
  std::vector<uint8_t> bytes(size);
  std::mt19937_64 rng(20261123);
  for (size_t i = 0; i + 8 <= size; i += 8) {
    const uint64_t value = rng();
    std::memcpy(bytes.data() + i, &value, 8);
  }
  return bytes;
}

}  // namespace

PhaseResult RunPhase(bus::Bus& bus, bus::EventLoop& loop, const PhaseSpec& spec,
                     const products::SenderOptions& sender_options) {
  products::ProductSender sender(bus, loop, sender_options);
  const std::vector<uint8_t> base = RandomBytes(spec.payload_bytes);
  PhaseResult result;
  result.name = spec.name;
  std::vector<double> latencies_ms;
  int finished = 0;
  auto on_done = [&](const products::SendResult& send) {
    ++finished;
    result.max_attempts = std::max(result.max_attempts, send.attempts);
    if (send.ok) {
      ++result.acknowledged;
      latencies_ms.push_back(static_cast<double>(send.latency_us) / 1000.0);
    } else {
      ++result.failed;
      if (result.first_error.empty()) result.first_error = send.error;
    }
  };
  auto send_next = [&] {
    if (result.sent >= spec.count) return;
    const int index = result.sent++;
    sender.Send(channels::kProductBench, spec.name + "/" + std::to_string(index),
                "application/octet-stream", Payload(base, index), on_done);
  };

  const int64_t start_us = MonotonicMicros();
  bus::EventLoop::TimerId timer = 0;
  if (spec.rate_hz > 0) {
    send_next();
    timer = loop.AddTimer(std::chrono::microseconds(static_cast<int64_t>(1e6 / spec.rate_hz)),
                          send_next, /*repeating=*/true);
  } else {
    while (result.sent < spec.count) send_next();
  }
  // Generous: the schedule plus the longest a product can spend being retried.
  const auto budget =
      std::chrono::seconds(90) + std::chrono::milliseconds(static_cast<int64_t>(
                                     spec.rate_hz > 0 ? 1000.0 * spec.count / spec.rate_hz : 0));
  loop.RunUntil([&] { return finished == spec.count; }, budget);
  if (timer != 0) loop.CancelTimer(timer);
  result.seconds = static_cast<double>(MonotonicMicros() - start_us) / 1e6;

  result.chunks_sent = sender.stats().chunks_sent;
  result.chunks_retransmitted = sender.stats().chunks_retransmitted;
  result.latency_ms = Summarize(latencies_ms);
  result.megabytes_per_second = static_cast<double>(result.acknowledged) *
                                static_cast<double>(spec.payload_bytes) / 1e6 / result.seconds;
  if (finished < spec.count && result.first_error.empty()) {
    result.first_error = std::to_string(spec.count - finished) + " products still unresolved";
  }
  return result;
}

}  // namespace avc::bench
