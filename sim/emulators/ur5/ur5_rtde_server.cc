#include "sim/emulators/ur5/ur5_rtde_server.h"

#include <fmt/format.h>

#include <algorithm>

namespace avc::sim::ur5 {

namespace rtde = robot::rtde;

RtdeSession::RtdeSession(int id, net::TcpStream stream, Ur5Controller& controller,
                         RtdeInputOwners& owners)
    : Session(id, std::move(stream)), controller_(controller), owners_(owners) {}

RtdeSession::~RtdeSession() {
  std::erase_if(owners_, [this](const auto& owner) { return owner.second == id(); });
}

void RtdeSession::Reply(rtde::PacketType type, const std::vector<uint8_t>& payload) {
  Queue(rtde::EncodePacket(type, payload));
}

void RtdeSession::Text(const std::string& text, rtde::MessageLevel level) {
  Reply(rtde::PacketType::kTextMessage,
        rtde::EncodeTextMessage({text.substr(0, 255), "RTDE", level}, protocol_));
}

void RtdeSession::Consume(const uint8_t* data, size_t size) {
  framer_.Append(data, size);
  while (auto packet = framer_.Next()) Handle(*packet);
}

void RtdeSession::OnMalformed(const std::string& what) {
  Text(what, rtde::MessageLevel::kException);
}

void RtdeSession::Handle(const rtde::Packet& packet) {
  switch (static_cast<rtde::PacketType>(packet.type)) {
    case rtde::PacketType::kRequestProtocolVersion: {
      const uint16_t version = rtde::DecodeProtocolVersionRequest(packet.payload);
      const bool accepted = version >= 1 && version <= controller_.options().max_protocol_version;
      if (accepted) protocol_ = version;
      Reply(rtde::PacketType::kRequestProtocolVersion, rtde::EncodeAccepted(accepted));
      return;
    }
    case rtde::PacketType::kGetUrcontrolVersion:
      Reply(rtde::PacketType::kGetUrcontrolVersion,
            rtde::EncodeControllerVersion(controller_.options().version));
      return;
    case rtde::PacketType::kSetupOutputs:
      SetupOutputs(rtde::DecodeSetupOutputsRequest(packet.payload, protocol_));
      return;
    case rtde::PacketType::kSetupInputs:
      SetupInputs(rtde::DecodeSetupInputsRequest(packet.payload));
      return;
    case rtde::PacketType::kStart:
      started_ = !output_names_.empty();
      since_last_ = period_;  // first package at the next tick
      Reply(rtde::PacketType::kStart, rtde::EncodeAccepted(started_));
      return;
    case rtde::PacketType::kPause:
      started_ = false;
      Reply(rtde::PacketType::kPause, rtde::EncodeAccepted(true));
      return;
    case rtde::PacketType::kDataPackage:
      WriteInputs(packet.payload);
      return;
    default:
      Text(fmt::format("unsupported RTDE packet {}", rtde::PacketTypeName(packet.type)),
           rtde::MessageLevel::kError);
  }
}

void RtdeSession::SetupOutputs(const rtde::SetupOutputsRequest& request) {
  rtde::RecipeReply reply;
  std::vector<rtde::ValueType> types;
  bool all_found = true;
  for (const auto& name : request.names) {
    const auto type = OutputType(name);
    all_found = all_found && type.has_value();
    reply.types.emplace_back(type ? rtde::ValueTypeName(*type) : "NOT_FOUND");
    if (type) types.push_back(*type);
  }
  const double max_frequency = controller_.options().control_frequency;
  const bool frequency_ok = request.frequency > 0 && request.frequency <= max_frequency;
  if (!frequency_ok) {
    Text(fmt::format("output frequency {} Hz is outside (0, {}]", request.frequency, max_frequency),
         rtde::MessageLevel::kError);
  }
  if (all_found && frequency_ok && !request.names.empty()) {
    reply.recipe_id = 1;
    output_names_ = request.names;
    output_types_ = std::move(types);
    period_ = 1.0 / request.frequency;
  }
  Reply(rtde::PacketType::kSetupOutputs,
        rtde::EncodeRecipeReply(reply, rtde::PacketType::kSetupOutputs, protocol_));
}

void RtdeSession::SetupInputs(const std::vector<std::string>& names) {
  rtde::RecipeReply reply;
  InputRecipe recipe;
  bool usable = !names.empty();
  for (const auto& name : names) {
    const auto type = InputType(name);
    const auto owner = owners_.find(name);
    if (!type) {
      reply.types.emplace_back("NOT_FOUND");
      usable = false;
    } else if (owner != owners_.end() && owner->second != id()) {
      reply.types.emplace_back("IN_USE");
      usable = false;
    } else {
      reply.types.emplace_back(rtde::ValueTypeName(*type));
      recipe.names.push_back(name);
      recipe.types.push_back(*type);
    }
  }
  if (usable) {
    reply.recipe_id = next_input_id_++;
    for (const auto& name : names) owners_[name] = id();
    inputs_[reply.recipe_id] = std::move(recipe);
  }
  Reply(rtde::PacketType::kSetupInputs,
        rtde::EncodeRecipeReply(reply, rtde::PacketType::kSetupInputs, protocol_));
}

void RtdeSession::WriteInputs(const std::vector<uint8_t>& payload) {
  // v1 packages carry no recipe id: they belong to the only input recipe.
  const uint8_t recipe_id = protocol_ >= 2 && !payload.empty() ? payload[0] : 1;
  const auto recipe = inputs_.find(recipe_id);
  if (recipe == inputs_.end()) {
    Text(fmt::format("data package for unknown input recipe {}", recipe_id),
         rtde::MessageLevel::kError);
    return;
  }
  const auto package = rtde::DecodeDataPackage(payload, recipe->second.types, protocol_);
  for (size_t i = 0; i < package.values.size(); ++i) {
    controller_.WriteRtdeInput(recipe->second.names[i], package.values[i]);
  }
}

void RtdeSession::OnTick() {
  if (!started_) return;
  since_last_ += controller_.dt();
  if (since_last_ + 1e-9 < period_) return;
  since_last_ = std::min(since_last_ - period_, period_);
  if (queued() > kMaxQueuedBytes) return;  // slow client: drop, do not queue
  rtde::DataPackage package;
  package.recipe_id = 1;
  for (const auto& name : output_names_) {
    package.values.push_back(OutputValue(name, controller_.rtde_state()));
  }
  Reply(rtde::PacketType::kDataPackage, rtde::EncodeDataPackage(package, output_types_, protocol_));
}

}  // namespace avc::sim::ur5
