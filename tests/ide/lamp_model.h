#pragma once
// Test support for the I/O list's tests: a model using the test part `lamp`
// (tests/data/parts/lamp.gdpn.yaml: digital and analogue inputs and outputs, and the control
// pattern `lamp_control`, which lights the lamp while it sees something).

#include <fstream>
#include <sstream>
#include <string>

namespace gdpn::ide::testing {

/// The lamp part's page types, then `rest` (more page types, indented as they are, or the
/// model's other sections).
inline std::string withLampPart(const std::string& rest) {
  std::ifstream in(std::string(GDPN_SOURCE_DIR) + "/tests/data/parts/lamp.gdpn.yaml");
  std::stringstream text;
  text << in.rdbuf();
  return text.str() + rest;
}

/// A lamp `lamp1` with its control pattern, its `light` mapped to coil 0 by hand (its other
/// I/O not mapped), and a transition whose guard reads its `height` through `sim.part`.
inline std::string lampModel() {
  return withLampPart(R"Y(io:
  coils:
    0: {part: lamp1, io: light}
pages:
  main:
    places:
      waiting: {tokens: 1}
      done: {}
    transitions:
      watch: {guard: 'sim.part("lamp1").height > 0.5'}
    arcs: [waiting -> watch, watch -> done]
    instances:
      lamp1: {type: lamp}
      lamp1_control: {type: lamp_control, part: lamp1}
scene:
  - Light: {}
  - Camera: {name: view, position: [2.6, -2.6, 2.2], target: [1, 0, 0.6]}
  - Transform: {translation: [0, 0, -0.3], children: [{Plane: {}}]}   # below the lamp's eye
)Y");
}

}  // namespace gdpn::ide::testing
