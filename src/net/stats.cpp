#include "gdpn/net/stats.h"

#include <algorithm>

namespace gdpn::net {

StatsCollector::StatsCollector(const Net& net) {
  transitions_.resize(net.transitions().size());
  places_.resize(net.places().size());
  place_of_.resize(net.placeSlots().size());
  for (PlaceSlotId ps{0}; ps < net.placeSlots().size(); ++ps) place_of_[ps] = net.placeSlots()[ps].place;
  for (PlaceId p{0}; p < net.places().size(); ++p) {
    const auto& place = net.places()[p];
    std::int64_t tokens = 0;
    for (auto ps = place.slots_begin; ps < place.slots_end; ++ps) tokens += net.placeSlots()[ps].initial;
    places_[p].tokens = tokens;
    places_[p].max = tokens;
  }
}

void StatsCollector::onStart(TransitionId t, std::int64_t step) {
  auto& s = transitions_[t];
  if (s.starts > 0) {
    const std::int64_t cycle = step - s.last_start;
    s.cycle_min = s.starts == 1 ? cycle : std::min(s.cycle_min, cycle);
    s.cycle_max = std::max(s.cycle_max, cycle);
    s.cycle_sum += cycle;
  }
  ++s.starts;
  s.last_start = step;
  ++s.running;
  s.running_starts += step;
}

void StatsCollector::onComplete(TransitionId t, std::int64_t step, std::int64_t started) {
  auto& s = transitions_[t];
  s.busy += step - started;
  --s.running;
  s.running_starts -= started;
}

void StatsCollector::change(PlaceId p, std::int64_t delta, std::int64_t step) {
  auto& s = places_[p];
  s.area += s.tokens * (step - s.since);
  s.since = step;
  s.tokens += delta;
  s.max = std::max(s.max, s.tokens);
}

void StatsCollector::onRemove(PlaceSlotId ps, std::int64_t count, std::span<const NodeRef>, std::int64_t step) {
  change(place_of_[ps], -count, step);
}

void StatsCollector::onDeposit(PlaceSlotId ps, std::int64_t count, std::span<const NodeRef>, std::int64_t step) {
  const PlaceId p = place_of_[ps];
  places_[p].deposited += count;
  change(p, count, step);
}

void StatsCollector::finish(std::int64_t step) {
  for (PlaceId p{0}; p < places_.size(); ++p) change(p, 0, step);
  for (auto& s : transitions_) {
    s.busy += s.running * step - s.running_starts;
  }
}

}  // namespace gdpn::net
