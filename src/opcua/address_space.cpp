// The address space: nodes and references, the standard nodes of namespace 0, and Read's
// attributes.

#include "gdpn/opcua/address_space.h"

#include "gdpn/opcua/status.h"

namespace gdpn::opcua {

namespace {

NodeId ns0(std::uint32_t n) { return NodeId::num(n); }

Node typeNode(std::uint32_t n, NodeClass cls, const char* name, bool is_abstract = false) {
  Node node;
  node.id = ns0(n);
  node.node_class = cls;
  node.browse_name = {0, name};
  node.display_name = {"", name};
  node.is_abstract = is_abstract;
  return node;
}

}  // namespace

AddressSpace::AddressSpace(std::vector<std::string> namespaces, const std::string& application_uri,
                           const std::string& product_name, const std::string& software_version)
    : namespaces_(std::move(namespaces)), start_time_(dateTimeNow()) {
  standardNodes(application_uri, product_name, software_version);
}

Node& AddressSpace::add(Node node) {
  const NodeId id = node.id;
  for (const auto& r : node.references) {
    if (auto* target = find(r.target)) target->references.push_back({r.type, id, !r.forward});
  }
  auto [it, fresh] = nodes_.insert_or_assign(id, std::move(node));
  (void)fresh;
  return it->second;
}

void AddressSpace::link(const NodeId& source, std::uint32_t type, const NodeId& target) {
  if (auto* s = find(source)) s->references.push_back({ns0(type), target, true});
  if (auto* t = find(target)) t->references.push_back({ns0(type), source, false});
}

Node& AddressSpace::addVariable(const NodeId& parent, NodeId nid, std::uint16_t ns, const std::string& name,
                                std::uint32_t data_type, bool property, std::uint32_t type_definition) {
  Node v;
  v.id = nid;
  v.node_class = NodeClass::Variable;
  v.browse_name = {ns, name};
  v.display_name = {"", name};
  v.data_type = ns0(data_type);
  v.references.push_back({ns0(id::kHasTypeDefinition), ns0(type_definition != 0 ? type_definition : property ? id::kPropertyType : id::kBaseDataVariableType), true});
  v.references.push_back({ns0(property ? id::kHasProperty : id::kHasComponent), parent, false});
  return add(std::move(v));
}

Node& AddressSpace::addObject(const NodeId& parent, NodeId nid, std::uint16_t ns, const std::string& name,
                              std::uint32_t type_definition) {
  Node o;
  o.id = nid;
  o.node_class = NodeClass::Object;
  o.browse_name = {ns, name};
  o.display_name = {"", name};
  o.references.push_back({ns0(id::kHasTypeDefinition), ns0(type_definition), true});
  const Node* p = find(parent);
  const bool folder = p && typeDefinition(*p) == ns0(id::kFolderType);
  o.references.push_back({ns0(folder ? id::kOrganizes : id::kHasComponent), parent, false});
  return add(std::move(o));
}

const Node* AddressSpace::find(const NodeId& nid) const {
  const auto it = nodes_.find(nid);
  return it == nodes_.end() ? nullptr : &it->second;
}

Node* AddressSpace::find(const NodeId& nid) {
  const auto it = nodes_.find(nid);
  return it == nodes_.end() ? nullptr : &it->second;
}

bool AddressSpace::isSubtype(const NodeId& type, const NodeId& super) const {
  NodeId at = type;
  for (int depth = 0; depth < 16; ++depth) {
    if (at == super) return true;
    const Node* n = find(at);
    if (!n) return false;
    const Reference* up = nullptr;
    for (const auto& r : n->references) {
      if (!r.forward && r.type == ns0(id::kHasSubtype)) up = &r;
    }
    if (!up) return false;
    at = up->target;
  }
  return false;
}

NodeId AddressSpace::typeDefinition(const Node& node) const {
  for (const auto& r : node.references) {
    if (r.forward && r.type == ns0(id::kHasTypeDefinition)) return r.target;
  }
  return {};
}

void AddressSpace::standardNodes(const std::string& application_uri, const std::string& product_name,
                                 const std::string& software_version) {
  // types first, each under its supertype, so that every later reference finds its target
  auto type = [this](std::uint32_t n, NodeClass cls, const char* name, std::uint32_t super, bool is_abstract = false) {
    Node t = typeNode(n, cls, name, is_abstract);
    if (super != 0) t.references.push_back({ns0(id::kHasSubtype), ns0(super), false});
    return &add(std::move(t));
  };
  using C = NodeClass;
  // reference types
  auto ref = [&](std::uint32_t n, const char* name, std::uint32_t super, const char* inverse, bool is_abstract = false,
                 bool symmetric = false) {
    Node* r = type(n, C::ReferenceType, name, super, is_abstract);
    r->symmetric = symmetric;
    if (inverse) r->inverse_name = {"", inverse};
  };
  ref(id::kReferences, "References", 0, nullptr, true, true);
  ref(id::kHierarchical, "HierarchicalReferences", id::kReferences, "InverseHierarchicalReferences", true);
  ref(id::kNonHierarchical, "NonHierarchicalReferences", id::kReferences, "InverseNonHierarchicalReferences", true);
  ref(id::kHasChild, "HasChild", id::kHierarchical, "ChildOf", true);
  ref(id::kOrganizes, "Organizes", id::kHierarchical, "OrganizedBy");
  ref(id::kHasEventSource, "HasEventSource", id::kHierarchical, "EventSourceOf");
  ref(id::kHasNotifier, "HasNotifier", id::kHasEventSource, "NotifierOf");
  ref(id::kAggregates, "Aggregates", id::kHasChild, "AggregatedBy", true);
  ref(id::kHasSubtype, "HasSubtype", id::kHasChild, "SubtypeOf");
  ref(id::kHasProperty, "HasProperty", id::kAggregates, "PropertyOf");
  ref(id::kHasComponent, "HasComponent", id::kAggregates, "ComponentOf");
  ref(id::kHasOrderedComponent, "HasOrderedComponent", id::kHasComponent, "OrderedComponentOf");
  ref(id::kHasTypeDefinition, "HasTypeDefinition", id::kNonHierarchical, "TypeDefinitionOf");
  ref(id::kHasModellingRule, "HasModellingRule", id::kNonHierarchical, "ModellingRuleOf");
  ref(id::kHasEncoding, "HasEncoding", id::kNonHierarchical, "EncodingOf");
  ref(id::kHasDescription, "HasDescription", id::kNonHierarchical, "DescriptionOf");
  ref(id::kGeneratesEvent, "GeneratesEvent", id::kNonHierarchical, "GeneratedBy");
  // data types
  type(id::kBaseDataType, C::DataType, "BaseDataType", 0, true);
  type(id::kNumber, C::DataType, "Number", id::kBaseDataType, true);
  type(id::kInteger, C::DataType, "Integer", id::kNumber, true);
  type(id::kUInteger, C::DataType, "UInteger", id::kNumber, true);
  type(id::kStructure, C::DataType, "Structure", id::kBaseDataType, true);
  type(id::kEnumeration, C::DataType, "Enumeration", id::kBaseDataType, true);
  type(1, C::DataType, "Boolean", id::kBaseDataType);
  type(2, C::DataType, "SByte", id::kInteger);
  type(3, C::DataType, "Byte", id::kUInteger);
  type(4, C::DataType, "Int16", id::kInteger);
  type(5, C::DataType, "UInt16", id::kUInteger);
  type(6, C::DataType, "Int32", id::kInteger);
  type(7, C::DataType, "UInt32", id::kUInteger);
  type(8, C::DataType, "Int64", id::kInteger);
  type(9, C::DataType, "UInt64", id::kUInteger);
  type(10, C::DataType, "Float", id::kNumber);
  type(11, C::DataType, "Double", id::kNumber);
  type(12, C::DataType, "String", id::kBaseDataType);
  type(13, C::DataType, "DateTime", id::kBaseDataType);
  type(14, C::DataType, "Guid", id::kBaseDataType);
  type(15, C::DataType, "ByteString", id::kBaseDataType);
  type(17, C::DataType, "NodeId", id::kBaseDataType);
  type(19, C::DataType, "StatusCode", id::kBaseDataType);
  type(20, C::DataType, "QualifiedName", id::kBaseDataType);
  type(21, C::DataType, "LocalizedText", id::kBaseDataType);
  type(id::kDuration, C::DataType, "Duration", 11);
  type(id::kUtcTime, C::DataType, "UtcTime", 13);
  type(id::kLocaleId, C::DataType, "LocaleId", 12);
  type(id::kArgument, C::DataType, "Argument", id::kStructure);
  type(id::kBuildInfo, C::DataType, "BuildInfo", id::kStructure);
  type(id::kServerStatusDataType, C::DataType, "ServerStatusDataType", id::kStructure);
  type(id::kRange, C::DataType, "Range", id::kStructure);
  type(id::kEUInformation, C::DataType, "EUInformation", id::kStructure);
  type(id::kServerState, C::DataType, "ServerState", id::kEnumeration);
  // object and variable types
  type(id::kBaseObjectType, C::ObjectType, "BaseObjectType", 0);
  type(id::kFolderType, C::ObjectType, "FolderType", id::kBaseObjectType);
  type(id::kServerType, C::ObjectType, "ServerType", id::kBaseObjectType);
  type(id::kServerCapabilitiesType, C::ObjectType, "ServerCapabilitiesType", id::kBaseObjectType);
  type(id::kOperationLimitsType, C::ObjectType, "OperationLimitsType", id::kFolderType);
  type(id::kBaseVariableType, C::VariableType, "BaseVariableType", 0, true);
  type(id::kBaseDataVariableType, C::VariableType, "BaseDataVariableType", id::kBaseVariableType);
  type(id::kPropertyType, C::VariableType, "PropertyType", id::kBaseVariableType);
  type(id::kServerStatusType, C::VariableType, "ServerStatusType", id::kBaseDataVariableType);
  type(id::kBuildInfoType, C::VariableType, "BuildInfoType", id::kBaseDataVariableType);
  type(id::kDataItemType, C::VariableType, "DataItemType", id::kBaseDataVariableType);
  type(id::kBaseAnalogType, C::VariableType, "BaseAnalogType", id::kDataItemType);
  type(id::kAnalogItemType, C::VariableType, "AnalogItemType", id::kBaseAnalogType);

  // the folders
  auto folder = [this](std::uint32_t n, const char* name) {
    Node f = typeNode(n, NodeClass::Object, name);
    f.references.push_back({ns0(id::kHasTypeDefinition), ns0(id::kFolderType), true});
    return &add(std::move(f));
  };
  folder(id::kRootFolder, "Root");
  folder(id::kObjectsFolder, "Objects");
  folder(id::kTypesFolder, "Types");
  folder(id::kViewsFolder, "Views");
  folder(88, "ObjectTypes");
  folder(89, "VariableTypes");
  folder(90, "DataTypes");
  folder(91, "ReferenceTypes");
  link(ns0(id::kRootFolder), id::kOrganizes, ns0(id::kObjectsFolder));
  link(ns0(id::kRootFolder), id::kOrganizes, ns0(id::kTypesFolder));
  link(ns0(id::kRootFolder), id::kOrganizes, ns0(id::kViewsFolder));
  for (const std::uint32_t f : {88u, 89u, 90u, 91u}) link(ns0(id::kTypesFolder), id::kOrganizes, ns0(f));
  link(ns0(88), id::kOrganizes, ns0(id::kBaseObjectType));
  link(ns0(89), id::kOrganizes, ns0(id::kBaseVariableType));
  link(ns0(90), id::kOrganizes, ns0(id::kBaseDataType));
  link(ns0(91), id::kOrganizes, ns0(id::kReferences));

  // the Server object
  {
    Node server = typeNode(id::kServer, NodeClass::Object, "Server");
    server.references.push_back({ns0(id::kHasTypeDefinition), ns0(id::kServerType), true});
    add(std::move(server));
    link(ns0(id::kObjectsFolder), id::kOrganizes, ns0(id::kServer));
  }
  const NodeId server = ns0(id::kServer);
  addVariable(server, ns0(id::kServerArray), 0, "ServerArray", 12, true).value = Variant::strings({application_uri});
  find(ns0(id::kServerArray))->value_rank = 1;
  addVariable(server, ns0(id::kNamespaceArray), 0, "NamespaceArray", 12, true).value = Variant::strings(namespaces_);
  find(ns0(id::kNamespaceArray))->value_rank = 1;
  addVariable(server, ns0(2267), 0, "ServiceLevel", 3, true).value = Variant::of(BuiltinType::Byte, std::uint64_t{255});
  addVariable(server, ns0(2994), 0, "Auditing", 1, true).value = Variant::boolean(false);

  // ServerStatus and its parts
  const DateTime start = start_time_;
  auto build_info = [=](Encoder& e) {
    e.string("https://gdpn.dev/" + product_name);
    e.string("gdpn");
    e.string(product_name);
    e.string(software_version);
    e.string(software_version);
    e.i64(start);
  };
  Node& status_node =
      addVariable(server, ns0(id::kServerStatus), 0, "ServerStatus", id::kServerStatusDataType, false, id::kServerStatusType);
  status_node.read = [=] {
    ExtensionObject x{ns0(id::kServerStatusEncoding), 1, {}};
    Encoder e(x.body);
    e.i64(start);
    e.i64(dateTimeNow());
    e.i32(0);  // Running
    build_info(e);
    e.u32(0);
    e.localizedText({});
    return Variant::of(BuiltinType::ExtensionObject, x);
  };
  const NodeId ss = ns0(id::kServerStatus);
  addVariable(ss, ns0(2257), 0, "StartTime", id::kUtcTime).value = Variant::of(BuiltinType::DateTime, start);
  addVariable(ss, ns0(id::kServerStatusCurrentTime), 0, "CurrentTime", id::kUtcTime).read = [] {
    return Variant::of(BuiltinType::DateTime, dateTimeNow());
  };
  addVariable(ss, ns0(id::kServerStatusState), 0, "State", id::kServerState).value = Variant::int32(0);
  Node& bi = addVariable(ss, ns0(2260), 0, "BuildInfo", id::kBuildInfo, false, id::kBuildInfoType);
  bi.value = [&] {
    ExtensionObject x{ns0(id::kBuildInfoEncoding), 1, {}};
    Encoder e(x.body);
    build_info(e);
    return Variant::of(BuiltinType::ExtensionObject, x);
  }();
  const NodeId b = ns0(2260);
  addVariable(b, ns0(2262), 0, "ProductUri", 12).value = Variant::string("https://gdpn.dev/" + product_name);
  addVariable(b, ns0(2263), 0, "ManufacturerName", 12).value = Variant::string("gdpn");
  addVariable(b, ns0(2261), 0, "ProductName", 12).value = Variant::string(product_name);
  addVariable(b, ns0(2264), 0, "SoftwareVersion", 12).value = Variant::string(software_version);
  addVariable(b, ns0(2265), 0, "BuildNumber", 12).value = Variant::string(software_version);
  addVariable(b, ns0(2266), 0, "BuildDate", id::kUtcTime).value = Variant::of(BuiltinType::DateTime, start);
  addVariable(ss, ns0(2992), 0, "SecondsTillShutdown", 7).value = Variant::uint32(0);
  addVariable(ss, ns0(2993), 0, "ShutdownReason", 21).value = Variant::of(BuiltinType::LocalizedText, LocalizedText{});
}

BuiltinType builtinOf(const NodeId& data_type) {
  if (data_type.ns != 0 || data_type.kind != NodeId::Kind::Numeric) return BuiltinType::Null;
  if (data_type.numeric >= 1 && data_type.numeric <= 25) return static_cast<BuiltinType>(data_type.numeric);
  switch (data_type.numeric) {
    case id::kDuration: return BuiltinType::Double;
    case id::kUtcTime: return BuiltinType::DateTime;
    case id::kLocaleId: return BuiltinType::String;
    case id::kServerState: return BuiltinType::Int32;
    default: return BuiltinType::Null;
  }
}

DataValue readAttribute(const AddressSpace& space, const Node& node, std::uint32_t attribute) {
  DataValue out;
  auto bad = [&out](StatusCode s) {
    out.status = s;
    return out;
  };
  auto put = [&out](Variant v) {
    out.value = std::move(v);
    return out;
  };
  const bool variable = node.node_class == NodeClass::Variable || node.node_class == NodeClass::VariableType;
  const bool type = node.node_class == NodeClass::ObjectType || node.node_class == NodeClass::VariableType ||
                    node.node_class == NodeClass::ReferenceType || node.node_class == NodeClass::DataType;
  if (attribute < 1 || attribute > 27) return bad(status::kBadAttributeIdInvalid);
  switch (static_cast<AttributeId>(attribute)) {
    case AttributeId::NodeId: return put(Variant::of(BuiltinType::NodeId, node.id));
    case AttributeId::NodeClass: return put(Variant::int32(static_cast<std::int32_t>(node.node_class)));
    case AttributeId::BrowseName: return put(Variant::of(BuiltinType::QualifiedName, node.browse_name));
    case AttributeId::DisplayName: return put(Variant::of(BuiltinType::LocalizedText, node.display_name));
    case AttributeId::Description: return put(Variant::of(BuiltinType::LocalizedText, node.description));
    case AttributeId::WriteMask:
    case AttributeId::UserWriteMask: return put(Variant::uint32(0));
    case AttributeId::IsAbstract:
      return type ? put(Variant::boolean(node.is_abstract)) : bad(status::kBadAttributeIdInvalid);
    case AttributeId::Symmetric:
      return node.node_class == NodeClass::ReferenceType ? put(Variant::boolean(node.symmetric))
                                                         : bad(status::kBadAttributeIdInvalid);
    case AttributeId::InverseName:
      return node.node_class == NodeClass::ReferenceType ? put(Variant::of(BuiltinType::LocalizedText, node.inverse_name))
                                                         : bad(status::kBadAttributeIdInvalid);
    case AttributeId::ContainsNoLoops: return node.node_class == NodeClass::View ? put(Variant::boolean(true)) : bad(status::kBadAttributeIdInvalid);
    case AttributeId::EventNotifier:
      return node.node_class == NodeClass::Object || node.node_class == NodeClass::View
                 ? put(Variant::of(BuiltinType::Byte, std::uint64_t{node.event_notifier}))
                 : bad(status::kBadAttributeIdInvalid);
    case AttributeId::Value:
      if (node.node_class == NodeClass::Variable) return put(node.valueNow());
      return node.node_class == NodeClass::VariableType ? put(Variant{}) : bad(status::kBadAttributeIdInvalid);
    case AttributeId::DataType:
      return variable ? put(Variant::of(BuiltinType::NodeId, node.data_type)) : bad(status::kBadAttributeIdInvalid);
    case AttributeId::ValueRank: return variable ? put(Variant::int32(node.value_rank)) : bad(status::kBadAttributeIdInvalid);
    case AttributeId::ArrayDimensions:
      if (!variable) return bad(status::kBadAttributeIdInvalid);
      {
        Variant dims;
        dims.type = BuiltinType::UInt32;
        dims.is_array = true;
        if (node.value_rank == 1) dims.elements.push_back(Variant::uint32(0));
        return put(dims);
      }
    case AttributeId::AccessLevel:
    case AttributeId::UserAccessLevel:
      if (node.node_class != NodeClass::Variable) return bad(status::kBadAttributeIdInvalid);
      return put(Variant::of(BuiltinType::Byte, std::uint64_t{node.write ? 3u : 1u}));
    case AttributeId::AccessLevelEx:
      if (node.node_class != NodeClass::Variable) return bad(status::kBadAttributeIdInvalid);
      return put(Variant::uint32(node.write ? 3u : 1u));
    case AttributeId::MinimumSamplingInterval:
      return node.node_class == NodeClass::Variable ? put(Variant::dbl(node.minimum_sampling)) : bad(status::kBadAttributeIdInvalid);
    case AttributeId::Historizing:
      return node.node_class == NodeClass::Variable ? put(Variant::boolean(false)) : bad(status::kBadAttributeIdInvalid);
    case AttributeId::Executable:
    case AttributeId::UserExecutable:
      return node.node_class == NodeClass::Method ? put(Variant::boolean(node.executable)) : bad(status::kBadAttributeIdInvalid);
    case AttributeId::DataTypeDefinition:
    case AttributeId::RolePermissions:
    case AttributeId::UserRolePermissions:
    case AttributeId::AccessRestrictions: return bad(status::kBadAttributeIdInvalid);
  }
  (void)space;
  return bad(status::kBadAttributeIdInvalid);
}

}  // namespace gdpn::opcua
