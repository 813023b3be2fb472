// The `io` section resolved against a run: Modbus table values read from the plant and the
// net, and a controller's writes applied to them.

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "gdpn/core/text.h"
#include "gdpn/model/io.h"
#include "gdpn/model/simulation.h"
#include "gdpn/model/part_run.h"
#include "io_section.h"
#include "probe.h"

namespace gdpn::model {

struct IoMap::Bound {
  IoEntry spec;
  Probe probe;                       // what a read gives (for a written entry: its field or place)
  scene::NodeHandle node = 0;        // written field: its node
  std::size_t field = 0;             // written field: its index
  scene::FieldKind kind = scene::FieldKind::Float;
  net::PlaceSlotId slot{0};         // written place: its control slot
  bool amount = false;               // written place: a continuous one, its amount set (value / scale)
  bool coil = false;                 // a place's coil: the state last written
  std::size_t part = 0;              // a part's I/O: the part (PartRun's index)
  std::string writer;                // the client that wrote it last
  double written = std::numeric_limits<double>::quiet_NaN();  // the value written last (NaN: none yet)
  [[nodiscard]] int width() const {
    return spec.table == IoTable::InputRegisters || spec.table == IoTable::HoldingRegisters ? ioWidth(spec.type) : 1;
  }
};

namespace {

bool isBit(IoTable t) { return t == IoTable::DiscreteInputs || t == IoTable::Coils; }

/// `x` held within [lo, hi] and rounded (NaN: 0).
std::int64_t held(double x, double lo, double hi) {
  if (std::isnan(x)) return 0;
  return static_cast<std::int64_t>(std::llround(std::clamp(x, lo, hi)));
}

/// `v` as a field of kind `kind` holds it: a bool, a whole number (rounded) or a number.
scene::FieldValue fieldValue(scene::FieldKind kind, double v) {
  scene::FieldValue out;
  if (kind == scene::FieldKind::Bool) {
    out.emplace<bool>(v != 0.0);
  } else if (kind == scene::FieldKind::Int) {
    out.emplace<std::int64_t>(static_cast<std::int64_t>(std::llround(v)));
  } else {
    out.emplace<double>(v);
  }
  return out;
}

/// The number a register of type `type` carries in the words `w` (the last word lowest).
double wireNumber(IoDataType type, std::uint64_t w) {
  switch (type) {
    case IoDataType::Boolean: return w != 0 ? 1.0 : 0.0;
    case IoDataType::Int16: return static_cast<std::int16_t>(static_cast<std::uint16_t>(w));
    case IoDataType::UInt16: return static_cast<std::uint16_t>(w);
    case IoDataType::Int32: return static_cast<std::int32_t>(static_cast<std::uint32_t>(w));
    case IoDataType::UInt32: return static_cast<std::uint32_t>(w);
    case IoDataType::Float: return static_cast<double>(std::bit_cast<float>(static_cast<std::uint32_t>(w)));
    case IoDataType::Double: return std::bit_cast<double>(w);
  }
  return 0;
}

/// The words a register of type `type` carries for the number `x` (the last word lowest), when
/// `x` is a number of that type: whole and in range for an integer type, finite and within
/// single precision's range for a Float (rounded to it), finite for a Double, 0 or 1 for a bit.
std::optional<std::uint64_t> wireBits(IoDataType type, double x) {
  const auto whole = [&](double lo, double hi) { return std::isfinite(x) && std::floor(x) == x && x >= lo && x <= hi; };
  switch (type) {
    case IoDataType::Boolean:
      if (x != 0.0 && x != 1.0) return std::nullopt;
      return x != 0.0 ? 1 : 0;
    case IoDataType::Int16:
      if (!whole(-32768, 32767)) return std::nullopt;
      return static_cast<std::uint16_t>(static_cast<std::int16_t>(x));
    case IoDataType::UInt16:
      if (!whole(0, 65535)) return std::nullopt;
      return static_cast<std::uint16_t>(x);
    case IoDataType::Int32:
      if (!whole(-2147483648.0, 2147483647.0)) return std::nullopt;
      return static_cast<std::uint32_t>(static_cast<std::int32_t>(x));
    case IoDataType::UInt32:
      if (!whole(0, 4294967295.0)) return std::nullopt;
      return static_cast<std::uint32_t>(x);
    case IoDataType::Float:
      if (!std::isfinite(x) || std::abs(x) > static_cast<double>(std::numeric_limits<float>::max())) return std::nullopt;
      return std::bit_cast<std::uint32_t>(static_cast<float>(x));
    case IoDataType::Double:
      if (!std::isfinite(x)) return std::nullopt;
      return std::bit_cast<std::uint64_t>(x);
  }
  return std::nullopt;
}

/// What `e` maps, for people: `station/eye.active`, `main/start`, `panel key g`.
std::string ioWhat(const IoEntry& e) {
  std::string what = e.target;
  if (!e.io.empty()) what += "." + e.io;
  if (!e.value.empty()) what += "=" + e.value;
  if (!e.quantity.empty()) what += "." + e.quantity;
  if (!e.field.empty()) what += "." + e.field;
  if (!e.key.empty()) what += " key " + e.key;
  return what;
}

}  // namespace

IoMap::IoMap(Simulation& sim) : sim_(sim) {}
IoMap::~IoMap() = default;

std::unique_ptr<IoMap> IoMap::create(Simulation& sim, const IoSpec& spec, core::Diagnostics& diags) {
  auto map = std::unique_ptr<IoMap>(new IoMap(sim));
  map->lockstep_ = spec.lockstep;
  // every point is served by its name: a spec not read from a file (edited) may repeat one
  bool ok = detail::checkIoNames(spec, [&](const core::SourceLoc& at, std::string message) {
    diags.error(at, std::move(message));
  });
  for (const IoEntry& e : spec.entries) {
    const std::string name = ioAddressName(e.table, e.address);
    const auto fail = [&](const std::string& why) {
      diags.error(e.loc, name + ": " + why);
      ok = false;
    };
    Bound b;
    b.spec = e;
    std::string why;
    std::optional<Probe> probe;
    if (e.source == IoEntry::Source::Part) {
      constexpr std::size_t kNone = static_cast<std::size_t>(-1);
      std::size_t part = kNone;
      if (!sim.parts()) why = "no part '" + e.target + "' (the model has none)";
      else part = sim.parts()->find(e.target, why).value_or(kNone);
      if (part == kNone) {
        fail(why);
        continue;
      }
      const PartIoSpec* io = sim.parts()->instances()[part].spec->findIo(e.io);
      if (!io) {
        (void)sim.parts()->read(part, e.io, why);
        fail(why);
        continue;
      }
      const bool written = e.table == IoTable::Coils || e.table == IoTable::HoldingRegisters;
      const bool bit = isBit(e.table);
      if (written != (io->direction == IoDirection::Output) || bit != (io->signal == IoSignal::Digital)) {
        const char* table = io->direction == IoDirection::Input
                                ? (io->signal == IoSignal::Digital ? "discrete_inputs" : "input_registers")
                                : (io->signal == IoSignal::Digital ? "coils" : "holding_registers");
        fail("'" + e.io + "' is a " + ioSignalName(io->signal) + " " + ioDirectionName(io->direction) + ": map it in " +
             table);
        continue;
      }
      b.part = part;
      map->bound_.push_back(std::move(b));
      continue;
    }
    if (e.source == IoEntry::Source::Place) {
      probe = placeProbe(sim, e.target, why);
      if (probe && probe->what == Probe::What::Amount &&
          (e.table == IoTable::Coils || e.table == IoTable::HoldingRegisters)) {
        // written: a continuous place's amount, by a register only
        if (e.table == IoTable::Coils) {
          fail("place '" + e.target + "' is continuous: a coil puts a token, and it holds an amount " +
               "(map it to a holding register, which sets the amount to value / scale)");
          continue;
        }
        b.amount = true;
      } else if (probe && (e.table == IoTable::Coils || e.table == IoTable::HoldingRegisters)) {
        // written: the place's one control slot
        const auto& place = sim.net().places()[probe->place];
        const auto& slots = sim.net().placeSlots();
        if (place.slots_end - place.slots_begin != 1 || slots[place.slots_begin].kind != net::SlotKind::Control) {
          fail("place '" + e.target + "' holds node tokens or several slots: a controller sets plain tokens only");
          continue;
        }
        b.slot = net::PlaceSlotId{place.slots_begin};
      }
      if (probe && !e.value.empty() && !countValue(sim, *probe, e.value, e.value_loc, name + ": ", diags)) {
        ok = false;
        continue;
      }
    } else if (!e.key.empty()) {
      probe = keyProbe(sim, e.target, e.key, why);
    } else {
      const bool written = e.table == IoTable::Coils || e.table == IoTable::HoldingRegisters;
      probe = nodeProbe(sim, e.target, written ? e.field : e.quantity, why);
      if (probe && written) {
        if (probe->what != Probe::What::Field) {
          fail("'" + e.field + "' is no field a controller can set (a number field, or a bool for a coil)");
          continue;
        }
        const scene::Node* node = sim.plant()->resolve(probe->node);
        const scene::FieldDesc& f = *node->type().fields[probe->field];
        b.node = probe->node;
        b.field = probe->field;
        b.kind = f.kind;
        if (e.table == IoTable::HoldingRegisters && f.kind == scene::FieldKind::Bool) {
          fail("'" + e.field + "' is true or false: map it to a coil");
          continue;
        }
        if (e.table == IoTable::Coils && f.kind != scene::FieldKind::Bool) {
          // the values of 1 and 0 must be ones the field takes
          for (const double v : {e.on, e.off}) {
            scene::FieldValue fv = fieldValue(f.kind, v);
            if (f.kind == scene::FieldKind::Int && std::floor(v) != v) {
              fail("'" + e.field + "' is a whole number; " + core::formatDouble(v) + " is not");
              break;
            }
            if (const auto no = scene::refusal(*node, probe->field, fv, sim.model().settings.angles); !no.empty()) {
              fail("'" + std::string(v == e.on ? "on" : "off") + "': " + no);
              break;
            }
          }
          if (!ok) continue;
        }
      }
    }
    if (!probe) {
      fail(why);
      continue;
    }
    if (probe->width() != 1) {
      fail("'" + e.quantity + "' is three numbers: name one axis (" + e.quantity + ".z)");
      continue;
    }
    b.probe = std::move(*probe);
    map->bound_.push_back(std::move(b));
  }
  if (!ok) return nullptr;
  std::stable_sort(map->bound_.begin(), map->bound_.end(), [](const Bound& a, const Bound& b) {
    return a.spec.table != b.spec.table ? a.spec.table < b.spec.table : a.spec.address < b.spec.address;
  });
  for (const Bound& b : map->bound_) {
    const IoEntry& e = b.spec;
    IoPoint p;
    p.name = ioEntryName(e);
    p.type = isBit(e.table) ? IoDataType::Boolean : e.type;
    p.unit = isBit(e.table) ? std::string() : e.unit;
    p.writable = e.table == IoTable::Coils || e.table == IoTable::HoldingRegisters;
    p.what = ioWhat(e);
    p.table = e.table;
    p.address = e.address;
    p.plc_node = e.plc_node;
    p.plc_node_loc = e.plc_node_loc;
    map->points_.push_back(std::move(p));
  }
  return map;
}

IoMap::Bound* IoMap::find(IoTable table, std::uint32_t address) {
  return const_cast<Bound*>(std::as_const(*this).find(table, address));
}

const IoMap::Bound* IoMap::find(IoTable table, std::uint32_t address) const {
  // the last entry of the table starting at or before `address`, if it covers it
  auto it = std::upper_bound(bound_.begin(), bound_.end(), std::pair(table, address), [](const auto& key, const Bound& b) {
    return key.first != b.spec.table ? key.first < b.spec.table : key.second < b.spec.address;
  });
  if (it == bound_.begin()) return nullptr;
  --it;
  if (it->spec.table != table || address >= it->spec.address + static_cast<std::uint32_t>(it->width())) return nullptr;
  return &*it;
}

bool IoMap::mapped(IoTable table, std::uint32_t first, std::uint32_t count) const {
  for (std::uint32_t a = first; a < first + count; ++a) {
    if (a > 65535) return false;
    if (table == IoTable::HoldingRegisters && lockstep_ && a == *lockstep_) continue;
    if (find(table, a) == nullptr) return false;
  }
  return true;
}

double IoMap::value(const Bound& b) const {
  if (b.spec.table == IoTable::Coils && b.spec.source == IoEntry::Source::Place) return b.coil ? 1.0 : 0.0;
  if (b.spec.source == IoEntry::Source::Part) {
    std::string why;
    return sim_.parts()->read(b.part, b.spec.io, why).value_or(0.0);
  }
  double v = 0.0;
  if (!readProbe(sim_, b.probe, &v)) return 0.0;  // its node was deleted
  if (b.spec.table == IoTable::Coils && b.kind != scene::FieldKind::Bool) return v == b.spec.on ? 1.0 : 0.0;
  return v;
}

std::uint64_t IoMap::encode(const Bound& b) const {
  const double v = value(b);
  if (isBit(b.spec.table)) return v != 0.0 ? 1 : 0;
  const double x = v * b.spec.scale;
  switch (b.spec.type) {
    case IoDataType::Boolean: return x != 0.0 ? 1 : 0;  // a register is never Boolean
    case IoDataType::Int16: return static_cast<std::uint16_t>(static_cast<std::int16_t>(held(x, -32768, 32767)));
    case IoDataType::UInt16: return static_cast<std::uint64_t>(held(x, 0, 65535));
    case IoDataType::Int32:
      return static_cast<std::uint32_t>(static_cast<std::int32_t>(held(x, -2147483648.0, 2147483647.0)));
    case IoDataType::UInt32: return static_cast<std::uint64_t>(held(x, 0, 4294967295.0));
    case IoDataType::Float: {
      const double lim = static_cast<double>(std::numeric_limits<float>::max());
      return std::bit_cast<std::uint32_t>(static_cast<float>(std::isnan(x) ? x : std::clamp(x, -lim, lim)));
    }
    case IoDataType::Double: return std::bit_cast<std::uint64_t>(x);
  }
  return 0;
}

bool IoMap::bit(IoTable table, std::uint16_t address) const {
  const Bound* b = find(table, address);
  return b != nullptr && encode(*b) != 0;
}

std::uint16_t IoMap::word(IoTable table, std::uint16_t address) const {
  if (table == IoTable::HoldingRegisters && lockstep_ && address == *lockstep_) {
    return static_cast<std::uint16_t>(std::min<std::uint32_t>(pending_steps_, 65535));
  }
  const Bound* b = find(table, address);
  if (b == nullptr) return 0;
  const std::uint64_t w = encode(*b);
  const auto below = static_cast<std::uint32_t>(b->width() - 1) - (address - b->spec.address);  // words after it
  return static_cast<std::uint16_t>(w >> (16 * below));  // high word first
}

double IoMap::read(std::size_t i) const {
  const Bound& b = bound_.at(i);
  return wireNumber(isBit(b.spec.table) ? IoDataType::Boolean : b.spec.type, encode(b));
}

IoError IoMap::write(std::size_t i, double value, const std::string& client) {
  // as the Modbus writes of the same words: one check, one write
  const Bound& b = bound_.at(i);
  if (b.spec.table != IoTable::Coils && b.spec.table != IoTable::HoldingRegisters) return IoError::IllegalFunction;
  const auto w = wireBits(isBit(b.spec.table) ? IoDataType::Boolean : b.spec.type, value);
  if (!w) return IoError::IllegalValue;
  if (isBit(b.spec.table)) return writeBits(b.spec.address, {*w != 0}, client);
  std::vector<std::uint16_t> words(static_cast<std::size_t>(b.width()));
  for (std::size_t k = 0; k < words.size(); ++k) {
    words[k] = static_cast<std::uint16_t>(*w >> (16 * (words.size() - 1 - k)));  // high word first
  }
  return writeWords(b.spec.address, words, client);
}

void IoMap::askSteps(std::uint32_t n) {
  pending_steps_ = n > std::numeric_limits<std::uint32_t>::max() - pending_steps_ ? std::numeric_limits<std::uint32_t>::max()
                                                                                  : pending_steps_ + n;
}

void IoMap::noteWrite(Bound& b, double value) {
  // a controller rewrites its outputs every scan: the trace has the changes
  if (value == b.written) return;
  b.written = value;
  sim_.note("io", std::string("\"table\":\"") + ioTableKey(b.spec.table) + "\",\"address\":" +
                      std::to_string(b.spec.address) + ",\"value\":" + core::formatDouble(value));
}

IoError IoMap::writeBits(std::uint16_t first, const std::vector<bool>& bits, const std::string& client) {
  if (!mapped(IoTable::Coils, first, static_cast<std::uint32_t>(bits.size()))) return IoError::IllegalAddress;
  for (std::size_t k = 0; k < bits.size(); ++k) {
    Bound& b = *find(IoTable::Coils, first + static_cast<std::uint32_t>(k));
    const bool on = bits[k];
    b.writer = client;
    if (b.spec.source == IoEntry::Source::Part) {
      std::string why;
      (void)sim_.parts()->write(b.part, b.spec.io, on ? 1.0 : 0.0, why);
    } else if (b.spec.source == IoEntry::Source::Place) {
      // a rising edge puts one token on the place (none when its capacity is full)
      if (on && !b.coil) (void)sim_.kernel().setMarking(b.slot, sim_.kernel().marking(b.slot) + 1);
      b.coil = on;
    } else if (scene::Node* node = sim_.plant()->resolve(b.node)) {
      const double v = b.kind == scene::FieldKind::Bool ? (on ? 1.0 : 0.0) : on ? b.spec.on : b.spec.off;
      (void)physics::assignField(*node, b.field, fieldValue(b.kind, v), sim_.model().settings.angles, sim_.physics());
    }
    noteWrite(b, on ? 1.0 : 0.0);
  }
  return IoError::None;
}

IoError IoMap::writeWords(std::uint16_t first, const std::vector<std::uint16_t>& words, const std::string& client) {
  const auto count = static_cast<std::uint32_t>(words.size());
  if (!mapped(IoTable::HoldingRegisters, first, count)) return IoError::IllegalAddress;
  // each entry's number from its words, all checked before any is written
  struct Write {
    Bound* b;
    double value;
  };
  std::vector<Write> writes;
  std::uint32_t steps = 0;
  for (std::uint32_t a = first; a < first + count;) {
    if (lockstep_ && a == *lockstep_) {
      steps = words[a - first];
      ++a;
      continue;
    }
    Bound* b = find(IoTable::HoldingRegisters, a);
    if (b->spec.address != a || a + static_cast<std::uint32_t>(b->width()) > first + count) {
      return IoError::IllegalAddress;  // part of a two- or four-word entry
    }
    std::uint64_t w = 0;
    for (std::uint32_t k = 0; k < static_cast<std::uint32_t>(b->width()); ++k) w = (w << 16) | words[a - first + k];
    const double v = wireNumber(b->spec.type, w) / b->spec.scale;
    if (!std::isfinite(v)) return IoError::IllegalValue;
    if (b->spec.source == IoEntry::Source::Part) {
      if (!sim_.parts()->refusal(b->part, b->spec.io, v).empty()) return IoError::IllegalValue;
    } else if (b->spec.source == IoEntry::Source::Place && b->amount) {
      // what the kernel would refuse: below 0, more than the capacity less the room promised
      const net::Fluid& fluid = *sim_.net().fluid();
      const double capacity = fluid.places[static_cast<std::size_t>(fluid.of_place[b->probe.place])].capacity;
      if (v < 0 || v + sim_.kernel().amountReserved(b->probe.place) > capacity) return IoError::IllegalValue;
    } else if (b->spec.source == IoEntry::Source::Place) {
      if (v < 0 || std::floor(v) != v || v > 9.0e15) return IoError::IllegalValue;  // whole, 0 to 2^53
    } else if (const scene::Node* node = sim_.plant()->resolve(b->node)) {
      if (b->kind == scene::FieldKind::Int && std::abs(v) > 9.0e15) return IoError::IllegalValue;
      if (!scene::refusal(*node, b->field, fieldValue(b->kind, v), sim_.model().settings.angles).empty()) {
        return IoError::IllegalValue;
      }
    }
    writes.push_back({b, v});
    a += static_cast<std::uint32_t>(b->width());
  }
  for (const auto& w : writes) {
    Bound& b = *w.b;
    b.writer = client;
    if (b.spec.source == IoEntry::Source::Part) {
      std::string why;
      if (!sim_.parts()->write(b.part, b.spec.io, w.value, why)) return IoError::IllegalValue;
    } else if (b.spec.source == IoEntry::Source::Place && b.amount) {
      if (!sim_.kernel().setAmount(b.probe.place, w.value).empty()) return IoError::IllegalValue;
    } else if (b.spec.source == IoEntry::Source::Place) {
      if (!sim_.kernel().setMarking(b.slot, static_cast<std::int64_t>(w.value)).empty()) return IoError::IllegalValue;
    } else if (scene::Node* node = sim_.plant()->resolve(b.node)) {
      if (!physics::assignField(*node, b.field, fieldValue(b.kind, w.value), sim_.model().settings.angles, sim_.physics())
               .empty()) {
        return IoError::IllegalValue;
      }
    }
    noteWrite(b, w.value);
  }
  askSteps(steps);  // the steps show in the trace as steps
  return IoError::None;
}

std::vector<IoMap::Row> IoMap::rows() const {
  std::vector<Row> out;
  for (const Bound& b : bound_) {
    Row r;
    r.table = b.spec.table;
    r.address = b.spec.address;
    const IoEntry& e = b.spec;
    r.name = ioEntryName(e);
    r.what = ioWhat(e);
    if (e.table == IoTable::InputRegisters || e.table == IoTable::HoldingRegisters) {
      std::vector<std::string> parts;
      if (e.scale != 1.0) parts.push_back("x " + core::formatDouble(e.scale));
      if (!e.unit.empty()) parts.push_back(e.unit);
      if (e.type != IoDataType::Int16) parts.emplace_back(ioDataTypeName(e.type));
      for (const auto& p : parts) r.wire += (r.wire.empty() ? "" : " ") + p;
    }
    r.value = value(b);
    const std::uint64_t w = encode(b);
    const IoDataType type = isBit(e.table) ? IoDataType::Boolean : e.type;
    switch (type) {
      case IoDataType::Boolean:
      case IoDataType::Int16:
      case IoDataType::UInt16:
      case IoDataType::Int32:
      case IoDataType::UInt32: r.raw = static_cast<std::int64_t>(wireNumber(type, w)); break;
      case IoDataType::Float:
      case IoDataType::Double: r.raw = static_cast<std::int64_t>(w); break;
    }
    r.writer = b.writer;
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace gdpn::model
