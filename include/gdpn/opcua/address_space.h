#pragma once
/// \file
/// A server's address space: nodes with their attributes and references, the standard nodes of
/// namespace 0 a client reads on connecting (the Server object, the reference, object, variable
/// and data types it browses), and what Read, Write, Browse and Call ask of a node.
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "gdpn/opcua/binary.h"

namespace gdpn::opcua {

/// A node's class (NodeClass, a bit each).
enum class NodeClass : std::uint32_t {
  Object = 1,
  Variable = 2,
  Method = 4,
  ObjectType = 8,
  VariableType = 16,
  ReferenceType = 32,
  DataType = 64,
  View = 128,
};

/// Attribute ids (Part 6, A.1).
enum class AttributeId : std::uint32_t {
  NodeId = 1,
  NodeClass = 2,
  BrowseName = 3,
  DisplayName = 4,
  Description = 5,
  WriteMask = 6,
  UserWriteMask = 7,
  IsAbstract = 8,
  Symmetric = 9,
  InverseName = 10,
  ContainsNoLoops = 11,
  EventNotifier = 12,
  Value = 13,
  DataType = 14,
  ValueRank = 15,
  ArrayDimensions = 16,
  AccessLevel = 17,
  UserAccessLevel = 18,
  MinimumSamplingInterval = 19,
  Historizing = 20,
  Executable = 21,
  UserExecutable = 22,
  DataTypeDefinition = 23,
  RolePermissions = 24,
  UserRolePermissions = 25,
  AccessRestrictions = 26,
  AccessLevelEx = 27,
};

/// Well-known NodeIds of namespace 0 (numeric).
namespace id {
inline constexpr std::uint32_t kRootFolder = 84, kObjectsFolder = 85, kTypesFolder = 86, kViewsFolder = 87;
inline constexpr std::uint32_t kReferences = 31, kNonHierarchical = 32, kHierarchical = 33, kHasChild = 34,
                               kOrganizes = 35, kHasEventSource = 36, kHasModellingRule = 37, kHasEncoding = 38,
                               kHasDescription = 39, kHasTypeDefinition = 40, kGeneratesEvent = 41, kAggregates = 44,
                               kHasSubtype = 45, kHasProperty = 46, kHasComponent = 47, kHasNotifier = 48,
                               kHasOrderedComponent = 49;
inline constexpr std::uint32_t kBaseObjectType = 58, kFolderType = 61, kBaseVariableType = 62,
                               kBaseDataVariableType = 63, kPropertyType = 68, kServerType = 2004,
                               kServerCapabilitiesType = 2013, kServerStatusType = 2138, kBuildInfoType = 3051,
                               kOperationLimitsType = 11564, kDataItemType = 2365, kAnalogItemType = 2368,
                               kBaseAnalogType = 15318;
inline constexpr std::uint32_t kBaseDataType = 24, kNumber = 26, kInteger = 27, kUInteger = 28, kStructure = 22,
                               kEnumeration = 29, kDuration = 290, kUtcTime = 294, kLocaleId = 295,
                               kArgument = 296, kBuildInfo = 338, kServerState = 852, kServerStatusDataType = 862,
                               kRange = 884, kEUInformation = 887;
inline constexpr std::uint32_t kServer = 2253, kServerArray = 2254, kNamespaceArray = 2255, kServerStatus = 2256,
                               kServerStatusState = 2259, kServerStatusCurrentTime = 2258;
inline constexpr std::uint32_t kModellingRuleMandatory = 78;
// binary encodings of the structures gdpn sends
inline constexpr std::uint32_t kArgumentEncoding = 298, kBuildInfoEncoding = 340,
                               kServerStatusEncoding = 864, kRangeEncoding = 886, kEUInformationEncoding = 889;
}  // namespace id

/// A reference from a node.
struct Reference {
  NodeId type;          ///< the reference type (HasComponent, Organizes...)
  NodeId target;        ///< the node it leads to
  bool forward = true;  ///< false: the inverse direction
};

/// What a method call learns of the server and may ask of it beyond its outputs.
struct CallContext {
  bool lockstep = false;        ///< in: the run takes steps only when a client asks for them
  std::uint32_t wait_steps = 0;  ///< out: answer only once the run has taken this many more steps
  /// out: fills the outputs when the answer goes (after `wait_steps` steps); null: they are ready now
  std::function<void(std::vector<Variant>& out)> complete;
};

/// One node and what a client may ask of it.
struct Node {
  NodeId id;                                  ///< its NodeId
  NodeClass node_class = NodeClass::Object;   ///< its class
  QualifiedName browse_name;                  ///< its BrowseName
  LocalizedText display_name;                 ///< its DisplayName
  LocalizedText description;                  ///< its Description ("": none)
  std::vector<Reference> references;          ///< both directions
  // Variables and VariableTypes
  NodeId data_type = NodeId::num(id::kBaseDataType);  ///< the value's DataType
  std::int32_t value_rank = -1;               ///< -1: scalar, 1: one-dimensional array
  /// The value now (null: the static `value`).
  std::function<Variant()> read;
  /// Writes a value already checked against the data type; a status (Good, or why not).
  /// Null: read-only (BadNotWritable).
  std::function<StatusCode(const Variant&)> write;
  Variant value;                              ///< the value when `read` is null
  double minimum_sampling = 0;                ///< ms; 0: as fast as it changes (a step)
  bool numeric = false;                       ///< a number that a deadband applies to
  // Types
  bool is_abstract = false;                   ///< IsAbstract of a type
  bool symmetric = false;                     ///< Symmetric of a reference type
  LocalizedText inverse_name;                 ///< InverseName of a reference type
  // Methods
  bool executable = false;                    ///< Executable (and UserExecutable)
  /// Calls the method: input arguments in, outputs out (or later, through `ctx`), and the
  /// status of each input in `in_results` (left empty when all are good); the call's status.
  std::function<StatusCode(const std::vector<Variant>& in, std::vector<Variant>& out,
                           std::vector<StatusCode>& in_results, CallContext& ctx)>
      call;
  // Objects
  std::uint8_t event_notifier = 0;            ///< EventNotifier

  /// The value now.
  [[nodiscard]] Variant valueNow() const { return read ? read() : value; }
};

/// The nodes of a server, by NodeId.
class AddressSpace {
 public:
  /// The standard nodes of namespace 0, with `namespaces` as the NamespaceArray (index 0 is
  /// OPC UA's own), the application's URI for ServerArray, and the ServerStatus' build info.
  AddressSpace(std::vector<std::string> namespaces, const std::string& application_uri,
               const std::string& product_name, const std::string& software_version);

  /// Adds `node` (its references in `references` are added as given, and their inverse to
  /// the targets already there). Returns it.
  Node& add(Node node);
  /// Adds a reference from `source` to `target` and its inverse.
  void link(const NodeId& source, std::uint32_t type, const NodeId& target);
  /// A variable under `parent` (HasComponent, or HasProperty with PropertyType when
  /// `property`), of `data_type`, BrowseName in namespace `ns`, of `type_definition` (0:
  /// BaseDataVariableType, or PropertyType for a property).
  Node& addVariable(const NodeId& parent, NodeId id, std::uint16_t ns, const std::string& name,
                    std::uint32_t data_type, bool property = false, std::uint32_t type_definition = 0);
  /// An object under `parent` (Organizes from a folder, else HasComponent) of `type_definition`.
  Node& addObject(const NodeId& parent, NodeId id, std::uint16_t ns, const std::string& name,
                  std::uint32_t type_definition = id::kFolderType);
  /// The node, or null.
  [[nodiscard]] const Node* find(const NodeId& id) const;
  /// The node, or null.
  Node* find(const NodeId& id);
  /// Whether reference type `type` is `super` or one of its subtypes.
  [[nodiscard]] bool isSubtype(const NodeId& type, const NodeId& super) const;
  /// The NamespaceArray.
  [[nodiscard]] const std::vector<std::string>& namespaces() const { return namespaces_; }
  /// The type definition of a node (its HasTypeDefinition's target), or the null NodeId.
  [[nodiscard]] NodeId typeDefinition(const Node& node) const;
  /// How many nodes.
  [[nodiscard]] std::size_t size() const { return nodes_.size(); }
  /// When the server started (ServerStatus.StartTime).
  [[nodiscard]] DateTime startTime() const { return start_time_; }

 private:
  void standardNodes(const std::string& application_uri, const std::string& product_name,
                     const std::string& software_version);
  std::map<NodeId, Node> nodes_;
  std::vector<std::string> namespaces_;
  DateTime start_time_ = 0;
};

/// Reads `attribute` of `node`: its value, or the status why not (BadAttributeIdInvalid for
/// one the node's class lacks).
DataValue readAttribute(const AddressSpace& space, const Node& node, std::uint32_t attribute);

/// The built-in type a DataType NodeId of namespace 0 stands for (Null for a structure or an
/// abstract type).
BuiltinType builtinOf(const NodeId& data_type);

}  // namespace gdpn::opcua
