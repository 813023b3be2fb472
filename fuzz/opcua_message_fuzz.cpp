// libFuzzer target: any bytes as what an OPC UA client sends on one connection. They reach the
// endpoint in pieces (as TCP may cut them); between pieces the run steps, samples and
// publishes. Whatever comes, the endpoint answers with whole UA TCP messages (ACK, ERR, OPN,
// MSG) or closes the connection: never a crash, a hang or a sanitizer report. Seeds: a
// session of node-opcua-client recorded (tests/data/opcua).

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>

#include "gdpn/opcua/endpoint.h"
#include "gdpn/opcua/status.h"

namespace {

using namespace gdpn::opcua;

struct FuzzSpace {
  AddressSpace space{{"http://opcfoundation.org/UA/", "urn:gdpn:model:fuzz"}, "urn:gdpn:server", "gdpn", "fuzz"};
  double x = 1.5;
  FuzzSpace() {
    const NodeId model = NodeId::str("model");
    space.addObject(NodeId::num(id::kObjectsFolder), model, 1, "fuzz", id::kBaseObjectType);
    space.addObject(model, NodeId::str("io"), 1, "IO");
    Node& v = space.addVariable(NodeId::str("io"), NodeId::str("io/x"), 1, "x", 11);
    v.read = [this] { return Variant::dbl(x); };
    v.write = [this](const Variant& value) {
      x = value.number().value_or(0);
      return StatusCode{0};
    };
    v.numeric = true;
    Node m;
    m.id = NodeId::str("step");
    m.node_class = NodeClass::Method;
    m.browse_name = {1, "Step"};
    m.executable = true;
    m.references.push_back({NodeId::num(id::kHasComponent), model, false});
    m.call = [](const std::vector<Variant>& in, std::vector<Variant>&, std::vector<StatusCode>&, CallContext& ctx) {
      if (in.size() != 1 || in[0].type != BuiltinType::UInt32) return status::kBadInvalidArgument;
      ctx.wait_steps = static_cast<std::uint32_t>(std::get<std::uint64_t>(in[0].scalar) % 1000);
      return status::kGood;
    };
    space.add(std::move(m));
  }
};

// whole messages of known types, or a trap
void checkOutput(const std::string& out) {
  std::size_t at = 0;
  while (at < out.size()) {
    if (out.size() - at < 8) __builtin_trap();
    const std::string type = out.substr(at, 3);
    if (type != "ACK" && type != "ERR" && type != "OPN" && type != "MSG") __builtin_trap();
    std::uint32_t size = 0;
    for (int k = 3; k >= 0; --k) size = (size << 8) | static_cast<std::uint8_t>(out[at + 4 + static_cast<std::size_t>(k)]);
    if (size < 8 || size > out.size() - at || size > 65535) __builtin_trap();
    at += size;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static FuzzSpace s;
  Endpoint ep(s.space, "opc.tcp://127.0.0.1:4840", {}, false, 1);  // the seed the seeds were recorded with
  ep.setLockstep(true);
  const ConnectionId c = ep.open("fuzz:1");
  auto now = Endpoint::Clock::now();
  double t = 0;
  for (std::size_t at = 0; at < size;) {
    const std::size_t piece = std::min<std::size_t>(size - at, 1 + (data[at] % 97) * 17);
    const bool open = ep.receive(c, data + at, piece);
    at += piece;
    checkOutput(ep.takeOutput(c));
    if (!open) break;
    t += 0.005;
    ep.sample(t);
    if (ep.pendingSteps() > 0) ep.stepTaken();
    now += std::chrono::milliseconds(30);
    ep.tick(now);
    checkOutput(ep.takeOutput(c));
  }
  ep.close(c);
  return 0;
}
