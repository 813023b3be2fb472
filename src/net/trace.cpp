#include "gdpn/net/trace.h"

#include "gdpn/core/text.h"

namespace gdpn::net {

TraceWriter::TraceWriter(std::ostream& out, const Net& net, double dt, NodeNamer namer)
    : out_(out), net_(net), dt_(dt), namer_(std::move(namer)) {}

void TraceWriter::head(std::int64_t step, const char* event) {
  out_ << "{\"step\":" << step << ",\"t\":" << core::formatTime(static_cast<double>(step) * dt_)
       << ",\"ev\":\"" << event << '"';
}

void TraceWriter::event(std::int64_t step, const char* event, const std::string& fields) {
  head(step, event);
  if (!fields.empty()) out_ << ',' << fields;
  out_ << "}\n";
}

void TraceWriter::endWithTransition(TransitionId t) {
  name_.clear();
  net_.appendTransitionName(name_, t);
  out_ << ",\"transition\":" << core::jsonQuote(name_) << "}\n";
}

void TraceWriter::onStart(TransitionId t, std::int64_t step) {
  head(step, "start");
  // a transition with variables: its line ends with its binding (onBinding, next)
  const Colouring* c = net_.colouring();
  if (c && c->of(t) && !c->of(t)->variables.empty()) return;
  endWithTransition(t);
}

void TraceWriter::onBinding(TransitionId t, const Binding& b, std::int64_t) {
  name_.clear();
  net_.appendTransitionName(name_, t);
  out_ << ",\"transition\":" << core::jsonQuote(name_) << ",\"binding\":{";
  const Colouring& c = *net_.colouring();
  const TransitionInscriptions& ti = *c.of(t);
  for (std::size_t k = 0; k < b.size() && k < ti.variables.size(); ++k) {
    out_ << (k ? "," : "") << core::jsonQuote(ti.variables[k]) << ':' << core::jsonQuote(c.colours.text(ti.sets[k], b[k]));
  }
  out_ << "}}\n";
}

void TraceWriter::onValues(PlaceSlotId ps, const Multiset& values, bool, std::int64_t) {
  const Colouring& c = *net_.colouring();
  out_ << ",\"values\":" << core::jsonQuote(c.colours.text(static_cast<ColourId>(c.slot_set[ps]), values)) << "}\n";
}

void TraceWriter::onComplete(TransitionId t, std::int64_t step, std::int64_t) {
  head(step, "complete");
  endWithTransition(t);
}

void TraceWriter::tokens(PlaceSlotId ps, std::int64_t count, std::span<const NodeRef> nodes) {
  const auto& slot = net_.placeSlots()[ps];
  name_.clear();
  net_.appendPlaceName(name_, slot.place);
  out_ << ",\"place\":" << core::jsonQuote(name_) << ",\"slot\":\""
       << slotName(slot.slot) << "\",\"count\":" << count;
  if (slot.kind == SlotKind::Node) {
    out_ << ",\"tokens\":[";
    for (std::size_t i = 0; i < nodes.size(); ++i) out_ << (i ? "," : "") << core::jsonQuote(namer_(nodes[i]));
    out_ << ']';
  }
  // a value slot's line ends with its values (onValues, next)
  if (slot.kind == SlotKind::Value) return;
  out_ << "}\n";
}

void TraceWriter::onRemove(PlaceSlotId ps, std::int64_t count, std::span<const NodeRef> nodes, std::int64_t step) {
  head(step, "remove");
  tokens(ps, count, nodes);
}

void TraceWriter::onDeposit(PlaceSlotId ps, std::int64_t count, std::span<const NodeRef> nodes, std::int64_t step) {
  head(step, "deposit");
  tokens(ps, count, nodes);
}

void TraceWriter::onAmount(PlaceId p, double moved, bool deposited, double now, std::int64_t step) {
  head(step, deposited ? "deposit" : "remove");
  name_.clear();
  net_.appendPlaceName(name_, p);
  out_ << ",\"place\":" << core::jsonQuote(name_) << ",\"amount\":" << core::formatDouble(moved)
       << ",\"now\":" << core::formatDouble(now) << "}\n";
}

void TraceWriter::onCross(PlaceId p, double level, double time, bool rising, std::int64_t step) {
  // the exact time of the crossing, not the step's end: written in full
  name_.clear();
  net_.appendPlaceName(name_, p);
  out_ << "{\"step\":" << step << ",\"t\":" << core::formatDouble(time) << ",\"ev\":\"cross\",\"place\":"
       << core::jsonQuote(name_) << ",\"level\":" << core::formatDouble(level) << ",\"rising\":" << (rising ? "true" : "false")
       << "}\n";
}

}  // namespace gdpn::net
