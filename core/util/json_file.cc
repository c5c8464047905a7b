#include "core/util/json_file.h"

#include <stdexcept>

#include "core/util/file_io.h"

namespace avc {

nlohmann::json ReadJsonFile(const std::filesystem::path& path) {
  const std::string bytes = ReadFile(path);
  try {
    return nlohmann::json::parse(bytes);
  } catch (const nlohmann::json::parse_error& error) {
    throw std::runtime_error(path.string() + ": not valid JSON (" + error.what() + ")");
  }
}

}  // namespace avc
