#pragma once

// Small encoders the scan report (report_html.h) puts its data into the page with: base64 of
// little-endian typed arrays that the page's JavaScript decodes into Float32Array & co., HTML
// escaping, and the one colour per cluster shared by the 3-D view and the SVG renders.

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/util/web_text.h"

namespace avc::report {

// The values as little-endian bytes, base64 encoded (a typed array's buffer on any host).
std::string Base64Floats(const std::vector<float>& values);
std::string Base64Ints(const std::vector<int32_t>& values);

// Text safe inside HTML elements and attribute values (core/util/web_text.h).
using ::avc::EscapeHtml;

// A distinct, stable colour for a cluster id (golden-angle hues); grey for negative ids
// (outliers, no cluster).
std::array<uint8_t, 3> ClusterColour(int32_t cluster);
// "#rrggbb".
std::string CssColour(const std::array<uint8_t, 3>& rgb);

}  // namespace avc::report
