#pragma once
/// \file
/// The scene tree: typed nodes with field values, owned by their parents, reachable by path
/// and by stable handles that notice when their node is gone.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "gdpn/core/diagnostics.h"
#include "gdpn/core/math.h"
#include "gdpn/scene/fields.h"
#include "gdpn/scene/types.h"
#include "gdpn/scene/user_data.h"

namespace gdpn::scene {

/// A stable reference to a node: slot index (low 32 bits) and generation (high 32 bits).
/// Handles of deleted nodes stop resolving. 0 is never a valid handle.
using NodeHandle = std::uint64_t;

class Scene;

/// One node of the tree.
class Node {
 public:
  /// Its type.
  [[nodiscard]] const NodeType& type() const { return *type_; }
  /// Its name ("" when unnamed); names are unique among siblings.
  [[nodiscard]] const std::string& name() const { return name_; }
  /// Its parent (null for the root).
  [[nodiscard]] Node* parent() const { return parent_; }
  /// Its children, in order.
  [[nodiscard]] const std::vector<std::unique_ptr<Node>>& children() const { return children_; }
  /// Its stable handle.
  [[nodiscard]] NodeHandle handle() const { return handle_; }
  /// Its path from the root: names joined by '/', "#i" for an unnamed node (its index among
  /// its siblings). The root's path is "".
  [[nodiscard]] std::string path() const;
  /// The child called `name` (or "#i"), or null. Constant time.
  [[nodiscard]] Node* child(std::string_view name) const;
  /// The node at `path` below this one ("a/b/#0"), or null. ".." goes up a level.
  [[nodiscard]] Node* find(std::string_view path) const;
  /// The sibling before or after this one, or null.
  [[nodiscard]] Node* prev() const;
  [[nodiscard]] Node* next() const;
  /// The nearest sibling before this one whose kind is exactly `kind`, or null. Logarithmic
  /// in the number of such siblings.
  [[nodiscard]] Node* previous(NodeKind kind) const;
  /// Its last child whose kind is exactly `kind`, or null. Constant time in the children.
  [[nodiscard]] Node* lastChild(NodeKind kind) const;
  /// This node's index among its siblings. Constant time.
  [[nodiscard]] std::size_t index() const;

  /// Its kind (its type's).
  [[nodiscard]] NodeKind kind() const { return type_->kind; }
  /// True when its type is `kind` or derives from it.
  [[nodiscard]] bool is(NodeKind kind) const;

  /// The value of field `i` (an index into type().fields).
  [[nodiscard]] const FieldValue& value(std::size_t i) const { return values_[i]; }
  /// Sets field `i`; the value's alternative must match the field's kind (asserted).
  void setValue(std::size_t i, FieldValue v);
  /// The index in type().fields of field `id`; the node must be of the kind that declares it
  /// (asserted: a field read from a node of another kind is a programming error).
  template <FieldId F>
  [[nodiscard]] std::size_t slot(F id) const {
    return slotOf(field::ownerOf(id), static_cast<std::size_t>(id));
  }
  /// The value of field `id`.
  template <FieldId F>
  [[nodiscard]] const FieldValue& value(F id) const { return values_[slot(id)]; }
  /// Sets field `id` (the value's alternative must match its kind).
  template <FieldId F>
  void setValue(F id, FieldValue v) { setValue(slot(id), std::move(v)); }
  /// Where field `id` was written (an empty location when it was left at its default).
  template <FieldId F>
  [[nodiscard]] const core::SourceLoc& fieldLoc(F id) const { return field_locs[slot(id)]; }
  /// A number field (Float or Int).
  template <FieldId F>
  [[nodiscard]] double number(F id) const { return numberAt(slot(id)); }
  /// A Vec3 or Color field.
  template <FieldId F>
  [[nodiscard]] core::Vec3 vec3(F id) const { return vec3At(slot(id)); }
  /// An Enum, String or File field.
  template <FieldId F>
  [[nodiscard]] const std::string& text(F id) const { return textAt(slot(id)); }
  /// A Bool field.
  template <FieldId F>
  [[nodiscard]] bool flag(F id) const { return flagAt(slot(id)); }
  /// An Enum field as the C++ enum `E` whose values list its words in order (fields.h).
  template <class E, FieldId F>
  [[nodiscard]] E choice(F id) const { return static_cast<E>(choiceAt(slot(id))); }
  /// True when every field has its default.
  [[nodiscard]] bool allDefault() const;

  /// This node's own placement: a Transform's translation and rotation, identity otherwise.
  [[nodiscard]] core::Pose localPose() const;
  /// A Transform's scale, (1, 1, 1) otherwise.
  [[nodiscard]] core::Vec3 localScale() const;
  /// The frame this node sets up for its children, placed in `frame` scaled by `scale`: its
  /// own translation (scaled) and rotation applied, unless the physics moves it (then `frame`).
  [[nodiscard]] core::Pose frameIn(const core::Pose& frame, const core::Vec3& scale) const;
  /// The world pose of the frame this node sets up for its children (m): a Transform's own
  /// translation and rotation included; `world` is the frame it is placed in. Up to date
  /// after updateTransforms.
  [[nodiscard]] core::Pose framePose() const { return frameIn(world, world_scale); }

  /// The user datum called `key`, or null.
  [[nodiscard]] const FieldValue* datum(std::string_view key) const;
  /// Sets the user datum `key` (added at the end when new).
  void setDatum(const std::string& key, FieldValue value);
  /// Removes the user datum `key`; false when there is none.
  bool eraseDatum(std::string_view key);

  /// Where the node was declared in the model file.
  core::SourceLoc loc;
  /// A template: the node and its subtree are kept in the scene to be copied (spawned) but are
  /// neither simulated, sensed nor drawn. A copy made by spawning is not a template.
  bool is_template = false;
  /// Its user data (datum(), setDatum()).
  UserData data;
  /// A field, or one number of a vector field, whose value a parameter gives (`speed:
  /// $belt_speed`) or an expression of parameters (`translation: [=length/2, 0, 0]`).
  struct Binding {
    std::uint32_t field = 0;      ///< the field's index
    std::int32_t component = -1;  ///< the number within a vector field (0: x); -1: the whole field
    std::string text;             ///< the parameter's name, or the expression as written ("=length/2")
    friend auto operator<=>(const Binding&, const Binding&) = default;
  };
  /// The fields parameters give, in field order. The value stays in the field; savers write
  /// the reference.
  std::vector<Binding> params;
  /// Where each field was written (empty loc for fields left at their default).
  std::vector<core::SourceLoc> field_locs;
  /// Set by the physics for a moving Body: its placement in the world, which then replaces
  /// the placement its parents give it.
  std::optional<core::Pose> dynamic_pose;
  /// World placement and accumulated scale, kept by updateTransforms().
  core::Pose world;
  core::Vec3 world_scale{1, 1, 1};

 private:
  friend class Scene;
  Node(const NodeType& type, std::string name);
  std::size_t slotOf(NodeKind owner, std::size_t index) const;
  double numberAt(std::size_t i) const;
  core::Vec3 vec3At(std::size_t i) const;
  const std::string& textAt(std::size_t i) const;
  bool flagAt(std::size_t i) const;
  std::size_t choiceAt(std::size_t i) const;
  const NodeType* type_;
  std::string name_;
  Node* parent_ = nullptr;
  std::vector<std::unique_ptr<Node>> children_;
  std::vector<FieldValue> values_;
  NodeHandle handle_ = 0;
  std::size_t index_ = 0;  // among the parent's children
  // the named children by name (the keys view the children's own names)
  std::unordered_map<std::string_view, Node*> by_name_;
  // the children of each kind present, in order (previous())
  std::vector<std::pair<NodeKind, std::vector<Node*>>> by_kind_;
  // per base name: no child is free among base_1 .. base_(k-1) (Scene::freshName)
  std::unordered_map<std::string, std::uint64_t> next_number_;
};

/// A tree of nodes with a root Group.
class Scene {
 public:
  /// An empty scene whose node types come from `types` (which must outlive it).
  explicit Scene(const TypeRegistry& types = builtinTypes());
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  /// The node types.
  [[nodiscard]] const TypeRegistry& types() const { return types_; }
  /// The root (a Group named "").
  [[nodiscard]] Node& root() const { return *root_; }
  /// Adds a new node of `type` named `name` as the last child of `parent`. Returns null when
  /// `parent` takes no children or already has a child of that name.
  Node* create(const NodeType& type, std::string name, Node& parent);
  /// "base_k" with the smallest k >= 1 that no child of `parent` is called; amortised
  /// constant time over a run of calls, each followed by the creation of that child.
  [[nodiscard]] std::string freshName(Node& parent, std::string_view base);
  /// Renames `node` (not the root) to `name`, keeping its place among its siblings. False when
  /// a sibling has that name already.
  bool rename(Node& node, std::string name);
  /// Removes `node` and its subtree (not the root); their handles stop resolving.
  void destroy(Node& node);
  /// Copies the subtree at `source` (from any scene with the same types) under `parent`,
  /// named `name` (source's own name when empty). Null on a name clash.
  Node* copy(const Node& source, Node& parent, std::string name = {});
  /// The node behind a handle, or null when it is gone.
  [[nodiscard]] Node* resolve(NodeHandle handle) const;
  /// The node at `path` from the root, or null.
  [[nodiscard]] Node* find(std::string_view path) const { return root_->find(path); }
  /// Number of nodes, the root included.
  [[nodiscard]] std::size_t size() const { return live_; }
  /// A deep copy of this scene (same types and tree; handles are the copy's own).
  [[nodiscard]] std::unique_ptr<Scene> clone() const;
  /// Same tree: types, names, values, in the same order (locations are not compared).
  [[nodiscard]] bool sameAs(const Scene& other) const;

 private:
  struct Slot {
    Node* node = nullptr;
    std::uint32_t generation = 0;
  };
  NodeHandle enroll(Node& node);
  void release(Node& node);

  const TypeRegistry& types_;
  std::unique_ptr<Node> root_;
  std::vector<Slot> slots_;
  std::vector<std::uint32_t> free_;
  std::size_t live_ = 0;
};

/// The unit a model writes angles in, in its file and in its scripts (`settings: angles`).
/// The scene stores degrees whatever the model writes.
enum class AngleUnit : std::uint8_t { Degrees, Radians };

/// The unit of field `i` of `n`: its description's, or the one its `unit_follows` field's word
/// gives (a slider's `lo1` is in m, a hinge's in deg).
[[nodiscard]] const std::string& unitOf(const Node& n, std::size_t i);
/// Whether field `i` of `n` is an angle (or an angular rate): a Rotation, or a field whose unit
/// in `n` (unitOf) is deg or deg/s.
[[nodiscard]] bool isAngular(const Node& n, std::size_t i);

/// Value `v` of field `i` of `n` converted between `unit` and the stored degrees: written to
/// stored when `to_stored`, else stored to written. Only angles change (a Rotation's angle,
/// not its axis); with AngleUnit::Degrees nothing does.
[[nodiscard]] FieldValue convertAngle(const Node& n, std::size_t i, FieldValue v, AngleUnit unit, bool to_stored);

/// Why field `i` of `n` refuses `v`, written in `unit` (converted to the stored unit, then
/// checked by the field's own rule, as a model file's value is), with a note when the angle
/// was given in radians; "" when it takes it.
[[nodiscard]] std::string refusal(const Node& n, std::size_t i, const FieldValue& v, AngleUnit unit);

}  // namespace gdpn::scene
