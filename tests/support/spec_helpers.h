#pragma once
// Test support: terse NetSpec construction.

#include <string>
#include <vector>

#include "gdpn/net/spec.h"

namespace gdpn::testing {

inline net::PlaceSpec place(std::string name, std::int64_t tokens = 0, std::int64_t capacity = -1) {
  net::PlaceSpec p;
  p.name = std::move(name);
  if (tokens > 0) p.tokens.push_back({net::kDefaultSlot, tokens, {}});
  if (capacity >= 0) p.capacity.push_back({net::kDefaultSlot, capacity, {}});
  return p;
}

inline net::TransitionSpec transition(std::string name, double seconds = 0.0) {
  net::TransitionSpec t;
  t.name = std::move(name);
  t.duration.a = seconds;
  return t;
}

inline net::ArcSpec arc(std::string from, std::string to,
                        std::vector<net::SlotCount> weights = {}) {
  net::ArcSpec a;
  a.from = std::move(from);
  a.to = std::move(to);
  a.weights = std::move(weights);
  return a;
}

}  // namespace gdpn::testing
