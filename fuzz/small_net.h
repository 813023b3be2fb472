#pragma once
// Fuzz support: a small net with a page path for the targets that read text against a net
// (queries, witnesses).

#include <memory>

#include "gdpn/net/builder.h"

namespace gdpn::fuzz {

/// Three places, two transitions and a page path: a cycle of one token, and a producer.
inline std::shared_ptr<const gdpn::net::Net> smallNet() {
  gdpn::net::NetBuilder b;
  const auto idle = b.addPlace("cell/idle");
  const auto busy = b.addPlace("cell/busy");
  const auto out = b.addPlace("U");
  b.setSlot(idle, gdpn::net::kDefaultSlot, gdpn::net::SlotKind::Control, gdpn::net::kUnbounded, 1);
  const auto start = b.addTransition("cell/start");
  const auto done = b.addTransition("cell/done");
  b.addInput(idle, start);
  b.addOutput(start, busy);
  b.addInput(busy, done);
  b.addOutput(done, idle);
  b.addOutput(done, out);
  return b.freeze();
}

}  // namespace gdpn::fuzz
