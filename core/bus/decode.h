#pragma once

// Decoding received bytes as an LCM type. The decode that lcm-gen 1.3.1 generates returns -1 for
// most malformed bytes but throws for some: a string length of 0 or less reaches
// std::string::assign as a huge size (std::length_error), and a negative or huge array count
// reaches std::vector::resize (std::length_error, std::bad_alloc). Every receiver decodes through
// this, so any malformed message is a plain refusal, never an exception.

#include <climits>
#include <cstddef>
#include <new>
#include <stdexcept>

namespace avc::bus {

// True when data[0, size) is one message of type T, then in *message.
template <class T>
bool DecodeMessage(const void* data, size_t size, T* message) {
  if (size > static_cast<size_t>(INT_MAX)) return false;
  try {
    return message->decode(data, 0, static_cast<int>(size)) >= 0;
  } catch (const std::length_error&) {
  } catch (const std::bad_alloc&) {
  }
  return false;
}

}  // namespace avc::bus
