#pragma once

// Launch files: which processes `avc up` runs, in TOML (.toml) or YAML (.yaml/.yml) with the
// same keys. See launch/demo-foundation.toml for a commented example.

#include <chrono>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "core/launch/launch_file_error.h"

namespace avc::launch {

enum class RestartPolicy { kAlways, kOnFailure, kNever };

const char* RestartPolicyName(RestartPolicy policy);

struct ProcessSpec {
  std::string name;
  // As written; a relative path with '/' is made absolute against the launch file's folder, and
  // ResolveCommands turns a bare name into the program that will run.
  std::string command;
  std::vector<std::string> args;
  std::string host;                        // empty = every host
  std::map<std::string, std::string> env;  // over LaunchSpec::env
  RestartPolicy restart = RestartPolicy::kOnFailure;
  std::chrono::milliseconds stop_timeout{5000};  // SIGTERM to SIGKILL
  std::string working_dir;                       // absolute; empty = the launcher's
  int line = 0;                                  // where the entry starts, for later errors
  int command_line = 0;                          // where 'command' is

  bool operator==(const ProcessSpec&) const = default;
};

struct LaunchSpec {
  std::string file;     // as given
  std::string log_dir;  // absolute
  std::map<std::string, std::string> env;
  std::vector<ProcessSpec> processes;

  bool operator==(const LaunchSpec&) const = default;
};

// Reads and checks a launch file; any problem throws LaunchFileError "<file>:<line>: <problem>".
LaunchSpec LoadLaunchFile(const std::string& path);
// The same on text already read; the format comes from file's extension, relative paths are
// relative to file's folder.
LaunchSpec ParseLaunchFile(std::string_view text, const std::string& file);

// Whether a process's host entry ("" = every host) names this host. Case-insensitive, and
// "lab-pc-1" matches "lab-pc-1.lab.example".
bool HostMatches(const std::string& process_host, const std::string& host);
// spec with only the processes that run on host.
LaunchSpec ForHost(LaunchSpec spec, const std::string& host);

// Turns each bare command name into the program to run: first <bin_dir>/<name> (the folder of
// the running avc), then PATH. Throws LaunchFileError at the command's line when none exists.
void ResolveCommands(LaunchSpec& spec, const std::filesystem::path& bin_dir);

}  // namespace avc::launch
