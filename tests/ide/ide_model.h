#pragma once
// Test support for the IDE tests: a small model with a scene and a net, written to a file of
// the test's own.

#include <string>

namespace gdpn::ide::testing {

// a box falls into a bin watched by a region; a loop of two transitions, one never enabled
inline const std::string kBinModel = R"Y(gdpn: 1
settings: {dt: 0.01, seed: 3}
scene:
  - Camera: {name: view, position: [4, -4, 3], target: [0, 0, 0.5]}
  - Transform: {translation: [0, 0, -0.1], children: [{Plane: {}}]}
  - Transform: {name: high, translation: [0, 0, 0.5], children: [{Region: {name: bin, size: [4, 4, 1], scope: world}}]}
  - Transform:
      name: drop
      translation: [0, 0, 3]
      children:
        - Material: {name: paint, diffuse: [0.8, 0.2, 0.1], bounce: 0.2}
        - Body: {name: box, mass: 1, children: [{Cube: {name: shape, size: [0.2, 0.2, 0.2]}}]}
pages:
  main:
    places:
      idle: {tokens: 2}
      watching: {sensors: {c0: high/bin}}
      landed: {}
      busy: {}
      never: {}
      spare: {tokens: 1}
    transitions:
      work: {duration: 0.3}
      rest: {duration: 0.2}
      see: {}
      stuck: {}
      manual: {probability: 0.000001}
    arcs:
      - idle -> work
      - work -> busy
      - busy -> rest
      - rest -> idle
      - {from: watching, to: see, condition: 'len(c0.items) > 0'}
      - see -> landed
      - never -> stuck
      - stuck -> landed
      - spare -> manual
      - manual -> landed
)Y";

// a push button: a Body holding a Cube and a MouseSensor, seen by the camera straight on; a
// click on it lets `press` fire once
inline const std::string kButtonModel = R"Y(gdpn: 1
settings: {dt: 0.01, seed: 1}
scene:
  - World: {gravity: [0, 0, 0]}
  - Light: {}
  - Camera: {name: view, position: [3, -3, 2], target: [0, 0, 0]}
  - Body:
      name: button
      children:
        - Cube: {name: cap, size: [0.5, 0.5, 0.5]}
        - MouseSensor: {name: mouse}
pages:
  main:
    places:
      panel: {sensors: {c0: button/mouse}}
      ready: {tokens: 1}
      pressed: {}
    transitions:
      press: {}
    arcs:
      - {from: panel, to: press, condition: 'c0.clicks > 0'}
      - ready -> press
      - press -> pressed
)Y";

}  // namespace gdpn::ide::testing
