// The discrete part of a hybrid net: what the analysis reads of it.

#include <algorithm>
#include <set>
#include <string>

#include "gdpn/net/fluid.h"

namespace gdpn::net {

bool hybrid(const NetSpec& spec) {
  for (const auto* pages : {&spec.pages, &spec.page_types}) {
    for (const auto& page : *pages) {
      if (std::any_of(page.places.begin(), page.places.end(), [](const PlaceSpec& p) { return p.continuous(); }) ||
          std::any_of(page.transitions.begin(), page.transitions.end(),
                      [](const TransitionSpec& t) { return t.continuous(); })) {
        return true;
      }
    }
  }
  return false;
}

NetSpec discretePart(const NetSpec& spec, DiscretePart* counts) {
  NetSpec out = spec;
  DiscretePart n;
  // the page types' ports that publish a continuous place: links to them go too
  std::set<std::pair<std::string, std::string>> gone_ports;  // (page type, place)
  for (const auto& type : spec.page_types) {
    for (const auto& p : type.places) {
      if (p.continuous()) gone_ports.emplace(type.name, p.name);
    }
  }
  auto strip = [&](PageSpec& page) {
    std::set<std::string> gone;
    for (const auto& p : page.places) {
      if (p.continuous()) gone.insert(p.name), ++n.places;
    }
    for (const auto& t : page.transitions) {
      if (t.continuous()) gone.insert(t.name), ++n.transitions;
    }
    for (const auto& inst : page.instances) {
      for (const auto& [type, place] : gone_ports) {
        if (type == inst.type) gone.insert(inst.name + "/" + place);
      }
    }
    std::erase_if(page.places, [](const PlaceSpec& p) { return p.continuous(); });
    std::erase_if(page.transitions, [](const TransitionSpec& t) { return t.continuous(); });
    std::erase_if(page.references, [&](const ReferenceSpec& r) { return gone.count(r.place) != 0; });
    const auto before = page.arcs.size();
    std::erase_if(page.arcs, [&](const ArcSpec& a) { return gone.count(a.from) != 0 || gone.count(a.to) != 0; });
    n.arcs += before - page.arcs.size();
  };
  for (auto& page : out.pages) strip(page);
  for (auto& type : out.page_types) strip(type);
  if (counts) *counts = n;
  return out;
}

}  // namespace gdpn::net
