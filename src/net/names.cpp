#include "gdpn/net/names.h"

namespace gdpn::net {

namespace {

std::size_t heapBytes(const std::string& s) { return s.capacity() > 15 ? s.capacity() + 1 : 0; }

}  // namespace

/// What NameTable compares a scope with: its qualified name, never built.
struct Names::PathOf {
  const Names* names;
  std::uint32_t scope;
  [[nodiscard]] bool is(std::string_view path) const { return names->scopeIs(scope, path); }
  friend bool operator==(const PathOf& p, std::string_view path) { return p.is(path); }
};

std::uint32_t Names::addTable() {
  tables_.emplace_back();
  return static_cast<std::uint32_t>(tables_.size() - 1);
}

std::uint32_t Names::addPlace(std::uint32_t table, std::string local, SourceLoc loc) {
  auto& t = tables_[table];
  t.places.push_back(std::move(local));
  t.place_locs.push_back(std::move(loc));
  return static_cast<std::uint32_t>(t.places.size() - 1);
}

std::uint32_t Names::addTransition(std::uint32_t table, std::string local, SourceLoc loc) {
  auto& t = tables_[table];
  t.transitions.push_back(std::move(local));
  t.transition_locs.push_back(std::move(loc));
  return static_cast<std::uint32_t>(t.transitions.size() - 1);
}

std::uint32_t Names::addScope(std::uint32_t parent, std::string_view name, std::uint32_t table,
                              std::uint32_t first_place, std::uint32_t first_transition) {
  Scope s;
  s.parent = parent;
  s.table = table;
  s.name_begin = static_cast<std::uint32_t>(scope_chars_.size());
  scope_chars_ += name;
  s.name_end = static_cast<std::uint32_t>(scope_chars_.size());
  s.first_place = first_place;
  s.first_transition = first_transition;
  scopes_.push_back(s);
  return static_cast<std::uint32_t>(scopes_.size() - 1);
}

std::uint32_t Names::scopeForPrefix(std::string_view prefix, bool bare) {
  if (bare) {
    if (bare_ == kNoScope) bare_ = addScope(kNoScope, "", addTable(), 0, 0);
    return bare_;
  }
  auto nameOf = [this](std::uint32_t i) { return scopeName(prefixes_[i]); };
  if (const auto i = prefix_index_.find(prefix, nameOf)) return prefixes_[*i];
  prefixes_.push_back(addScope(kNoScope, prefix, addTable(), 0, 0));
  prefix_index_.insert(prefix, static_cast<std::uint32_t>(prefixes_.size() - 1), nameOf);
  return prefixes_.back();
}

void Names::freeze() {
  auto ignore = [](std::uint32_t, std::uint32_t) {};  // the first of a name is found (compile() refuses twins)
  for (auto& t : tables_) {
    t.place_index.insertAll(static_cast<std::uint32_t>(t.places.size()),
                            [&](std::uint32_t i) -> std::string_view { return t.places[i]; }, ignore);
    t.transition_index.insertAll(static_cast<std::uint32_t>(t.transitions.size()),
                                 [&](std::uint32_t i) -> std::string_view { return t.transitions[i]; }, ignore);
  }
  scope_index_.reserve(scopes_.size());
  std::string path;
  for (std::uint32_t s = 0; s < scopes_.size(); ++s) {
    if (s == bare_) continue;
    path.clear();
    appendScopePath(path, s);
    scope_index_.insert(path, s, [this](std::uint32_t id) { return PathOf{this, id}; });
  }
  prefixes_ = {};
  prefix_index_ = {};
}

std::string_view Names::scopeName(std::uint32_t scope) const {
  const auto& s = scopes_[scope];
  return std::string_view(scope_chars_).substr(s.name_begin, s.name_end - s.name_begin);
}

void Names::appendScopePath(std::string& out, std::uint32_t scope) const {
  const auto parent = scopes_[scope].parent;
  if (parent != kNoScope) {
    appendScopePath(out, parent);
    out += '/';
  }
  out += scopeName(scope);
}

void Names::appendName(std::string& out, std::uint32_t scope, std::string_view local) const {
  if (scope != bare_) {
    appendScopePath(out, scope);
    out += '/';
  }
  out += local;
}

bool Names::scopeIs(std::uint32_t scope, std::string_view path) const {
  const auto name = scopeName(scope);
  const auto parent = scopes_[scope].parent;
  if (parent == kNoScope) return path == name;
  if (path.size() <= name.size() || !path.ends_with(name)) return false;
  const auto rest = path.size() - name.size() - 1;
  return path[rest] == '/' && scopeIs(parent, path.substr(0, rest));
}

std::optional<std::uint32_t> Names::findScope(std::string_view path) const {
  return scope_index_.find(path, [this](std::uint32_t s) { return PathOf{this, s}; });
}

std::pair<std::optional<std::uint32_t>, std::string_view> Names::split(std::string_view qualified_name) const {
  const auto slash = qualified_name.rfind('/');
  if (slash == std::string_view::npos) {
    return {bare_ == kNoScope ? std::nullopt : std::optional<std::uint32_t>(bare_), qualified_name};
  }
  return {findScope(qualified_name.substr(0, slash)), qualified_name.substr(slash + 1)};
}

std::optional<std::uint32_t> Names::find(std::string_view qualified_name, bool place) const {
  const auto [scope, local] = split(qualified_name);
  if (!scope) return std::nullopt;
  const auto& s = scopes_[*scope];
  const auto& t = tables_[s.table];
  const auto& names = place ? t.places : t.transitions;
  const auto& ids = place ? t.place_ids : t.transition_ids;
  const auto id = (place ? t.place_index : t.transition_index)
                      .find(local, [&](std::uint32_t i) -> std::string_view { return names[i]; });
  if (!id) return std::nullopt;
  if (!ids.empty()) return ids[*id];
  if (!place) return s.first_transition + *id;
  return scope_place_ids_.empty() ? s.first_place + *id : scope_place_ids_[s.first_place + *id];
}

std::size_t Names::memoryBytes() const {
  std::size_t bytes = tables_.capacity() * sizeof(ConstructTable) + scopes_.capacity() * sizeof(Scope) +
                      heapBytes(scope_chars_) + scope_index_.memoryBytes() +
                      scope_place_ids_.capacity() * sizeof(std::uint32_t);
  for (const auto& t : tables_) {
    bytes += (t.places.capacity() + t.transitions.capacity()) * sizeof(std::string) +
             (t.place_locs.capacity() + t.transition_locs.capacity()) * sizeof(SourceLoc) +
             (t.place_ids.capacity() + t.transition_ids.capacity()) * sizeof(std::uint32_t) +
             t.place_index.memoryBytes() + t.transition_index.memoryBytes();
    for (const auto& n : t.places) bytes += heapBytes(n);
    for (const auto& n : t.transitions) bytes += heapBytes(n);
    for (const auto& l : t.place_locs) bytes += heapBytes(l.file);
    for (const auto& l : t.transition_locs) bytes += heapBytes(l.file);
  }
  return bytes;
}

}  // namespace gdpn::net
