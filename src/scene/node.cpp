#include "gdpn/scene/node.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "gdpn/core/assert.h"
#include "gdpn/core/math.h"
#include "gdpn/scene/sensor_rules.h"

namespace gdpn::scene {
namespace {

template <class T>
const T& as(const FieldValue& v) {
  GDPN_ASSERT(std::holds_alternative<T>(v), "field read as the kind it is declared with");
  return std::get<T>(v);
}

}  // namespace

Node::Node(const NodeType& type, std::string name) : type_(&type), name_(std::move(name)) {
  values_.reserve(type.fields.size());
  for (const auto* f : type.fields) values_.push_back(f->initial);
  field_locs.resize(type.fields.size());
}

std::size_t Node::index() const { return parent_ ? index_ : 0; }

const FieldValue* Node::datum(std::string_view key) const {
  for (const auto& [k, v] : data) {
    if (k == key) return &v;
  }
  return nullptr;
}

void Node::setDatum(const std::string& key, FieldValue value) {
  for (auto& [k, v] : data) {
    if (k == key) {
      v = std::move(value);
      return;
    }
  }
  data.emplace_back(key, std::move(value));
}

bool Node::eraseDatum(std::string_view key) {
  const auto it = std::find_if(data.begin(), data.end(), [&](const auto& kv) { return kv.first == key; });
  if (it == data.end()) return false;
  data.erase(it);
  return true;
}

std::string Node::path() const {
  if (!parent_) return {};
  const std::string segment = name_.empty() ? "#" + std::to_string(index()) : name_;
  const std::string up = parent_->path();
  return up.empty() ? segment : up + "/" + segment;
}

Node* Node::child(std::string_view name) const {
  if (!name.empty() && name[0] == '#') {
    std::size_t i = 0;
    for (char c : name.substr(1)) {
      if (c < '0' || c > '9') return nullptr;
      i = i * 10 + static_cast<std::size_t>(c - '0');
      if (i > children_.size()) return nullptr;
    }
    return i < children_.size() && name.size() > 1 ? children_[i].get() : nullptr;
  }
  const auto it = by_name_.find(name);
  return it == by_name_.end() ? nullptr : it->second;
}

Node* Node::find(std::string_view path) const {
  Node* at = const_cast<Node*>(this);
  while (at && !path.empty()) {
    const auto slash = path.find('/');
    const std::string_view segment = path.substr(0, slash);
    at = segment == ".." ? at->parent_ : segment.empty() ? at : at->child(segment);
    path = slash == std::string_view::npos ? std::string_view() : path.substr(slash + 1);
  }
  return at;
}

Node* Node::prev() const {
  if (!parent_) return nullptr;
  const auto i = index();
  return i > 0 ? parent_->children_[i - 1].get() : nullptr;
}

Node* Node::next() const {
  if (!parent_) return nullptr;
  const auto i = index();
  return i + 1 < parent_->children_.size() ? parent_->children_[i + 1].get() : nullptr;
}

Node* Node::previous(NodeKind kind) const {
  if (!parent_) return nullptr;
  for (const auto& [k, nodes] : parent_->by_kind_) {
    if (k != kind) continue;
    // the last of that kind with a smaller index
    auto it = std::lower_bound(nodes.begin(), nodes.end(), index_, [](const Node* n, std::size_t i) { return n->index_ < i; });
    return it == nodes.begin() ? nullptr : *std::prev(it);
  }
  return nullptr;
}

Node* Node::lastChild(NodeKind kind) const {
  for (const auto& [k, nodes] : by_kind_) {
    if (k == kind) return nodes.empty() ? nullptr : nodes.back();
  }
  return nullptr;
}

bool Node::is(NodeKind kind) const {
  for (const NodeType* t = type_; t; t = t->base) {
    if (t->kind == kind) return true;
  }
  return false;
}

void Node::setValue(std::size_t i, FieldValue v) {
  GDPN_ASSERT(i < values_.size() && v.index() == valueIndex(type_->fields[i]->kind),
              "a field is set to a value of its own kind");
  values_[i] = std::move(v);
}

std::size_t Node::slotOf(NodeKind owner, std::size_t index) const {
  // the owner's own fields follow those of its bases
  for (const NodeType* t = type_; t; t = t->base) {
    if (t->kind != owner) continue;
    GDPN_ASSERT(index < t->own.size(), "a field id is one of its kind's fields");
    return (t->base ? t->base->fields.size() : 0) + index;
  }
  GDPN_ASSERT(false, "a field is read from a node of the kind that declares it");
  return 0;
}

double Node::numberAt(std::size_t i) const {
  const auto& v = values_[i];
  if (std::holds_alternative<std::int64_t>(v)) return static_cast<double>(std::get<std::int64_t>(v));
  return as<double>(v);
}

core::Vec3 Node::vec3At(std::size_t i) const {
  const auto& a = as<std::array<double, 3>>(values_[i]);
  return {a[0], a[1], a[2]};
}

const std::string& Node::textAt(std::size_t i) const { return as<std::string>(values_[i]); }

bool Node::flagAt(std::size_t i) const { return as<bool>(values_[i]); }

std::size_t Node::choiceAt(std::size_t i) const {
  const auto& choices = type_->fields[i]->choices;
  const auto it = std::find(choices.begin(), choices.end(), as<std::string>(values_[i]));
  GDPN_ASSERT(it != choices.end(), "an Enum field holds one of its words");
  return static_cast<std::size_t>(it - choices.begin());
}

bool Node::allDefault() const {
  for (std::size_t i = 0; i < values_.size(); ++i) {
    if (!(values_[i] == type_->fields[i]->initial)) return false;
  }
  return true;
}

core::Pose Node::localPose() const {
  if (!is(NodeKind::Transform)) return {};
  const auto& tr = as<std::array<double, 3>>(value(field::Transform::Translation));
  const auto& rot = as<std::array<double, 4>>(value(field::Transform::Rotation));
  core::Pose p;
  p.position = {tr[0], tr[1], tr[2]};
  const core::Vec3 axis{rot[0], rot[1], rot[2]};
  if (axis.length() > 0 && rot[3] != 0) p.rotation = core::Quat::axisAngle(axis, core::radians(rot[3]));
  return p;
}

core::Pose Node::frameIn(const core::Pose& frame, const core::Vec3& scale) const {
  if (dynamic_pose) return frame;
  core::Pose local = localPose();
  local.position = local.position.times(scale);
  return frame * local;
}

core::Vec3 Node::localScale() const {
  if (!is(NodeKind::Transform)) return {1, 1, 1};
  return vec3(field::Transform::Scale);
}

Scene::Scene(const TypeRegistry& types) : types_(types) {
  const NodeType* group = types_.find(NodeKind::Group);
  GDPN_ASSERT(group != nullptr, "a scene's registry has the Group type");
  root_.reset(new Node(*group, ""));
  enroll(*root_);
}

NodeHandle Scene::enroll(Node& node) {
  std::uint32_t index = 0;
  if (!free_.empty()) {
    index = free_.back();
    free_.pop_back();
  } else {
    index = static_cast<std::uint32_t>(slots_.size());
    slots_.push_back({nullptr, 1});
  }
  slots_[index].node = &node;
  node.handle_ = (NodeHandle{slots_[index].generation} << 32) | index;
  ++live_;
  return node.handle_;
}

void Scene::release(Node& node) {
  for (auto& c : node.children_) release(*c);
  const auto index = static_cast<std::uint32_t>(node.handle_);
  slots_[index].node = nullptr;
  ++slots_[index].generation;
  free_.push_back(index);
  --live_;
}

Node* Scene::create(const NodeType& type, std::string name, Node& parent) {
  if (!parent.type_->has_children) return nullptr;
  if (!name.empty() && parent.child(name)) return nullptr;
  std::unique_ptr<Node> node(new Node(type, std::move(name)));
  node->parent_ = &parent;
  node->index_ = parent.children_.size();
  enroll(*node);
  if (!node->name_.empty()) parent.by_name_.emplace(node->name_, node.get());
  auto kind = std::find_if(parent.by_kind_.begin(), parent.by_kind_.end(), [&](const auto& k) { return k.first == type.kind; });
  if (kind == parent.by_kind_.end()) kind = parent.by_kind_.insert(kind, {type.kind, {}});
  kind->second.push_back(node.get());
  parent.children_.push_back(std::move(node));
  return parent.children_.back().get();
}

std::string Scene::freshName(Node& parent, std::string_view base) {
  const auto hint = parent.next_number_.try_emplace(std::string(base), 1).first;
  std::string name;
  for (;; ++hint->second) {
    name.assign(base);
    name += '_';
    name += std::to_string(hint->second);
    if (!parent.child(name)) return name;
  }
}

bool Scene::rename(Node& node, std::string name) {
  Node* parent = node.parent_;
  if (parent == nullptr) return false;
  if (name == node.name_) return true;
  if (!name.empty() && parent->child(name)) return false;
  if (!node.name_.empty()) parent->by_name_.erase(node.name_);
  node.name_ = std::move(name);
  if (!node.name_.empty()) parent->by_name_.emplace(node.name_, &node);
  return true;
}

void Scene::destroy(Node& node) {
  GDPN_ASSERT(node.parent_ != nullptr, "the root is not destroyed");
  release(node);
  Node& parent = *node.parent_;
  // a freed "base_k" lowers base's next number to k
  const auto us = node.name_.rfind('_');
  if (us != std::string::npos && us + 1 < node.name_.size()) {
    if (auto hint = parent.next_number_.find(node.name_.substr(0, us)); hint != parent.next_number_.end()) {
      std::uint64_t k = 0;
      const char* last = node.name_.data() + node.name_.size();
      const auto [end, error] = std::from_chars(node.name_.data() + us + 1, last, k);
      if (error == std::errc() && end == last && k >= 1) hint->second = std::min(hint->second, k);
    }
  }
  if (!node.name_.empty()) parent.by_name_.erase(node.name_);
  for (auto& [kind, nodes] : parent.by_kind_) {
    if (kind == node.kind()) nodes.erase(std::find(nodes.begin(), nodes.end(), &node));
  }
  auto& sib = parent.children_;
  const std::size_t at = node.index_;
  GDPN_ASSERT(at < sib.size() && sib[at].get() == &node, "a node knows its index among its siblings");
  sib.erase(sib.begin() + static_cast<std::ptrdiff_t>(at));
  for (std::size_t i = at; i < sib.size(); ++i) sib[i]->index_ = i;
}

Node* Scene::copy(const Node& source, Node& parent, std::string name) {
  Node* made = create(source.type(), name.empty() ? source.name_ : std::move(name), parent);
  if (!made) return nullptr;
  made->values_ = source.values_;
  made->field_locs = source.field_locs;
  made->loc = source.loc;
  made->is_template = source.is_template;
  made->data = source.data;
  made->params = source.params;
  for (const auto& c : source.children_) copy(*c, *made);
  return made;
}

Node* Scene::resolve(NodeHandle handle) const {
  const auto index = static_cast<std::uint32_t>(handle);
  const auto generation = static_cast<std::uint32_t>(handle >> 32);
  if (index >= slots_.size() || slots_[index].generation != generation) return nullptr;
  return slots_[index].node;
}

std::unique_ptr<Scene> Scene::clone() const {
  auto out = std::make_unique<Scene>(types_);
  for (const auto& c : root_->children_) out->copy(*c, out->root());
  return out;
}

namespace {

bool sameTree(const Node& a, const Node& b) {
  if (&a.type() != &b.type() || a.name() != b.name() || a.children().size() != b.children().size() ||
      a.is_template != b.is_template || a.data != b.data || a.params != b.params) {
    return false;
  }
  for (std::size_t i = 0; i < a.type().fields.size(); ++i) {
    if (!(a.value(i) == b.value(i))) return false;
  }
  for (std::size_t i = 0; i < a.children().size(); ++i) {
    if (!sameTree(*a.children()[i], *b.children()[i])) return false;
  }
  return true;
}

}  // namespace

bool Scene::sameAs(const Scene& other) const { return sameTree(*root_, *other.root_); }

const std::string& unitOf(const Node& n, std::size_t i) {
  const FieldDesc& f = *n.type().fields[i];
  if (f.unit_follows.empty()) return f.unit;
  const int by = n.type().fieldIndex(f.unit_follows);
  GDPN_ASSERT(by >= 0, "a unit follows a field of the same type");
  const auto& word = n.value(static_cast<std::size_t>(by));
  return std::holds_alternative<std::string>(word) ? f.unitFor(std::get<std::string>(word)) : f.unit;
}

bool isAngular(const Node& n, std::size_t i) {
  const FieldDesc& f = *n.type().fields[i];
  if (f.kind == FieldKind::Rotation) return true;
  if (f.kind != FieldKind::Float) return false;
  const auto& unit = unitOf(n, i);
  return unit == "deg" || unit == "deg/s";
}

namespace {

/// Radians to write for the stored `degrees`: the shortest decimal that converts back to
/// exactly those degrees, so that 0.1 rad written is 0.1 read and saved (not
/// 0.10000000000000002), and a file's radians read and saved read back to the same degrees.
double radiansOf(double degrees) {
  const double x = core::radians(degrees);
  for (int digits = 1; digits <= 17; ++digits) {
    char text[40];
    std::snprintf(text, sizeof text, "%.*g", digits, x);
    const double y = std::strtod(text, nullptr);
    if (core::degrees(y) == degrees) return y;
  }
  // no short decimal: the nearest double that does (degrees read from radians always have one)
  double below = x, above = x;
  for (int step = 0; step < 8; ++step) {
    below = std::nextafter(below, -INFINITY);
    above = std::nextafter(above, INFINITY);
    if (core::degrees(below) == degrees) return below;
    if (core::degrees(above) == degrees) return above;
  }
  return x;
}

}  // namespace

FieldValue convertAngle(const Node& n, std::size_t i, FieldValue v, AngleUnit unit, bool to_stored) {
  if (unit == AngleUnit::Degrees || !isAngular(n, i)) return v;
  auto convert = [to_stored](double& x) { x = to_stored ? core::degrees(x) : radiansOf(x); };
  if (auto* x = std::get_if<double>(&v)) convert(*x);
  if (auto* r = std::get_if<std::array<double, 4>>(&v)) convert((*r)[3]);
  return v;
}

std::string refusal(const Node& n, std::size_t i, const FieldValue& v, AngleUnit unit) {
  const FieldValue converted = convertAngle(n, i, v, unit, true);
  const auto bad = n.type().fields[i]->check(converted);
  if (!bad) return sensorRule(n, i, converted).message;  // a rule between the node's fields
  const bool radians = unit == AngleUnit::Radians && isAngular(n, i);
  return bad->message + (radians ? " (in degrees; the model writes angles in radians)" : "");
}

}  // namespace gdpn::scene
