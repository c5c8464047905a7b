#include "core/stage/stage_client.h"

#include <fmt/format.h>

#include <algorithm>
#include <avc/stage_job_t.hpp>
#include <utility>

#include "core/bus/channels.h"
#include "core/bus/decode.h"
#include "core/stage/stage_files.h"
#include "core/util/log.h"
#include "core/util/session_tag.h"
#include "core/util/sha256.h"

namespace avc::stage {
namespace {

using Clock = std::chrono::steady_clock;

int64_t SteadyMicros() {
  return std::chrono::duration_cast<std::chrono::microseconds>(Clock::now().time_since_epoch())
      .count();
}

}  // namespace

StageClient::StageClient(bus::Bus& bus, bus::EventLoop& loop, std::string name)
    : bus_(bus), loop_(loop), name_(std::move(name)), id_prefix_(name_ + "-" + SessionTag()) {
  receiver_ = std::make_unique<products::ProductReceiver>(
      bus_, name_, std::string(channels::kProductStageResult),
      [this](const products::Product& product, const bus::RxInfo&) { OnResult(product); });
  subscriptions_.push_back(bus_.Subscribe<avc::heartbeat_t>(
      channels::kHeartbeat, [this](const avc::heartbeat_t& beat, const bus::RxInfo&) {
        beats_[beat.service] = {beat.pid, SteadyMicros()};
      }));
  subscriptions_.push_back(bus_.Subscribe<avc::progress_t>(
      channels::kProgress, [this](const avc::progress_t& progress, const bus::RxInfo&) {
        if (!waiting_for_.empty() && progress.task == waiting_for_ && progress_) {
          progress_(progress.detail);
        }
      }));
}

StageClient::~StageClient() {
  for (bus::Bus::SubscriptionId id : subscriptions_) bus_.Unsubscribe(id);
}

products::ProductSender& StageClient::SenderFor(const std::string& service) {
  std::unique_ptr<products::ProductSender>& sender = senders_[service];
  if (!sender) {
    products::SenderOptions options;
    options.required_receivers = {service};
    options.max_chunk_bytes = kStageChunkBytes;
    sender = std::make_unique<products::ProductSender>(bus_, loop_, options);
  }
  return *sender;
}

void StageClient::OnResult(const products::Product& product) {
  avc::stage_result_t result{};
  if (product.content_type != products::ContentTypeOf<avc::stage_result_t>() ||
      !bus::DecodeMessage(product.payload.data(), product.payload.size(), &result)) {
    log::Warn("{}: stage result '{}' from {} does not decode as stage_result_t; ignored", name_,
              product.name, product.source);
    return;
  }
  if (waiting_for_.empty() || result.request_id != waiting_for_) return;
  result_ = std::move(result);
}

StageAnswer StageClient::Run(const StageRequest& request,
                             const std::function<void(const std::string&)>& progress,
                             const std::function<bool()>& stop) {
  avc::stage_job_t job{};
  job.request_id = fmt::format("{}-{}", id_prefix_, next_request_++);
  job.scan_id = request.scan_id;
  job.stage = request.stage;
  job.service = request.service;
  job.reply_to = name_;
  job.settings = request.settings;
  job.num_settings = static_cast<int32_t>(job.settings.size());
  job.files = request.files;
  job.num_files = static_cast<int32_t>(job.files.size());

  StageAnswer answer;
  answer.request_id = job.request_id;
  answer.bytes_sent = FileBytes(job.files);
  waiting_for_ = job.request_id;
  result_.reset();
  progress_ = progress;
  struct Reset {
    StageClient* client;
    ~Reset() {
      client->waiting_for_.clear();
      client->progress_ = nullptr;
    }
  } reset{this};
  // Silence is counted from the send when the service was never heard (or long ago).
  const int64_t sent_us = SteadyMicros();
  const auto beat = [&]() -> Beat {
    Beat latest = beats_[request.service];
    latest.received_us = std::max(latest.received_us, sent_us);
    return latest;
  };

  // Shared with the sender's callback, which may run after Run returned (a send still pending).
  auto send_error = std::make_shared<std::optional<std::string>>();
  int32_t sent_to_pid = 0;  // the process the job last went to (0: not heard yet)
  const auto send = [&] {
    ++answer.sends;
    sent_to_pid = beats_[request.service].pid;
    SenderFor(request.service)
        .SendMessage(channels::kProductStageJob, fmt::format("stage/{}", job.request_id), job,
                     [send_error](const products::SendResult& sent) {
                       if (!sent.ok) *send_error = sent.error;
                     });
  };
  const auto fail = [&](const std::string& what) {
    return StageFailure(fmt::format("{} ({} of scan {}): {}", request.service, request.stage,
                                    request.scan_id, what));
  };
  const auto start = Clock::now();
  send();
  while (!result_) {
    loop_.RunUntil([&] { return result_.has_value() || send_error->has_value(); },
                   std::chrono::milliseconds(200));
    if (result_) break;
    if (stop && stop()) throw fail("stopped while waiting for the result");
    if (*send_error) throw fail("did not take the job: " + **send_error);
    const Beat latest = beat();
    const double silent_s = (SteadyMicros() - latest.received_us) * 1e-6;
    if (silent_s * 1000 > request.silence_timeout.count()) {
      throw fail(
          fmt::format("no heartbeat for {:.0f} s while it had the job; is it running?", silent_s));
    }
    // Heard from a process other than the one that took the job: it restarted and lost it.
    if (latest.pid != 0 && sent_to_pid != 0 && latest.pid != sent_to_pid) {
      log::Warn("{}: {} restarted (pid {} -> {}); sending job {} again", name_, request.service,
                sent_to_pid, latest.pid, job.request_id);
      send();
    } else if (sent_to_pid == 0 && latest.pid != 0) {
      sent_to_pid = latest.pid;  // first heard since sending: that process has the job
    }
    if (Clock::now() - start > request.timeout) {
      throw fail(fmt::format("no result within {} s", request.timeout.count() / 1000));
    }
  }
  answer.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  avc::stage_result_t& result = *result_;
  if (result.scan_id != request.scan_id || result.stage != request.stage ||
      result.service != request.service) {
    throw fail(fmt::format("answered request {} for {} {} of scan {}; result not used",
                           job.request_id, result.service, result.stage, result.scan_id));
  }
  if (!result.ok) throw fail(result.error);
  for (const avc::file_t& file : result.files) {
    if (const std::string problem = RelativePathProblem(file.path); !problem.empty()) {
      throw fail(fmt::format("sent a malformed result: file '{}': {}", file.path, problem));
    }
  }
  if (Sha256Hex(result.config_text) != result.config_sha256 &&
      !(result.config_text.empty() && result.config_sha256.empty())) {
    throw fail("sent a malformed result: its configuration text does not match its SHA-256");
  }
  answer.files = std::move(result.files);
  answer.config_sha256 = result.config_sha256;
  answer.config_text = result.config_text;
  answer.stage_seconds = result.seconds;
  answer.bytes_received = FileBytes(answer.files);
  return answer;
}

}  // namespace avc::stage
