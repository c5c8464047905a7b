#pragma once

// Every options struct has one validation contract: `std::string Validate() const` returns ""
// when the options are usable and otherwise one sentence naming the field at fault. FirstProblem
// collects that sentence from a list of checks; RequireValid turns it into std::invalid_argument
// where a function is handed options it cannot run with.

#include <stdexcept>
#include <string>
#include <string_view>

namespace avc {

class FirstProblem {
 public:
  // Keeps `what` when `ok` is false and no earlier check failed.
  void Require(bool ok, std::string_view what) {
    if (!ok && text_.empty()) text_ = what;
  }
  // Keeps a nested struct's Validate() answer (which names its own struct and field).
  void Include(const std::string& problem) {
    if (text_.empty()) text_ = problem;
  }
  const std::string& text() const { return text_; }

 private:
  std::string text_;
};

template <typename Options>
void RequireValid(const Options& options) {
  if (std::string problem = options.Validate(); !problem.empty()) {
    throw std::invalid_argument(problem);
  }
}

}  // namespace avc
