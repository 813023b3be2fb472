#pragma once
/// \file
/// Parts: page types that bring a machine (their `scene`), numbers set per instance (their
/// `params`: a belt's length, a pusher's stroke), named inputs and outputs (their `io`, as a
/// PLC's I/O list names them) and, for the palette, a name, a version, a group and a picture
/// (their `part` section). docs/parts.md lists the parts gdpn ships; docs/format.md the keys.

#include <cstdint>
#include <string>
#include <vector>

#include "gdpn/core/diagnostics.h"
#include "gdpn/model/param.h"

namespace gdpn::model {

/// Which way one of a part's I/O goes, seen from the controller, as a PLC's I/O list says it.
enum class IoDirection : std::uint8_t {
  Input,   ///< the plant tells the controller (a sensor: a limit switch, a photo-eye)
  Output,  ///< the controller drives the plant (an actuator: a valve, a motor, a lamp)
};

/// `input` or `output`.
const char* ioDirectionName(IoDirection direction);

/// What one of a part's I/O carries.
enum class IoSignal : std::uint8_t {
  Digital,  ///< a bit: 1 or 0
  Analog,   ///< a number in its unit
};

/// `digital` or `analog`.
const char* ioSignalName(IoSignal signal);

/// One named input or output of a part, bound to a sensor's channel or an actuator's field of
/// the part's scene.
struct PartIoSpec {
  std::string name;                          ///< an identifier: `front_limit`, `extend`
  IoDirection direction = IoDirection::Input;  ///< which way it goes
  IoSignal signal = IoSignal::Digital;       ///< a bit or a number
  std::string unit;                          ///< an analogue value's unit, for people ("m/s")
  std::string description;                   ///< what it means, for people
  std::string node;                          ///< the node it is bound to, a path in the part's scene
  std::string of;                            ///< an input's quantity (as a signal's `of`: `active`, `reading`, a channel, a field)
  std::string field;                         ///< an output's field of the node
  /// a digital output's values for 1 and for 0, one text per number of the field (a number, a
  /// `$param` or an `=expression` of the part's parameters); empty: 1 and 0 (true and false)
  std::vector<std::string> on, off;
  core::SourceLoc loc;                       ///< where it is declared
  friend bool operator==(const PartIoSpec& a, const PartIoSpec& b) {
    return a.name == b.name && a.direction == b.direction && a.signal == b.signal && a.unit == b.unit &&
           a.description == b.description && a.node == b.node && a.of == b.of && a.field == b.field &&
           a.on == b.on && a.off == b.off;
  }
};

/// A part a control pattern works with besides the one it controls (its `uses`): a role
/// (`eye`, `belt`) that any part instance with the named I/O fills.
struct PartUse {
  std::string name;              ///< the role: an identifier (`eye`)
  std::vector<std::string> io;   ///< the I/O a part needs to fill it (`[detected, colour]`)
  bool optional = false;         ///< an instance may leave it unfilled (scripts see None)
  std::string description;       ///< what it is for, for people
  core::SourceLoc loc;           ///< where it is declared
  friend bool operator==(const PartUse& a, const PartUse& b) {
    return a.name == b.name && a.io == b.io && a.optional == b.optional && a.description == b.description;
  }
};

/// What makes a page type a part: its parameters, its I/O and how the palette shows it.
struct PartSpec {
  bool listed = false;              ///< it has a `part` section: the palette offers it
  int version = 1;                  ///< grows with each change a model using it should take
  std::string group;                ///< where the palette lists it ("Conveyors", "Sensors")
  std::string picture;              ///< a PNG beside the file that holds it, for the palette
  std::string control;              ///< the page type of its usual control (its control pattern); "" none
  std::string controls;             ///< a control pattern's: the part type it controls; "" none
  std::vector<Param> params;        ///< numbers each instance may set (`params: {length: 3}`)
  std::vector<PartIoSpec> io;       ///< its inputs and outputs, in declaration order
  std::vector<PartUse> uses;        ///< a control pattern's: the other parts it works with, by role
  core::SourceLoc loc;              ///< where the page type is declared
  /// The role named `name`, or null.
  [[nodiscard]] const PartUse* findUse(const std::string& name) const {
    for (const auto& u : uses) {
      if (u.name == name) return &u;
    }
    return nullptr;
  }
  /// Whether it has every I/O `use` needs.
  [[nodiscard]] bool fills(const PartUse& use) const {
    for (const auto& n : use.io) {
      if (findIo(n) == nullptr) return false;
    }
    return true;
  }
  /// The I/O named `name`, or null.
  [[nodiscard]] const PartIoSpec* findIo(const std::string& name) const {
    for (const auto& i : io) {
      if (i.name == name) return &i;
    }
    return nullptr;
  }
  friend bool operator==(const PartSpec& a, const PartSpec& b) {
    return a.listed == b.listed && a.version == b.version && a.group == b.group && a.picture == b.picture &&
           a.control == b.control && a.controls == b.controls && a.params == b.params && a.io == b.io && a.uses == b.uses;
  }
};

}  // namespace gdpn::model
