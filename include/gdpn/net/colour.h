#pragma once
/// \file
/// Colour sets and their values (semantics: *Value tokens*): the types of value tokens, the
/// values themselves, and multisets of them. The net module's own: no Python, no scene.

#include <compare>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gdpn/core/diagnostics.h"

namespace gdpn::net {

using core::SourceLoc;

/// What kind of colour set.
enum class ColourKind : std::uint8_t {
  Dot,      ///< one value, `dot` (the plain token of a P/T place)
  Bool,     ///< `false`, `true`
  Integer,  ///< whole numbers: the built-in `int` (64 bits, not finite) or a range `lo..hi` (finite)
  Enum,     ///< named constants in order; cyclic when the successor of the last is the first
  String,   ///< text (not finite)
  Product,  ///< tuples `(a, b, ...)` of component sets
  Record,   ///< records `{f = a, g = b}`: a product whose components have names
};

/// "dot", "bool", "integer", "enum", "string", "product", "record".
const char* colourKindName(ColourKind kind);

/// Index of a colour set in a Colours table.
using ColourId = std::uint32_t;

/// A value token's value. Its set says what it means: an enum constant is its index, a record
/// a tuple in field order. Ordered (the canonical order of bindings and markings): by kind,
/// then booleans false < true, numbers and enum indices as numbers, strings bytewise, tuples
/// component by component.
struct Value {
  /// How the value is held.
  enum class Tag : std::uint8_t { Dot, Bool, Int, String, Tuple };
  Tag tag = Tag::Dot;          ///< which of the members below holds it
  std::int64_t i = 0;          ///< Bool (0, 1), Int (the number), an Enum's constant index (also Int)
  std::string s;               ///< String
  std::vector<Value> items;    ///< Tuple: the components (a product's or a record's, in field order)

  /// The value `dot`.
  static Value dot() { return {}; }
  /// `b`.
  static Value boolean(bool b) { return Value{Tag::Bool, b ? 1 : 0, {}, {}}; }
  /// The number (or enum index) `n`.
  static Value integer(std::int64_t n) { return Value{Tag::Int, n, {}, {}}; }
  /// The text `text`.
  static Value string(std::string text) { return Value{Tag::String, 0, std::move(text), {}}; }
  /// The tuple of `parts`.
  static Value tuple(std::vector<Value> parts) { return Value{Tag::Tuple, 0, {}, std::move(parts)}; }

  friend bool operator==(const Value&, const Value&) = default;
  friend std::strong_ordering operator<=>(const Value& a, const Value& b);
};

/// A multiset of values: each value with its multiplicity (> 0), in the canonical order.
using Multiset = std::map<Value, std::int64_t>;

/// Tokens in `m`, all values together.
std::int64_t multisetSize(const Multiset& m);
/// True when `small` is contained in `big` (every value's multiplicity at most big's).
bool containedIn(const Multiset& small, const Multiset& big);

/// A colour set as the model declares it (`colours:`), before it is resolved.
struct ColourSetSpec {
  std::string name;                     ///< unique among colour sets and not a built-in's name
  SourceLoc loc;                        ///< where it is declared
  ColourKind kind = ColourKind::Dot;    ///< what it is
  std::int64_t lo = 0, hi = 0;          ///< Integer: the range lo..hi (both in); none when !range
  bool range = false;                   ///< Integer: true for a range (the built-in `int` has none)
  std::vector<std::string> constants;   ///< Enum: the constants, in order
  bool cyclic = false;                  ///< Enum: successor of the last is the first
  std::vector<std::string> components;  ///< Product, Record: the component sets, by name
  std::vector<std::string> fields;      ///< Record: the field names (as many as components)
  /// Read from PNML: the namedsort's id and each constant's id where they differ from the
  /// names (empty: the same), so that writing back gives the same ids. Not compared.
  std::string pnml_id{};
  std::vector<std::string> constant_pnml_ids{};  ///< per constant, "" where its id is its name
  friend bool operator==(const ColourSetSpec& x, const ColourSetSpec& y) {
    return x.name == y.name && x.kind == y.kind && x.lo == y.lo && x.hi == y.hi && x.range == y.range &&
           x.constants == y.constants && x.cyclic == y.cyclic && x.components == y.components && x.fields == y.fields;
  }
};

/// A variable of the inscriptions (`variables:`), typed by a colour set.
struct VariableSpec {
  std::string name;    ///< unique among variables, colour sets and enum constants
  std::string colour;  ///< its colour set, by name
  SourceLoc loc;       ///< where it is declared
  std::string pnml_id{};  ///< read from PNML: the variabledecl's id where it differs from the name. Not compared.
  friend bool operator==(const VariableSpec& x, const VariableSpec& y) {
    return x.name == y.name && x.colour == y.colour;
  }
};

/// A resolved colour set.
struct ColourSet {
  std::string name;                   ///< its name ("int", "bool", "string", "dot" for the built-ins)
  ColourKind kind = ColourKind::Dot;  ///< what it is
  bool range = false;                 ///< Integer: a range lo..hi
  std::int64_t lo = 0, hi = 0;        ///< Integer range: both ends, in
  std::vector<std::string> constants; ///< Enum: constant names, in order
  bool cyclic = false;                ///< Enum: cyclic
  std::vector<ColourId> components;   ///< Product, Record: component sets
  std::vector<std::string> fields;    ///< Record: field names
  /// Values it has when finite (product of the components' sizes), else nullopt. Sizes above
  /// 2^62 count as not finite.
  std::optional<std::int64_t> size;
};

/// The colour sets of a net: the built-ins first (dot, bool, int, string at kDot, kBool, kInt,
/// kString), then the declared ones in declaration order.
class Colours {
 public:
  static constexpr ColourId kDot = 0;     ///< `dot`
  static constexpr ColourId kBool = 1;    ///< `bool`
  static constexpr ColourId kInt = 2;     ///< `int`: every 64-bit whole number
  static constexpr ColourId kString = 3;  ///< `string`

  /// The built-ins alone.
  Colours();
  /// Adds the declared sets `specs` in order (a set may name only sets before it); mistakes
  /// (a clash of names, an unknown component, an empty range or enumeration, a repeated
  /// constant or field) go to `diags` at the declaration. False when there was one.
  bool declare(const std::vector<ColourSetSpec>& specs, core::Diagnostics& diags);

  /// All sets, by ColourId.
  [[nodiscard]] const std::vector<ColourSet>& sets() const { return sets_; }
  /// Set `id`.
  [[nodiscard]] const ColourSet& at(ColourId id) const { return sets_[id]; }
  /// How deep set `id`'s products and records nest (1 for a set without components).
  [[nodiscard]] int depthOf(ColourId id) const { return id < depth_.size() ? depth_[id] : 1; }
  /// The deepest products and records may nest.
  static constexpr int kMostNesting = 64;
  /// The set called `name`, if any.
  [[nodiscard]] std::optional<ColourId> find(std::string_view name) const;
  /// The enum set and index of the constant called `name` (constants are unique over sets).
  [[nodiscard]] std::optional<std::pair<ColourId, std::int64_t>> constant(std::string_view name) const;

  /// True when `v` is a value of set `id` (right shape; a number in its range; an index in
  /// its enumeration).
  [[nodiscard]] bool contains(ColourId id, const Value& v) const;
  /// Every value of finite set `id`, in the canonical order; empty for a set that is not finite.
  [[nodiscard]] std::vector<Value> values(ColourId id) const;
  /// `v` (a value of set `id`) as the inscription language writes it: `3`, `true`, `p1`,
  /// `"text"`, `(1, p2)`, `{id = 1, name = "a"}`, `dot`.
  [[nodiscard]] std::string text(ColourId id, const Value& v) const;
  /// `m` as the language writes a multiset: `2'p1 ++ 1'p3`; `empty` when empty.
  [[nodiscard]] std::string text(ColourId id, const Multiset& m) const;

 private:
  std::vector<ColourSet> sets_;
  std::vector<int> depth_;  // per set: how deep its components nest (a built-in's: 1)
  std::map<std::string, ColourId, std::less<>> by_name_;  // each name's first set
  std::map<std::string, std::pair<ColourId, std::int64_t>, std::less<>> constants_;  // each constant's first set
};

}  // namespace gdpn::net
