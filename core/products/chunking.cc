#include "core/products/chunking.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "core/util/sha256.h"

namespace avc::products {
namespace {

// Room left in every chunk for the header the bus stamps (source and cell strings).
constexpr size_t kHeaderReserve = 512;

bool IsHexDigest(const std::string& text) {
  return text.size() == 64 && std::all_of(text.begin(), text.end(), [](char c) {
           return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
         });
}

}  // namespace

size_t ChunkPayloadBytes(size_t max_message_bytes, const Product& product) {
  avc::product_chunk_t empty{};
  empty.product_id = product.product_id;
  empty.name = product.name;
  empty.content_type = product.content_type;
  empty.sha256 = std::string(64, '0');
  empty.size = 0;
  const size_t overhead = static_cast<size_t>(empty.getEncodedSize()) + kHeaderReserve;
  if (max_message_bytes <= overhead + 1024) {
    throw std::invalid_argument(fmt::format("message cap {} is too small for product '{}'",
                                            max_message_bytes, product.name));
  }
  return max_message_bytes - overhead;
}

std::vector<avc::product_chunk_t> SplitIntoChunks(const Product& product,
                                                  size_t max_message_bytes) {
  const size_t per_chunk = ChunkPayloadBytes(max_message_bytes, product);
  const size_t total = product.payload.size();
  const size_t count = std::max<size_t>(1, (total + per_chunk - 1) / per_chunk);
  if (count > static_cast<size_t>(INT32_MAX)) {
    throw std::invalid_argument("product '" + product.name + "' needs too many chunks");
  }
  std::vector<avc::product_chunk_t> chunks(count);
  for (size_t i = 0; i < count; ++i) {
    avc::product_chunk_t& chunk = chunks[i];
    chunk.product_id = product.product_id;
    chunk.name = product.name;
    chunk.content_type = product.content_type;
    chunk.sha256 = product.sha256;
    chunk.total_size = static_cast<int64_t>(total);
    chunk.chunk_index = static_cast<int32_t>(i);
    chunk.chunk_count = static_cast<int32_t>(count);
    const size_t begin = i * per_chunk;
    const size_t end = std::min(total, begin + per_chunk);
    chunk.offset = static_cast<int64_t>(begin);
    chunk.attempt = 0;
    chunk.data.assign(product.payload.begin() + static_cast<std::ptrdiff_t>(begin),
                      product.payload.begin() + static_cast<std::ptrdiff_t>(end));
    chunk.size = static_cast<int32_t>(chunk.data.size());
  }
  return chunks;
}

Reassembler::Reassembler(size_t remember_completed, size_t max_pending_bytes)
    : remember_completed_(remember_completed), max_pending_bytes_(max_pending_bytes) {}

Reassembler::Outcome Reassembler::Add(const avc::product_chunk_t& chunk) {
  Outcome outcome;
  auto invalid = [&outcome, &chunk](const std::string& why) {
    outcome.status = Status::kInvalid;
    outcome.error = fmt::format("chunk {} of product '{}' ({}): {}", chunk.chunk_index, chunk.name,
                                chunk.product_id, why);
    return outcome;
  };
  if (chunk.product_id.empty()) return invalid("empty product id");
  if (completed_.contains(chunk.product_id)) {
    outcome.status = Status::kDuplicate;
    return outcome;
  }
  if (chunk.chunk_count < 1) return invalid("chunk_count < 1");
  if (chunk.chunk_index < 0 || chunk.chunk_index >= chunk.chunk_count) {
    return invalid(fmt::format("index outside 0..{}", chunk.chunk_count - 1));
  }
  if (chunk.size < 0 || static_cast<size_t>(chunk.size) != chunk.data.size()) {
    return invalid("size field disagrees with the data");
  }
  if (chunk.total_size < 0 || chunk.offset < 0 || chunk.offset + chunk.size > chunk.total_size) {
    return invalid(fmt::format("bytes {}..{} lie outside the {}-byte product", chunk.offset,
                               chunk.offset + chunk.size, chunk.total_size));
  }
  // Every chunk but an empty product's only one carries a byte: a count above the size is a lie
  // that would make the chunk bookkeeping billions long (fuzz/product_chunks timed out on one).
  if (chunk.chunk_count > std::max<int64_t>(1, chunk.total_size)) {
    return invalid(
        fmt::format("{} chunks for a {}-byte product", chunk.chunk_count, chunk.total_size));
  }
  if (static_cast<uint64_t>(chunk.total_size) > max_pending_bytes_) {
    return invalid(fmt::format("{} bytes is over the receiver's limit of {}", chunk.total_size,
                               max_pending_bytes_));
  }
  if (!IsHexDigest(chunk.sha256)) return invalid("sha256 is not 64 lower-case hex digits");

  auto it = pending_.find(chunk.product_id);
  if (it == pending_.end()) {
    while (!pending_.empty() &&
           pending_bytes_ + static_cast<size_t>(chunk.total_size) > max_pending_bytes_) {
      EvictOldestPending();
    }
    Pending fresh;
    fresh.product.product_id = chunk.product_id;
    fresh.product.name = chunk.name;
    fresh.product.content_type = chunk.content_type;
    fresh.product.sha256 = chunk.sha256;
    fresh.product.source = chunk.header.source;
    fresh.product.utime = chunk.header.utime;
    fresh.product.payload.resize(static_cast<size_t>(chunk.total_size));
    fresh.chunk_count = chunk.chunk_count;
    fresh.have.assign(static_cast<size_t>(chunk.chunk_count), false);
    fresh.arrival = ++arrivals_;
    pending_bytes_ += static_cast<size_t>(chunk.total_size);
    it = pending_.emplace(chunk.product_id, std::move(fresh)).first;
  }
  Pending& pending = it->second;
  if (pending.chunk_count != chunk.chunk_count ||
      pending.product.payload.size() != static_cast<size_t>(chunk.total_size) ||
      pending.product.sha256 != chunk.sha256 || pending.product.name != chunk.name ||
      pending.product.content_type != chunk.content_type) {
    return invalid("disagrees with earlier chunks of the same product");
  }
  // The earliest header time seen stands for the product, whatever order chunks arrive in.
  pending.product.utime = std::min(pending.product.utime, chunk.header.utime);
  const size_t index = static_cast<size_t>(chunk.chunk_index);
  if (!pending.have[index]) {
    std::copy(chunk.data.begin(), chunk.data.end(),
              pending.product.payload.begin() + static_cast<std::ptrdiff_t>(chunk.offset));
    pending.have[index] = true;
    ++pending.received;
  }
  if (pending.received < pending.chunk_count) {
    outcome.status = Status::kIncomplete;
    return outcome;
  }
  Product product = std::move(pending.product);
  pending_bytes_ -= product.payload.size();
  pending_.erase(it);
  if (Sha256Hex(product.payload) != product.sha256) {
    outcome.status = Status::kCorrupt;
    outcome.error = fmt::format("product '{}' ({}): sha256 mismatch after reassembly", product.name,
                                product.product_id);
    return outcome;
  }
  RememberCompleted(product.product_id);
  outcome.status = Status::kComplete;
  outcome.product = std::move(product);
  return outcome;
}

std::vector<int32_t> Reassembler::Missing(const std::string& product_id) const {
  std::vector<int32_t> missing;
  auto it = pending_.find(product_id);
  if (it == pending_.end()) return missing;
  for (size_t i = 0; i < it->second.have.size(); ++i) {
    if (!it->second.have[i]) missing.push_back(static_cast<int32_t>(i));
  }
  return missing;
}

bool Reassembler::IsCompleted(const std::string& product_id) const {
  return completed_.contains(product_id);
}

void Reassembler::ForgetCompleted(const std::string& product_id) {
  completed_.erase(product_id);
  std::erase(completed_order_, product_id);
}

void Reassembler::RememberCompleted(const std::string& product_id) {
  completed_.insert(product_id);
  completed_order_.push_back(product_id);
  while (completed_order_.size() > remember_completed_) {
    completed_.erase(completed_order_.front());
    completed_order_.pop_front();
  }
}

void Reassembler::EvictOldestPending() {
  auto oldest = std::min_element(
      pending_.begin(), pending_.end(),
      [](const auto& a, const auto& b) { return a.second.arrival < b.second.arrival; });
  pending_bytes_ -= oldest->second.product.payload.size();
  pending_.erase(oldest);
}

}  // namespace avc::products
