#pragma once

// The serving side of a reconstruction stage on the bus (avc-builder "build", avc-clusterer
// "cluster", avc-surfacer "surface"): takes stage_job_t products on PRODUCT/STAGE_JOB addressed
// to this service, unpacks the job's files into a scratch folder, runs the stage there on a
// worker thread (one job at a time, the rest queued in arrival order), and sends the output
// folder back as one stage_result_t product on PRODUCT/STAGE_RESULT to the job's reply_to.
//  - A request id answered before gets the remembered answer again (the requester re-sent it
//    because the result was lost or it restarted); one queued or running is not run twice.
//  - A job that fails (bad files, the stage throws) is answered with ok = false and the reason.
//  - Progress goes out on PROGRESS with task = the job's request id, so the requester can show
//    the stage's own progress while it waits.
// The handler gets the same folder layout `avc reconstruct` uses, so the bus and the offline
// tool run the same code on the same files.

#include <avc/stage_job_t.hpp>
#include <avc/stage_result_t.hpp>
#include <deque>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "core/bus/bus.h"
#include "core/bus/event_loop.h"
#include "core/products/product_receiver.h"
#include "core/products/product_sender.h"

namespace avc::stage {

struct StageWork {
  std::filesystem::path input_dir;    // the job's files
  std::filesystem::path output_dir;   // empty; everything written here is sent back
  std::vector<std::string> settings;  // the job's "section.field=value" overrides
  std::string scan_id;                // the scan the job is for
  // A line of progress ("mvs 12/36"); safe from the worker thread.
  std::function<void(const std::string&)> progress;
};

// Runs the stage. Throws (any std::exception) with a message naming what failed.
using StageHandler = std::function<void(const StageWork&)>;

struct StageServerOptions {
  std::string service;  // e.g. "avc-builder": the jobs it takes and the receiver name it acks as
  std::string stage;    // e.g. "build"
  StageHandler handler;
  // The service's configuration in force (its CONFIG), sent with every result.
  std::string config_text;
  std::string config_sha256;
  std::filesystem::path work_root;   // default: $TMPDIR/<service>-<pid>
  size_t remembered_results = 2;     // answers kept for repeated request ids
  products::SenderOptions products;  // required_receivers: set per job to its reply_to
};

struct StageServerStats {
  int64_t jobs_run = 0;
  int64_t jobs_failed = 0;
  int64_t answered_again = 0;  // repeated request ids answered from memory
  int64_t ignored = 0;         // for another service, undecodable, or already in hand
};

class StageServer {
 public:
  // Loop thread only. Throws std::invalid_argument without service, stage or handler.
  StageServer(bus::Bus& bus, bus::EventLoop& loop, StageServerOptions options);
  // The defaults for the rest.
  StageServer(bus::Bus& bus, bus::EventLoop& loop, std::string service, std::string stage,
              StageHandler handler);
  // Waits for the job in progress; queued jobs are dropped (their requester sends them again).
  ~StageServer();
  StageServer(const StageServer&) = delete;
  StageServer& operator=(const StageServer&) = delete;

  bool busy() const { return worker_.joinable(); }
  const StageServerStats& stats() const { return stats_; }

 private:
  void OnJobProduct(const products::Product& product);
  void StartNext();
  avc::stage_result_t RunJob(const avc::stage_job_t& job, const std::filesystem::path& folder);
  void Finish(avc::stage_result_t result, std::string reply_to);
  void Send(const avc::stage_result_t& result, const std::string& reply_to);
  products::ProductSender& SenderFor(const std::string& reply_to);
  void PublishProgress(const std::string& request_id, const std::string& line);

  bus::Bus& bus_;
  bus::EventLoop& loop_;
  StageServerOptions options_;
  std::deque<avc::stage_job_t> queue_;
  std::string running_;  // request id of the job on the worker
  std::thread worker_;
  int64_t jobs_started_ = 0;
  // Answers by request id, oldest first.
  std::deque<std::pair<avc::stage_result_t, std::string>> answers_;
  StageServerStats stats_;
  std::shared_ptr<int> alive_ = std::make_shared<int>(0);
  // One sender per requester: each must acknowledge the results sent to it.
  std::map<std::string, std::unique_ptr<products::ProductSender>> senders_;
  std::unique_ptr<products::ProductReceiver> receiver_;
};

}  // namespace avc::stage
