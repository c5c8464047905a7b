#pragma once

// The names of a plan job's settings ("name=value", see services/planner/plan_settings.h for
// their meaning and ranges), and the arm's safety envelope written as such settings. One place,
// shared by the scan that sends them and the planner that reads them.

#include <map>
#include <optional>
#include <string>

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

// Adds the envelope avc robot enforces (`driver`) as table_z, table_clearance and keep_out.
void AddEnvelopeSettings(const kinematics::SafetyEnvelope& driver,
                         std::map<std::string, std::string>* settings);

}  // namespace avc::plan
