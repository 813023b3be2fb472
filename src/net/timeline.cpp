#include "gdpn/net/timeline.h"

#include <algorithm>

namespace gdpn::net {

Timeline::Timeline(const Net& net, std::size_t budget)
    : net_(net), budget_(budget), open_(net.transitions().size()), tokens_(net.places().size()),
      places_(net.places().size()) {
  for (PlaceId p{0}; p < net.places().size(); ++p) {
    const auto& place = net.places()[p];
    for (auto ps = place.slots_begin; ps < place.slots_end; ++ps) tokens_[p] += net.placeSlots()[ps].initial;
    places_[p].push_back({0, tokens_[p]});
  }
}

bool Timeline::keep(std::int64_t step) {
  if (kept_ < budget_) {
    ++kept_;
    return true;
  }
  if (cut_at_ < 0) cut_at_ = step;
  ++dropped_;
  return false;
}

void Timeline::onStart(TransitionId t, std::int64_t step) {
  if (!keep(step)) return;
  open_[t].push_back(occurrences_.size());
  occurrences_.push_back({t, step, -1});
}

void Timeline::onComplete(TransitionId t, std::int64_t step, std::int64_t started) {
  // open_[t] lists the occurrences kept, by start; the first still open that started when this
  // one did is this one (with one server, the front), and closed ones leave from the front
  auto& open = open_[t];
  auto it = std::lower_bound(open.begin(), open.end(), started,
                             [this](std::size_t i, std::int64_t s) { return occurrences_[i].start < s; });
  for (; it != open.end() && occurrences_[*it].start == started; ++it) {
    if (occurrences_[*it].end >= 0) continue;
    occurrences_[*it].end = step;
    break;
  }
  while (!open.empty() && occurrences_[open.front()].end >= 0) open.pop_front();
}

void Timeline::change(PlaceSlotId ps, std::int64_t delta, std::int64_t step) {
  const PlaceId p = net_.placeSlots()[ps].place;
  tokens_[p] += delta;
  auto& changes = places_[p];
  if (changes.back().step == step) {  // merged into this step's record
    changes.back().tokens = tokens_[p];
    return;
  }
  if (!keep(step)) return;
  changes.push_back({step, tokens_[p]});
}

void Timeline::onRemove(PlaceSlotId ps, std::int64_t count, std::span<const NodeRef>, std::int64_t step) {
  change(ps, -count, step);
}

void Timeline::onDeposit(PlaceSlotId ps, std::int64_t count, std::span<const NodeRef>, std::int64_t step) {
  change(ps, count, step);
}

}  // namespace gdpn::net
