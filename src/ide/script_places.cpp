// The model's scripts placed on the lines of the text that Save writes.

#include "gdpn/ide/script_places.h"

#include <algorithm>
#include <vector>

#include "gdpn/core/diagnostics.h"
#include "gdpn/model/model.h"
#include "gdpn/script/syntax.h"

namespace gdpn::ide {
namespace {

/// Every script of `net` with where it is, in forEachScript's order; `Spec` is ScriptSpec or
/// const ScriptSpec.
template <typename Net, typename Visit>
void walk(Net& net, const Visit& visit) {
  if (!net.globals.empty()) visit(ScriptAt{}, net.globals);
  for (auto* pages : {&net.pages, &net.page_types}) {
    for (auto& page : *pages) {
      for (auto& place : page.places) {
        for (auto& s : place.scripts) {
          for (const auto k : net::kSlotScripts) {
            auto& script = net::scriptOf(s, k);
            if (!script.empty()) visit(ScriptAt{page.name, place.name, k, s.slot, -1}, script);
          }
        }
      }
      for (auto& t : page.transitions) {
        for (const auto k : net::kTransitionScripts) {
          auto& script = net::scriptOf(t, k);
          if (!script.empty()) visit(ScriptAt{page.name, t.name, k, net::kDefaultSlot, -1}, script);
        }
      }
      int index = 0;
      for (auto& a : page.arcs) {
        // an arc's scripts belong to its transition: the end that is no place on the page
        const bool from_place = std::any_of(page.places.begin(), page.places.end(), [&](const auto& p) { return p.name == a.from; });
        const std::string& transition = from_place ? a.to : a.from;
        for (auto& p : a.predicates) {
          if (!p.expression.empty()) visit(ScriptAt{page.name, transition, net::ScriptKind::Predicate, p.slot, index}, p.expression);
        }
        for (auto& c : a.conditions) {
          if (!c.expression.empty()) visit(ScriptAt{page.name, transition, net::ScriptKind::Condition, c.slot, index}, c.expression);
        }
        ++index;
      }
    }
  }
}

}  // namespace

void forEachScript(const net::NetSpec& net, const std::function<void(const ScriptAt&, const net::ScriptSpec&)>& visit) {
  walk(net, visit);
}

const net::ScriptSpec* scriptAt(const net::NetSpec& net, const ScriptAt& at) {
  const net::ScriptSpec* found = nullptr;
  walk(net, [&](const ScriptAt& here, const net::ScriptSpec& s) {
    if (found == nullptr && here == at) found = &s;
  });
  return found;
}

void placeScripts(model::Model& model, const std::string& text) {
  // a traceback quotes the lines the run's scripts were compiled at, not the file on disk
  script::quoteSourceAs(model.path, text);
  core::Diagnostics diags;
  const auto written = model::parseModel(text, model.path, diags);
  // the same net, read back: its scripts stand where the text puts them
  if (!written || !(written->net == model.net)) return;
  std::vector<const net::ScriptSpec*> placed;
  walk(written->net, [&](const ScriptAt&, const net::ScriptSpec& s) { placed.push_back(&s); });
  std::size_t i = 0;
  walk(model.net, [&](const ScriptAt&, net::ScriptSpec& s) {
    if (i >= placed.size()) return;
    const auto& from = *placed[i++];
    s.loc = from.loc;
    s.lines = from.lines;
    s.indent = from.indent;
  });
}

int scriptLineOf(const net::ScriptSpec& script, int file_line) {
  if (file_line <= 0 || !script.file.empty()) return 0;
  const int count = 1 + static_cast<int>(std::count(script.code.begin(), script.code.end(), '\n')) -
                    (!script.code.empty() && script.code.back() == '\n' ? 1 : 0);
  if (!script.lines.empty()) {
    // a folded block or a quoted string: the first of its lines on that file line
    const auto it = std::find(script.lines.begin(), script.lines.end(), file_line);
    return it == script.lines.end() ? 0 : static_cast<int>(it - script.lines.begin()) + 1;
  }
  const int line = file_line - script.loc.line + 1;
  return script.loc.line > 0 && line >= 1 && line <= count ? line : 0;
}

}  // namespace gdpn::ide
