#pragma once

// libgphoto2 2.5.30's PTP/IP disconnect (ptp_ptpip_disconnect) also closes params->jpgfd, which
// only the Fuji PTP/IP path sets and which is otherwise 0: closing a PTP/IP camera closes file
// descriptor 0 (strace shows close(0) in gp_camera_exit and again when the camera is freed).
// If fd 0 had been reused by then (a socket, a file, the emulator's listener), that descriptor
// dies. So: fd 0 is kept open before libgphoto2 creates sockets (none of them can be fd 0), and
// whatever fd 0 was is put back after a camera is exited or freed.

namespace avc::camera_driver {

// Opens /dev/null as fd 0 if fd 0 is closed.
void EnsureFd0Open();

// Remembers fd 0 on construction and restores it on destruction if it was closed meanwhile.
class Fd0Guard {
 public:
  Fd0Guard();
  ~Fd0Guard();
  Fd0Guard(const Fd0Guard&) = delete;
  Fd0Guard& operator=(const Fd0Guard&) = delete;

 private:
  int saved_ = -1;
};

}  // namespace avc::camera_driver
