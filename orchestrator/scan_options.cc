#include "orchestrator/scan_options.h"

#include <fmt/format.h>

#include <string>
#include <string_view>

#include "core/kinematics/envelope_option_table.h"
#include "core/plan/plan_settings.h"
#include "core/segmentation/mask_option_table.h"

namespace avc::orchestrator {
namespace {

using Table = config::OptionTable<ScanOptions>;

bool HasEnvelope(const kinematics::SafetyEnvelope& envelope) {
  return envelope.table_z_base_m || envelope.keep_out;
}

void AddTimeouts(Table& table) {
  table
      .Add("scan.ready_timeout", [](auto& o) -> auto& { return o.run.ready_timeout; },
           {"ms", "the longest a step waits for the services it needs to be READY", 1, 3600000})
      .Add("scan.stage_timeout", [](auto& o) -> auto& { return o.run.stage_timeout; },
           {"ms", "the longest a stage (or one plan job) may take", 1000, 86400000})
      .Add("scan.stage_silence_timeout",
           [](auto& o) -> auto& { return o.run.stage_silence_timeout; },
           {"ms", "the longest a stage's service may go without a heartbeat", 100, 3600000});
}

void AddCapture(Table& table) {
  table.AddText(
      "capture.encoding",
      [](const ScanOptions& o) {
        return o.run.capture.encoding == avc::image_t::ENCODING_JPEG ? "jpeg" : "png";
      },
      [](ScanOptions& o, std::string_view text) {
        if (text == "png") {
          o.run.capture.encoding = avc::image_t::ENCODING_PNG;
        } else if (text == "jpeg") {
          o.run.capture.encoding = avc::image_t::ENCODING_JPEG;
        } else {
          throw std::invalid_argument("not png or jpeg");
        }
      },
      {"", "png is lossless (the simulated camera); jpeg keeps a real camera's own file"});
  table
      .Add("capture.motion_timeout", [](auto& o) -> auto& { return o.run.capture.motion_timeout; },
           {"ms", "the longest one move of the arm and the turntable may take", 1, 3600000})
      .Add("capture.capture_timeout",
           [](auto& o) -> auto& { return o.run.capture.capture_timeout; },
           {"ms", "the longest one photograph may take", 1, 3600000})
      .Add("capture.pose_tolerance", [](auto& o) -> auto& { return o.run.capture.pose_tolerance; },
           {"rad", "a recorded capture answers a request at these joints and table angle", 0, 0.1});
  segmentation::AddMaskOptions(
      table, "capture.masks", [](auto& o) -> auto& { return o.run.capture.mask; });
}

// Each of Algorithm 1's settings as text ("none": not sent, the planner keeps its own), checked
// against the planner's declared range before the scan starts.
void AddPlanner(Table& table) {
  for (const plan::AlgorithmSetting& setting : plan::AlgorithmSettings()) {
    const std::string key = setting.name;
    config::OptionSpec spec = setting.spec;
    spec.doc += " (none: the planner's own)";
    table.AddText(
        "planner." + key,
        [key](const ScanOptions& o) {
          const auto it = o.run.planner_settings.find(key);
          return it == o.run.planner_settings.end() ? std::string(config::kNone) : it->second;
        },
        [key, setting](ScanOptions& o, std::string_view text) {
          if (text == config::kNone) {
            o.run.planner_settings.erase(key);
            o.run.planner_settings_given.erase(key);
            return;
          }
          // The parsers throw ConfigError, an std::invalid_argument the table names.
          o.run.planner_settings[key] =
              setting.integer ? std::to_string(config::ParseInteger(text, setting.spec))
                              : fmt::format("{}", config::ParseReal(text, setting.spec));
          // Chosen on purpose: a resume may not change it (scan_planner_settings.h).
          o.run.planner_settings_given.insert(key);
        },
        spec);
  }
}

Table MakeTable() {
  Table table("scan", [](const ScanOptions& o) {
    if (!HasEnvelope(o.envelope)) return std::string();
    const std::string problem = o.envelope.Validate();
    return problem.empty() ? problem : "the safety envelope is not usable: " + problem;
  });
  AddTimeouts(table);
  AddCapture(table);
  AddPlanner(table);
  kinematics::AddFixedEnvelopeOptions(
      table, "envelope", [](auto& o) -> auto& { return o.envelope; });
  return table;
}

}  // namespace

ScanRunOptions ScanOptions::RunOptions() const {
  ScanRunOptions options = run;
  if (HasEnvelope(envelope)) plan::AddEnvelopeSettings(envelope, &options.planner_settings);
  return options;
}

const config::OptionTable<ScanOptions>& ScanOptionTable() {
  static const Table table = MakeTable();
  return table;
}

}  // namespace avc::orchestrator
