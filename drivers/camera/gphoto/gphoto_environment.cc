#include "drivers/camera/gphoto/gphoto_environment.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "drivers/camera/camera_backend.h"

namespace avc::camera_driver {

void RequireWritableGphotoHome() {
  const char* home = std::getenv("HOME");
  if (home == nullptr || *home == '\0') {
    throw CameraError(CameraError::Kind::kFailed,
                      "HOME is not set: libgphoto2 keeps its settings in $HOME/.gphoto/settings; "
                      "set HOME to a writable directory");
  }
  const std::filesystem::path dir = std::filesystem::path(home) / ".gphoto";
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error || access(dir.c_str(), W_OK) != 0) {
    throw CameraError(CameraError::Kind::kFailed,
                      fmt::format("HOME={} is not writable ({} cannot be created or written): "
                                  "libgphoto2 keeps its settings in $HOME/.gphoto/settings; set "
                                  "HOME to a writable directory",
                                  home, dir.string()));
  }
  const std::filesystem::path settings = dir / "settings";
  if (std::filesystem::exists(settings, error) && access(settings.c_str(), W_OK) != 0) {
    throw CameraError(
        CameraError::Kind::kFailed,
        fmt::format("{} is not writable: libgphoto2 needs to update it", settings.string()));
  }
}

std::string NormalizePortPath(const std::string& path) {
  const std::string prefix = "ptpip:";
  if (path.rfind(prefix, 0) != 0) return path;
  const std::string rest = path.substr(prefix.size());
  if (std::count(rest.begin(), rest.end(), ':') != 1) return path;
  const std::string port = rest.substr(rest.find(':') + 1);
  if (port.empty()) return path;
  return path + ":" + port;
}

}  // namespace avc::camera_driver
