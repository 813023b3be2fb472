// libFuzzer target: any bytes as what a Modbus TCP client sends. The stream is cut into frames
// as the server cuts it; each frame is taken apart, and a well-formed request is served by an
// io map over a small station (a place, a conveyor, a slider, a region): reads give words,
// writes change the plant or are refused, never a crash, a hang or a sanitizer report.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>

#include "gdpn/modbus/request.h"
#include "gdpn/model/io.h"
#include "gdpn/model/model.h"
#include "gdpn/model/simulation.h"

namespace {

constexpr const char* kStation = R"(gdpn: 1
scene:
  - Transform: {name: belt, children: [{Conveyor: {name: drive, speed: 0}}, {Cube: {size: [2, 0.5, 0.1]}}]}
  - Region: {name: eye, size: [0.1, 0.1, 0.1]}
  - Joint: {name: pusher, kind: slider, lo1: 0, hi1: 0.5, control: position, children: [{Body: {children: [{Cube: {}}]}}]}
io:
  lockstep: 9
  discrete_inputs: {0: {node: eye, of: active}, 1: {place: main/parts}}
  input_registers: {0: {node: pusher, of: angle, scale: 1000}, 1: {node: belt/drive, of: speed, type: float32}}
  coils: {0: {name: belt_on, node: belt/drive, field: speed, on: 0.5}, 1: {place: main/start}}
  holding_registers:
    0: {node: pusher, field: target1, scale: 1000, type: int32}
    2: {place: main/parts}
    3: {name: belt_speed, node: belt/drive, field: speed, type: Double}
pages:
  main:
    places: {start: {}, parts: {tokens: 3}}
    transitions: {go: {}}
    arcs: [start -> go]
)";

struct Station {
  std::unique_ptr<gdpn::model::Simulation> sim;
  std::unique_ptr<gdpn::model::IoMap> io;
};

Station& station() {
  static Station s = [] {
    Station out;
    gdpn::core::Diagnostics diags;
    auto model = gdpn::model::parseModel(kStation, "station.gdpn.yaml", diags);
    if (!model) __builtin_trap();
    out.sim = gdpn::model::Simulation::create(*model, diags);
    if (!out.sim) __builtin_trap();
    out.io = gdpn::model::IoMap::create(*out.sim, model->io, diags);
    if (!out.io) __builtin_trap();
    return out;
  }();
  return s;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using gdpn::model::IoError;
  using gdpn::model::IoTable;
  Station& s = station();
  std::span<const std::uint8_t> stream(data, size);
  while (!stream.empty()) {
    const std::ptrdiff_t length = gdpn::modbus::frameLength(stream);
    if (length <= 0) break;  // more bytes needed, or no Modbus TCP: the server closes
    if (static_cast<std::size_t>(length) > stream.size() || static_cast<std::size_t>(length) > gdpn::modbus::kMaxFrameBytes) {
      __builtin_trap();
    }
    const auto r = gdpn::modbus::decodeRequest(stream.first(static_cast<std::size_t>(length)));
    stream = stream.subspan(static_cast<std::size_t>(length));
    if (r.error != IoError::None) continue;
    if (r.count < 1 || std::uint32_t{r.address} + r.count > 65536) __builtin_trap();
    if (!s.io->mapped(r.table, r.address, r.count)) continue;
    if (r.write) {
      if (r.table == IoTable::Coils) {
        if (r.bits.size() != r.count) __builtin_trap();
        (void)s.io->writeBits(r.address, r.bits, "fuzz");
      } else {
        if (r.words.size() != r.count) __builtin_trap();
        (void)s.io->writeWords(r.address, r.words, "fuzz");
      }
      s.sim->step();  // what was written takes effect
    } else {
      for (std::uint32_t k = 0; k < r.count; ++k) {
        const auto a = static_cast<std::uint16_t>(r.address + k);
        if (r.table == IoTable::DiscreteInputs || r.table == IoTable::Coils) {
          (void)s.io->bit(r.table, a);
        } else {
          (void)s.io->word(r.table, a);
        }
      }
    }
  }
  return 0;
}
