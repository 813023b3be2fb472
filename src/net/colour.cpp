// Colour sets, values and multisets: the table of a net's sets (built-ins first), the values of
// a finite set in their canonical order, and values written as the inscription language does.

#include "gdpn/net/colour.h"

#include <algorithm>
#include <limits>
#include <set>

namespace gdpn::net {

const char* colourKindName(ColourKind kind) {
  switch (kind) {
    case ColourKind::Dot: return "dot";
    case ColourKind::Bool: return "bool";
    case ColourKind::Integer: return "integer";
    case ColourKind::Enum: return "enum";
    case ColourKind::String: return "string";
    case ColourKind::Product: return "product";
    case ColourKind::Record: return "record";
  }
  return "?";
}

std::strong_ordering operator<=>(const Value& a, const Value& b) {
  if (a.tag != b.tag) return a.tag <=> b.tag;
  switch (a.tag) {
    case Value::Tag::Dot: return std::strong_ordering::equal;
    case Value::Tag::Bool:
    case Value::Tag::Int: return a.i <=> b.i;
    case Value::Tag::String: {
      const int c = a.s.compare(b.s);  // bytewise, as unsigned chars
      return c < 0 ? std::strong_ordering::less : c > 0 ? std::strong_ordering::greater : std::strong_ordering::equal;
    }
    case Value::Tag::Tuple: {
      const std::size_t n = std::min(a.items.size(), b.items.size());
      for (std::size_t k = 0; k < n; ++k) {
        const std::strong_ordering c = a.items[k] <=> b.items[k];
        if (c != std::strong_ordering::equal) return c;
      }
      return a.items.size() <=> b.items.size();
    }
  }
  return std::strong_ordering::equal;
}

std::int64_t multisetSize(const Multiset& m) {
  std::int64_t n = 0;
  for (const auto& [v, k] : m) n += k;
  return n;
}

bool containedIn(const Multiset& small, const Multiset& big) {
  for (const auto& [v, k] : small) {
    if (k <= 0) continue;
    const auto it = big.find(v);
    if (it == big.end() || it->second < k) return false;
  }
  return true;
}

namespace {

constexpr std::int64_t kFiniteLimit = std::int64_t{1} << 62;
// no set: a value written by its shape alone
constexpr ColourId kNoSet = std::numeric_limits<ColourId>::max();

ColourSet builtin(std::string name, ColourKind kind, std::optional<std::int64_t> size) {
  ColourSet s;
  s.name = std::move(name);
  s.kind = kind;
  s.size = size;
  return s;
}

// `text` in double quotes, its quotes and backslashes escaped (as the parser reads them)
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else {
      out += c;
    }
  }
  return out + '"';
}

}  // namespace

Colours::Colours() {
  sets_.push_back(builtin("dot", ColourKind::Dot, 1));
  sets_.push_back(builtin("bool", ColourKind::Bool, 2));
  sets_.push_back(builtin("int", ColourKind::Integer, std::nullopt));
  sets_.push_back(builtin("string", ColourKind::String, std::nullopt));
  for (ColourId id = 0; id < sets_.size(); ++id) by_name_.emplace(sets_[id].name, id);
}

bool Colours::declare(const std::vector<ColourSetSpec>& specs, core::Diagnostics& diags) {
  bool ok = true;
  auto error = [&](const SourceLoc& loc, std::string message) {
    diags.error(loc, std::move(message));
    ok = false;
  };
  std::vector<SourceLoc> where(sets_.size());  // where each set was declared (none for the built-ins)
  for (const ColourSetSpec& spec : specs) {
    // every spec becomes a set, mistakes and all, so that ids follow the declaration order
    ColourSet s;
    s.name = spec.name;
    s.kind = spec.kind;
    const std::string what = "colour set '" + spec.name + "'";
    if (spec.name.empty()) error(spec.loc, "a colour set needs a name");
    if (const auto before = find(spec.name); before && !spec.name.empty()) {
      if (*before < 4) {
        error(spec.loc, "'" + spec.name + "' is a built-in colour set");
      } else {
        error(spec.loc, what + " is declared twice");
        diags.note(where[*before], "first declared here");
      }
    }
    switch (spec.kind) {
      case ColourKind::Dot: s.size = 1; break;
      case ColourKind::Bool: s.size = 2; break;
      case ColourKind::String: break;
      case ColourKind::Integer:
        s.range = spec.range;
        s.lo = spec.lo;
        s.hi = spec.hi;
        if (spec.range) {
          if (spec.lo > spec.hi) {
            error(spec.loc, what + " is an empty range " + std::to_string(spec.lo) + ".." + std::to_string(spec.hi));
            s.size = 0;
          } else {
            const std::uint64_t span = static_cast<std::uint64_t>(spec.hi) - static_cast<std::uint64_t>(spec.lo);
            if (span < static_cast<std::uint64_t>(kFiniteLimit)) s.size = static_cast<std::int64_t>(span) + 1;
          }
        }
        break;
      case ColourKind::Enum: {
        s.constants = spec.constants;
        s.cyclic = spec.cyclic;
        if (spec.constants.empty()) error(spec.loc, what + " has no constants");
        std::set<std::string> seen;
        for (const std::string& c : spec.constants) {
          if (!seen.insert(c).second) {
            error(spec.loc, "constant '" + c + "' of " + what + " is declared twice");
          } else if (const auto other = constant(c)) {
            error(spec.loc, "constant '" + c + "' of " + what + " is also a constant of '" + sets_[other->first].name +
                                "' (constants are unique over colour sets)");
          }
        }
        s.size = static_cast<std::int64_t>(spec.constants.size());
        break;
      }
      case ColourKind::Product:
      case ColourKind::Record: {
        if (spec.components.empty()) error(spec.loc, what + " has no components");
        std::optional<std::int64_t> size = 1;
        for (const std::string& c : spec.components) {
          const auto id = find(c);
          if (!id) {
            error(spec.loc, what + " names an unknown colour set '" + c + "' (a set may name only sets before it)");
          }
          const ColourId cid = id.value_or(kDot);
          s.components.push_back(cid);
          const auto& csize = sets_[cid].size;
          if (!size || !csize) {
            size.reset();
          } else if (*csize != 0 && *size > kFiniteLimit / *csize) {
            size.reset();
          } else {
            size = *size * *csize;
          }
        }
        s.size = size;
        if (spec.kind == ColourKind::Record) {
          s.fields = spec.fields;
          if (spec.fields.size() != spec.components.size()) {
            error(spec.loc, what + " has " + std::to_string(spec.fields.size()) + " field names for " +
                                std::to_string(spec.components.size()) + " components");
          }
          std::set<std::string> seen;
          for (const std::string& f : spec.fields) {
            if (!seen.insert(f).second) error(spec.loc, "field '" + f + "' of " + what + " is declared twice");
          }
        }
        break;
      }
    }
    // products of products: the evaluator and the printer recurse as deep
    int depth = 1;
    for (const ColourId c : s.components) depth = std::max(depth, depthOf(c) + 1);
    if (depth > kMostNesting) {
      error(spec.loc, what + " nests products and records " + std::to_string(depth) + " deep, more than " +
                          std::to_string(kMostNesting));
      s.components.assign(s.components.size(), kDot);
      depth = 2;
    }
    depth_.resize(sets_.size(), 1);
    depth_.push_back(depth);
    const auto id = static_cast<ColourId>(sets_.size());
    if (!by_name_.contains(s.name)) by_name_.emplace(s.name, id);
    if (s.kind == ColourKind::Enum) {
      for (std::size_t k = 0; k < s.constants.size(); ++k) {
        constants_.emplace(s.constants[k], std::pair<ColourId, std::int64_t>{id, static_cast<std::int64_t>(k)});
      }
    }
    sets_.push_back(std::move(s));
    where.push_back(spec.loc);
  }
  return ok;
}

std::optional<ColourId> Colours::find(std::string_view name) const {
  const auto it = by_name_.find(name);
  if (it == by_name_.end()) return std::nullopt;
  return it->second;
}

std::optional<std::pair<ColourId, std::int64_t>> Colours::constant(std::string_view name) const {
  const auto it = constants_.find(name);
  if (it == constants_.end()) return std::nullopt;
  return it->second;
}

bool Colours::contains(ColourId id, const Value& v) const {
  if (id >= sets_.size()) return false;
  const ColourSet& s = sets_[id];
  switch (s.kind) {
    case ColourKind::Dot: return v.tag == Value::Tag::Dot;
    case ColourKind::Bool: return v.tag == Value::Tag::Bool && (v.i == 0 || v.i == 1);
    case ColourKind::Integer: return v.tag == Value::Tag::Int && (!s.range || (s.lo <= v.i && v.i <= s.hi));
    case ColourKind::Enum:
      return v.tag == Value::Tag::Int && v.i >= 0 && v.i < static_cast<std::int64_t>(s.constants.size());
    case ColourKind::String: return v.tag == Value::Tag::String;
    case ColourKind::Product:
    case ColourKind::Record:
      if (v.tag != Value::Tag::Tuple || v.items.size() != s.components.size()) return false;
      for (std::size_t k = 0; k < v.items.size(); ++k) {
        if (!contains(s.components[k], v.items[k])) return false;
      }
      return true;
  }
  return false;
}

std::vector<Value> Colours::values(ColourId id) const {
  std::vector<Value> out;
  if (id >= sets_.size() || !sets_[id].size) return out;
  const ColourSet& s = sets_[id];
  switch (s.kind) {
    case ColourKind::Dot: out.push_back(Value::dot()); break;
    case ColourKind::Bool: out = {Value::boolean(false), Value::boolean(true)}; break;
    case ColourKind::Integer:
      if (!s.range || s.lo > s.hi) break;
      out.reserve(static_cast<std::size_t>(*s.size));
      for (std::int64_t n = s.lo;; ++n) {
        out.push_back(Value::integer(n));
        if (n == s.hi) break;
      }
      break;
    case ColourKind::Enum:
      for (std::size_t k = 0; k < s.constants.size(); ++k) out.push_back(Value::integer(static_cast<std::int64_t>(k)));
      break;
    case ColourKind::String: break;
    case ColourKind::Product:
    case ColourKind::Record: {
      // the first component varies slowest: the tuples' own order
      out.push_back(Value::tuple({}));
      for (const ColourId c : s.components) {
        const std::vector<Value> part = values(c);
        std::vector<Value> next;
        next.reserve(out.size() * part.size());
        for (const Value& prefix : out) {
          for (const Value& p : part) {
            Value t = prefix;
            t.items.push_back(p);
            next.push_back(std::move(t));
          }
        }
        out = std::move(next);
      }
      break;
    }
  }
  return out;
}

std::string Colours::text(ColourId id, const Value& v) const {
  const ColourSet* s = id < sets_.size() ? &sets_[id] : nullptr;
  switch (v.tag) {
    case Value::Tag::Dot: return "dot";
    case Value::Tag::Bool: return v.i != 0 ? "true" : "false";
    case Value::Tag::Int:
      if (s != nullptr && s->kind == ColourKind::Enum && v.i >= 0 && v.i < static_cast<std::int64_t>(s->constants.size())) {
        return s->constants[static_cast<std::size_t>(v.i)];
      }
      return std::to_string(v.i);
    case Value::Tag::String: return quoted(v.s);
    case Value::Tag::Tuple: {
      const bool shaped = s != nullptr && (s->kind == ColourKind::Product || s->kind == ColourKind::Record) &&
                          s->components.size() == v.items.size();
      const bool record = shaped && s->kind == ColourKind::Record && s->fields.size() == v.items.size();
      std::string out = record ? "{" : "(";
      for (std::size_t k = 0; k < v.items.size(); ++k) {
        if (k > 0) out += ", ";
        if (record) out += s->fields[k] + " = ";
        out += text(shaped ? s->components[k] : kNoSet, v.items[k]);
      }
      return out + (record ? "}" : ")");
    }
  }
  return "?";
}

std::string Colours::text(ColourId id, const Multiset& m) const {
  if (m.empty()) return "empty";
  std::string out;
  for (const auto& [v, k] : m) {
    if (!out.empty()) out += " ++ ";
    std::string value = text(id, v);
    // n'v takes a value that does not start with a sign
    if (!value.empty() && value[0] == '-') value = "(" + value + ")";
    out += std::to_string(k) + "'" + value;
  }
  return out;
}

}  // namespace gdpn::net
