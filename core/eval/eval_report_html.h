#pragma once

// The evaluation report as one self-contained HTML page: the tables of the text summary and the
// error plot inlined as a base64 PNG, rendered from the report JSON (see report_text.h).

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace avc::eval {

// plot_png may be empty (the page then has no picture). Same inputs → same bytes.
std::string RenderHtml(const nlohmann::json& report, const std::vector<uint8_t>& plot_png);

}  // namespace avc::eval
