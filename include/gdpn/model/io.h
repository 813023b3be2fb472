#pragma once
/// \file
/// The model's `io` section: the plant and the net mapped to the four Modbus tables (discrete
/// inputs, input registers, coils, holding registers), so that a controller outside the
/// process (a PLC, a soft PLC) reads sensors and drives actuators. `IoMap` is the section
/// resolved against a run: it reads the plant into table values and writes table values into
/// the plant, with the model file's checks. The transport (Modbus TCP) is `gdpn::modbus`.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gdpn/core/diagnostics.h"

namespace gdpn::model {

class Simulation;

/// One of the four tables of the Modbus data model.
enum class IoTable : std::uint8_t {
  DiscreteInputs,    ///< bits the controller reads (a region holds something, a place is marked)
  InputRegisters,    ///< 16-bit words the controller reads (a distance, an angle, a count)
  Coils,             ///< bits the controller writes and reads back (a belt runs, a token)
  HoldingRegisters,  ///< 16-bit words the controller writes and reads back (a speed, a target)
};

/// The table's key in the `io` section: `discrete_inputs`, `input_registers`, `coils`,
/// `holding_registers`.
const char* ioTableKey(IoTable table);

/// How messages name an address: "coil 3", "input register 7".
std::string ioAddressName(IoTable table, std::uint32_t address);

/// The data type an I/O point has on every protocol (OPC UA's built-in type of that name). Bits
/// are Boolean; a register entry's type says how its number is put into Modbus words.
enum class IoDataType : std::uint8_t {
  Boolean,  ///< a bit: 0 or 1 (discrete inputs, coils)
  Int16,    ///< one word, two's complement, -32768 to 32767 (a register's default)
  UInt16,   ///< one word, 0 to 65535
  Int32,    ///< two words, high word first, two's complement
  UInt32,   ///< two words, high word first, 0 to 4294967295
  Float,    ///< two words, high word first, IEEE 754 single precision
  Double,   ///< four words, highest word first, IEEE 754 double precision
};

/// OPC UA's name of `type`: "Boolean", "Int16", "UInt16", "Int32", "UInt32", "Float", "Double"
/// (the `type` key of an io entry).
const char* ioDataTypeName(IoDataType type);

/// The name `type` had before it took OPC UA's ("int16", "uint16", "int32", "uint32", "float32";
/// null for Boolean and Double, which had none): files that use it still load.
const char* ioDataTypeOldName(IoDataType type);

/// Modbus words (16 bits each) a register of type `type` takes: 1, 2 or 4 (Boolean: 1, a bit).
inline int ioWidth(IoDataType type) {
  return type == IoDataType::Int32 || type == IoDataType::UInt32 || type == IoDataType::Float ? 2
         : type == IoDataType::Double                                                      ? 4
                                                                                           : 1;
}

/// One address (or two or four, for wider types) of a table, as the model file writes it.
struct IoEntry {
  /// What the entry stands for.
  enum class Source : std::uint8_t {
    Place,  ///< `place: NAME`: read, its tokens (a bit: marked), or with `value` one value's; written, a coil's rising edge adds a token, a register sets the tokens
    Node,   ///< `node: PATH` with `of: QUANTITY` (read) or `field: NAME` (written), or `key: KEY` (a KeyboardSensor's key held down)
    Part,   ///< `part: INSTANCE` with `io: NAME`: one of a part's inputs (read) or outputs (written)
  };
  IoTable table = IoTable::DiscreteInputs;  ///< its table
  std::uint16_t address = 0;                ///< its (first) address, 0-based as on the wire
  Source source = Source::Node;             ///< a place or a node
  std::string target;                       ///< the place's qualified name, the node's path or the part instance
  std::string io;                           ///< a part's: the name of its input or output
  std::string value;                        ///< a place read: one value of its value slot's set (inscription language), whose tokens are read; empty: all its tokens
  core::SourceLoc value_loc;                ///< where `value`'s first character is written
  std::string quantity;                     ///< inputs: what is read (`of`: as a signal's, with `active` and `position.z`)
  std::string field;                        ///< coils, holding registers: the field written
  std::string key;                          ///< discrete inputs: a KeyboardSensor's key
  double scale = 1.0;                       ///< registers: word = value x scale (rounded, held within the type's range)
  std::string unit;                         ///< registers: the word's unit after scaling, for people (`mm`)
  IoDataType type = IoDataType::Int16;      ///< registers: how the number is put into words (bits: unused)
  std::string name;                         ///< as written (`name`); "" : derived, see ioEntryName
  core::SourceLoc name_loc;                 ///< where `name` is written
  std::string plc_node;                     ///< `opcua`: the PLC's node it is mapped to in client mode ("" none)
  core::SourceLoc plc_node_loc;             ///< where `opcua` is written
  double on = 1.0;                          ///< coils on a number field: the value for 1
  double off = 0.0;                         ///< coils on a number field: the value for 0
  core::SourceLoc loc;                      ///< where the address is written
  friend bool operator==(const IoEntry& a, const IoEntry& b) {
    return a.table == b.table && a.address == b.address && a.source == b.source && a.target == b.target && a.io == b.io && a.value == b.value &&
           a.quantity == b.quantity && a.field == b.field && a.key == b.key && a.scale == b.scale && a.unit == b.unit &&
           a.type == b.type && a.on == b.on && a.off == b.off && a.name == b.name && a.plc_node == b.plc_node;
  }
};

/// The name `e` has: its `name`, or without one the name derived from what it maps: the last
/// segment of its node path, place or part instance (after the last `/`), then `_` and the
/// quantity (`of`), the field, `key_` and the key, the part's `io`, or a place's `value`; every
/// run of characters other than letters, digits and `_` becomes one `_` (none at either end), and
/// a name that would start with a digit starts with `_`. `station/eye/beam` of `active`:
/// `beam_active`; `feeder/stock`: `stock`; `main/pusher1` io `extend`: `pusher1_extend`.
std::string ioEntryName(const IoEntry& e);

/// The `io` section.
struct IoSpec {
  std::vector<IoEntry> entries;            ///< by table (in IoTable's order), then by address
  std::optional<std::uint16_t> lockstep;   ///< the holding register a controller writes to ask for steps
  core::SourceLoc lockstep_loc;            ///< where `lockstep` is written
  /// True when the model has the section.
  [[nodiscard]] bool empty() const { return entries.empty() && !lockstep; }
  friend bool operator==(const IoSpec& a, const IoSpec& b) {
    return a.entries == b.entries && a.lockstep == b.lockstep;
  }
};

/// A Modbus exception code (0: none).
enum class IoError : std::uint8_t {
  None = 0,
  IllegalFunction = 1,     ///< the server does not offer it (writes to a read-only server)
  IllegalAddress = 2,      ///< an address no entry maps, or part of a two- or four-word entry
  IllegalValue = 3,        ///< a value the field refuses, or a malformed request
};

/// One named I/O point, as every protocol serves it (Modbus by table and address, OPC UA by name).
struct IoPoint {
  std::string name;              ///< unique in the section (ioEntryName)
  IoDataType type = IoDataType::Boolean;  ///< Boolean for bits
  std::string unit;              ///< engineering unit of the value on the wire ("" none)
  bool writable = false;         ///< coils and holding registers: inputs to the plant
  std::string what;              ///< what it maps, as Row::what
  IoTable table = IoTable::DiscreteInputs;  ///< its Modbus table
  std::uint16_t address = 0;     ///< its (first) Modbus address
  std::string plc_node;          ///< the entry's `opcua` ("" none)
  core::SourceLoc plc_node_loc;  ///< where it is written
};

/// The `io` section resolved against a run: table values read from the plant and the net,
/// and writes applied to them. Single-threaded: call it between steps.
class IoMap {
 public:
  /// Resolves `spec` against `sim` (its net and plant): unknown places, nodes, quantities and
  /// fields, values a field refuses, places no write can change and names two entries share are
  /// located errors in `diags`; then null. A spec with no lockstep register (or no entries) works.
  static std::unique_ptr<IoMap> create(Simulation& sim, const IoSpec& spec, core::Diagnostics& diags);
  ~IoMap();
  IoMap(const IoMap&) = delete;
  IoMap& operator=(const IoMap&) = delete;

  /// Whether every address from `first` to `first + count - 1` of `table` is mapped (the
  /// lockstep register counts as mapped).
  [[nodiscard]] bool mapped(IoTable table, std::uint32_t first, std::uint32_t count) const;
  /// The bit at `address` (discrete inputs, coils), read from the run now; false when unmapped.
  [[nodiscard]] bool bit(IoTable table, std::uint16_t address) const;
  /// The word at `address` (input and holding registers), read from the run now; 0 when unmapped.
  [[nodiscard]] std::uint16_t word(IoTable table, std::uint16_t address) const;
  /// Writes coils `first...` (one bit each); IllegalAddress when one is unmapped. Nothing is
  /// written unless every bit may be. `client` names the writer (shown by `lastWriter`).
  IoError writeBits(std::uint16_t first, const std::vector<bool>& bits, const std::string& client);
  /// Writes holding registers `first...`; IllegalAddress when one is unmapped or a two- or
  /// four-word entry is written in part, IllegalValue when a field refuses its value. Nothing is written
  /// unless every word may be. A write to the lockstep register asks for that many steps more.
  IoError writeWords(std::uint16_t first, const std::vector<std::uint16_t>& words, const std::string& client);

  /// The entries as named points, in table order (as `rows`); point i is row i.
  [[nodiscard]] const std::vector<IoPoint>& points() const { return points_; }
  /// Point i's value now as on the wire: a bit 0 or 1, a register's number after scaling (an
  /// integer type's rounded and held in range, a Float's as single precision), in its `unit`.
  [[nodiscard]] double read(std::size_t i) const;
  /// Writes point i (`value` as on the wire, as `read` gives it): IllegalFunction when it is not
  /// writable, IllegalValue when `value` is no number of its type (out of range, not whole for an
  /// integer type, a bit other than 0 or 1) or the field refuses it. The checks and the write are
  /// the Modbus writes' own, traced as they are; `client` names the writer.
  IoError write(std::size_t i, double value, const std::string& client);
  /// Asks for `n` steps more (lockstep), as a write of `n` to the lockstep register does.
  void askSteps(std::uint32_t n);

  /// Steps the controller has asked for and the run has not taken (lockstep).
  [[nodiscard]] std::uint32_t pendingSteps() const { return pending_steps_; }
  /// One asked-for step taken.
  void stepTaken() {
    if (pending_steps_ > 0) --pending_steps_;
  }
  /// Whether the section has a lockstep register.
  [[nodiscard]] bool lockstep() const { return lockstep_.has_value(); }

  /// One row of the live table (the IDE's I/O view, `gdpn run --modbus` at the end).
  struct Row {
    IoTable table;           ///< its table
    std::uint16_t address;   ///< its first address
    std::string name;        ///< its point's name (ioEntryName)
    std::string what;        ///< what it maps: `station/eye.active`, `main/start`, `belt/drive.speed`, `panel key g`
    std::string wire;        ///< how the word is made, for registers: `x 1000 mm`, `Float` ("" for bits and plain Int16)
    double value;            ///< the value now in the model's units (a bit: 0 or 1)
    std::int64_t raw;        ///< the value on the wire (a bit: 0 or 1; a register: the integer, or a Float's or Double's bits)
    std::string writer;      ///< the client that wrote it last ("" when none)
  };
  /// The entries in table order, each with its value now.
  [[nodiscard]] std::vector<Row> rows() const;

 private:
  struct Bound;
  explicit IoMap(Simulation& sim);
  const Bound* find(IoTable table, std::uint32_t address) const;  // the entry covering `address`, or null
  Bound* find(IoTable table, std::uint32_t address);
  double value(const Bound& b) const;            // the quantity now, before scaling
  std::uint64_t encode(const Bound& b) const;    // the word(s) on the wire now (the last word lowest)
  void noteWrite(Bound& b, double value);         // traces a write that changes what was written last
  Simulation& sim_;
  std::vector<Bound> bound_;                      // sorted by table, then address
  std::vector<IoPoint> points_;                   // bound_'s entries as points
  std::optional<std::uint16_t> lockstep_;
  std::uint32_t pending_steps_ = 0;
};

}  // namespace gdpn::model
