// The I/O list's model side: every part's I/O with the scripts and addresses that use it, its
// state in the run, forces asked through the run's parts, and the mapping for a PLC.

#include "gdpn/ide/io_list.h"

#include <algorithm>

#include "gdpn/ide/document.h"
#include "gdpn/ide/run_control.h"
#include "gdpn/model/part_library.h"
#include "gdpn/model/part_run.h"
#include "gdpn/net/script_kind.h"
#include "gdpn/net/slot.h"

namespace gdpn::ide {

namespace {

/// How deep instances inside page types are followed (a model being edited may hold a type
/// that instantiates itself: compile() refuses it, the list must not loop).
constexpr int kMostDepth = 16;

bool identifierChar(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

/// True when `text` holds `word` not followed by an identifier's character (`.seen`, not `.seen2`).
bool mentions(const std::string& text, const std::string& word) {
  for (auto at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
    const auto end = at + word.size();
    if (end == text.size() || !identifierChar(text[end])) return true;
  }
  return false;
}

/// True when `text` holds `word` whole: neither preceded nor followed by an identifier's
/// character or a dot (`lamp.seen`, not `a.lamp.seen` or `flamp.seen`).
bool mentionsWhole(const std::string& text, const std::string& word) {
  for (auto at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
    const auto end = at + word.size();
    const bool before = at == 0 || (!identifierChar(text[at - 1]) && text[at - 1] != '.');
    if (before && (end == text.size() || !identifierChar(text[end]))) return true;
  }
  return false;
}

/// True when `code` reaches I/O `io` through `call` (`part("lamp1")`): `call.io` directly, or
/// through a name it was assigned to (`p = sim.part("lamp1")` ... `p.io`).
bool reaches(const std::string& code, const std::string& call, const std::string& io) {
  if (mentions(code, call + "." + io)) return true;
  for (auto at = code.find(call); at != std::string::npos; at = code.find(call, at + 1)) {
    // back over `sim.`, blanks and one `=` (not `==`) to the name assigned
    auto i = at;
    while (i > 0 && (identifierChar(code[i - 1]) || code[i - 1] == '.')) --i;
    while (i > 0 && (code[i - 1] == ' ' || code[i - 1] == '\t')) --i;
    const bool assigned = i > 0 && code[i - 1] == '=' &&
                          (i == 1 || (code[i - 2] != '=' && code[i - 2] != '!' && code[i - 2] != '<' && code[i - 2] != '>'));
    if (!assigned) continue;
    --i;
    while (i > 0 && (code[i - 1] == ' ' || code[i - 1] == '\t')) --i;
    const auto end = i;
    while (i > 0 && identifierChar(code[i - 1])) --i;
    if (i == end) continue;
    if (mentionsWhole(code, code.substr(i, end - i) + "." + io)) return true;
  }
  return false;
}

/// One inline script of a construct as the run names it.
struct ScriptText {
  std::string where;      // `main/c/light guard`
  const std::string* code;
  std::string self_part;  // what `self.part` is there (qualified; "" none)
};

/// Walks the pages and the instances inside them, gathering the parts' rows and the scripts.
class Walker {
 public:
  explicit Walker(const model::Model& m) : m_(m) {}

  void walk(const net::PageSpec& page, const std::string& prefix, bool top, const std::string& self_part, int depth) {
    scripts(page, prefix, self_part);
    if (depth >= kMostDepth) return;
    for (const auto& inst : page.instances) {
      const std::string q = prefix + "/" + inst.name;
      const auto spec = m_.parts.find(inst.type);
      const bool is_part = spec != m_.parts.end() && spec->second.controls.empty();
      std::string inner = self_part;
      if (is_part) {
        inner = q;
        for (const auto& io : spec->second.io) {
          IoListRow row;
          row.part = q;
          row.page = top ? prefix : std::string();
          row.instance = inst.name;
          row.type = inst.type;
          row.io = io;
          rows.push_back(std::move(row));
        }
      } else if (!inst.part.empty()) {
        inner = prefix + "/" + inst.part;  // a control pattern's: the part it names on this page
      }
      for (const auto& type : m_.net.page_types) {
        if (type.name == inst.type) walk(type, q, false, inner, depth + 1);
      }
    }
  }

  std::vector<IoListRow> rows;
  std::vector<ScriptText> texts;

 private:
  void add(std::string where, const net::ScriptSpec& s, const std::string& self_part) {
    if (!s.code.empty()) texts.push_back({std::move(where), &s.code, self_part});
  }

  void scripts(const net::PageSpec& page, const std::string& prefix, const std::string& self_part) {
    const auto slot = [](net::SlotId id) { return id == net::kDefaultSlot ? std::string(" ") : " " + net::slotName(id) + " "; };
    for (const auto& t : page.transitions) {
      for (const auto kind : net::kTransitionScripts) {
        add(prefix + "/" + t.name + " " + std::string(net::info(kind).key), net::scriptOf(t, kind), self_part);
      }
    }
    for (const auto& p : page.places) {
      for (const auto& s : p.scripts) {
        for (const auto kind : net::kSlotScripts) {
          add(prefix + "/" + p.name + slot(s.slot) + std::string(net::info(kind).key), net::scriptOf(s, kind), self_part);
        }
      }
    }
    for (const auto& a : page.arcs) {
      const std::string arc = prefix + "/" + a.from + " -> " + a.to;
      for (const auto& p : a.predicates) add(arc + slot(p.slot) + "predicate", p.expression, self_part);
      for (const auto& c : a.conditions) add(arc + slot(c.slot) + "condition", c.expression, self_part);
    }
  }

  const model::Model& m_;
};

/// The run's parts while a run is going or paused; null otherwise.
model::PartRun* runParts(const RunControl& run) {
  if (run.mode() == RunMode::Edit || run.session() == nullptr) return nullptr;
  return run.session()->simulation().parts();
}

}  // namespace

std::vector<IoListRow> ioListRows(const model::Model& model) {
  Walker w(model);
  for (const auto& page : model.net.pages) w.walk(page, page.name, true, {}, 0);
  if (!model.net.globals.code.empty()) w.texts.push_back({"globals", &model.net.globals.code, {}});
  for (auto& row : w.rows) {
    // what a script writes to reach it: self.part in its own constructs, part("...") anywhere
    for (const auto& t : w.texts) {
      bool used = t.self_part == row.part && reaches(*t.code, "self.part", row.io.name);
      for (const auto* name : {&row.part, &row.instance}) {
        for (const char quote : {'"', '\''}) {
          used = used || reaches(*t.code, std::string("part(") + quote + *name + quote + ")", row.io.name);
        }
      }
      if (used) row.uses.push_back(t.where);
    }
    for (const auto& e : model.io.entries) {
      const bool names = e.target == row.part || e.target == row.instance;
      if (e.source == model::IoEntry::Source::Part && e.io == row.io.name && names) {
        row.addresses.push_back(model::ioAddressName(e.table, e.address));
        row.names.push_back(model::ioEntryName(e));
      }
    }
  }
  return std::move(w.rows);
}

std::map<std::string, IoLive> ioLiveValues(const RunControl& run) {
  std::map<std::string, IoLive> out;
  const auto* parts = runParts(run);
  if (parts == nullptr) return out;
  for (const auto& r : parts->rows()) {
    out[parts->instances()[r.part].placed.name + "." + r.io->name] = {r.value, r.forced, r.pending, r.asked};
  }
  return out;
}

std::string forceIo(RunControl& run, const std::string& part, const std::string& io, double value) {
  auto* parts = runParts(run);
  if (parts == nullptr) return "forcing needs a run: Run or Step first";
  std::string why;
  const auto index = parts->find(part, why);
  if (!index || !parts->force(*index, io, value, why)) return why;
  return {};
}

std::string releaseIo(RunControl& run, const std::string& part, const std::string& io) {
  auto* parts = runParts(run);
  if (parts == nullptr) return "nothing is forced outside a run";
  std::string why;
  const auto index = parts->find(part, why);
  if (!index) return why;
  if (!parts->release(*index, io)) return part + "." + io + " is not forced";
  return {};
}

std::string releaseAllIo(RunControl& run) {
  auto* parts = runParts(run);
  if (parts == nullptr) return "nothing is forced outside a run";
  parts->releaseAll();
  return {};
}

std::string MapPartIoCommand::apply(Document& doc) {
  // mapPartIo reads the instance's page and part type and the io section: a model of just those
  model::Model scratch;
  const auto& m = doc.model();
  for (const auto& page : m.net.pages) {
    if (page.name != page_) continue;
    net::PageSpec p;
    p.name = page.name;
    for (const auto& inst : page.instances) {
      if (inst.name == instance_) p.instances.push_back(inst);
    }
    for (const auto& inst : p.instances) {
      if (const auto spec = m.parts.find(inst.type); spec != m.parts.end()) scratch.parts.insert(*spec);
    }
    scratch.net.pages.push_back(std::move(p));
  }
  scratch.io = m.io;
  std::string why;
  added_ = model::mapPartIo(scratch, page_, instance_, why);
  if (added_.empty()) return why.empty() ? "every I/O of " + instance_ + " is mapped already" : why;
  before_ = m.io;
  doc.editableIo() = std::move(scratch.io);
  return {};
}

void MapPartIoCommand::revert(Document& doc) { doc.editableIo() = before_; }

}  // namespace gdpn::ide
