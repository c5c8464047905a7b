#pragma once

// The one thread that talks to the camera. libgphoto2 calls block for up to seconds (exposure,
// download, re-init), so they never run on the bus loop; jobs run one at a time, in order, and
// are the only code that touches the backend (the device has a single owner).

#include <condition_variable>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>

#include "drivers/camera/camera_backend.h"

namespace avc::camera_driver {

class CameraWorker {
 public:
  using Job = std::function<void(CameraBackend&)>;

  explicit CameraWorker(std::unique_ptr<CameraBackend> backend);
  // Finishes the running job, drops the queued ones, closes the camera and joins.
  ~CameraWorker();
  CameraWorker(const CameraWorker&) = delete;
  CameraWorker& operator=(const CameraWorker&) = delete;

  void Submit(Job job);
  // Jobs queued or running.
  size_t pending() const;

 private:
  void Run();

  std::unique_ptr<CameraBackend> backend_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<Job> jobs_;
  bool running_job_ = false;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace avc::camera_driver
