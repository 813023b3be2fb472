#include "gdpn/scene/types.h"

#include <algorithm>
#include <cmath>

#include "gdpn/core/assert.h"
#include "gdpn/core/text.h"

namespace gdpn::scene {

const char* fieldKindName(FieldKind kind) {
  switch (kind) {
    case FieldKind::Bool: return "bool";
    case FieldKind::Int: return "int";
    case FieldKind::Float: return "float";
    case FieldKind::Vec3: return "vec3";
    case FieldKind::Color: return "color";
    case FieldKind::Rotation: return "rotation";
    case FieldKind::Enum: return "enum";
    case FieldKind::String: return "string";
    case FieldKind::File: return "file";
    case FieldKind::FloatList: return "list";
  }
  return "?";
}

std::string FieldDesc::rangeError(double x) const {
  if (!std::isfinite(x)) return "'" + name + "' must be a finite number, got " + core::formatDouble(x);
  if ((min_open ? x > min : x >= min) && x <= max) return {};
  const bool low = boundedBelow() || x < min, high = boundedAbove() || x > max;
  std::string rule = low && high ? "must lie in " + rangeText()
                     : low       ? (min_open ? "must be above " : "must be at least ") + core::formatDouble(min)
                                 : "must be at most " + core::formatDouble(max);
  return "'" + name + "' " + rule + ", got " + core::formatDouble(x);
}

std::string FieldDesc::rangeText() const {
  if (kind == FieldKind::Enum) {
    std::string s;
    for (const auto& c : choices) s += (s.empty() ? "" : " | ") + c;
    return s;
  }
  if (!boundedBelow() && !boundedAbove()) return "";
  // the plant's limit where it is the bound (fmax1 in [0, 1e12]); a joint's "no limit" is inf
  const auto bound = [](double x) {
    return std::abs(x) >= 1e299 ? std::string(x < 0 ? "-inf" : "inf") : core::formatDouble(x);
  };
  return (min_open ? "(" : "[") + bound(min) + ", " + bound(max) + "]";
}

const std::string& FieldDesc::unitFor(std::string_view choice) const {
  for (const auto& [word, u] : units_by_choice) {
    if (word == choice) return u;
  }
  return unit;
}

std::size_t valueIndex(FieldKind kind) {
  switch (kind) {
    case FieldKind::Bool: return 0;
    case FieldKind::Int: return 1;
    case FieldKind::Float: return 2;
    case FieldKind::Vec3:
    case FieldKind::Color: return 3;
    case FieldKind::Rotation: return 4;
    case FieldKind::Enum:
    case FieldKind::String:
    case FieldKind::File: return 5;
    case FieldKind::FloatList: return 6;
  }
  return 0;
}

std::optional<FieldError> FieldDesc::check(const FieldValue& value) const {
  if (value.index() != valueIndex(kind)) {
    return FieldError{"'" + name + "' expects a " + std::string(fieldKindName(kind)) + " value", -1};
  }
  // every number in range, each located by its place in the value
  auto numbers = [&](const double* x, std::size_t n, bool whole) -> std::optional<FieldError> {
    for (std::size_t k = 0; k < n; ++k) {
      if (auto why = rangeError(x[k]); !why.empty()) return FieldError{why, whole ? -1 : static_cast<int>(k)};
    }
    return std::nullopt;
  };
  switch (kind) {
    case FieldKind::Bool:
    case FieldKind::String:
    case FieldKind::File: return std::nullopt;
    case FieldKind::Int: {
      const double x = static_cast<double>(std::get<std::int64_t>(value));
      return numbers(&x, 1, true);
    }
    case FieldKind::Float: return numbers(&std::get<double>(value), 1, true);
    case FieldKind::Vec3:
    case FieldKind::Color: return numbers(std::get<std::array<double, 3>>(value).data(), 3, false);
    case FieldKind::Rotation: {
      const auto& r = std::get<std::array<double, 4>>(value);
      if (auto bad = numbers(r.data(), 4, false)) return bad;
      if (r[0] == 0 && r[1] == 0 && r[2] == 0 && r[3] != 0) {
        return FieldError{"'" + name + "' needs an axis that is not zero", -1};
      }
      return std::nullopt;
    }
    case FieldKind::Enum: {
      const auto& word = std::get<std::string>(value);
      if (std::find(choices.begin(), choices.end(), word) != choices.end()) return std::nullopt;
      std::string list;
      for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
      return FieldError{"'" + name + "' is one of " + list + ", got \"" + word + "\"" + core::didYouMean(word, choices), -1};
    }
    case FieldKind::FloatList: {
      const auto& list = std::get<std::vector<double>>(value);
      return numbers(list.data(), list.size(), false);
    }
  }
  return std::nullopt;
}

int NodeType::fieldIndex(std::string_view field) const {
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (fields[i]->name == field) return static_cast<int>(i);
  }
  return -1;
}

bool NodeType::is(const NodeType& other) const {
  for (const NodeType* t = this; t; t = t->base) {
    if (t == &other) return true;
  }
  return false;
}

const NodeType& TypeRegistry::add(NodeType type, std::string_view base) {
  if (!base.empty()) {
    type.base = find(base);
    GDPN_ASSERT(type.base != nullptr, "a base type is registered before the types that derive from it");
  }
  GDPN_ASSERT(find(type.kind) == nullptr, "each node kind is registered once");
  for (std::size_t i = 0; i < type.own.size(); ++i) {
    GDPN_ASSERT(type.own[i].owner == type.kind && type.own[i].index == i,
                "a type declares its own fields in the order of their ids (fields.h)");
  }
  auto stored = std::make_unique<NodeType>(std::move(type));
  if (stored->base) stored->fields = stored->base->fields;
  for (const auto& f : stored->own) stored->fields.push_back(&f);
  stored->id = static_cast<std::uint32_t>(types_.size());
  const NodeType& ref = *stored;
  by_name_[ref.name] = &ref;
  by_kind_[static_cast<std::size_t>(ref.kind)] = &ref;
  types_.push_back(std::move(stored));
  return ref;
}

const NodeType* TypeRegistry::find(std::string_view name) const {
  auto it = by_name_.find(name);
  return it == by_name_.end() ? nullptr : it->second;
}

std::vector<const NodeType*> TypeRegistry::all() const {
  std::vector<const NodeType*> out;
  for (const auto& t : types_) out.push_back(t.get());
  return out;
}

const TypeRegistry& builtinTypes() {
  static const TypeRegistry registry = [] {
    TypeRegistry r;
    registerBuiltinNodes(r);
    return r;
  }();
  return registry;
}

}  // namespace gdpn::scene
