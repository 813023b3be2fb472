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
#include <variant>
#include <vector>

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

/// One field of a node type.
struct FieldDesc {
  std::string name;                   ///< as written in files and seen from Python
  FieldKind kind = FieldKind::Float;  ///< what it holds
  FieldValue initial;                 ///< its default
  std::string unit;                   ///< "m", "kg", "deg", "m/s", "" when none
  std::string doc;                    ///< one line for the inspector and docs
  std::vector<std::string> choices;   ///< the words an Enum accepts
  double min = -1e300;                ///< smallest accepted number (Int, Float, each component)
  double max = 1e300;                 ///< largest accepted number

  /// "" when `x` is in range, else why not ("'bounce' must lie in [0, 1], got 1.5").
  [[nodiscard]] std::string rangeError(double x) const;
};

/// What role a node type plays (for dispatch by actions and physics).
enum class Category : std::uint8_t { Group, Look, Shape, Dynamics, Sensor, Field };

/// A node type: its own fields, its base type's fields before them.
struct NodeType {
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
  /// Adds a type; its base (if any) must be added already. Returns the stored type.
  const NodeType& add(NodeType type, std::string_view base = {});
  /// The type called `name`, or null.
  [[nodiscard]] const NodeType* find(std::string_view name) const;
  /// Every type, in the order added.
  [[nodiscard]] std::vector<const NodeType*> all() const;

 private:
  std::vector<std::unique_ptr<NodeType>> types_;
  std::map<std::string, const NodeType*, std::less<>> by_name_;
};

/// Registers the built-in types: Group, Transform, Material, Light, Camera, Fog, Cube,
/// Sphere, Cylinder, Cone, Plane, Mesh, Terrain, World, Body, Joint, Conveyor, GradientField,
/// Region, RangeFinder, TimeSensor, GradientSensor.
void registerBuiltinNodes(TypeRegistry& registry);

/// The registry with the built-in types, made once.
const TypeRegistry& builtinTypes();

}  // namespace gdpn::scene
