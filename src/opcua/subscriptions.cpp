// Subscriptions and monitored items: items sampled at the run's step boundaries (each at its
// sampling interval of model time, through its filter), subscriptions publishing on the wall
// clock into the Publish requests their session keeps waiting; keep-alives, lifetimes,
// retransmission for Republish.

#include <algorithm>
#include <cmath>

#include "endpoint_state.h"

namespace gdpn::opcua::detail {

namespace {

constexpr double kMinInterval = 10;        // ms, the fastest publishing interval
constexpr double kMaxInterval = 3600000;   // ms

double revisedInterval(double requested) {
  return std::isfinite(requested) && requested > kMinInterval ? std::min(requested, kMaxInterval) : kMinInterval;
}

struct ItemRequest {
  std::uint32_t client_handle = 0;
  double sampling = 0;
  ExtensionObject filter;
  std::uint32_t queue_size = 0;
  bool discard_oldest = true;
};

/// The parameters a client asked for, revised into `item`: the sampling interval (ms of model
/// time; -1 or none: the subscription's interval; at most an hour), the queue size (1 to `most`).
void revise(MonitoredItem& item, const ItemRequest& p, const Subscription& sub, std::uint32_t timestamps, std::size_t most) {
  item.client_handle = p.client_handle;
  item.timestamps = timestamps;
  item.sampling = p.sampling < 0 || !std::isfinite(p.sampling) ? sub.interval : std::min(p.sampling, kMaxInterval);
  item.queue_size = std::clamp<std::size_t>(p.queue_size, 1, most);
  item.discard_oldest = p.discard_oldest;
}

ItemRequest readParameters(Decoder& d) {
  ItemRequest p;
  p.client_handle = d.u32();
  p.sampling = d.f64();
  p.filter = d.extensionObject();
  p.queue_size = d.u32();
  p.discard_oldest = d.boolean();
  return p;
}

}  // namespace

Subscription* EndpointState::subscription(Session& s, std::uint32_t id) {
  const auto it = subscriptions.find(id);
  return it == subscriptions.end() || it->second.session != s.number ? nullptr : &it->second;
}

void EndpointState::deleteSubscription(std::uint32_t id) {
  const auto it = subscriptions.find(id);
  if (it == subscriptions.end()) return;
  item_count -= it->second.items.size();
  subscriptions.erase(it);
}

void EndpointState::createSubscription(const Pending& to, Session& s, Decoder& d) {
  const double interval = d.f64();
  const std::uint32_t lifetime = d.u32();
  const std::uint32_t keepalive = d.u32();
  const std::uint32_t max_notifications = d.u32();
  const bool enabled = d.boolean();
  const std::uint8_t priority = d.u8();
  const auto held = std::count_if(subscriptions.begin(), subscriptions.end(),
                                  [&s](const auto& p) { return p.second.session == s.number; });
  if (static_cast<std::size_t>(held) >= limits.subscriptions_per_session) return fault(to, status::kBadTooManySubscriptions);
  Subscription sub;
  sub.id = next_subscription++;
  sub.session = s.number;
  sub.interval = revisedInterval(interval);
  sub.keepalive = std::clamp<std::uint32_t>(keepalive == 0 ? 10 : keepalive, 1, 1000);
  sub.lifetime = std::max<std::uint32_t>(lifetime, 3 * sub.keepalive);
  sub.max_notifications = max_notifications;
  sub.enabled = enabled;
  sub.priority = priority;
  sub.due = now + std::chrono::duration_cast<Endpoint::Clock::duration>(std::chrono::duration<double, std::milli>(sub.interval));
  std::string out = responseHeader(to.handle);
  Encoder e(out);
  e.u32(sub.id);
  e.f64(sub.interval);
  e.u32(sub.lifetime);
  e.u32(sub.keepalive);
  subscriptions[sub.id] = std::move(sub);
  respond(to, kCreateSubscription, out);
}

void EndpointState::modifySubscription(const Pending& to, Session& s, Decoder& d) {
  const std::uint32_t id = d.u32();
  const double interval = d.f64();
  const std::uint32_t lifetime = d.u32();
  const std::uint32_t keepalive = d.u32();
  const std::uint32_t max_notifications = d.u32();
  const std::uint8_t priority = d.u8();
  Subscription* sub = subscription(s, id);
  if (!sub) return fault(to, status::kBadSubscriptionIdInvalid);
  sub->interval = revisedInterval(interval);
  sub->keepalive = std::clamp<std::uint32_t>(keepalive == 0 ? 10 : keepalive, 1, 1000);
  sub->lifetime = std::max<std::uint32_t>(lifetime, 3 * sub->keepalive);
  sub->max_notifications = max_notifications;
  sub->priority = priority;
  std::string out = responseHeader(to.handle);
  Encoder e(out);
  e.f64(sub->interval);
  e.u32(sub->lifetime);
  e.u32(sub->keepalive);
  respond(to, kModifySubscription, out);
}

void EndpointState::setPublishingMode(const Pending& to, Session& s, Decoder& d) {
  const bool enabled = d.boolean();
  const auto ids = d.u32s();
  if (ids.empty()) return fault(to, status::kBadNothingToDo);
  std::vector<StatusCode> results;
  for (const auto id : ids) {
    Subscription* sub = subscription(s, id);
    if (sub) sub->enabled = enabled;
    results.push_back(sub ? 0 : status::kBadSubscriptionIdInvalid);
  }
  respondResults(to, kSetPublishingMode, results);
}

void EndpointState::deleteSubscriptions(const Pending& to, Session& s, Decoder& d) {
  const auto ids = d.u32s();
  if (ids.empty()) return fault(to, status::kBadNothingToDo);
  std::vector<StatusCode> results;
  for (const auto id : ids) {
    const bool mine = subscription(s, id) != nullptr;
    if (mine) deleteSubscription(id);
    results.push_back(mine ? 0 : status::kBadSubscriptionIdInvalid);
  }
  respondResults(to, kDeleteSubscriptions, results);
  // Publish requests with nothing left to wait for
  const bool any = std::any_of(subscriptions.begin(), subscriptions.end(), [&s](const auto& p) { return p.second.session == s.number; });
  if (!any) {
    for (auto& p : s.publish) fault(p.to, status::kBadNoSubscription, false);
    s.publish.clear();
  }
}

// the filter of a monitored item: a status, with the item's trigger and deadband set
static StatusCode applyFilter(const AddressSpace& space, MonitoredItem& item, const ExtensionObject& filter) {
  item.trigger = 1;
  item.deadband.reset();
  if (filter.type.isNull() && filter.encoding == 0) return 0;
  if (filter.type == NodeId::num(kEventFilter) || filter.type == NodeId::num(kAggregateFilter)) {
    return status::kBadMonitoredItemFilterUnsupported;
  }
  if (filter.type != NodeId::num(kDataChangeFilter) || filter.encoding != 1) return status::kBadMonitoredItemFilterInvalid;
  if (item.attribute != 13) return status::kBadFilterNotAllowed;
  Decoder d(filter.body);
  const std::uint32_t trigger = d.u32();
  const std::uint32_t type = d.u32();
  const double value = d.f64();
  if (trigger > 2) return status::kBadMonitoredItemFilterInvalid;
  item.trigger = trigger;
  if (type == 0) return 0;
  const Node* node = space.find(item.node);
  if (type == 2) return status::kBadDeadbandFilterInvalid;  // percent: gdpn's variables have no EURange
  if (type != 1 || !(value >= 0)) return status::kBadDeadbandFilterInvalid;
  if (!node || !node->numeric) return status::kBadFilterNotAllowed;
  item.deadband = value;
  return 0;
}

void EndpointState::createItems(const Pending& to, Session& s, Decoder& d) {
  const std::uint32_t id = d.u32();
  const std::uint32_t timestamps = d.u32();
  const std::size_t n = d.length(8);
  Subscription* sub = subscription(s, id);
  if (!sub) return fault(to, status::kBadSubscriptionIdInvalid);
  if (timestamps > 3) return fault(to, status::kBadTimestampsToReturnInvalid);
  if (n == 0) return fault(to, status::kBadNothingToDo);
  if (n > limits.nodes_per_request) return fault(to, status::kBadTooManyOperations);
  std::string out = responseHeader(to.handle);
  Encoder e(out);
  e.length(n);
  for (std::size_t i = 0; i < n; ++i) {
    MonitoredItem item;
    item.node = d.nodeId();
    item.attribute = d.u32();
    const std::string range = d.string(256);
    const QualifiedName encoding = d.qualifiedName();
    item.mode = d.u32();
    const ItemRequest p = readParameters(d);
    const Node* node = space.find(item.node);
    StatusCode r = 0;
    if (!node) r = status::kBadNodeIdUnknown;
    else if (item.attribute < 1 || item.attribute > 27 || readAttribute(space, *node, item.attribute).status == status::kBadAttributeIdInvalid)
      r = status::kBadAttributeIdInvalid;
    else if (!range.empty()) r = status::kBadIndexRangeInvalid;
    else if (!defaultEncoding(encoding)) r = status::kBadDataEncodingInvalid;
    else if (item.mode > 2) r = status::kBadMonitoringModeInvalid;
    else if (sub->items.size() >= limits.items_per_subscription || item_count >= limits.items) r = status::kBadTooManyMonitoredItems;
    else r = applyFilter(space, item, p.filter);
    if (r != 0) {
      e.u32(r);
      e.u32(0);
      e.f64(0);
      e.u32(0);
      e.extensionObject({});
      continue;
    }
    item.id = next_item++;
    revise(item, p, *sub, timestamps, limits.queue_size);
    e.u32(0);
    e.u32(item.id);
    e.f64(item.sampling);
    e.u32(static_cast<std::uint32_t>(item.queue_size));
    e.extensionObject({});
    MonitoredItem& kept = sub->items[item.id] = std::move(item);
    ++item_count;
    if (kept.mode != 0) sampleItem(kept);  // the first value goes at once
  }
  e.length(0);
  respond(to, kCreateMonitoredItems, out);
}

void EndpointState::modifyItems(const Pending& to, Session& s, Decoder& d) {
  const std::uint32_t id = d.u32();
  const std::uint32_t timestamps = d.u32();
  const std::size_t n = d.length(8);
  Subscription* sub = subscription(s, id);
  if (!sub) return fault(to, status::kBadSubscriptionIdInvalid);
  if (timestamps > 3) return fault(to, status::kBadTimestampsToReturnInvalid);
  if (n == 0) return fault(to, status::kBadNothingToDo);
  if (n > limits.nodes_per_request) return fault(to, status::kBadTooManyOperations);
  std::string out = responseHeader(to.handle);
  Encoder e(out);
  e.length(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t item_id = d.u32();
    const ItemRequest p = readParameters(d);
    const auto it = sub->items.find(item_id);
    StatusCode r = it == sub->items.end() ? status::kBadMonitoredItemIdInvalid : 0;
    if (r == 0) {
      MonitoredItem trial = it->second;
      r = applyFilter(space, trial, p.filter);
      if (r == 0) {
        revise(trial, p, *sub, timestamps, limits.queue_size);
        while (trial.queue.size() > trial.queue_size) trial.queue.pop_front();
        it->second = std::move(trial);
      }
    }
    e.u32(r);
    e.f64(r == 0 ? it->second.sampling : 0);
    e.u32(r == 0 ? static_cast<std::uint32_t>(it->second.queue_size) : 0);
    e.extensionObject({});
  }
  e.length(0);
  respond(to, kModifyMonitoredItems, out);
}

void EndpointState::setMonitoringMode(const Pending& to, Session& s, Decoder& d) {
  const std::uint32_t id = d.u32();
  const std::uint32_t mode = d.u32();
  const auto ids = d.u32s();
  Subscription* sub = subscription(s, id);
  if (!sub) return fault(to, status::kBadSubscriptionIdInvalid);
  if (mode > 2) return fault(to, status::kBadMonitoringModeInvalid);
  if (ids.empty()) return fault(to, status::kBadNothingToDo);
  std::vector<StatusCode> results;
  for (const auto item_id : ids) {
    const auto it = sub->items.find(item_id);
    if (it == sub->items.end()) {
      results.push_back(status::kBadMonitoredItemIdInvalid);
      continue;
    }
    const bool was_off = it->second.mode == 0;
    it->second.mode = mode;
    if (mode == 0) it->second.queue.clear();
    if (was_off && mode != 0) {
      it->second.last.reset();
      sampleItem(it->second);
    }
    results.push_back(0);
  }
  respondResults(to, kSetMonitoringMode, results);
}

void EndpointState::deleteItems(const Pending& to, Session& s, Decoder& d) {
  const std::uint32_t id = d.u32();
  const auto ids = d.u32s();
  Subscription* sub = subscription(s, id);
  if (!sub) return fault(to, status::kBadSubscriptionIdInvalid);
  if (ids.empty()) return fault(to, status::kBadNothingToDo);
  std::vector<StatusCode> results;
  for (const auto item_id : ids) {
    const bool erased = sub->items.erase(item_id) != 0;
    item_count -= erased ? 1 : 0;
    results.push_back(erased ? 0 : status::kBadMonitoredItemIdInvalid);
  }
  respondResults(to, kDeleteMonitoredItems, results);
}

void EndpointState::sampleItem(MonitoredItem& item) {
  DataValue v = readValue(item.node, item.attribute, item.timestamps);
  if (item.last) {
    const DataValue& last = *item.last;
    bool changed = last.status.value_or(0) != v.status.value_or(0);
    if (!changed && item.trigger >= 1) {
      const auto a = last.value ? last.value->number() : std::nullopt;
      const auto b = v.value ? v.value->number() : std::nullopt;
      if (item.deadband && a && b) changed = std::abs(*a - *b) > *item.deadband;
      else changed = last.value != v.value;
    }
    if (!changed && item.trigger == 2) changed = last.source_time != v.source_time;
    if (!changed) return;
  }
  item.last = v;
  if (item.mode != 2) return;  // sampling without reporting: kept, not queued
  if (item.queue.size() >= item.queue_size) {
    if (item.discard_oldest) item.queue.pop_front();
    else item.queue.pop_back();
  }
  item.queue.push_back(std::move(v));
}

void EndpointState::sampleAll() {
  for (auto& [id, sub] : subscriptions) {
    for (auto& [item_id, item] : sub.items) {
      if (item.mode == 0 || model_time < item.next_sample) continue;
      sampleItem(item);
      item.next_sample = model_time + std::llround(item.sampling * 1e4);  // ms of model time
    }
  }
}

void EndpointState::publish(const Pending& to, Session& s, Decoder& d, std::uint32_t timeout_hint) {
  const std::size_t n = d.length(8);
  std::vector<StatusCode> acks;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t id = d.u32();
    const std::uint32_t sequence = d.u32();
    Subscription* sub = subscription(s, id);
    if (!sub) {
      acks.push_back(status::kBadSubscriptionIdInvalid);
      continue;
    }
    const auto it = std::find_if(sub->retransmit.begin(), sub->retransmit.end(), [&](const auto& m) { return m.first == sequence; });
    if (it == sub->retransmit.end()) {
      acks.push_back(status::kBadSequenceNumberUnknown);
    } else {
      sub->retransmit.erase(it);
      acks.push_back(0);
    }
  }
  const bool any = std::any_of(subscriptions.begin(), subscriptions.end(), [&s](const auto& p) { return p.second.session == s.number; });
  if (!any) return fault(to, status::kBadNoSubscription, false);
  if (s.publish.size() >= limits.publish_requests) {
    fault(s.publish.front().to, status::kBadTooManyPublishRequests);
    s.publish.pop_front();
  }
  const auto deadline = timeout_hint == 0 ? Endpoint::Clock::time_point::max()
                                          : now + std::chrono::milliseconds(timeout_hint);
  s.publish.push_back({to, deadline, std::move(acks)});
  // a Publish request received: every subscription of the session lives on
  for (auto& [id, sub] : subscriptions) {
    if (sub.session == s.number) sub.lifetime_count = 0;
  }
  // an expired subscription's last word first, then the late ones, the longest waiting first
  while (!s.publish.empty()) {
    Subscription* first = nullptr;
    for (auto& [id, sub] : subscriptions) {
      if (sub.session != s.number || !(sub.closing || sub.late)) continue;
      if (!first || (sub.closing && !first->closing) || (!first->closing && sub.last_sent < first->last_sent)) first = &sub;
    }
    if (!first) break;
    if (first->closing) {
      sendClosing(*first, s);  // erases it
      continue;
    }
    first->late = false;
    if (!sendNotifications(*first, s)) sendKeepAlive(*first, s);
  }
}

void EndpointState::republish(const Pending& to, Session& s, Decoder& d) {
  const std::uint32_t id = d.u32();
  const std::uint32_t sequence = d.u32();
  Subscription* sub = subscription(s, id);
  if (!sub) return fault(to, status::kBadSubscriptionIdInvalid);
  const auto it = std::find_if(sub->retransmit.begin(), sub->retransmit.end(), [&](const auto& m) { return m.first == sequence; });
  if (it == sub->retransmit.end()) return fault(to, status::kBadMessageNotAvailable);
  std::string out = responseHeader(to.handle);
  out += it->second;
  respond(to, kRepublish, out);
}

namespace {

void publishResponse(EndpointState& st, const PublishRequest& p, const Subscription& sub, bool more, const std::string& message) {
  std::string out = st.responseHeader(p.to.handle);
  Encoder e(out);
  e.u32(sub.id);
  e.length(sub.retransmit.size());
  for (const auto& [seq, m] : sub.retransmit) e.u32(seq);
  e.boolean(more);
  out += message;
  e.statuses(p.ack_results);
  e.length(0);
  st.respond(p.to, kPublish, out);
}

}  // namespace

bool EndpointState::sendNotifications(Subscription& sub, Session& s) {
  if (s.publish.empty() || !sub.enabled) return false;
  std::string items;
  Encoder ie(items);
  std::size_t count = 0;
  const std::size_t cap = sub.max_notifications == 0 ? SIZE_MAX : sub.max_notifications;
  bool more = false;
  const std::size_t room = messageRoom(s.publish.front().to);
  for (auto& [item_id, item] : sub.items) {
    while (!item.queue.empty() && count < cap && items.size() < room) {
      ie.u32(item.client_handle);
      ie.dataValue(item.queue.front());
      item.queue.pop_front();
      ++count;
    }
    more = more || !item.queue.empty();
  }
  if (count == 0) return false;
  ExtensionObject change{NodeId::num(kDataChangeNotification), 1, {}};
  Encoder ce(change.body);
  ce.length(count);
  change.body += items;
  ce.length(0);
  std::string message;
  Encoder me(message);
  const std::uint32_t sequence = sub.next_sequence++;
  me.u32(sequence);
  me.i64(dateTimeNow());
  me.length(1);
  me.extensionObject(change);
  sub.retransmit.emplace_back(sequence, message);
  while (sub.retransmit.size() > limits.retransmissions) sub.retransmit.pop_front();
  const PublishRequest p = std::move(s.publish.front());
  s.publish.pop_front();
  publishResponse(*this, p, sub, more, message);
  stats.notifications += count;
  sub.keepalive_count = 0;
  sub.lifetime_count = 0;
  sub.sent_once = true;
  sub.late = false;
  sub.last_sent = now;
  return true;
}

void EndpointState::sendKeepAlive(Subscription& sub, Session& s) {
  if (s.publish.empty()) return;
  std::string message;
  Encoder me(message);
  me.u32(sub.next_sequence);  // the next one, not used up
  me.i64(dateTimeNow());
  me.length(0);
  const PublishRequest p = std::move(s.publish.front());
  s.publish.pop_front();
  publishResponse(*this, p, sub, false, message);
  sub.keepalive_count = 0;
  sub.lifetime_count = 0;
  sub.sent_once = true;
  sub.late = false;
  sub.last_sent = now;
}

bool EndpointState::sendClosing(Subscription& sub, Session& s) {
  if (s.publish.empty() || !sub.closing) return false;
  ExtensionObject change{NodeId::num(kStatusChangeNotification), 1, {}};
  Encoder ce(change.body);
  ce.u32(*sub.closing);
  ce.u8(0);
  std::string message;
  Encoder me(message);
  me.u32(sub.next_sequence++);
  me.i64(dateTimeNow());
  me.length(1);
  me.extensionObject(change);
  const PublishRequest p = std::move(s.publish.front());
  s.publish.pop_front();
  publishResponse(*this, p, sub, false, message);
  deleteSubscription(sub.id);
  return true;
}

std::size_t EndpointState::messageRoom(const Pending& to) const {
  std::size_t most = limits.response_bytes;
  const auto it = connections.find(to.connection);
  if (it != connections.end() && it->second.max_send_message != 0) most = std::min<std::size_t>(most, it->second.max_send_message);
  return most > 1024 ? most - 1024 : 0;  // room for the headers around the notifications
}

void EndpointState::publishDue() {
  std::vector<std::uint32_t> gone;
  for (auto& [id, sub] : subscriptions) {
    if (sub.due > now) continue;
    const auto step = std::chrono::duration_cast<Endpoint::Clock::duration>(std::chrono::duration<double, std::milli>(sub.interval));
    sub.due += step;
    if (sub.due <= now) sub.due = now + step;  // fell behind: no burst to catch up
    const auto sit = sessions.find(sub.session);
    if (sit == sessions.end()) {
      gone.push_back(id);
      continue;
    }
    Session& s = sit->second;
    if (sub.closing) continue;  // waits for a Publish request to say it went
    if (sendNotifications(sub, s)) continue;
    const bool has_news = sub.enabled && std::any_of(sub.items.begin(), sub.items.end(), [](const auto& p) { return !p.second.queue.empty(); });
    const bool keepalive_due = !has_news && (!sub.sent_once || ++sub.keepalive_count >= sub.keepalive);
    if (keepalive_due && !s.publish.empty()) {
      sendKeepAlive(sub, s);
      continue;
    }
    if (!has_news && !keepalive_due) continue;
    // something to send and no Publish request to send it with
    sub.late = true;
    if (++sub.lifetime_count >= sub.lifetime) sub.closing = status::kBadTimeout;
  }
  for (const auto id : gone) deleteSubscription(id);
}

}  // namespace gdpn::opcua::detail
