#include "core/stage/stage_server.h"

#include <fmt/format.h>
#include <unistd.h>

#include <avc/progress_t.hpp>
#include <chrono>
#include <stdexcept>
#include <utility>

#include "core/bus/channels.h"
#include "core/bus/decode.h"
#include "core/stage/stage_files.h"
#include "core/util/log.h"

namespace avc::stage {

namespace fs = std::filesystem;

StageServer::StageServer(bus::Bus& bus, bus::EventLoop& loop, StageServerOptions options)
    : bus_(bus), loop_(loop), options_(std::move(options)) {
  if (options_.service.empty() || options_.stage.empty() || !options_.handler) {
    throw std::invalid_argument("a stage server needs a service, a stage and a handler");
  }
  if (options_.work_root.empty()) {
    options_.work_root =
        fs::temp_directory_path() / fmt::format("{}-{}", options_.service, ::getpid());
  }
  receiver_ = std::make_unique<products::ProductReceiver>(
      bus_, options_.service, std::string(channels::kProductStageJob),
      [this](const products::Product& product, const bus::RxInfo&) { OnJobProduct(product); });
}

namespace {

StageServerOptions DefaultOptions(std::string service, std::string stage, StageHandler handler) {
  StageServerOptions options;
  options.service = std::move(service);
  options.stage = std::move(stage);
  options.handler = std::move(handler);
  return options;
}

}  // namespace

StageServer::StageServer(bus::Bus& bus, bus::EventLoop& loop, std::string service,
                         std::string stage, StageHandler handler)
    : StageServer(bus, loop,
                  DefaultOptions(std::move(service), std::move(stage), std::move(handler))) {}

StageServer::~StageServer() {
  receiver_.reset();
  if (worker_.joinable()) worker_.join();
  std::error_code ignored;
  fs::remove_all(options_.work_root, ignored);
}

void StageServer::OnJobProduct(const products::Product& product) {
  avc::stage_job_t job{};
  if (product.content_type != products::ContentTypeOf<avc::stage_job_t>() ||
      !bus::DecodeMessage(product.payload.data(), product.payload.size(), &job)) {
    ++stats_.ignored;
    log::Warn("{}: stage job product '{}' from {} does not decode as stage_job_t; ignored",
              options_.service, product.name, product.source);
    return;
  }
  if (job.service != options_.service) return;  // another stage's job
  if (job.stage != options_.stage || job.request_id.empty() || job.reply_to.empty()) {
    avc::stage_result_t refusal{};
    refusal.request_id = job.request_id;
    refusal.scan_id = job.scan_id;
    refusal.stage = job.stage;
    refusal.service = options_.service;
    refusal.ok = false;
    refusal.error = job.stage != options_.stage
                        ? fmt::format("{} runs stage '{}', not '{}'", options_.service,
                                      options_.stage, job.stage)
                        : "a stage job needs a request_id and a reply_to";
    ++stats_.ignored;
    log::Warn("{}: job '{}' refused: {}", options_.service, job.request_id, refusal.error);
    if (!job.reply_to.empty()) Send(refusal, job.reply_to);
    return;
  }
  for (const auto& [answer, reply_to] : answers_) {
    if (answer.request_id == job.request_id) {
      ++stats_.answered_again;
      log::Info("{}: job {} answered again from memory", options_.service, job.request_id);
      Send(answer, job.reply_to);
      return;
    }
  }
  if (running_ == job.request_id) {
    ++stats_.ignored;
    return;
  }
  for (const avc::stage_job_t& queued : queue_) {
    if (queued.request_id == job.request_id) {
      ++stats_.ignored;
      return;
    }
  }
  log::Info("{}: job {} for scan {} ({} files, {} bytes) queued", options_.service, job.request_id,
            job.scan_id, job.files.size(), FileBytes(job.files));
  queue_.push_back(std::move(job));
  StartNext();
}

void StageServer::StartNext() {
  if (worker_.joinable() || queue_.empty()) return;
  avc::stage_job_t job = std::move(queue_.front());
  queue_.pop_front();
  running_ = job.request_id;
  const fs::path folder = options_.work_root / fmt::format("job-{}", ++jobs_started_);
  worker_ = std::thread([this, job = std::move(job), folder, alive = std::weak_ptr<int>(alive_)] {
    avc::stage_result_t result = RunJob(job, folder);
    std::string reply_to = job.reply_to;
    loop_.Post([this, alive, result = std::move(result), reply_to = std::move(reply_to)]() mutable {
      if (alive.expired()) return;
      Finish(std::move(result), std::move(reply_to));
    });
  });
}

avc::stage_result_t StageServer::RunJob(const avc::stage_job_t& job, const fs::path& folder) {
  avc::stage_result_t result{};
  result.request_id = job.request_id;
  result.scan_id = job.scan_id;
  result.stage = job.stage;
  result.service = options_.service;
  result.config_sha256 = options_.config_sha256;
  result.config_text = options_.config_text;
  const auto start = std::chrono::steady_clock::now();
  try {
    std::error_code ignored;
    fs::remove_all(folder, ignored);
    StageWork work;
    work.input_dir = folder / "in";
    work.output_dir = folder / "out";
    work.settings = job.settings;
    work.scan_id = job.scan_id;
    fs::create_directories(work.input_dir);
    fs::create_directories(work.output_dir);
    UnpackFiles(job.files, work.input_dir);
    const std::string request_id = job.request_id;
    work.progress = [this, request_id](const std::string& line) {
      PublishProgress(request_id, line);
    };
    options_.handler(work);
    result.files = PackFolder(work.output_dir);
    result.ok = true;
  } catch (const std::exception& error) {
    result.ok = false;
    result.error = error.what();
    result.files.clear();
  }
  result.num_files = static_cast<int32_t>(result.files.size());
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::error_code ignored;
  fs::remove_all(folder, ignored);
  return result;
}

void StageServer::Finish(avc::stage_result_t result, std::string reply_to) {
  if (worker_.joinable()) worker_.join();
  running_.clear();
  if (result.ok) {
    ++stats_.jobs_run;
    log::Info("{}: job {} done in {:.1f} s ({} files, {} bytes)", options_.service,
              result.request_id, result.seconds, result.files.size(), FileBytes(result.files));
  } else {
    ++stats_.jobs_failed;
    log::Warn("{}: job {} failed: {}", options_.service, result.request_id, result.error);
  }
  Send(result, reply_to);
  answers_.emplace_back(std::move(result), std::move(reply_to));
  while (answers_.size() > options_.remembered_results) answers_.pop_front();
  StartNext();
}

products::ProductSender& StageServer::SenderFor(const std::string& reply_to) {
  std::unique_ptr<products::ProductSender>& sender = senders_[reply_to];
  if (!sender) {
    products::SenderOptions options = options_.products;
    options.required_receivers = {reply_to};
    if (options.max_chunk_bytes == 0) options.max_chunk_bytes = kStageChunkBytes;
    sender = std::make_unique<products::ProductSender>(bus_, loop_, options);
  }
  return *sender;
}

void StageServer::Send(const avc::stage_result_t& result, const std::string& reply_to) {
  const std::string service = options_.service;
  const std::string request_id = result.request_id;
  SenderFor(reply_to).SendMessage(
      channels::kProductStageResult, fmt::format("stage/{}", result.request_id), result,
      [service, request_id, reply_to](const products::SendResult& sent) {
        if (!sent.ok) {
          log::Warn("{}: the result of job {} did not reach {}: {}", service, request_id, reply_to,
                    sent.error);
        }
      });
}

void StageServer::PublishProgress(const std::string& request_id, const std::string& line) {
  avc::progress_t progress;
  progress.task = request_id;
  progress.phase = options_.stage;
  progress.eta_us = -1;
  progress.detail = line;
  bus_.Publish(channels::kProgress, progress);  // Bus::Publish is thread-safe
}

}  // namespace avc::stage
