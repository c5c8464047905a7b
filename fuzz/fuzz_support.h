#pragma once

// Shared by the fuzz targets: turning libFuzzer's bytes into the files and parts the project's
// readers take. Each process works in its own temporary directory, so several fuzzers (or
// libFuzzer's -jobs) never see each other's files.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace avc::fuzz {

// Separates the files of one input for targets that read several ("cameras.txt" and
// "images.txt"): short, printable, and unlikely inside the files themselves.
inline constexpr std::string_view kPartSeparator = "\n--8<--\n";

std::string_view AsText(const uint8_t* data, size_t size);

// The voxel-map targets' cap on expanded voxels: far below the reader's 64 million, which a
// 1 kB tree of a few pruned nodes legitimately reaches (filling and sorting them takes 10 s
// under the sanitizers, a "slow unit" but no bug); the cap's own refusal is a unit test.
inline constexpr uint64_t kFuzzMaxVoxels = uint64_t{1} << 20;

// This process's directory ($TMPDIR/avc-fuzz-<pid>-XXXXXX), created on first use and removed at
// exit.
const std::filesystem::path& TempDir();

// An empty directory TempDir()/name (removed and recreated), so no file of a previous input is
// read with this one.
std::filesystem::path FreshDir(const std::string& name);

// Writes bytes to dir/name, replacing the file; returns the path.
std::filesystem::path WriteFile(const std::filesystem::path& dir, const std::string& name,
                                std::string_view bytes);

// text split at kPartSeparator into exactly `count` parts: the last takes the rest, missing ones
// are empty.
std::vector<std::string_view> SplitParts(std::string_view text, size_t count);

// The mesh file targets (PLY, OBJ, OFF): the bytes written to TempDir()/name, whose extension
// picks the format, and read with geometry::ReadMesh and geometry::ReadPointCloud (and
// PlyHasFaces for .ply). Their documented std::runtime_error is a refusal, not a finding.
void ReadMeshFile(const std::string& name, const uint8_t* data, size_t size);

}  // namespace avc::fuzz
