#include "scene_io.h"

#include <algorithm>
#include <cmath>


#include "gdpn/core/text.h"
#include "gdpn/model/param.h"

namespace gdpn::model::detail {
namespace {

using scene::FieldDesc;
using scene::FieldKind;
using scene::FieldValue;

class SceneReader {
 public:
  SceneReader(YamlReader& r, scene::Scene& s, scene::AngleUnit angles) : r_(r), scene_(s), angles_(angles) {}

  void readList(const YAML::Node& list, scene::Node& parent, const core::SourceLoc& at) {
    if (!list.IsSequence()) {
      r_.error(r_.loc(list, at), "a scene is a list of nodes, each written '- Type: {fields}', got " + describe(list));
      return;
    }
    for (const auto& item : list) readNode(item, parent, at);
  }

 private:
  void readNode(const YAML::Node& item, scene::Node& parent, const core::SourceLoc& at) {
    if (!item.IsMap() || item.size() != 1) {
      r_.error(r_.loc(item, at), "a scene node is written '- Type: {fields}' with one type, got " + describe(item));
      return;
    }
    const auto entries = r_.entries(item, "a scene node", {});
    if (entries.empty()) return;
    const Entry& e = entries[0];
    const scene::NodeType* type = scene_.types().find(e.key);
    if (!type) {
      std::vector<std::string> names;
      for (const auto* t : scene_.types().all()) names.push_back(t->name);
      r_.error(e.loc, "unknown node type '" + e.key + "'" + core::didYouMean(e.key, names));
      return;
    }
    // the name comes first: it decides whether the node can be made
    std::string name;
    if (e.value.IsMap()) {
      if (const YAML::Node n = e.value["name"]) {
        if (auto s = r_.string(n, "name")) {
          if (!core::isIdentifier(*s)) {
            r_.error(n, "node name '" + *s + "' is not an identifier (letters, digits and '_')");
          } else if (parent.child(*s)) {
            r_.error(n, "'" + parent.path() + (parent.path().empty() ? "" : "/") + *s + "' is defined twice");
            return;
          } else {
            name = *s;
          }
        }
      }
    } else if (!e.value.IsNull()) {
      r_.error(r_.loc(e.value, e.loc), "the fields of a " + e.key + " are a map, got " + describe(e.value));
      return;
    }
    if (!parent.type().has_children) return;  // reported with the parent's 'children'
    scene::Node* node = scene_.create(*type, name, parent);
    if (!node) return;
    node->loc = e.loc;
    if (!e.value.IsMap()) return;

    std::vector<std::string> keys = {"name", "children", "template", "data"};
    std::vector<std::pair<std::size_t, Entry>> read;  // fields read, in the file's order
    for (const auto* f : type->fields) keys.push_back(f->name);
    // a node placed by a field it does not have: Transforms place what is below them
    auto hint = [&](const std::string& key) -> std::string {
      if (key != "translation" && key != "rotation" && key != "scale" && key != "position") return {};
      return "; a " + e.key + " is placed by a Transform above it: `- Transform: {" +
             (key == "position" ? std::string("translation") : key) + ": [...], children: [{" + e.key + ": {...}}]}`";
    };
    for (const auto& field : r_.entries(e.value, "a " + e.key, keys, hint)) {
      if (field.key == "name") continue;
      if (field.key == "template") {
        bool b = false;
        const YAML::Node& n = field.value;
        if (n.IsScalar() && n.Tag() != "!" && YAML::convert<bool>::decode(n, b)) {
          node->is_template = b;
        } else {
          r_.error(r_.loc(n, field.loc), "'template' expects true or false, got " + describe(n));
        }
        continue;
      }
      if (field.key == "data") {
        readData(field, *node);
        continue;
      }
      if (field.key == "children") {
        if (!type->has_children) {
          r_.error(field.loc, "a " + e.key + " has no children");
        } else {
          readList(field.value, *node, field.loc);
        }
        continue;
      }
      const auto i = static_cast<std::size_t>(type->fieldIndex(field.key));  // a key entries() accepted
      if (auto v = parse(*type->fields[i], field)) {
        node->setValue(i, std::move(*v));
        node->field_locs[i] = r_.loc(field.value, field.loc);
        for (auto& [component, text] : bound_) {
          node->params.push_back({static_cast<std::uint32_t>(i), component, std::move(text)});
        }
        read.emplace_back(i, field);
      }
    }
    std::sort(node->params.begin(), node->params.end());
    // with every field read (a joint's kind decides whether its limits are angles), each value
    // in the stored units, then checked by the field's own rules (FieldDesc::check, shared
    // with scripts and the inspector); a value that fails goes back to its default. The words
    // come first: a kind the file misspelt is the default kind before a limit asks for it.
    std::stable_partition(read.begin(), read.end(),
                          [&](const auto& r) { return type->fields[r.first]->kind == FieldKind::Enum; });
    for (const auto& [i, field] : read) {
      node->setValue(i, scene::convertAngle(*node, i, node->value(i), angles_, true));
      if (auto bad = type->fields[i]->check(node->value(i))) {
        const YAML::Node& n = field.value;
        const bool part = bad->component >= 0 && n.IsSequence() && static_cast<std::size_t>(bad->component) < n.size();
        const bool radians = angles_ == scene::AngleUnit::Radians && scene::isAngular(*node, i);
        r_.error(part ? r_.loc(n[static_cast<std::size_t>(bad->component)], field.loc) : r_.loc(n, field.loc),
                 bad->message + (radians ? " (in degrees; the model writes angles in radians)" : ""));
        node->setValue(i, type->fields[i]->initial);
      }
    }
    check(*node);
  }

  /// A node's user data: a map of names to a bool, a number, text or a list of numbers.
  void readData(const Entry& data, scene::Node& node) {
    if (!data.value.IsMap()) {
      r_.error(r_.loc(data.value, data.loc), "'data' is a map of names to values ({kind: red, order: 17}), got " +
                                                 describe(data.value));
      return;
    }
    for (const auto& d : r_.entries(data.value, "'data'", {})) {
      const YAML::Node& n = d.value;
      if (!core::isIdentifier(d.key)) {
        r_.error(d.loc, "datum name '" + d.key + "' is not an identifier (letters, digits and '_')");
      } else if (n.IsScalar()) {
        // a quoted value is text whatever it says
        node.setDatum(d.key, n.Tag() == "!" ? FieldValue(n.Scalar()) : scene::datumFromText(n.Scalar()));
      } else if (n.IsSequence()) {
        std::vector<double> list;
        for (const auto& x : n) {
          auto v = r_.number(x, d.key);
          if (!v) return;
          if (!std::isfinite(*v)) {
            r_.error(x, "datum '" + d.key + "' holds finite numbers, got " + describe(x));
            return;
          }
          list.push_back(*v);
        }
        node.setDatum(d.key, std::move(list));
      } else {
        r_.error(r_.loc(n, d.loc), "datum '" + d.key + "' is a bool, a number, text or a list of numbers, got " +
                                       describe(n));
      }
    }
  }

  /// Checks that span fields: a GradientField's vectors must fill its grid.
  void check(const scene::Node& node) {
    if (node.kind() != scene::NodeKind::GradientField) return;
    using F = scene::field::GradientField;
    const auto nx = static_cast<std::size_t>(node.number(F::Nx)), ny = static_cast<std::size_t>(node.number(F::Ny));
    const auto& v = std::get<std::vector<double>>(node.value(F::Vectors));
    if (v.size() != 2 * nx * ny) {
      r_.error(node.fieldLoc(F::Vectors).line > 0 ? node.fieldLoc(F::Vectors) : node.loc,
               "a GradientField of " + std::to_string(nx) + " x " + std::to_string(ny) + " points needs " +
                   std::to_string(2 * nx * ny) + " numbers in 'vectors' (x, y per point), got " +
                   std::to_string(v.size()));
    }
  }

  template <std::size_t N>
  std::optional<std::array<double, N>> numbers(const YAML::Node& n, const FieldDesc& f, const char* what) {
    if (!n.IsSequence() || n.size() != N) {
      r_.error(n, "'" + f.name + "' expects " + what + ", got " + describe(n));
      return std::nullopt;
    }
    std::array<double, N> out{};
    for (std::size_t k = 0; k < N; ++k) {
      std::string bound;
      auto v = r_.number(n[k], f.name, &bound);
      if (!v) return std::nullopt;
      out[k] = *v;
      if (!bound.empty()) bound_.emplace_back(static_cast<std::int32_t>(k), std::move(bound));
    }
    return out;
  }

  /// The value as written, read as the field's kind (its syntax only).
  std::optional<FieldValue> parse(const FieldDesc& f, const Entry& e) {
    const YAML::Node& n = e.value;
    bound_.clear();
    std::string param;
    const auto whole = [&] {
      if (!param.empty()) bound_.emplace_back(-1, std::move(param));
    };
    switch (f.kind) {
      case FieldKind::Bool: {
        bool b = false;
        if (n.IsScalar() && n.Tag() != "!" && YAML::convert<bool>::decode(n, b)) return b;
        r_.error(r_.loc(n, e.loc), "'" + f.name + "' expects true or false, got " + describe(n));
        return std::nullopt;
      }
      case FieldKind::Int:
        if (auto v = r_.integer(n, f.name, &param)) return whole(), *v;
        return std::nullopt;
      case FieldKind::Float:
        if (auto v = r_.number(n, f.name, &param)) return whole(), *v;
        return std::nullopt;
      case FieldKind::Vec3:
      case FieldKind::Color:
        if (auto v = numbers<3>(n, f, f.kind == FieldKind::Color ? "a colour [r, g, b]" : "[x, y, z]")) return *v;
        return std::nullopt;
      case FieldKind::Rotation:
        if (auto v = numbers<4>(n, f, "[axis x, axis y, axis z, angle in degrees]")) return *v;
        return std::nullopt;
      case FieldKind::Enum:
      case FieldKind::String:
      case FieldKind::File:
        if (auto s = r_.string(n, f.name)) return *s;
        return std::nullopt;
      case FieldKind::FloatList: {
        if (!n.IsSequence()) {
          r_.error(r_.loc(n, e.loc), "'" + f.name + "' expects a list of numbers, got " + describe(n));
          return std::nullopt;
        }
        std::vector<double> out;
        for (const auto& x : n) {
          auto v = r_.number(x, f.name);
          if (!v) return std::nullopt;
          out.push_back(*v);
        }
        return out;
      }
    }
    return std::nullopt;
  }

  YamlReader& r_;
  scene::Scene& scene_;
  scene::AngleUnit angles_;
  // what the numbers of the field parse() read last refer to: (component or -1, reference)
  std::vector<std::pair<std::int32_t, std::string>> bound_;
};

void writeValue(YAML::Emitter& out, const FieldValue& v) {
  if (const auto* b = std::get_if<bool>(&v)) {
    out << *b;
  } else if (const auto* i = std::get_if<std::int64_t>(&v)) {
    out << *i;
  } else if (const auto* d = std::get_if<double>(&v)) {
    out << core::formatDouble(*d);
  } else if (const auto* a3 = std::get_if<std::array<double, 3>>(&v)) {
    out << YAML::Flow << YAML::BeginSeq;
    for (double x : *a3) out << core::formatDouble(x);
    out << YAML::EndSeq;
  } else if (const auto* a4 = std::get_if<std::array<double, 4>>(&v)) {
    out << YAML::Flow << YAML::BeginSeq;
    for (double x : *a4) out << core::formatDouble(x);
    out << YAML::EndSeq;
  } else if (const auto* list = std::get_if<std::vector<double>>(&v)) {
    out << YAML::Flow << YAML::BeginSeq;
    for (double x : *list) out << core::formatDouble(x);
    out << YAML::EndSeq;
  } else {
    out << std::get<std::string>(v);
  }
}

void writeNode(YAML::Emitter& out, const scene::Node& node, scene::AngleUnit angles) {
  const bool block = !node.children().empty();
  out << YAML::BeginMap << YAML::Key << node.type().name << YAML::Value << (block ? YAML::Block : YAML::Flow)
      << YAML::BeginMap;
  if (!node.name().empty()) out << YAML::Key << "name" << YAML::Value << node.name();
  if (node.is_template) out << YAML::Key << "template" << YAML::Value << true;
  auto bound = node.params.begin();  // the fields parameters give, in field order
  for (std::size_t i = 0; i < node.type().fields.size(); ++i) {
    const FieldDesc& f = *node.type().fields[i];
    while (bound != node.params.end() && bound->field < i) ++bound;
    if (bound != node.params.end() && bound->field == i && bound->component < 0) {
      out << YAML::Key << f.name << YAML::Value << referenceText(bound->text);
      continue;
    }
    if (bound != node.params.end() && bound->field == i) {
      // a vector some of whose numbers parameters give
      const FieldValue v = scene::convertAngle(node, i, node.value(i), angles, false);
      std::vector<double> numbers;
      if (const auto* a3 = std::get_if<std::array<double, 3>>(&v)) numbers.assign(a3->begin(), a3->end());
      if (const auto* a4 = std::get_if<std::array<double, 4>>(&v)) numbers.assign(a4->begin(), a4->end());
      out << YAML::Key << f.name << YAML::Value << YAML::Flow << YAML::BeginSeq;
      for (std::size_t k = 0; k < numbers.size(); ++k) {
        const auto b = std::find_if(bound, node.params.end(), [&](const scene::Node::Binding& x) {
          return x.field == i && x.component == static_cast<std::int32_t>(k);
        });
        if (b != node.params.end() && b->field == i) out << referenceText(b->text);
        else out << core::formatDouble(numbers[k]);
      }
      out << YAML::EndSeq;
      continue;
    }
    if (node.value(i) == f.initial) continue;
    out << YAML::Key << f.name << YAML::Value;
    writeValue(out, scene::convertAngle(node, i, node.value(i), angles, false));
  }
  if (!node.data.empty()) {
    out << YAML::Key << "data" << YAML::Value << YAML::Flow << YAML::BeginMap;
    // YAML reads these plain words as null: quoted, names and text stay what they are
    const auto null = [](const std::string& s) { return s == "~" || s == "null" || s == "Null" || s == "NULL"; };
    for (const auto& [key, value] : node.data) {
      out << YAML::Key;
      if (null(key)) out << YAML::DoubleQuoted;
      out << key << YAML::Value;
      const auto* text = std::get_if<std::string>(&value);
      // text that would read back as something else is quoted
      if (text && (scene::datumNeedsQuotes(*text) || null(*text))) out << YAML::DoubleQuoted << *text;
      else if (text) out << *text;
      else if (std::holds_alternative<double>(value)) out << scene::datumText(value);
      else writeValue(out, value);
    }
    out << YAML::EndMap;
  }
  if (block) {
    out << YAML::Key << "children" << YAML::Value << YAML::BeginSeq;
    for (const auto& c : node.children()) writeNode(out, *c, angles);
    out << YAML::EndSeq;
  }
  out << YAML::EndMap << YAML::EndMap;
}

}  // namespace

std::shared_ptr<scene::Scene> readScene(const YAML::Node& list, YamlReader& r, const core::SourceLoc& at,
                                        scene::AngleUnit angles) {
  auto s = std::make_shared<scene::Scene>();
  if (list.IsNull()) return s;
  SceneReader(r, *s, angles).readList(list, s->root(), at);
  return s;
}

void writeScene(YAML::Emitter& out, const scene::Scene& scene, scene::AngleUnit angles) {
  out << YAML::BeginSeq;
  for (const auto& c : scene.root().children()) writeNode(out, *c, angles);
  out << YAML::EndSeq;
}

}  // namespace gdpn::model::detail
