#pragma once

// Figures formatted the same way in the text and HTML reports (report_text.h, eval_report_html.h),
// read from the report JSON.

#include <nlohmann/json.hpp>
#include <string>

namespace avc::eval {

// The distance statistic stats[key] (metres) in mm with 3 decimals; "-" when absent or not a
// number (no points to measure).
std::string FormatMillimetres(const nlohmann::json& stats, const char* key);

// A fraction (0..1) as a percentage with 1 decimal, without the % sign.
std::string FormatPercent(const nlohmann::json& fraction);

}  // namespace avc::eval
