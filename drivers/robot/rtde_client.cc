#include "drivers/robot/rtde_client.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <utility>

namespace avc::robot {
namespace {

using Clock = std::chrono::steady_clock;

// The variables a recipe reply marks with `marker` ("NOT_FOUND" or "IN_USE").
std::vector<std::string> Marked(const std::vector<std::string>& names,
                                const std::vector<std::string>& types, std::string_view marker) {
  std::vector<std::string> marked;
  for (size_t i = 0; i < names.size() && i < types.size(); ++i) {
    if (types[i] == marker) marked.push_back(names[i]);
  }
  return marked;
}

std::string JoinForMessage(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

}  // namespace

RtdeClient::RtdeClient(std::string host, uint16_t port, net::Milliseconds timeout)
    : stream_(net::TcpStream::Connect(host, port, timeout)), timeout_(timeout) {}

std::string RtdeClient::Where(const std::string& step) const {
  return fmt::format("RTDE {}: {}", stream_.peer(), step);
}

void RtdeClient::Send(rtde::PacketType type, const std::vector<uint8_t>& payload) {
  const auto bytes = rtde::EncodePacket(type, payload);
  stream_.SendAll(bytes.data(), bytes.size(), timeout_);
}

bool RtdeClient::Fill(net::Milliseconds timeout) {
  uint8_t buffer[8192];
  const size_t n = stream_.ReceiveSome(buffer, sizeof(buffer), timeout);
  if (n == 0) return false;
  framer_.Append(buffer, n);
  return true;
}

std::optional<RtdeSample> RtdeClient::Absorb(const rtde::Packet& packet) {
  if (packet.type == static_cast<uint8_t>(rtde::PacketType::kTextMessage)) {
    text_messages_.push_back(rtde::DecodeTextMessage(packet.payload, protocol_version_));
    return std::nullopt;
  }
  if (packet.type == static_cast<uint8_t>(rtde::PacketType::kDataPackage)) {
    if (output_types_.empty()) {
      throw std::runtime_error(Where("data package arrived before an output recipe was set up"));
    }
    RtdeSample sample;
    sample.package = rtde::DecodeDataPackage(packet.payload, output_types_, protocol_version_);
    if (protocol_version_ >= 2 && sample.package.recipe_id != output_recipe_id_) {
      throw std::runtime_error(
          Where(fmt::format("data package for unknown recipe {}", sample.package.recipe_id)));
    }
    sample.state = RobotStateFromPackage(output_names_, sample.package.values);
    return sample;
  }
  throw std::runtime_error(
      Where(fmt::format("unexpected packet {}", rtde::PacketTypeName(packet.type))));
}

rtde::Packet RtdeClient::AwaitReply(rtde::PacketType type, const std::string& step) {
  const auto deadline = Clock::now() + timeout_;
  while (true) {
    while (auto packet = framer_.Next()) {
      if (packet->type == static_cast<uint8_t>(type)) return *packet;
      if (auto sample = Absorb(*packet)) pending_samples_.push_back(std::move(*sample));
    }
    const auto left = std::chrono::duration_cast<net::Milliseconds>(deadline - Clock::now());
    try {
      if (left.count() <= 0 || !Fill(left)) {
        throw std::runtime_error(
            Where(fmt::format("{}: no {} reply within {} ms", step,
                              rtde::PacketTypeName(static_cast<uint8_t>(type)), timeout_.count())));
      }
    } catch (const net::ConnectionError& error) {
      throw net::ConnectionError(fmt::format("RTDE {}: {}", step, error.what()));
    }
  }
}

int RtdeClient::NegotiateProtocol() {
  for (uint16_t version : {uint16_t{2}, uint16_t{1}}) {
    Send(rtde::PacketType::kRequestProtocolVersion, rtde::EncodeProtocolVersionRequest(version));
    const auto reply = AwaitReply(rtde::PacketType::kRequestProtocolVersion,
                                  fmt::format("request protocol version {}", version));
    if (rtde::DecodeAccepted(reply.payload, Where("protocol version reply"))) {
      protocol_version_ = version;
      return version;
    }
  }
  throw std::runtime_error(Where("controller accepts neither protocol version 2 nor 1"));
}

rtde::ControllerVersion RtdeClient::GetControllerVersion() {
  Send(rtde::PacketType::kGetUrcontrolVersion, {});
  const auto reply = AwaitReply(rtde::PacketType::kGetUrcontrolVersion, "get controller version");
  const auto version = rtde::DecodeControllerVersion(reply.payload);
  max_frequency_ = version.major < 5 ? kCb3MaxFrequency : kESeriesMaxFrequency;
  return version;
}

void RtdeClient::SetupOutputs(double frequency, const std::vector<std::string>& names) {
  if (!(frequency > 0 && frequency <= max_frequency_)) {
    throw std::runtime_error(Where(fmt::format("setup outputs: frequency {} Hz is outside (0, {}]",
                                               frequency, max_frequency_)));
  }
  if (names.empty()) throw std::runtime_error(Where("setup outputs: no variables requested"));
  Send(rtde::PacketType::kSetupOutputs,
       rtde::EncodeSetupOutputsRequest({frequency, names}, protocol_version_));
  const auto reply =
      rtde::DecodeRecipeReply(AwaitReply(rtde::PacketType::kSetupOutputs, "setup outputs").payload,
                              rtde::PacketType::kSetupOutputs, protocol_version_);
  const auto not_found = Marked(names, reply.types, "NOT_FOUND");
  if (!not_found.empty()) {
    throw std::runtime_error(Where(fmt::format(
        "setup outputs: controller does not know variable(s): {}", JoinForMessage(not_found))));
  }
  if (reply.types.size() != names.size()) {
    throw std::runtime_error(Where(fmt::format("setup outputs: {} types returned for {} names",
                                               reply.types.size(), names.size())));
  }
  std::vector<rtde::ValueType> types;
  for (size_t i = 0; i < names.size(); ++i) {
    const auto type = rtde::ParseValueType(reply.types[i]);
    if (!type) {
      throw std::runtime_error(Where(
          fmt::format("setup outputs: variable '{}' has type '{}'", names[i], reply.types[i])));
    }
    types.push_back(*type);
  }
  output_recipe_id_ = reply.recipe_id;
  output_names_ = names;
  output_types_ = std::move(types);
}

uint8_t RtdeClient::SetupInputs(const std::vector<std::string>& names) {
  if (names.empty()) throw std::runtime_error(Where("setup inputs: no variables requested"));
  Send(rtde::PacketType::kSetupInputs, rtde::EncodeSetupInputsRequest(names));
  const auto reply =
      rtde::DecodeRecipeReply(AwaitReply(rtde::PacketType::kSetupInputs, "setup inputs").payload,
                              rtde::PacketType::kSetupInputs, protocol_version_);
  const auto not_found = Marked(names, reply.types, "NOT_FOUND");
  const auto in_use = Marked(names, reply.types, "IN_USE");
  if (!not_found.empty() || !in_use.empty()) {
    std::string problem;
    if (!not_found.empty()) problem += "unknown variable(s): " + JoinForMessage(not_found);
    if (!in_use.empty()) {
      problem += (problem.empty() ? "" : "; ") + std::string("in use by another client: ") +
                 JoinForMessage(in_use);
    }
    throw std::runtime_error(Where("setup inputs: " + problem));
  }
  std::vector<rtde::ValueType> types;
  for (size_t i = 0; i < names.size() && i < reply.types.size(); ++i) {
    const auto type = rtde::ParseValueType(reply.types[i]);
    if (!type) {
      throw std::runtime_error(Where(
          fmt::format("setup inputs: variable '{}' has type '{}'", names[i], reply.types[i])));
    }
    types.push_back(*type);
  }
  if (types.size() != names.size() || reply.recipe_id == 0) {
    throw std::runtime_error(Where("setup inputs: malformed recipe reply"));
  }
  if (input_types_.size() <= reply.recipe_id) input_types_.resize(reply.recipe_id + 1u);
  input_types_[reply.recipe_id] = std::move(types);
  return reply.recipe_id;
}

void RtdeClient::Start() {
  Send(rtde::PacketType::kStart, {});
  const auto reply = AwaitReply(rtde::PacketType::kStart, "start");
  if (!rtde::DecodeAccepted(reply.payload, Where("start reply"))) {
    throw std::runtime_error(Where("start: controller refused to start streaming"));
  }
}

void RtdeClient::Pause() {
  Send(rtde::PacketType::kPause, {});
  const auto reply = AwaitReply(rtde::PacketType::kPause, "pause");
  if (!rtde::DecodeAccepted(reply.payload, Where("pause reply"))) {
    throw std::runtime_error(Where("pause: controller refused to pause"));
  }
  pending_samples_.clear();
}

void RtdeClient::SendInputs(uint8_t recipe_id, const std::vector<rtde::Value>& values) {
  if (recipe_id >= input_types_.size() || input_types_[recipe_id].empty()) {
    throw std::invalid_argument(Where(fmt::format("send inputs: unknown recipe {}", recipe_id)));
  }
  Send(rtde::PacketType::kDataPackage,
       rtde::EncodeDataPackage({recipe_id, values}, input_types_[recipe_id], protocol_version_));
}

std::optional<RtdeSample> RtdeClient::Receive(net::Milliseconds timeout) {
  const auto deadline = Clock::now() + timeout;
  while (true) {
    if (!pending_samples_.empty()) {
      RtdeSample sample = std::move(pending_samples_.front());
      pending_samples_.erase(pending_samples_.begin());
      return sample;
    }
    while (auto packet = framer_.Next()) {
      if (auto sample = Absorb(*packet)) return sample;
    }
    const auto left = std::chrono::duration_cast<net::Milliseconds>(deadline - Clock::now());
    try {
      if (!Fill(std::max(left, net::Milliseconds(0)))) return std::nullopt;
    } catch (const net::ConnectionError& error) {
      throw net::ConnectionError(fmt::format("RTDE receive state: {}", error.what()));
    }
  }
}

std::optional<RtdeSample> RtdeClient::ReceiveLatest(net::Milliseconds timeout) {
  std::optional<RtdeSample> latest = Receive(timeout);
  if (!latest) return latest;
  while (auto newer = Receive(net::Milliseconds(0))) latest = std::move(newer);
  return latest;
}

std::vector<rtde::TextMessage> RtdeClient::TakeTextMessages() {
  return std::exchange(text_messages_, {});
}

void RtdeClient::Handshake(const std::vector<std::string>& outputs, double frequency) {
  NegotiateProtocol();
  GetControllerVersion();
  SetupOutputs(frequency > 0 ? frequency : max_frequency_, outputs);
  Start();
}

}  // namespace avc::robot
