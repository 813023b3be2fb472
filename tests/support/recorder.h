#pragma once
// Test support: an observer that records kernel events as compact strings.

#include <string>
#include <vector>

#include "gdpn/net/observer.h"

namespace gdpn::testing {

/// Records "start T @3", "complete T @4", "remove P.a0 x1 @3", "deposit P.d0 [0 1] @4".
class Recorder : public net::NetObserver {
 public:
  explicit Recorder(const net::Net& net) : net_(net) {}
  void onStart(net::TransitionId t, std::int64_t step) override {
    events.push_back("start " + net_.transitionName(t) + " @" + std::to_string(step));
    starts.emplace_back(net_.transitionName(t), step);
  }
  void onComplete(net::TransitionId t, std::int64_t step, std::int64_t) override {
    events.push_back("complete " + net_.transitionName(t) + " @" + std::to_string(step));
  }
  void onRemove(net::PlaceSlotId ps, std::int64_t n, std::span<const net::NodeRef> nodes, std::int64_t step) override {
    events.push_back("remove " + where(ps) + " x" + std::to_string(n) + list(nodes) + " @" + std::to_string(step));
  }
  void onDeposit(net::PlaceSlotId ps, std::int64_t n, std::span<const net::NodeRef> nodes, std::int64_t step) override {
    events.push_back("deposit " + where(ps) + " x" + std::to_string(n) + list(nodes) + " @" + std::to_string(step));
  }
  /// Steps at which transition `name` started.
  std::vector<std::int64_t> startsOf(const std::string& name) const {
    std::vector<std::int64_t> out;
    for (const auto& [n, s] : starts) {
      if (n == name) out.push_back(s);
    }
    return out;
  }

  std::vector<std::string> events;
  std::vector<std::pair<std::string, std::int64_t>> starts;

 private:
  std::string where(net::PlaceSlotId ps) const {
    const auto& s = net_.placeSlots()[ps];
    return net_.placeName(s.place) + "." + net::slotName(s.slot);
  }
  static std::string list(std::span<const net::NodeRef> nodes) {
    if (nodes.empty()) return "";
    std::string s = " [";
    for (std::size_t i = 0; i < nodes.size(); ++i) s += (i ? " " : "") + std::to_string(nodes[i]);
    return s + "]";
  }
  const net::Net& net_;
};

}  // namespace gdpn::testing
