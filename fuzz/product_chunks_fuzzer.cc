// A stream of product_chunk_t messages into one Reassembler, as a product receiver gets them
// (any order, repeats, lies about counts and sizes), and each completed product through the
// collector's ToStoredFile. The input is a sequence of [uint16 little-endian length][encoded
// chunk] records.

#include <cstdint>
#include <stdexcept>

#include "core/bus/decode.h"
#include "core/products/chunking.h"
#include "core/products/product_archive.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  // Small limits so that eviction and deduplication are reached within a short input.
  avc::products::Reassembler reassembler(/*remember_completed=*/4, /*max_pending_bytes=*/1 << 16);
  while (size >= 2) {
    const size_t length = data[0] | (static_cast<size_t>(data[1]) << 8);
    data += 2;
    size -= 2;
    if (length > size) break;
    avc::product_chunk_t chunk;
    if (avc::bus::DecodeMessage(data, length, &chunk)) {  // as ProductReceiver decodes
      const auto outcome = reassembler.Add(chunk);
      if (outcome.product) {
        try {
          avc::products::ToStoredFile(*outcome.product);
        } catch (const std::invalid_argument&) {  // a name leaving the archive, a bad payload
        }
      }
    }
    data += length;
    size -= length;
  }
  return 0;
}
