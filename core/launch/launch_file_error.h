#pragma once

// The one error a bad launch file produces: "<file>:<line>: <problem>".

#include <stdexcept>
#include <string>

namespace avc::launch {

class LaunchFileError : public std::runtime_error {
 public:
  // line 0 means the problem concerns the whole file (unreadable, wrong extension).
  LaunchFileError(const std::string& file, int line, const std::string& problem)
      : std::runtime_error(file + (line > 0 ? ":" + std::to_string(line) : "") + ": " + problem),
        file_(file),
        line_(line),
        problem_(problem) {}

  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string file_;
  int line_;
  std::string problem_;
};

}  // namespace avc::launch
