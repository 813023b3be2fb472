#pragma once
/// \file
/// Node types, each described once: its fields (name, kind, default, unit, range) and its base
/// type. Reading and writing the model file, the Python attributes and the IDE inspector all
/// come from this one description.

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "gdpn/scene/kind.h"

namespace gdpn::scene {

/// What a field holds.
enum class FieldKind : std::uint8_t {
  Bool,      ///< true or false
  Int,       ///< a whole number
  Float,     ///< a number
  Vec3,      ///< three numbers
  Color,     ///< three numbers in [0, 1]: red, green, blue
  Rotation,  ///< four numbers: an axis (x, y, z) and an angle in degrees
  Enum,      ///< one word out of a fixed list
  String,    ///< text
  File,      ///< a file path, relative to the model's folder
  FloatList, ///< a list of numbers
};

/// "bool", "int", ...
const char* fieldKindName(FieldKind kind);

/// The value of a field. Vec3 and Color use the 3-array; Rotation the 4-array; Enum, String
/// and File the string.
using FieldValue = std::variant<bool, std::int64_t, double, std::array<double, 3>, std::array<double, 4>, std::string,
                                std::vector<double>>;

/// Why a value does not fit a field.
struct FieldError {
  std::string message;  ///< "'bounce' must lie in [0, 1], got 1.5"
  int component = -1;   ///< which number of a vector or list is wrong (-1: the whole value)
};

/// The largest magnitude a number of the plant may have unless its field allows more (a
/// joint's "no limit"): the physics calls a body beyond it run away. A field bounded only by
/// it is shown as unbounded.
inline constexpr double kPlantLimit = 1e12;

/// One field of a node type.
struct FieldDesc {
  std::string name;                   ///< as written in files and seen from Python
  FieldKind kind = FieldKind::Float;  ///< what it holds
  FieldValue initial;                 ///< its default
  std::string unit;                   ///< "m", "kg", "deg", "m/s", "" when none
  /// The name of the node's Enum field whose word may change the unit ("kind" for a Joint's
  /// axis-1 fields, "" when the unit is always `unit`).
  std::string unit_follows;
  /// The words of `unit_follows` that give another unit than `unit`, each with its unit
  /// ({"slider", "m"} for a Joint's `lo1`).
  std::vector<std::pair<std::string, std::string>> units_by_choice;
  std::string doc;                    ///< one line for the inspector and docs
  std::vector<std::string> choices;   ///< the words an Enum accepts
  double min = -1e300;                ///< smallest accepted number (Int, Float, each component)
  bool min_open = false;              ///< `min` itself refused: numbers must lie above it (a length: > 0)
  double max = 1e300;                 ///< largest accepted number
  NodeKind owner = NodeKind::Group;   ///< the node kind that declares it
  std::uint8_t index = 0;             ///< its place among its owner's own fields (its id)

  /// Whether the field has a lower (upper) bound of its own, tighter than kPlantLimit.
  [[nodiscard]] bool boundedBelow() const { return min > -kPlantLimit; }
  [[nodiscard]] bool boundedAbove() const { return max < kPlantLimit; }  ///< see boundedBelow()
  /// "" when the number `x` is finite and in range, else why not ("'bounce' must lie in
  /// [0, 1], got 1.5"; "'radius' must be above 0, got 0").
  [[nodiscard]] std::string rangeError(double x) const;
  /// The range as the inspector and docs show it: "[0, 1]", "(0, inf)", "" when unbounded.
  [[nodiscard]] std::string rangeText() const;
  /// The unit in a node whose `unit_follows` field holds `choice` (`unit` for any other word).
  [[nodiscard]] const std::string& unitFor(std::string_view choice) const;
  /// Why `value` cannot be this field's value, or nullopt when it can: the alternative must
  /// match the kind, numbers must be finite and in range, an Enum's word one of its choices,
  /// a Rotation's axis not zero unless its angle is. The one check that the model loader,
  /// scripts assigning fields and the inspector share.
  [[nodiscard]] std::optional<FieldError> check(const FieldValue& value) const;
};

/// The FieldValue alternative that holds values of `kind` (its index in the variant).
std::size_t valueIndex(FieldKind kind);

/// What role a node type plays (for dispatch by actions and physics).
enum class Category : std::uint8_t { Group, Look, Shape, Dynamics, Sensor, Field };

/// A node type: its own fields, its base type's fields before them.
struct NodeType {
  NodeKind kind = NodeKind::Group;  ///< which type it is, for `switch`
  std::string name;                 ///< "Cube", "Body", ...
  const NodeType* base = nullptr;   ///< inherited fields come first
  Category category = Category::Group;
  bool has_children = false;        ///< may it hold child nodes?
  std::string doc;                  ///< one line
  std::vector<FieldDesc> own;       ///< fields this type adds
  std::vector<const FieldDesc*> fields;  ///< all fields, base first (filled on registration)
  std::uint32_t id = 0;             ///< index in its registry

  /// The index of field `name` in fields, or -1.
  [[nodiscard]] int fieldIndex(std::string_view name) const;
  /// True when this type is `other` or derives from it.
  [[nodiscard]] bool is(const NodeType& other) const;
};

/// All node types known to a scene. Types are added by explicit calls, never by static
/// initialisers.
class TypeRegistry {
 public:
  /// Adds a type; its base (if any) must be added already, its kind not. Its own fields must
  /// be declared in the order of their ids (fields.h). Returns the stored type.
  const NodeType& add(NodeType type, std::string_view base = {});
  /// The type called `name`, or null.
  [[nodiscard]] const NodeType* find(std::string_view name) const;
  /// The type of kind `kind`, or null when it is not registered.
  [[nodiscard]] const NodeType* find(NodeKind kind) const { return by_kind_[static_cast<std::size_t>(kind)]; }
  /// Every type, in the order added.
  [[nodiscard]] std::vector<const NodeType*> all() const;

 private:
  std::vector<std::unique_ptr<NodeType>> types_;
  std::map<std::string, const NodeType*, std::less<>> by_name_;
  std::array<const NodeType*, kNodeKinds> by_kind_{};
};

/// Registers the built-in types: Group, Transform, Material, Light, Camera, Fog, Cube,
/// Sphere, Cylinder, Cone, Plane, Mesh, Terrain, World, Body, Joint, Conveyor, GradientField,
/// Region, RangeFinder, TimeSensor, GradientSensor.
void registerBuiltinNodes(TypeRegistry& registry);

/// The registry with the built-in types, made once.
const TypeRegistry& builtinTypes();

}  // namespace gdpn::scene
