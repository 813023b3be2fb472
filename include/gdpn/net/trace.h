#pragma once
/// \file
/// The trace (semantics §10): one JSON object per line for every kernel event, written as
/// it happens. Keys come in a fixed order and numbers in their shortest exact form, so the
/// same run gives the same bytes.

#include <functional>
#include <ostream>
#include <string>

#include "gdpn/net/observer.h"

namespace gdpn::net {

/// Names a node token in the trace (the kernel only knows opaque NodeRefs).
using NodeNamer = std::function<std::string(NodeRef)>;

/// Writes kernel events to a stream as JSON Lines.
class TraceWriter : public NetObserver {
 public:
  /// Writes to `out`; times are step * `dt` seconds; `namer` names node tokens.
  TraceWriter(std::ostream& out, const Net& net, double dt, NodeNamer namer);
  void onStart(TransitionId t, std::int64_t step) override;
  void onComplete(TransitionId t, std::int64_t step, std::int64_t started) override;
  void onRemove(PlaceSlotId ps, std::int64_t count, std::span<const NodeRef> nodes, std::int64_t step) override;
  void onDeposit(PlaceSlotId ps, std::int64_t count, std::span<const NodeRef> nodes, std::int64_t step) override;
  void onBinding(TransitionId t, const Binding& b, std::int64_t step) override;
  void onValues(PlaceSlotId ps, const Multiset& values, bool deposited, std::int64_t step) override;
  void onAmount(PlaceId p, double moved, bool deposited, double now, std::int64_t step) override;
  void onCross(PlaceId p, double level, double time, bool rising, std::int64_t step) override;
  /// Writes a free event line: {"step":..,"t":..,"ev":`event`,`fields`} where `fields` is
  /// already JSON text of the form "\"key\":value,..." (or empty).
  void event(std::int64_t step, const char* event, const std::string& fields);

 private:
  void head(std::int64_t step, const char* event);
  void tokens(PlaceSlotId ps, std::int64_t count, std::span<const NodeRef> nodes);
  std::ostream& out_;
  const Net& net_;
  double dt_;
  NodeNamer namer_;
  /// Writes `,"transition":NAME}` and the line's end: the rest of a start or completion.
  void endWithTransition(TransitionId t);
  std::string name_;  // the name being written (kept, so that writing it allocates nothing)
};

}  // namespace gdpn::net
