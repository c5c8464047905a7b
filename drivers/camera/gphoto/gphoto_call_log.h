#pragma once

// Collects what libgphoto2 says during the calls of one GphotoCamera: the GPContext error and
// message callbacks, and gp_log lines at error level. libgphoto2's log sink is process-wide, so
// it is installed once and routes lines to the collector active on the calling thread.

#include <gphoto2/gphoto2-context.h>
#include <gphoto2/gphoto2-port-log.h>

#include "drivers/camera/gphoto/gphoto_errors.h"

namespace avc::camera_driver {

class GphotoCallLog {
 public:
  GphotoCallLog();
  ~GphotoCallLog();
  GphotoCallLog(const GphotoCallLog&) = delete;
  GphotoCallLog& operator=(const GphotoCallLog&) = delete;

  // A context whose callbacks feed this log (owned here).
  GPContext* context() const { return context_; }

  // Forgets the previous operation and collects for the next one, on this thread.
  void Begin();
  const GphotoDiagnostics& diagnostics() const { return diagnostics_; }

 private:
  static void OnContextError(GPContext* context, const char* text, void* self);
  static void OnLog(GPLogLevel level, const char* domain, const char* text, void* data);

  GPContext* context_;
  GphotoDiagnostics diagnostics_;
};

}  // namespace avc::camera_driver
