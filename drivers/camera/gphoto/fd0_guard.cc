#include "drivers/camera/gphoto/fd0_guard.h"

#include <fcntl.h>
#include <unistd.h>

namespace avc::camera_driver {
namespace {

bool Fd0IsOpen() { return fcntl(0, F_GETFD) != -1; }

}  // namespace

void EnsureFd0Open() {
  if (Fd0IsOpen()) return;
  const int fd = open("/dev/null", O_RDONLY);  // the lowest free descriptor: 0
  if (fd > 0) {
    dup2(fd, 0);
    close(fd);
  }
}

Fd0Guard::Fd0Guard() {
  if (Fd0IsOpen()) saved_ = fcntl(0, F_DUPFD_CLOEXEC, 3);
}

Fd0Guard::~Fd0Guard() {
  if (!Fd0IsOpen()) {
    if (saved_ >= 0) {
      dup2(saved_, 0);
    } else {
      EnsureFd0Open();
    }
  }
  if (saved_ >= 0) close(saved_);
}

}  // namespace avc::camera_driver
