#pragma once

// The names of a plan job's settings ("name=value", see services/planner/plan_settings.h for
// their meaning and ranges), and the arm's safety envelope written as such settings. One place,
// shared by the scan that sends them and the planner that reads them.

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/config/option_text.h"
#include "core/kinematics/safety_envelope.h"

namespace avc::plan {

inline constexpr char kMaxViews[] = "max_views";
inline constexpr char kLevels[] = "levels";
inline constexpr char kViewsPerLevel[] = "views_per_level";
inline constexpr char kPruneFaceLoss[] = "prune_face_loss";
inline constexpr char kKeepOutMargin[] = "keep_out_margin";
inline constexpr char kTableZ[] = "table_z";
inline constexpr char kTableClearance[] = "table_clearance";
inline constexpr char kKeepOut[] = "keep_out";  // "x y radius z_min z_max", base frame, m

// Algorithm 1's settings (the first five names above) with their units, ranges and docs,
// declared once for avc-planner's options and for avc scan's, which checks what it will send.
struct AlgorithmSetting {
  const char* name;
  bool integer;
  config::OptionSpec spec;
};
const std::vector<AlgorithmSetting>& AlgorithmSettings();
// The spec of one of them; throws std::logic_error for another name.
const config::OptionSpec& AlgorithmSettingSpec(std::string_view name);

// Adds the envelope avc robot enforces (`driver`) as table_z, table_clearance and keep_out.
void AddEnvelopeSettings(const kinematics::SafetyEnvelope& driver,
                         std::map<std::string, std::string>* settings);

}  // namespace avc::plan
