#include "gdpn/ide/page_from_selection.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <set>
#include <sstream>

#include "gdpn/core/text.h"
#include "gdpn/ide/document.h"
#include "gdpn/ide/net_edit.h"

namespace gdpn::ide {

namespace {

using NameMap = std::vector<std::pair<std::string, std::string>>;

/// One string literal of Python code: where its text starts and ends (between the quotes).
struct Literal {
  std::size_t begin = 0;  // offset of the first character inside the quotes
  std::size_t end = 0;    // offset of the closing quote
  bool formatted = false; // an f-string: its `{...}` parts are computed at run time
};

bool identStart(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool identChar(char c) { return identStart(c) || (c >= '0' && c <= '9'); }

/// The string literals of `code`, in order (comments left out).
std::vector<Literal> literalsOf(const std::string& code) {
  std::vector<Literal> out;
  std::size_t i = 0;
  const std::size_t n = code.size();
  while (i < n) {
    const char c = code[i];
    if (c == '#') {
      while (i < n && code[i] != '\n') ++i;
      continue;
    }
    bool formatted = false;
    if (identStart(c)) {
      std::size_t j = i;
      while (j < n && identChar(code[j])) ++j;
      std::string word = code.substr(i, j - i);
      std::transform(word.begin(), word.end(), word.begin(), [](char ch) { return static_cast<char>(std::tolower(ch)); });
      const bool prefix = word == "r" || word == "b" || word == "u" || word == "f" || word == "rb" || word == "br" ||
                          word == "fr" || word == "rf";
      if (!(prefix && j < n && (code[j] == '\'' || code[j] == '"'))) {
        i = j;
        continue;
      }
      formatted = word.find('f') != std::string::npos;
      i = j;
    }
    if (code[i] != '\'' && code[i] != '"') {
      ++i;
      continue;
    }
    // a literal: single or triple quoted; a backslash always escapes the next character
    const char q = code[i];
    const bool triple = i + 2 < n && code[i + 1] == q && code[i + 2] == q;
    const std::size_t open = triple ? 3 : 1;
    Literal lit{i + open, n, formatted};
    std::size_t k = i + open;
    while (k < n) {
      if (code[k] == '\\') {
        k += 2;
        continue;
      }
      if (!triple && code[k] == '\n') break;
      if (code[k] == q && (!triple || (k + 2 < n && code[k + 1] == q && code[k + 2] == q))) break;
      ++k;
    }
    lit.end = std::min(k, n);
    out.push_back(lit);
    i = std::min(n, k + (k < n ? open : 0));
  }
  return out;
}

/// Where offset `at` of `script`'s code stands in the model file (or `file`, for a script file).
core::SourceLoc locOf(const net::ScriptSpec& script, const std::string& code, std::size_t at) {
  int line = 0;
  std::size_t line_start = 0;
  for (std::size_t k = 0; k < at && k < code.size(); ++k) {
    if (code[k] == '\n') {
      ++line;
      line_start = k + 1;
    }
  }
  const int column = static_cast<int>(at - line_start);
  core::SourceLoc loc = script.loc;
  if (loc.line == 0) return loc;
  if (!script.lines.empty() && static_cast<std::size_t>(line) < script.lines.size()) {
    loc.line = script.lines[static_cast<std::size_t>(line)];
    loc.column = (line == 0 ? script.loc.column : script.indent + 1) + column;
  } else {
    loc.line = script.loc.line + line;
    loc.column = (line == 0 ? script.loc.column : script.indent + 1) + column;
  }
  return loc;
}

/// What a literal's text does with the moved names: the new name it becomes, or why it cannot
/// be followed ("" and "" when it names none of them).
struct Match {
  std::string becomes;
  std::string why;
};

Match matchLiteral(const std::string& text, bool formatted, const NameMap& names, const std::vector<std::string>& prefixes) {
  const std::size_t brace = formatted ? text.find('{') : std::string::npos;
  if (brace == std::string::npos) {
    for (const auto& [from, to] : names) {
      if (text == from) return {to, {}};
    }
  }
  const std::string head = text.substr(0, brace);
  const std::string tail = brace == std::string::npos ? text : text.substr(text.rfind('}') + 1);
  for (const auto& [from, to] : names) {
    // the start of a moved name, finished at run time ("line/" + name, f"line/{name}")
    const bool started = std::any_of(prefixes.begin(), prefixes.end(), [&](const std::string& p) {
      return head.size() > p.size() && head.starts_with(p + "/");
    });
    if (started && from.starts_with(head) && head != from) {
      return {{}, "'" + head + "' begins the name '" + from + "', which moves to '" + to +
                      "', but the rest of it is made at run time, so it cannot be followed"};
    }
    // its end, joined to a page made at run time (page + "/x")
    if (tail.size() > 1 && tail.front() == '/' && from.ends_with(tail) && tail != from) {
      return {{}, "'" + tail + "' ends the name '" + from + "', which moves to '" + to +
                      "', but the rest of it is made at run time, so it cannot be followed"};
    }
  }
  return {};
}

/// Follows the moved names in `script`'s inline code (rewriting the literals that name them) or
/// reports the ones that cannot be followed; a script file is only checked (it is not the
/// model's to rewrite).
void followInScript(net::ScriptSpec& script, const NameMap& names, const std::vector<std::string>& prefixes,
                    const std::string& model_dir, std::set<std::string>& files_seen, core::Diagnostics& diags) {
  if (!script.file.empty()) {
    const std::string path = (std::filesystem::path(model_dir) / script.file).lexically_normal().string();
    if (!files_seen.insert(path).second) return;
    std::ifstream in(path, std::ios::binary);
    if (!in) return;  // the loader reports a missing file
    std::ostringstream text;
    text << in.rdbuf();
    const std::string code = text.str();
    net::ScriptSpec at;
    at.loc = {path, 1, 1};
    for (const Literal& lit : literalsOf(code)) {
      const Match m = matchLiteral(code.substr(lit.begin, lit.end - lit.begin), lit.formatted, names, prefixes);
      if (!m.becomes.empty()) {
        diags.error(locOf(at, code, lit.begin), "the script file names '" + code.substr(lit.begin, lit.end - lit.begin) +
                                                    "', which moves to '" + m.becomes +
                                                    "'; the IDE does not rewrite script files: change it there");
      } else if (!m.why.empty()) {
        diags.error(locOf(at, code, lit.begin), m.why);
      }
    }
    return;
  }
  if (script.code.empty()) return;
  std::string code = script.code;
  const auto literals = literalsOf(code);
  for (auto it = literals.rbegin(); it != literals.rend(); ++it) {
    const Match m = matchLiteral(code.substr(it->begin, it->end - it->begin), it->formatted, names, prefixes);
    if (!m.why.empty()) diags.error(locOf(script, script.code, it->begin), m.why);
    if (!m.becomes.empty()) code.replace(it->begin, it->end - it->begin, m.becomes);
  }
  script.code = std::move(code);
}

/// Calls `visit` for every script of `net`.
void forEveryScript(net::NetSpec& net, const std::function<void(net::ScriptSpec&)>& visit) {
  visit(net.globals);
  for (auto* pages : {&net.pages, &net.page_types}) {
    for (auto& page : *pages) {
      for (auto& p : page.places) {
        for (auto& s : p.scripts) {
          for (const net::ScriptKind k : net::kSlotScripts) visit(net::scriptOf(s, k));
        }
      }
      for (auto& t : page.transitions) {
        for (const net::ScriptKind k : net::kTransitionScripts) visit(net::scriptOf(t, k));
      }
      for (auto& a : page.arcs) {
        for (auto& p : a.predicates) visit(p.expression);
        for (auto& c : a.conditions) visit(c.expression);
      }
    }
  }
}

/// The qualified names `page` has in the compiled net: itself for a top-level page, each
/// instance's path for a page type.
std::vector<std::string> prefixesOf(const net::NetSpec& net, const std::string& page, bool is_type) {
  if (!is_type) return {page};
  std::vector<std::string> out;
  std::function<void(const net::PageSpec&, const std::string&, int)> walk = [&](const net::PageSpec& p,
                                                                                const std::string& at, int depth) {
    if (depth > 32) return;  // a type that holds itself: compile() reports it
    for (const auto& inst : p.instances) {
      const std::string path = at + "/" + inst.name;
      if (inst.type == page) out.push_back(path);
      for (const auto& t : net.page_types) {
        if (t.name == inst.type) walk(t, path, depth + 1);
      }
    }
  };
  for (const auto& p : net.pages) walk(p, p.name, 0);
  return out;
}

int indexOf(const std::vector<net::PlaceSpec>& v, const std::string& name) {
  for (std::size_t k = 0; k < v.size(); ++k) {
    if (v[k].name == name) return static_cast<int>(k);
  }
  return -1;
}

int indexOf(const std::vector<net::TransitionSpec>& v, const std::string& name) {
  for (std::size_t k = 0; k < v.size(); ++k) {
    if (v[k].name == name) return static_cast<int>(k);
  }
  return -1;
}

}  // namespace

std::string followName(const PageFromSelectionResult& result, const std::string& name) {
  for (const auto& [from, to] : result.renamed) {
    if (from == name) return to;
  }
  return name;
}

std::optional<model::Model> makePageFromSelection(const model::Model& model, const PageFromSelection& request,
                                                  core::Diagnostics& diags, PageFromSelectionResult* result) {
  core::Diagnostics errs;
  bool is_type = false;
  const net::PageSpec* page = findPage(model.net, request.page, &is_type);
  core::SourceLoc file_loc{model.path, 0, 0};
  if (!page) {
    diags.error(file_loc, "no page or page type '" + request.page + "'");
    return std::nullopt;
  }
  const core::SourceLoc at_page = page->loc.line ? page->loc : file_loc;
  if (is_type && (model.parts.count(page->name) || model.type_scenes.count(page->name))) {
    errs.error(at_page, "page type '" + page->name + "' is a part or has a scene: what its scripts reach as "
                        "self.part, self.params and self.instance would change inside a nested instance");
  }
  if (!core::isIdentifier(request.type)) {
    errs.error(at_page, "the new page type's name '" + request.type + "' is not an identifier ([A-Za-z_][A-Za-z0-9_]*)");
  } else if (findPage(model.net, request.type)) {
    errs.error(at_page, "there is already a page or page type '" + request.type + "'");
  }
  if (!core::isIdentifier(request.instance)) {
    errs.error(at_page, "the instance's name '" + request.instance + "' is not an identifier ([A-Za-z_][A-Za-z0-9_]*)");
  } else if (indexOf(page->places, request.instance) >= 0 || indexOf(page->transitions, request.instance) >= 0 ||
             std::any_of(page->instances.begin(), page->instances.end(),
                         [&](const net::InstanceSpec& i) { return i.name == request.instance; })) {
    errs.error(at_page, "page '" + page->name + "' already has a construct named '" + request.instance + "'");
  }

  // the selection: places and transitions of the page
  std::vector<bool> place_moves(page->places.size(), false), transition_moves(page->transitions.size(), false);
  for (std::string name : request.names) {
    if (const auto slash = name.find('/'); slash != std::string::npos) {
      const std::string on = name.substr(0, slash);
      if (on != page->name) {
        errs.error(at_page, "'" + name + "' is on page '" + on + "', not on '" + page->name +
                                "': a page type is made from the constructs of one page");
        continue;
      }
      name = name.substr(slash + 1);
    }
    if (const int p = indexOf(page->places, name); p >= 0) {
      place_moves[static_cast<std::size_t>(p)] = true;
    } else if (const int t = indexOf(page->transitions, name); t >= 0) {
      transition_moves[static_cast<std::size_t>(t)] = true;
    } else if (const auto inst = std::find_if(page->instances.begin(), page->instances.end(),
                                              [&](const net::InstanceSpec& i) { return i.name == name; });
               inst != page->instances.end()) {
      errs.error(inst->loc, "instance '" + name + "' is selected: a page type is made from places and transitions "
                            "only (an instance's scene and links would have to move with it)");
    } else {
      errs.error(at_page, "page '" + page->name + "' has no place or transition '" + name + "'");
    }
  }
  if (std::none_of(place_moves.begin(), place_moves.end(), [](bool b) { return b; }) &&
      std::none_of(transition_moves.begin(), transition_moves.end(), [](bool b) { return b; }) && !errs.hasErrors()) {
    errs.error(at_page, "nothing is selected on page '" + page->name + "'");
  }

  // the places a selected transition's arcs reach move in too; an instance's reference cannot
  const std::vector<bool> selected_places = place_moves;
  for (const auto& arc : page->arcs) {
    const int tf = indexOf(page->transitions, arc.from), tt = indexOf(page->transitions, arc.to);
    const bool output = tf >= 0;
    const int t = output ? tf : tt;
    if (t < 0 || !transition_moves[static_cast<std::size_t>(t)]) continue;
    const std::string& end = output ? arc.to : arc.from;
    if (const int p = indexOf(page->places, end); p >= 0) {
      place_moves[static_cast<std::size_t>(p)] = true;
    } else {
      errs.error(arc.loc.line ? arc.loc : at_page,
                 "the arc between '" + arc.from + "' and '" + arc.to + "' joins selected transition '" +
                     page->transitions[static_cast<std::size_t>(t)].name + "' to '" + end +
                     "', a reference of an instance that stays on the page; a page type's arcs reach only its own "
                     "places (select the instance's other transitions instead, or leave this one out)");
    }
  }

  // what a moved place may not carry
  for (std::size_t p = 0; p < page->places.size(); ++p) {
    if (!place_moves[p]) continue;
    const auto& place = page->places[p];
    const std::string what = selected_places[p] ? "place '" + place.name + "'"
                                                : "place '" + place.name + "' (it joins a selected transition, so it moves in)";
    if (!place.fusion.empty()) {
      errs.error(place.fusion_loc.line ? place.fusion_loc : place.loc,
                 what + " is a member of fusion set '" + place.fusion + "', whose other members stay where they are");
    }
    if (!place.nodes.empty()) {
      errs.error(place.nodes.front().loc.line ? place.nodes.front().loc : place.loc,
                 what + " holds node tokens by scene path; inside a page type a path is relative to the instance, "
                        "so they would name other nodes");
    }
    if (!place.sensors.empty()) {
      errs.error(place.sensors.front().loc.line ? place.sensors.front().loc : place.loc,
                 what + " reads a sensor by scene path; inside a page type a path is relative to the instance, so it "
                        "would name another node");
    }
    if (std::any_of(page->references.begin(), page->references.end(),
                    [&](const net::ReferenceSpec& r) { return r.place == place.name; })) {
      errs.error(place.loc, what + " is a reference of page type '" + page->name + "'; a reference cannot move into an instance");
    }
  }

  // the names that move, for each qualified name the page has
  const std::vector<std::string> prefixes = prefixesOf(model.net, page->name, is_type);
  NameMap names;
  for (const auto& prefix : prefixes) {
    for (std::size_t p = 0; p < page->places.size(); ++p) {
      if (place_moves[p]) names.emplace_back(prefix + "/" + page->places[p].name, prefix + "/" + request.instance + "/" + page->places[p].name);
    }
    for (std::size_t t = 0; t < page->transitions.size(); ++t) {
      if (transition_moves[t]) {
        names.emplace_back(prefix + "/" + page->transitions[t].name,
                           prefix + "/" + request.instance + "/" + page->transitions[t].name);
      }
    }
  }
  if (errs.hasErrors()) {
    diags.append(errs);
    return std::nullopt;
  }

  // the new page type: the moved constructs and the arcs between them; the crossing arcs stay,
  // reaching the moved places as links
  model::Model out = model;
  net::PageSpec* from = findPage(out.net, request.page);
  net::PageSpec type;
  type.name = request.type;
  std::vector<net::PlaceSpec> places;
  std::vector<net::TransitionSpec> transitions;
  std::set<std::string> referenced;
  std::vector<net::ArcSpec> arcs;
  for (auto& arc : from->arcs) {
    const int tf = indexOf(from->transitions, arc.from), tt = indexOf(from->transitions, arc.to);
    const bool output = tf >= 0;
    const int t = output ? tf : tt;
    std::string& end = output ? arc.to : arc.from;
    const int p = indexOf(from->places, end);
    const bool t_moves = t >= 0 && transition_moves[static_cast<std::size_t>(t)];
    const bool p_moves = p >= 0 && place_moves[static_cast<std::size_t>(p)];
    if (t_moves) {
      type.arcs.push_back(arc);  // its place moves too (checked above)
      continue;
    }
    if (p_moves) {
      referenced.insert(end);
      end = request.instance + "/" + end;
    }
    arcs.push_back(arc);
  }
  from->arcs = std::move(arcs);
  double lo[2] = {std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  double hi[2] = {std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest()};
  bool placed = false;
  const auto widen = [&](const std::optional<net::EditorPos>& pos) {
    if (!pos) return;
    placed = true;
    for (int k = 0; k < 2; ++k) {
      lo[k] = std::min(lo[k], (*pos)[static_cast<std::size_t>(k)]);
      hi[k] = std::max(hi[k], (*pos)[static_cast<std::size_t>(k)]);
    }
  };
  for (std::size_t p = 0; p < from->places.size(); ++p) {
    if (place_moves[p]) {
      if (selected_places[p]) widen(from->places[p].position);
      if (referenced.count(from->places[p].name)) {
        type.references.push_back({from->places[p].name, {}});
        if (result) result->references.push_back(from->places[p].name);
      }
      if (!selected_places[p] && result) result->pulled_in.push_back(page->name + "/" + from->places[p].name);
      type.places.push_back(std::move(from->places[p]));
    } else {
      places.push_back(std::move(from->places[p]));
    }
  }
  for (std::size_t t = 0; t < from->transitions.size(); ++t) {
    if (transition_moves[t]) {
      widen(from->transitions[t].position);
      type.transitions.push_back(std::move(from->transitions[t]));
    } else {
      transitions.push_back(std::move(from->transitions[t]));
    }
  }
  from->places = std::move(places);
  from->transitions = std::move(transitions);
  net::InstanceSpec inst;
  inst.name = request.instance;
  inst.type = request.type;
  if (placed) inst.position = net::EditorPos{(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2};
  from->instances.push_back(std::move(inst));
  out.net.page_types.push_back(std::move(type));

  // declaration order breaks ties: an instance's transitions come before its page's own
  std::size_t k = 0;
  while (k < transition_moves.size() && transition_moves[k]) ++k;
  if (std::any_of(transition_moves.begin() + static_cast<std::ptrdiff_t>(k), transition_moves.end(), [](bool b) { return b; })) {
    diags.warning(at_page, "the moved transitions now come before page '" + page->name +
                               "''s other transitions in declaration order, which breaks ties between transitions "
                               "that compete (declare them first on the page to keep the order)");
  }

  // the names that moved, followed wherever the model writes them
  const std::string dir = std::filesystem::path(model.path).parent_path().string();
  std::set<std::string> files_seen;
  forEveryScript(out.net, [&](net::ScriptSpec& s) { followInScript(s, names, prefixes, dir, files_seen, errs); });
  for (auto& signal : out.signals) {
    switch (signal.kind) {
      case model::SignalSpec::Kind::Place:
        for (const auto& [old_name, new_name] : names) {
          if (signal.target == old_name) {
            signal.target = new_name;
            break;
          }
        }
        break;
      case model::SignalSpec::Kind::Expression: {
        net::ScriptSpec s;
        s.code = signal.target;
        s.loc = signal.loc;
        followInScript(s, names, prefixes, dir, files_seen, errs);
        signal.target = s.code;
        break;
      }
      case model::SignalSpec::Kind::Node: break;
    }
  }
  for (auto& entry : out.io.entries) {
    switch (entry.source) {
      case model::IoEntry::Source::Place:
        for (const auto& [old_name, new_name] : names) {
          if (entry.target == old_name) {
            entry.target = new_name;
            break;
          }
        }
        break;
      case model::IoEntry::Source::Node:
      case model::IoEntry::Source::Part: break;
    }
  }
  if (errs.hasErrors()) {
    diags.append(errs);
    return std::nullopt;
  }
  diags.append(errs);
  if (result) result->renamed = names;
  return out;
}

std::string PageFromSelectionCommand::apply(Document& doc) {
  diags_ = {};
  result_ = {};
  auto made = makePageFromSelection(doc.model(), request_, diags_, &result_);
  if (!made) {
    for (const auto& d : diags_.all()) {
      if (d.severity == core::Severity::Error) return d.str();
    }
    return "the page type could not be made";
  }
  model::Model& m = doc.editableModel();
  before_ = model::Model{};
  before_->net = std::move(m.net);
  before_->io = std::move(m.io);
  before_->signals = std::move(m.signals);
  m.net = std::move(made->net);
  m.io = std::move(made->io);
  m.signals = std::move(made->signals);
  // the new instance, by its qualified name (a page type's: in its first instance)
  std::string where = request_.page + "/" + request_.instance;
  if (!result_.renamed.empty()) {
    const std::string& moved = result_.renamed.front().second;
    where = moved.substr(0, moved.rfind('/'));
  }
  doc.select({SelectionKind::Instance, where});
  doc.touched(false);
  return {};
}

void PageFromSelectionCommand::revert(Document& doc) {
  if (!before_) return;
  model::Model& m = doc.editableModel();
  m.net = std::move(before_->net);
  m.io = std::move(before_->io);
  m.signals = std::move(before_->signals);
  before_.reset();
  doc.touched(false);
}

std::string PageFromSelectionCommand::label() const {
  return "make page type " + request_.type + " from " + std::to_string(request_.names.size()) + " constructs of " +
         request_.page;
}

}  // namespace gdpn::ide
