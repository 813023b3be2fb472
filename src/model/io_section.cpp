// The `io` section of a model file: read with every mistake located, and written back.

#include "io_section.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "gdpn/core/text.h"
#include "gdpn/model/schema.h"

namespace gdpn::model {

const char* ioTableKey(IoTable table) {
  switch (table) {
    case IoTable::DiscreteInputs: return "discrete_inputs";
    case IoTable::InputRegisters: return "input_registers";
    case IoTable::Coils: return "coils";
    case IoTable::HoldingRegisters: return "holding_registers";
  }
  return "?";
}

const char* ioDataTypeName(IoDataType type) {
  switch (type) {
    case IoDataType::Boolean: return "Boolean";
    case IoDataType::Int16: return "Int16";
    case IoDataType::UInt16: return "UInt16";
    case IoDataType::Int32: return "Int32";
    case IoDataType::UInt32: return "UInt32";
    case IoDataType::Float: return "Float";
    case IoDataType::Double: return "Double";
  }
  return "?";
}

const char* ioDataTypeOldName(IoDataType type) {
  switch (type) {
    case IoDataType::Int16: return "int16";
    case IoDataType::UInt16: return "uint16";
    case IoDataType::Int32: return "int32";
    case IoDataType::UInt32: return "uint32";
    case IoDataType::Float: return "float32";
    case IoDataType::Boolean:
    case IoDataType::Double: return nullptr;
  }
  return nullptr;
}

namespace {

/// `text` as a name: each run of characters other than ASCII letters, digits and `_` one `_`,
/// none at either end.
std::string ioNamePart(const std::string& text) {
  std::string out;
  bool gap = false;
  for (const char c : text) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
    if (!ok) {
      gap = true;
      continue;
    }
    if (gap && !out.empty()) out += '_';
    gap = false;
    out += c;
  }
  return out;
}

}  // namespace

std::string ioEntryName(const IoEntry& e) {
  if (!e.name.empty()) return e.name;
  const auto slash = e.target.rfind('/');
  std::string name = ioNamePart(slash == std::string::npos ? e.target : e.target.substr(slash + 1));
  std::string what;
  if (!e.io.empty()) what = e.io;
  else if (!e.value.empty()) what = e.value;
  else if (!e.quantity.empty()) what = e.quantity;
  else if (!e.field.empty()) what = e.field;
  else if (!e.key.empty()) what = "key_" + e.key;
  what = ioNamePart(what);
  if (!what.empty()) name += (name.empty() ? "" : "_") + what;
  if (name.empty() || (name[0] >= '0' && name[0] <= '9')) name.insert(0, "_");
  return name;
}

std::string ioAddressName(IoTable table, std::uint32_t address) {
  static const char* names[] = {"discrete input", "input register", "coil", "holding register"};
  return std::string(names[static_cast<int>(table)]) + " " + std::to_string(address);
}

namespace detail {

namespace {

constexpr IoTable kTables[] = {IoTable::DiscreteInputs, IoTable::InputRegisters, IoTable::Coils,
                               IoTable::HoldingRegisters};
/// The types a register may have, in the schema's order.
constexpr IoDataType kRegisterTypes[] = {IoDataType::Int16, IoDataType::UInt16, IoDataType::Int32,
                                         IoDataType::UInt32, IoDataType::Float, IoDataType::Double};

bool isRegister(IoTable t) { return t == IoTable::InputRegisters || t == IoTable::HoldingRegisters; }
bool isWritten(IoTable t) { return t == IoTable::Coils || t == IoTable::HoldingRegisters; }

/// An address: a whole number from 0 to 65535.
std::optional<std::uint16_t> address(YamlReader& r, const std::string& text, const core::SourceLoc& at,
                                     const std::string& what) {
  const auto v = core::parseNumber(text);
  if (!v || *v != std::floor(*v) || *v < 0 || *v > 65535 || text.find_first_not_of("0123456789") != std::string::npos) {
    r.error(at, what + " is an address from 0 to 65535 (as on the wire: the first is 0), got '" + text + "'");
    return std::nullopt;
  }
  return static_cast<std::uint16_t>(*v);
}

std::optional<IoEntry> readEntry(YamlReader& r, const SourceMap& source, IoTable table, std::uint16_t addr,
                                 const Entry& e) {
  IoEntry out;
  out.table = table;
  out.address = addr;
  out.loc = e.loc;
  const std::string name = ioAddressName(table, addr);
  if (!r.expectMap(e.value, name)) return std::nullopt;
  int sources = 0;
  bool ok = true;
  for (const auto& k : r.entries(e.value, name, schema::ioEntryKeyNames(table))) {
    if (k.key == "scale" || k.key == "on" || k.key == "off") {
      const auto v = r.number(k.value, k.key);
      if (!v) {
        ok = false;
      } else if (!std::isfinite(*v) || (k.key == "scale" && *v == 0)) {
        r.error(r.loc(k.value, k.loc), "'" + k.key + "' of " + name + " is a finite number" +
                                           (k.key == "scale" ? std::string(" other than 0") : std::string()));
        ok = false;
      } else {
        (k.key == "scale" ? out.scale : k.key == "on" ? out.on : out.off) = *v;
      }
      continue;
    }
    if (k.key == "value") {
      // one value's tokens: its syntax is checked now, its type when a run is made ready
      if (auto text = readInscription(k.value, k.loc, net::kDefaultSlot, "value", source, r)) {
        out.value = std::move(text->text);
        out.value_loc = text->loc;
      } else {
        ok = false;
      }
      continue;
    }
    const auto text = r.string(k.value, k.key);
    if (!text) {
      ok = false;
      continue;
    }
    if (k.key == "place" || k.key == "node" || k.key == "part") {
      ++sources;
      out.source = k.key == "place"  ? IoEntry::Source::Place
                   : k.key == "node" ? IoEntry::Source::Node
                                     : IoEntry::Source::Part;
      out.target = *text;
    } else if (k.key == "io") {
      out.io = *text;
    } else if (k.key == "of") {
      out.quantity = *text;
    } else if (k.key == "field") {
      out.field = *text;
    } else if (k.key == "key") {
      out.key = *text;
    } else if (k.key == "unit") {
      out.unit = *text;
    } else if (k.key == "name") {
      if (!core::isIdentifier(*text)) {
        r.error(r.loc(k.value, k.loc), "'name' of " + name +
                                           " is an identifier (a letter or _, then letters, digits and _), got '" +
                                           *text + "'");
        ok = false;
      } else {
        out.name = *text;
        out.name_loc = r.loc(k.value, k.loc);
      }
    } else if (k.key == "opcua") {
      out.plc_node = *text;  // a NodeId: the opcua module reads it
      out.plc_node_loc = r.loc(k.value, k.loc);
    } else if (k.key == "type") {
      // OPC UA's names, and the old ones (float32 ...) still read
      const auto* t = std::find_if(std::begin(kRegisterTypes), std::end(kRegisterTypes), [&](IoDataType x) {
        const char* old = ioDataTypeOldName(x);
        return *text == ioDataTypeName(x) || (old != nullptr && *text == old);
      });
      if (t == std::end(kRegisterTypes)) {
        const auto& types = schema::key(schema::Section::IoEntry, "type");
        r.error(r.loc(k.value, k.loc), "'type' is one of " + schema::choiceList(types, "", ", ") + ", got '" + *text + "'");
        ok = false;
      } else {
        out.type = *t;
      }
    }
  }
  if (!ok) return std::nullopt;
  if (sources != 1) {
    r.error(e.loc, name + (sources == 0 ? " maps nothing: give it a 'place', a 'node' or a 'part'"
                                        : " maps more than one of 'place', 'node' and 'part': keep one"));
    return std::nullopt;
  }
  if ((out.source == IoEntry::Source::Part) != !out.io.empty()) {
    r.error(e.loc, name + (out.io.empty() ? ": a 'part' needs 'io', the name of its input or output"
                                          : ": 'io' goes with 'part'"));
    return std::nullopt;
  }
  if (!out.value.empty() && out.source != IoEntry::Source::Place) {
    r.error(e.loc, name + ": 'value' goes with 'place'");
    return std::nullopt;
  }
  if (out.source == IoEntry::Source::Part) {
    if (!out.quantity.empty() || !out.field.empty() || !out.key.empty()) {
      r.error(e.loc, name + ": 'of', 'field' and 'key' go with 'node'; a part's I/O says what it reads or sets");
      return std::nullopt;
    }
    return out;
  }
  if (out.source == IoEntry::Source::Place) {
    if (!out.quantity.empty() || !out.field.empty() || !out.key.empty()) {
      r.error(e.loc, name + ": 'of', 'field' and 'key' go with 'node', not with 'place'");
      return std::nullopt;
    }
    return out;
  }
  if (isWritten(table)) {
    if (out.field.empty()) {
      r.error(e.loc, name + " is written by the controller: it needs 'field', the node's field it sets (speed, target1)");
      return std::nullopt;
    }
  } else if (out.quantity.empty() == out.key.empty()) {
    r.error(e.loc, name + " needs " +
                       (table == IoTable::DiscreteInputs ? std::string("one of 'of' (active, a bool field) or 'key'")
                                                         : std::string("'of': reading, angle, rate, position.z, a field")));
    return std::nullopt;
  }
  return out;
}

}  // namespace

IoSpec readIo(const YAML::Node& section, YamlReader& r, const SourceMap& source) {
  IoSpec io;
  if (section.IsNull() || !r.expectMap(section, "io")) return io;
  for (const auto& e : r.entries(section, "io", schema::keyNames(schema::Section::Io))) {
    if (e.key == "lockstep") {
      const auto text = r.string(e.value, "lockstep");
      if (!text) continue;
      io.lockstep = address(r, *text, r.loc(e.value, e.loc), "'lockstep' (a holding register)");
      io.lockstep_loc = r.loc(e.value, e.loc);
      continue;
    }
    const IoTable table = *std::find_if(std::begin(kTables), std::end(kTables), [&](IoTable t) { return e.key == ioTableKey(t); });
    if (e.value.IsNull() || !r.expectMap(e.value, e.key)) continue;
    for (const auto& a : r.entries(e.value, e.key, {})) {
      const auto addr = address(r, a.key, a.loc, "a key of '" + e.key + "'");
      if (!addr) continue;
      if (auto entry = readEntry(r, source, table, *addr, a)) io.entries.push_back(std::move(*entry));
    }
  }
  // every address mapped once per table (a two-word entry takes the next address too): sorted
  // by table and address, each entry is checked against the one before it, and the later of
  // the two in the file is the one reported
  std::vector<std::size_t> order(io.entries.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  const auto width = [](const IoEntry& e) { return isRegister(e.table) ? ioWidth(e.type) : 1; };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    const IoEntry& a = io.entries[x];
    const IoEntry& b = io.entries[y];
    return a.table != b.table ? a.table < b.table : a.address < b.address;
  });
  for (std::size_t k = 0; k < order.size(); ++k) {
    const IoEntry& a = io.entries[order[k]];
    const int wa = width(a);
    if (a.address + wa - 1 > 65535) {
      r.error(a.loc, ioAddressName(a.table, a.address) + " is a " + ioDataTypeName(a.type) + ": it takes " +
                         (wa == 2 ? "two" : "four") + " addresses, and 65535 is the last");
    }
    if (io.lockstep && a.table == IoTable::HoldingRegisters && a.address <= *io.lockstep &&
        *io.lockstep < a.address + wa) {
      r.error(a.loc, ioAddressName(a.table, a.address) + " overlaps the lockstep register " +
                         std::to_string(*io.lockstep));
    }
    if (k == 0) continue;
    const IoEntry& b = io.entries[order[k - 1]];
    const int wb = width(b);
    if (a.table != b.table || a.address >= b.address + wb) continue;
    const bool a_later = order[k] > order[k - 1];
    const IoEntry& later = a_later ? a : b;
    const IoEntry& earlier = a_later ? b : a;
    const int we = a_later ? wb : wa;
    r.error(later.loc, ioAddressName(later.table, later.address) + " overlaps " +
                           ioAddressName(earlier.table, earlier.address) +
                           (we > 1 ? std::string(" (a ") + ioDataTypeName(earlier.type) +
                                         (we == 2 ? ", two addresses)" : ", four addresses)")
                                   : std::string()) +
                           ", written at line " + std::to_string(earlier.loc.line));
  }
  checkIoNames(io, [&](const core::SourceLoc& at, std::string message) { r.error(at, std::move(message)); });
  // kept in table and address order, as written back: a model read again is the same
  std::vector<IoEntry> sorted;
  sorted.reserve(order.size());
  for (const std::size_t i : order) sorted.push_back(std::move(io.entries[i]));
  io.entries = std::move(sorted);
  return io;
}

bool checkIoNames(const IoSpec& io, const std::function<void(const core::SourceLoc&, std::string)>& error) {
  // in file order (line, then column): of two entries with one name, the later is reported,
  // unless only it has its name written: then the one whose name is derived needs a `name`
  std::vector<const IoEntry*> order;
  order.reserve(io.entries.size());
  for (const auto& e : io.entries) order.push_back(&e);
  std::stable_sort(order.begin(), order.end(), [](const IoEntry* a, const IoEntry* b) {
    return a->loc.line != b->loc.line ? a->loc.line < b->loc.line : a->loc.column < b->loc.column;
  });
  std::map<std::string, const IoEntry*> seen;
  bool ok = true;
  for (const IoEntry* e : order) {
    const std::string name = ioEntryName(*e);
    const auto [it, fresh] = seen.emplace(name, e);
    if (fresh) continue;
    ok = false;
    const IoEntry* other = it->second;
    const IoEntry* at = e->name.empty() || !other->name.empty() ? e : other;  // the one reported
    const IoEntry* first = at == e ? other : e;
    const std::string where = ioAddressName(first->table, first->address) + " (line " + std::to_string(first->loc.line) + ")";
    if (at->name.empty()) {
      error(at->loc, ioAddressName(at->table, at->address) + " is named '" + name + "' after what it maps, as " +
                               where + " is: give it a 'name' (names are unique in the io section)");
    } else {
      error(at->name_loc, "'" + name + "' is the name of " + where + " too: names are unique in the io section");
    }
    if (at == other) it->second = e;
  }
  return ok;
}

void writeIo(YAML::Emitter& out, const IoSpec& io) {
  // what an entry leaves out: the schema's defaults
  using schema::Section;
  const double on_default = schema::defaultNumber(Section::IoEntry, "on");
  const double off_default = schema::defaultNumber(Section::IoEntry, "off");
  const double scale_default = schema::defaultNumber(Section::IoEntry, "scale");
  const std::string& type_default = schema::key(Section::IoEntry, "type").initial;
  const auto text = [&](const char* key, const std::string& value) {
    if (!value.empty()) out << YAML::Key << key << YAML::Value << value;
  };
  const auto entry = [&](IoTable t, const IoEntry& e) {
    // a value written as a block (it spans lines) needs a block map
    out << YAML::Key << e.address << YAML::Value << (inscriptionIsBlock(e.value) ? YAML::Block : YAML::Flow)
        << YAML::BeginMap;
    const bool place = e.source == IoEntry::Source::Place;
    const bool coil = t == IoTable::Coils && e.source == IoEntry::Source::Node;  // a coil on a node's number field
    const bool word = isRegister(t);
    schema::inSchemaOrder(
        Section::IoEntry,
        {
            {"name", [&] { text("name", e.name); }},
            {"place", [&] { if (place) out << YAML::Key << "place" << YAML::Value << e.target; }},
            {"value",
             [&] {
               if (place && !e.value.empty()) {
                 out << YAML::Key << "value" << YAML::Value;
                 writeInscription(out, e.value);
               }
             }},
            {"node", [&] { if (e.source == IoEntry::Source::Node) out << YAML::Key << "node" << YAML::Value << e.target; }},
            {"part", [&] { if (e.source == IoEntry::Source::Part) out << YAML::Key << "part" << YAML::Value << e.target; }},
            {"io", [&] { if (!e.io.empty()) out << YAML::Key << "io" << YAML::Value << e.io; }},
            {"of", [&] { if (!e.quantity.empty()) out << YAML::Key << "of" << YAML::Value << e.quantity; }},
            {"key", [&] { if (!e.key.empty()) out << YAML::Key << "key" << YAML::Value << e.key; }},
            {"field", [&] { if (!e.field.empty()) out << YAML::Key << "field" << YAML::Value << e.field; }},
            {"on", [&] { if (coil && e.on != on_default) out << YAML::Key << "on" << YAML::Value << core::formatDouble(e.on); }},
            {"off",
             [&] { if (coil && e.off != off_default) out << YAML::Key << "off" << YAML::Value << core::formatDouble(e.off); }},
            {"scale",
             [&] {
               if (word && e.scale != scale_default) out << YAML::Key << "scale" << YAML::Value << core::formatDouble(e.scale);
             }},
            {"unit", [&] { if (word && !e.unit.empty()) out << YAML::Key << "unit" << YAML::Value << e.unit; }},
            {"type",
             [&] {
               if (word && ioDataTypeName(e.type) != type_default) {
                 out << YAML::Key << "type" << YAML::Value << ioDataTypeName(e.type);
               }
             }},
            {"opcua", [&] { text("opcua", e.plc_node); }},
        });
    out << YAML::EndMap;
  };
  out << YAML::BeginMap;
  std::vector<schema::KeyWriter> keys = {
      {"lockstep", [&] { if (io.lockstep) out << YAML::Key << "lockstep" << YAML::Value << *io.lockstep; }},
  };
  for (IoTable t : kTables) {
    keys.push_back({ioTableKey(t), [&, t] {
                      std::vector<const IoEntry*> of;
                      for (const auto& e : io.entries) {
                        if (e.table == t) of.push_back(&e);
                      }
                      if (of.empty()) return;
                      std::stable_sort(of.begin(), of.end(),
                                       [](const IoEntry* a, const IoEntry* b) { return a->address < b->address; });
                      out << YAML::Key << ioTableKey(t) << YAML::Value << YAML::BeginMap;
                      for (const IoEntry* e : of) entry(t, *e);
                      out << YAML::EndMap;
                    }});
  }
  schema::inSchemaOrder(Section::Io, keys);
  out << YAML::EndMap;
}

}  // namespace detail
}  // namespace gdpn::model
