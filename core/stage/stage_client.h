#pragma once

// The requesting side of a reconstruction stage on the bus: sends a stage_job_t product to the
// named service and runs the event loop until its stage_result_t comes back.
//  - The job is sent reliably (the service must acknowledge the product). If the service
//    restarts while it works (its heartbeat comes from a new process), the job is sent again
//    under the same request id; a service that answered it already answers from memory.
//  - A service that stops heartbeating, a job that is not taken, a result that is not ok, a
//    result of another scan or stage, and the overall timeout: each throws StageFailure naming
//    the service and what went wrong, and nothing of that result is kept.
//  - Results for other request ids (an earlier run's, another requester's) are ignored.

#include <avc/file_t.hpp>
#include <avc/heartbeat_t.hpp>
#include <avc/progress_t.hpp>
#include <avc/stage_result_t.hpp>
#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/bus/bus.h"
#include "core/bus/event_loop.h"
#include "core/products/product_receiver.h"
#include "core/products/product_sender.h"

namespace avc::stage {

class StageFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct StageRequest {
  std::string service;  // "avc-builder"
  std::string stage;    // "build"
  std::string scan_id;
  std::vector<std::string> settings;
  std::vector<avc::file_t> files;
  std::chrono::milliseconds timeout{std::chrono::minutes(30)};
  // No heartbeat from the service for this long: it is gone.
  std::chrono::milliseconds silence_timeout{std::chrono::seconds(15)};
};

struct StageAnswer {
  std::string request_id;
  std::vector<avc::file_t> files;
  std::string config_sha256;   // the service's configuration in force
  std::string config_text;     // ... as TOML
  double stage_seconds = 0;    // the stage's own run time, as the service measured it
  double wall_seconds = 0;     // request to answer, here
  int64_t bytes_sent = 0;      // the job's files
  int64_t bytes_received = 0;  // the result's files
  int sends = 0;               // the job's transmissions (more than 1 after a restart)
};

class StageClient {
 public:
  // `name` is this requester's product receiver name (the services send results to it) and
  // starts every request id. Loop thread only (the thread that runs `loop`).
  StageClient(bus::Bus& bus, bus::EventLoop& loop, std::string name);
  ~StageClient();
  StageClient(const StageClient&) = delete;
  StageClient& operator=(const StageClient&) = delete;

  // `progress` hears the stage's own progress lines; `stop` (optional), polled, ends the wait
  // with StageFailure("stopped").
  StageAnswer Run(const StageRequest& request,
                  const std::function<void(const std::string&)>& progress = {},
                  const std::function<bool()>& stop = {});

 private:
  void OnResult(const products::Product& product);
  products::ProductSender& SenderFor(const std::string& service);

  bus::Bus& bus_;
  bus::EventLoop& loop_;
  std::string name_;
  std::string id_prefix_;
  int64_t next_request_ = 1;
  std::map<std::string, std::unique_ptr<products::ProductSender>> senders_;  // by service
  std::unique_ptr<products::ProductReceiver> receiver_;
  std::vector<bus::Bus::SubscriptionId> subscriptions_;

  // The latest heartbeat of every service and when it came (steady clock, µs): a job goes to
  // the process heard last, so a restart shows as another pid.
  struct Beat {
    int32_t pid = 0;
    int64_t received_us = 0;
  };
  std::map<std::string, Beat> beats_;
  // The request in flight.
  std::string waiting_for_;
  std::optional<avc::stage_result_t> result_;
  std::function<void(const std::string&)> progress_;
};

}  // namespace avc::stage
