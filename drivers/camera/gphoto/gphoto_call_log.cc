#include "drivers/camera/gphoto/gphoto_call_log.h"

#include <gphoto2/gphoto2-port-log.h>

#include <mutex>
#include <string>

namespace avc::camera_driver {
namespace {

// Where the driver operation running on this thread collects log lines, if any.
thread_local GphotoDiagnostics* active_diagnostics = nullptr;

// Error-level lines only: formatting debug output for every packet would cost time.
void InstallLogSinkOnce(GPLogFunc sink) {
  static std::once_flag once;
  std::call_once(once, [&] { gp_log_add_func(GP_LOG_ERROR, sink, nullptr); });
}

constexpr size_t kMaxLines = 50;

}  // namespace

GphotoCallLog::GphotoCallLog() : context_(gp_context_new()) {
  gp_context_set_error_func(context_, &GphotoCallLog::OnContextError, this);
  gp_context_set_message_func(context_, &GphotoCallLog::OnContextError, this);
  InstallLogSinkOnce(&GphotoCallLog::OnLog);
}

GphotoCallLog::~GphotoCallLog() {
  if (active_diagnostics == &diagnostics_) active_diagnostics = nullptr;
  gp_context_unref(context_);
}

void GphotoCallLog::Begin() {
  diagnostics_ = {};
  active_diagnostics = &diagnostics_;
}

void GphotoCallLog::OnContextError(GPContext* /*context*/, const char* text, void* self) {
  auto* log = static_cast<GphotoCallLog*>(self);
  if (text != nullptr && log->diagnostics_.context_errors.size() < kMaxLines) {
    log->diagnostics_.context_errors.emplace_back(text);
  }
}

void GphotoCallLog::OnLog(GPLogLevel level, const char* domain, const char* text, void*) {
  if (level != GP_LOG_ERROR || active_diagnostics == nullptr || text == nullptr) return;
  if (active_diagnostics->log_errors.size() >= kMaxLines) return;
  std::string line = domain != nullptr ? std::string(domain) + ": " : std::string();
  line += text;
  while (!line.empty() && (line.back() == '\n' || line.back() == ' ')) line.pop_back();
  active_diagnostics->log_errors.push_back(std::move(line));
}

}  // namespace avc::camera_driver
