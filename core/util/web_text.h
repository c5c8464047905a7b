#pragma once

// Text for web pages we write (the evaluation page, the scan report): binary data as base64 and
// any text made safe inside HTML.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace avc {

// Standard base64 (RFC 4648) with '=' padding.
std::string Base64Encode(std::span<const uint8_t> bytes);

// Text safe inside HTML elements and attribute values (& < > " ' escaped).
std::string EscapeHtml(std::string_view text);

}  // namespace avc
