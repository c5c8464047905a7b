#include "drivers/camera/camera_worker.h"

#include <utility>

#include "core/util/log.h"

namespace avc::camera_driver {

CameraWorker::CameraWorker(std::unique_ptr<CameraBackend> backend)
    : backend_(std::move(backend)), thread_([this] { Run(); }) {}

CameraWorker::~CameraWorker() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    jobs_.clear();
  }
  wake_.notify_all();
  thread_.join();
  backend_->Close();
}

void CameraWorker::Submit(Job job) {
  {
    std::lock_guard lock(mutex_);
    if (stopping_) return;
    jobs_.push_back(std::move(job));
  }
  wake_.notify_one();
}

size_t CameraWorker::pending() const {
  std::lock_guard lock(mutex_);
  return jobs_.size() + (running_job_ ? 1 : 0);
}

void CameraWorker::Run() {
  std::unique_lock lock(mutex_);
  while (true) {
    wake_.wait(lock, [this] { return stopping_ || !jobs_.empty(); });
    if (stopping_) return;
    Job job = std::move(jobs_.front());
    jobs_.pop_front();
    running_job_ = true;
    lock.unlock();
    try {
      job(*backend_);
    } catch (const std::exception& error) {
      // Jobs report their own failures; this only guards the thread against a bug in one.
      log::Error("camera worker: job failed unexpectedly: {}", error.what());
    }
    lock.lock();
    running_job_ = false;
  }
}

}  // namespace avc::camera_driver
