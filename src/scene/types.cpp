#include "gdpn/scene/types.h"

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
  if (x >= min && x <= max) return {};
  const bool low = min > -1e299, high = max < 1e299;
  std::string rule = low && high ? "must lie in [" + core::formatDouble(min) + ", " + core::formatDouble(max) + "]"
                     : low       ? "must be at least " + core::formatDouble(min)
                                 : "must be at most " + core::formatDouble(max);
  return "'" + name + "' " + rule + ", got " + core::formatDouble(x);
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
  auto stored = std::make_unique<NodeType>(std::move(type));
  if (stored->base) stored->fields = stored->base->fields;
  for (const auto& f : stored->own) stored->fields.push_back(&f);
  stored->id = static_cast<std::uint32_t>(types_.size());
  const NodeType& ref = *stored;
  by_name_[ref.name] = &ref;
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
