#pragma once
/// \file
/// Names: the names and declaration locations of a net's places and transitions, stored once
/// per page type. A table holds a page's (or page type's) local names and locations; a scope
/// is one instantiated page (its parent scope, its table, its own local name). A construct is
/// a (scope, local) pair, and its qualified name ("line/cellA/buffer") is built on request.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "gdpn/core/diagnostics.h"
#include "gdpn/core/name_table.h"
#include "gdpn/net/id.h"

namespace gdpn::net {

using core::SourceLoc;

/// No scope: the parent of a root scope.
inline constexpr std::uint32_t kNoScope = 0xffffffffu;

/// One page's (or page type's) own places and transitions: local names and locations,
/// shared by all the scopes that instantiate the page.
struct ConstructTable {
  std::vector<std::string> places;         ///< local names, in declaration order
  std::vector<SourceLoc> place_locs;       ///< where each place was declared
  std::vector<std::string> transitions;    ///< local names, in declaration order
  std::vector<SourceLoc> transition_locs;  ///< where each transition was declared
  /// Only for a table made by NetBuilder's name-splitting calls (one scope, constructs added
  /// in any order): the net's id of each local place, resp. transition. Empty when the
  /// scope's constructs are consecutive from its first ones.
  std::vector<std::uint32_t> place_ids, transition_ids;
  core::NameTable place_index;       ///< local name -> local place (filled by Names::freeze)
  core::NameTable transition_index;  ///< local name -> local transition (filled by Names::freeze)
};

/// One instantiated page.
struct Scope {
  std::uint32_t parent = kNoScope;       ///< the enclosing scope; kNoScope for a root
  std::uint32_t table = 0;               ///< its ConstructTable
  std::uint32_t name_begin = 0;          ///< its local name: range in the shared characters
  std::uint32_t name_end = 0;            ///< end of that range
  std::uint32_t first_place = 0;         ///< the net's id of its local place 0
  std::uint32_t first_transition = 0;    ///< the net's id of its local transition 0
};

/// The tables and scopes of one net, with the lookups from qualified names.
class Names {
 public:
  /// Adds an empty table and returns its id.
  std::uint32_t addTable();
  /// Appends a place called `local` to table `table`; returns its local index.
  std::uint32_t addPlace(std::uint32_t table, std::string local, SourceLoc loc);
  /// Appends a transition called `local` to table `table`; returns its local index.
  std::uint32_t addTransition(std::uint32_t table, std::string local, SourceLoc loc);
  /// Records that the last place of name-splitting table `table` is the
  /// net's place `id` (see ConstructTable::place_ids).
  void addPlaceId(std::uint32_t table, std::uint32_t id) { tables_[table].place_ids.push_back(id); }
  /// Records the net's id of the last transition of name-splitting table `table`.
  void addTransitionId(std::uint32_t table, std::uint32_t id) { tables_[table].transition_ids.push_back(id); }
  /// Adds a scope called `name` inside `parent` (kNoScope for a root) using table `table`;
  /// its constructs are consecutive in the net from `first_place` and `first_transition`.
  std::uint32_t addScope(std::uint32_t parent, std::string_view name, std::uint32_t table,
                         std::uint32_t first_place, std::uint32_t first_transition);
  /// Sets where the transitions of `scope` start in the net (known after its instances).
  void setFirstTransition(std::uint32_t scope, std::uint32_t first) { scopes_[scope].first_transition = first; }
  /// The scope, with a table of its own, for qualified names with prefix `prefix` (a name
  /// with no '/' when `bare`); made on first use. For NetBuilder's name-splitting calls.
  std::uint32_t scopeForPrefix(std::string_view prefix, bool bare);
  /// Makes the place that scopes number `v` (from their `first_place`) the net's place
  /// `ids[v]`: several numbers name one place where fusion sets join places. Without it,
  /// number `v` is place `v`.
  void setPlaceIds(std::vector<std::uint32_t> ids) { scope_place_ids_ = std::move(ids); }
  /// Builds the name indexes; call once, when every name is in.
  void freeze();

  /// The table `table`.
  [[nodiscard]] const ConstructTable& table(std::uint32_t table) const { return tables_[table]; }
  /// The scope `scope`.
  [[nodiscard]] const Scope& scope(std::uint32_t scope) const { return scopes_[scope]; }
  /// Number of scopes.
  [[nodiscard]] std::size_t scopeCount() const { return scopes_.size(); }
  /// The local name of scope `scope` ("cellA").
  [[nodiscard]] std::string_view scopeName(std::uint32_t scope) const;
  /// Appends the qualified name of `scope` ("line/cellA"; "" for the bare scope) to `out`.
  void appendScopePath(std::string& out, std::uint32_t scope) const;
  /// Appends the qualified name of construct `local` of `scope` to `out`.
  void appendName(std::string& out, std::uint32_t scope, std::string_view local) const;
  /// The scope whose qualified name is `path`, if there is one (never the bare scope).
  [[nodiscard]] std::optional<std::uint32_t> findScope(std::string_view path) const;
  /// The net's place called `qualified_name`, if there is one.
  [[nodiscard]] std::optional<PlaceId> findPlace(std::string_view qualified_name) const {
    const auto id = find(qualified_name, true);
    return id ? std::optional<PlaceId>(*id) : std::nullopt;
  }
  /// The net's transition called `qualified_name`, if there is one.
  [[nodiscard]] std::optional<TransitionId> findTransition(std::string_view qualified_name) const {
    const auto id = find(qualified_name, false);
    return id ? std::optional<TransitionId>(*id) : std::nullopt;
  }
  /// Approximate heap bytes held.
  [[nodiscard]] std::size_t memoryBytes() const;

 private:
  struct PathOf;
  /// Whether the qualified name of `scope` is `path`, without building it.
  [[nodiscard]] bool scopeIs(std::uint32_t scope, std::string_view path) const;
  /// The index of the net's place (`place`) or transition called `qualified_name`, if any.
  [[nodiscard]] std::optional<std::uint32_t> find(std::string_view qualified_name, bool place) const;
  /// The (scope, rest) that `qualified_name` splits into at its last '/'; no scope when none.
  [[nodiscard]] std::pair<std::optional<std::uint32_t>, std::string_view> split(std::string_view qualified_name) const;

  std::vector<ConstructTable> tables_;
  std::vector<Scope> scopes_;
  std::string scope_chars_;             // the scopes' local names, one after another
  core::NameTable scope_index_;         // qualified scope name -> scope (all but the bare one)
  std::uint32_t bare_ = kNoScope;       // the scope of names without '/', if any
  std::vector<std::uint32_t> prefixes_; // scopes made by scopeForPrefix (builder only; cleared by freeze)
  core::NameTable prefix_index_;        // their prefixes -> index in prefixes_ (builder only)
  std::vector<std::uint32_t> scope_place_ids_;  // see setPlaceIds; empty when each number is its place
};

}  // namespace gdpn::net
