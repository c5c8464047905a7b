#pragma once

// A JSON file read whole, with the file named in every error.

#include <filesystem>
#include <nlohmann/json.hpp>

namespace avc {

// Throws std::runtime_error "PATH: cannot read ..." or "PATH: not valid JSON (...)".
nlohmann::json ReadJsonFile(const std::filesystem::path& path);

}  // namespace avc
