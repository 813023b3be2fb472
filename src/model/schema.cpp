// The model file's keys, each described once: one table per section. Units: seconds, metres;
// editor units for `at` (one unit is the distance between neighbours).

#include "gdpn/model/schema.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "gdpn/core/assert.h"
#include "gdpn/core/text.h"
#include "gdpn/net/net.h"
#include "gdpn/net/script_kind.h"
#include "gdpn/net/slot.h"
#include "gdpn/net/spec.h"
#include "gdpn/model/part.h"

namespace gdpn::model::schema {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// A key of `type` with its default (as written in a file; empty: none) and its help.
KeyDesc k(std::string name, ValueType type, std::string initial, std::string help) {
  KeyDesc d;
  d.name = std::move(name);
  d.type = type;
  d.initial = std::move(initial);
  d.help = std::move(help);
  return d;
}

/// `d` with the docs' type column written as `form`.
KeyDesc form(KeyDesc d, std::string text) {
  d.form = std::move(text);
  return d;
}

/// `d` holding values from `min` to `max` (open ends when asked), in `unit`.
KeyDesc range(KeyDesc d, double min, double max, std::string unit = {}, bool min_open = false, bool max_open = false) {
  d.min = min;
  d.max = max;
  d.min_open = min_open;
  d.max_open = max_open;
  d.unit = std::move(unit);
  return d;
}

/// `d` in `unit`, unbounded.
KeyDesc unit(KeyDesc d, std::string text) {
  d.unit = std::move(text);
  return d;
}

/// A Word key: one of `choices`, the first the default.
KeyDesc word(std::string name, std::vector<std::string> choices, std::string help) {
  KeyDesc d = k(std::move(name), ValueType::Word, choices.front(), std::move(help));
  d.choices = std::move(choices);
  return d;
}

/// The key of script kind `kind` (its name is the script table's: net::kScriptKinds).
KeyDesc script(net::ScriptKind kind, std::string form_text, std::string help) {
  const auto& info = net::info(kind);
  return form(k(std::string(info.key), info.expression ? ValueType::Expression : ValueType::Script, "", std::move(help)),
              std::move(form_text));
}

/// An io entry's key, taken by the entries of `tables`.
KeyDesc io(KeyDesc d, std::initializer_list<IoTable> tables) {
  for (const IoTable t : tables) d.tables = static_cast<std::uint8_t>(d.tables | (1U << static_cast<unsigned>(t)));
  return d;
}

const std::string kAtHelp =
    "position in the net editor, editor units: x right, y down; one unit is the distance between neighbours (an "
    "inch, 72 points, in `gdpn render --net`); a page where any place, transition or instance lacks `at` is laid out "
    "by Graphviz";

std::vector<KeyDesc> modelKeys() {
  return {
      k("gdpn", ValueType::Integer, "", "format version; this gdpn reads 1"),
      k("description", ValueType::Text, "", "free text"),
      form(k("settings", ValueType::Map, "", "how a run steps, draws and reads angles (below)"), "map"),
      form(k("params", ValueType::Map, "", "named values that fields and scripts read, and runs may set (below)"),
           "map name → parameter"),
      form(k("signals", ValueType::Map, "", "what a run records over time when asked (below)"), "map name → signal"),
      form(k("io", ValueType::Map, "", "the plant and the net as the four Modbus tables, for a controller outside (below)"),
           "map"),
      form(k("colours", ValueType::Map, "",
             "colour sets, the types of value tokens, in order (a set may name those before it): a word `bool`, "
             "`int`, `string` or `dot` (that built-in set under a name of its own), or one of the forms below "
             "(*Colour sets*)"),
           "map name → word or colour set"),
      form(k("variables", ValueType::Map, "",
             "the variables of arc inscriptions and conditions, each of a colour set (*Colour sets*)"),
           "map name → colour set"),
      form(k("pages", ValueType::Map, "", "the top-level nets; constructs are named `page/name`"), "map name → page"),
      form(k("page_types", ValueType::Map, "", "pages to instantiate"), "map name → page type"),
      form(k("fusion", ValueType::Map, "",
             "fusion sets: places that are one place, each a member by its `fusion` key; `global`: one place for "
             "the whole net; `instance`: members on one page or page type, one place per instance of it (*Fusion "
             "places*)"),
           "map name → `global` or `instance`"),
      form(k("scene", ValueType::List, "", "the plant: a tree of typed nodes (below)"), "list of nodes"),
      form(k("scripts", ValueType::Map, "", "`globals`: Python run once at load; every script sees its names"), "map"),
  };
}

std::vector<KeyDesc> settingsKeys() {
  return {
      range(k("dt", ValueType::Number, "1/60", "the step"), 0, kInf, "s", true),
      range(k("seed", ValueType::Integer, "1", "the seed of the model's random generator"), 0, kInf),
      range(k("until", ValueType::Number, "", "the default end of a run (none: a run goes on until stopped)"), 0, kInf,
            "s"),
      word("angles", {"degrees", "radians"}, "the unit of every angle the file and its scripts write"),
      word("ties", {"order", "random"},
           "how transitions of one priority enabled in the same step are ordered: in declaration order, or drawn "
           "from the seed (semantics.md, *Ties*)"),
  };
}

std::vector<KeyDesc> paramKeys() {
  return {
      k("value", ValueType::Number, "",
        "the parameter's value: written without a point, a whole number (at most 2^53) that only whole numbers may "
        "set later"),
      k("unit", ValueType::Text, "", "for people: gdpn converts nothing"),
      k("description", ValueType::Text, "", "free text"),
  };
}

std::vector<KeyDesc> signalKeys() {
  return {
      k("place", ValueType::Name, "", "the tokens on the place (qualified name), all its slots together"),
      k("value", ValueType::Inscription, "",
        "with `place`: the tokens of this one value on the place's value slot (the place has one), a value of its "
        "colour set (`lathe`, `(lathe, shaft)`, `{id = 1, kind = shaft}`)"),
      k("node", ValueType::Name, "", "a node's path: what it reads is `of`"),
      k("of", ValueType::Text, "",
        "with `node`: `position`, `velocity`, `angle`, `rate`, `reading`, `active`, one axis (`position.x`) or a field"),
      k("expression", ValueType::Expression, "", "a number from the model's globals, as scripts see them"),
      range(k("every", ValueType::Number, "", "the sampling period (none: every step)"), 0, kInf, "s", true),
  };
}

std::vector<KeyDesc> ioKeys() {
  std::vector<KeyDesc> keys = {
      range(k("lockstep", ValueType::Integer, "",
              "a holding register that takes a number of steps for `gdpn run --lockstep`"),
            0, 65535),
  };
  const IoTable tables[] = {IoTable::DiscreteInputs, IoTable::InputRegisters, IoTable::Coils, IoTable::HoldingRegisters};
  const char* helps[] = {"bits the controller reads", "16-bit words the controller reads",
                         "bits the controller writes", "words the controller writes"};
  for (std::size_t i = 0; i < std::size(tables); ++i) {
    keys.push_back(form(k(ioTableKey(tables[i]), ValueType::Map, "", helps[i]), "map address → entry"));
  }
  return keys;
}

std::vector<KeyDesc> ioEntryKeys() {
  using enum IoTable;
  return {
      io(k("name", ValueType::Name, "",
           "the point's name, an identifier unique in the section, as OPC UA serves it (none: derived from what it "
           "maps, *Names*)"),
         {DiscreteInputs, InputRegisters, Coils, HoldingRegisters}),
      io(k("place", ValueType::Name, "", "a place: its tokens, all slots together"),
         {DiscreteInputs, InputRegisters, Coils, HoldingRegisters}),
      io(k("value", ValueType::Inscription, "",
           "with `place`: the tokens of this one value on the place's value slot (as a signal's `value`)"),
         {DiscreteInputs, InputRegisters}),
      io(k("node", ValueType::Name, "", "a node's path"), {DiscreteInputs, InputRegisters, Coils, HoldingRegisters}),
      io(k("part", ValueType::Name, "", "a part instance (its name, or qualified: `main/pusher1`): with `io`"),
         {DiscreteInputs, InputRegisters, Coils, HoldingRegisters}),
      io(k("io", ValueType::Name, "",
           "the part's input (for `discrete_inputs`, `input_registers`) or output (`coils`, `holding_registers`)"),
         {DiscreteInputs, InputRegisters, Coils, HoldingRegisters}),
      io(k("of", ValueType::Text, "", "what of the node is read (as a signal's `of`)"),
         {DiscreteInputs, InputRegisters}),
      io(k("key", ValueType::Text, "", "a KeyboardSensor's key held down"), {DiscreteInputs}),
      io(k("field", ValueType::Text, "", "the node's field the controller sets"), {Coils, HoldingRegisters}),
      io(k("on", ValueType::Number, "1", "on a number field: the value for 1"), {Coils}),
      io(k("off", ValueType::Number, "0", "on a number field: the value for 0"), {Coils}),
      io(k("scale", ValueType::Number, "1", "the word is the value times this (not 0), rounded"),
         {InputRegisters, HoldingRegisters}),
      io(k("unit", ValueType::Text, "", "for people, the word's unit after scaling"),
         {InputRegisters, HoldingRegisters}),
      io(word("type",
              {ioDataTypeName(IoDataType::Int16), ioDataTypeName(IoDataType::UInt16), ioDataTypeName(IoDataType::Int32),
               ioDataTypeName(IoDataType::UInt32), ioDataTypeName(IoDataType::Float), ioDataTypeName(IoDataType::Double)},
              "the number's type, OPC UA's name; on Modbus, words high first: Int16, UInt16 one, Int32, UInt32, Float "
              "two, Double four (the old `int16`, `uint16`, `int32`, `uint32`, `float32` still read; *Types*)"),
         {InputRegisters, HoldingRegisters}),
      io(k("opcua", ValueType::Text, "",
           "client mode: the PLC's OPC UA node it is mapped to, a NodeId (`ns=1;s=Eye`)"),
         {DiscreteInputs, InputRegisters, Coils, HoldingRegisters}),
  };
}

/// The keys of a page, or of a page type (`type`) with its references and scene.
std::vector<KeyDesc> pageKeys(bool type) {
  std::vector<KeyDesc> keys = {k("description", ValueType::Text, "", "free text")};
  if (type) {
    keys.push_back(form(k("references", ValueType::List, "", "the places published as ports"), "list of place names"));
  }
  keys.push_back(form(k("places", ValueType::Map, "", "the page's places"), "map name → place"));
  keys.push_back(form(k("transitions", ValueType::Map, "", "the page's transitions"), "map name → transition"));
  keys.push_back(form(k("instances", ValueType::Map, "", "instances of page types on this page"), "map name → instance"));
  keys.push_back(form(k("arcs", ValueType::List, "", "the page's arcs"), "list of arcs"));
  if (type) {
    keys.push_back(form(k("scene", ValueType::List, "",
                          "the machine it controls: each instance gets a copy under a Transform named after it"),
                        "list of nodes"));
    keys.push_back(form(k("part", ValueType::Map, "", "makes it a part the palette offers: version, group, picture, "
                                                      "control pattern (*Parts*)"),
                        "map"));
    keys.push_back(form(k("params", ValueType::Map, "",
                          "numbers each instance may set (`params: {length: 3}`), as the model's `params` are written; "
                          "its scene's fields refer to them as `$name` or in `=expressions`"),
                        "map name → parameter"));
    keys.push_back(form(k("io", ValueType::Map, "", "its named inputs and outputs, each bound to a node of its scene"),
                        "map name → I/O"));
    keys.push_back(form(k("uses", ValueType::Map, "",
                          "a control pattern's: the other parts it works with, each a role that any part with the "
                          "named I/O fills (a photo-eye, a belt); scripts reach them as `self.uses.ROLE`"),
                        "map role → use"));
  }
  return keys;
}

std::vector<KeyDesc> placeKeys() {
  using net::ScriptKind;
  const std::string slot_script = "script, or map slot → script";
  // `slots` maps slot names to the words of net::SlotKind
  KeyDesc slots = k("slots", ValueType::Map, "", "declares slot kinds explicitly");
  slots.choices = {net::slotKindName(net::SlotKind::Control), net::slotKindName(net::SlotKind::Node),
                   net::slotKindName(net::SlotKind::Sensor), net::slotKindName(net::SlotKind::Value)};
  slots.form = "map slot → " + choiceList(slots, "`");
  return {
      k("description", ValueType::Text, "", "free text"),
      k("fusion", ValueType::Name, "",
        "the fusion set it is a member of: it is one place with the set's other members; one member declares "
        "the keys below (the others name the set alone) (*Fusion places*)"),
      slots,
      form(k("colour", ValueType::Name, "",
             "the colour set of a value slot, which holds a multiset of its values: a slot with a colour is a value "
             "slot (a name alone means `a0`)"),
           "name, or map slot → name"),
      range(form(k("tokens", ValueType::Integer, "0",
                   "initial marking. An integer is a count on `a0`; a list of node paths (`[box1, line/box2]`) puts "
                   "node tokens on `a0`; a map names slots: `{a0: 2, d0: [box1, box2]}`"),
                 "integer, list, or map slot → integer or list"),
            0, kInf),
      form(k("values", ValueType::Inscription, "",
             "a value slot's initial marking, a multiset in the inscription language: `all`, `1'p1 ++ 2'p3`, "
             "`(1, \"a\")` (a text alone means `a0`)"),
           "inscription, or map slot → inscription"),
      range(form(k("capacity", ValueType::Integer, "",
                   "capacity per slot; unbounded when absent; an integer means `a0`"),
                 "integer or map slot → integer"),
            0, kInf),
      form(k("sensors", ValueType::Map, "", "binds sensor slots to sensor nodes (*Sensors in the net*)"),
           "map slot → node path"),
      form(k("continuous", ValueType::Map, "",
             "makes it a continuous place holding a real amount, not tokens (hybrid nets, *Continuous places*): "
             "`true`, or `{amount, capacity, unit, drives}` (below)"),
           "`true` or map"),
      script(ScriptKind::OnDeposit, slot_script, "runs per token that arrives (a script alone means slot `a0`)"),
      script(ScriptKind::OnRemove, slot_script, "runs per token that leaves (a script alone means slot `a0`)"),
      script(ScriptKind::OnEnter, slot_script,
             "a sensor slot's: runs per item that entered its Region (a script alone means the first sensor slot)"),
      script(ScriptKind::OnExit, slot_script, "a sensor slot's: runs per item that left its Region"),
      script(ScriptKind::OnSample, slot_script, "a sensor slot's: runs every step while the sensor reports anything"),
      script(ScriptKind::OnChange, slot_script, "a value sensor's slot: runs when its value changes (sees `value`)"),
      form(k("at", ValueType::Position, "", kAtHelp), "`[x, y]`"),
  };
}

std::vector<KeyDesc> transitionKeys() {
  using net::ScriptKind;
  return {
      k("description", ValueType::Text, "", "free text"),
      unit(form(k("duration", ValueType::Number, "",
                  "`2.5`, `{uniform: [lo, hi]}`, `{normal: [mean, sd]}` (redrawn below 0), `{exponential: mean}`; "
                  "`0` written (or a parameter of 0) makes the transition immediate: it starts and completes within "
                  "the firing phase (semantics.md); without a duration, one step"),
                "number, or one law"),
           "s"),
      k("priority", ValueType::Integer, "0", "higher starts first"),
      range(k("probability", ValueType::Number, "1", "chance to start in a step while enabled"), 0, 1, "", true),
      range(form(k("servers", ValueType::Integer, "1",
                   "how many occurrences may run at once: a machine with two spindles is `servers: 2`, a conveyor "
                   "section carrying any number of parts is `unlimited` (semantics.md, *Servers*); `unlimited` needs "
                   "an input arc that takes tokens"),
                 "whole number or `unlimited`"),
            1, static_cast<double>(net::kMostServers)),
      form(k("continuous", ValueType::Map, "",
             "makes it a continuous transition that flows at its rate, never fires (hybrid nets): `{rate: 0.5}`, "
             "`{rate: k * tank, reads: {...}}` (below); discrete places switch it by test and inhibitor arcs"),
           "map"),
      k("when", ValueType::Inscription, "",
        "a condition over the variables of its arcs' inscriptions, in the inscription language (`x <> y and n < "
        "3`), not Python: a binding occurs only where it is true"),
      script(ScriptKind::Guard, "expression", "the transition may start only while it is true"),
      script(ScriptKind::PreFire, "script", "runs when an occurrence starts"),
      script(ScriptKind::InFire, "script", "runs in every step of an occurrence (`self.elapsed`, `self.progress`)"),
      script(ScriptKind::PostFire, "script", "runs when an occurrence completes, before its deposits"),
      form(k("at", ValueType::Position, "", kAtHelp), "`[x, y]`"),
  };
}

std::vector<KeyDesc> arcKeys() {
  using net::ScriptKind;
  return {
      k("from", ValueType::Name, "", "one end is a transition; the other a place or a link `instance/reference`"),
      k("to", ValueType::Name, "", "the other end"),
      word("kind", {net::arcKindName(net::ArcKind::Normal), net::arcKindName(net::ArcKind::Test),
                    net::arcKindName(net::ArcKind::Inhibitor)},
           "input arcs only"),
      range(form(k("weight", ValueType::Integer, "1",
                   "tokens per slot; an integer means `a0`; on an arc with a continuous place, a number > 0 in the "
                   "place's unit (`2.5`)"),
                 "integer or map slot → integer; a number"),
            1, static_cast<double>(net::kMaxWeight)),
      form(k("inscription", ValueType::Inscription, "",
             "on a value slot: the multiset it takes or puts, in the inscription language over the variables "
             "(`x`, `(p, n+1)`, `2'x ++ y`; a text alone means `a0`); not with a `weight` on the same slot"),
           "inscription, or map slot → inscription"),
      script(ScriptKind::Predicate, "expression, or map slot → expression",
             "on a node slot of an input arc: which tokens are eligible (an expression alone means the arc's one slot)"),
      script(ScriptKind::Condition, "expression, or map slot → expression",
             "on an arc from a place's sensor slot: the transition may start only while it is true; it sees the "
             "sensor under its slot's name and as `value` (an expression alone means slot `c0`)"),
      form(k("via", ValueType::List, "",
             "its route in the net editor: bend points from `from` to `to`, editor units as for `at`; the arc is "
             "drawn from its source's outline through each to its target's outline (none: straight, or as Graphviz "
             "routes it)"),
           "list of `[x, y]`"),
      form(k("label_at", ValueType::Position, "",
             "where its inscription (the weight) stands: an offset from the middle of the drawn arc (half its length "
             "along it), editor units, as PNML's annotation offset (none: beside the arc where it fits)"),
           "`[dx, dy]`"),
  };
}

std::vector<KeyDesc> instanceKeys() {
  return {
      k("type", ValueType::Name, "", "the page type it instantiates"),
      form(k("at", ValueType::Position, "", "position in the net editor, editor units, as for places"), "`[x, y]`"),
      unit(form(k("translation", ValueType::Vector, "[0, 0, 0]", "where the copy of the type's scene stands"),
                "`[x, y, z]`"),
           "m"),
      form(k("rotation", ValueType::Vector, "[0, 0, 1, 0]", "how the copy of the type's scene is turned: axis and degrees"),
           "`[x, y, z, angle]`"),
      form(k("params", ValueType::Map, "", "values for the type's parameters (the others keep the type's)"),
           "map name → number"),
      k("part", ValueType::Name, "", "a control pattern's: the part instance on this page it controls"),
      form(k("uses", ValueType::Map, "", "a control pattern's: the part instance on this page that fills each of its roles"),
           "map role → instance name"),
  };
}

std::vector<KeyDesc> partKeys() {
  return {
      range(k("version", ValueType::Integer, "1", "grows with each change a model using the part should take"), 1, kInf),
      k("group", ValueType::Text, "", "where the palette lists it: `Conveyors`, `Sensors`, `Actuators`, `Items`"),
      form(k("picture", ValueType::Name, "", "a PNG of it, relative to the file, for the palette"), "path"),
      k("control", ValueType::Name, "", "the page type of its usual control (a control pattern), offered when it is placed"),
      k("controls", ValueType::Name, "",
        "a control pattern's: the part type it controls; each instance names its part with `part:`"),
  };
}

std::vector<KeyDesc> partIoKeys() {
  return {
      word("direction", {ioDirectionName(IoDirection::Input), ioDirectionName(IoDirection::Output)},
           "seen from the controller: an input tells it (a sensor), an output drives the plant (an actuator)"),
      word("signal", {ioSignalName(IoSignal::Digital), ioSignalName(IoSignal::Analog)}, "a bit, or a number in `unit`"),
      k("unit", ValueType::Text, "", "an analogue value's unit, for people"),
      k("description", ValueType::Text, "", "what it means, for people"),
      k("node", ValueType::Name, "", "the node it is bound to: a path in the part's scene (an output's may hold `*` for every child: it sets each node matched)"),
      k("of", ValueType::Text, "", "an input's: what of the node is read (as a signal's `of`)"),
      k("field", ValueType::Text, "", "an output's: the node's field it sets"),
      form(k("on", ValueType::Number, "1", "a digital output's value for 1 (a vector field's: three numbers)"),
           "number or list"),
      form(k("off", ValueType::Number, "0", "a digital output's value for 0"), "number or list"),
  };
}

std::vector<KeyDesc> partUseKeys() {
  return {
      form(k("io", ValueType::List, "", "the I/O a part needs to fill the role (`[detected, colour]`)"), "list of names"),
      word("optional", {"false", "true"}, "an instance may leave it unfilled (scripts see None)"),
      k("description", ValueType::Text, "", "what it is for, for people"),
  };
}

std::vector<KeyDesc> scriptsKeys() {
  return {script(net::ScriptKind::Globals, "script", "Python run once at load; every script sees its names")};
}

std::vector<KeyDesc> scriptFileKeys() {
  return {
      form(k("file", ValueType::Name, "", "the `.py` file, relative to the model; it runs once, in the model's namespace"),
           "path"),
      k("function", ValueType::Name, "", "the function called (not for `globals`)"),
  };
}

std::vector<KeyDesc> durationKeys() {
  return {
      unit(form(k("uniform", ValueType::Vector, "", "drawn evenly from lo up to hi"), "`[lo, hi]`"), "s"),
      unit(form(k("normal", ValueType::Vector, "", "drawn from a normal law, redrawn below 0"), "`[mean, sd]`"), "s"),
      unit(form(k("exponential", ValueType::Number, "", "drawn from an exponential law of this mean"), "mean"), "s"),
  };
}

std::vector<KeyDesc> colourKeys() {
  return {
      form(k("range", ValueType::Vector, "", "the whole numbers from lo to hi, both in (lo at most hi)"), "`[lo, hi]`"),
      form(k("enum", ValueType::List, "", "named constants, in order (each a name, once over every set)"),
           "list of names"),
      form(k("cyclic", ValueType::List, "",
             "an enumeration whose last constant's successor is the first (`succ`, `pred` wrap around)"),
           "list of names"),
      form(k("product", ValueType::List, "", "tuples `(a, b)` of the sets named, in order"), "list of colour sets"),
      form(k("record", ValueType::Map, "", "records `{f = a, g = b}`: fields, in the order written, each of a set"),
           "map field → colour set"),
  };
}

std::vector<KeyDesc> continuousKeys() {
  return {
      range(k("amount", ValueType::Number, "0", "the amount it holds at the start, in its unit"), 0, kInf),
      range(k("capacity", ValueType::Number, "", "the most it holds, in its unit (none: unbounded)"), 0, kInf, "", true),
      k("unit", ValueType::Text, "", "for people: `L`, `kg`, `Ah`; the report, the IDE and the trace's texts show it"),
      form(k("drives", ValueType::List, "",
             "plant fields the amount sets after every step: `{node: tank/liquid, field: size.z, scale: 0.01}` "
             "(*Drives*)"),
           "list of drives"),
  };
}

std::vector<KeyDesc> flowKeys() {
  return {
      form(unit(k("rate", ValueType::Expression, "",
                  "how fast it flows: a number, or an expression (`+ - * /`, `min`, `max`, `sqrt`, `exp`, ...) over "
                  "the amounts of the continuous places on its page (by name), its `reads` and the model's "
                  "parameters; each input arc takes, each output arc puts, its weight times the rate; below 0 counts "
                  "as 0"),
                "units/s"),
           "number or expression"),
      form(k("reads", ValueType::Map, "",
             "numbers of the plant the rate names: `{opening: {node: plant/valve, of: angle}}` (what a signal's "
             "`node` and `of` read), each read at the end of a step and held over the next"),
           "map name → `{node, of}`"),
  };
}

std::vector<KeyDesc> flowReadKeys() {
  return {
      k("node", ValueType::Name, "", "a node's path (relative to the instance in a page type)"),
      k("of", ValueType::Text, "", "what of it: `reading`, `angle`, `rate`, `position.z`, a field (as a signal's `of`)"),
  };
}

std::vector<KeyDesc> driveKeys() {
  return {
      k("node", ValueType::Name, "", "a node's path (relative to the instance in a page type)"),
      k("field", ValueType::Text, "", "its number field (`height`, `radius`) or one component of a vector (`size.z`, `translation.x`)"),
      k("scale", ValueType::Number, "1", "field units per unit of amount"),
      k("offset", ValueType::Number, "0", "the field's value at amount 0"),
  };
}

std::vector<KeyDesc> build(Section section) {
  switch (section) {
    case Section::Model: return modelKeys();
    case Section::Settings: return settingsKeys();
    case Section::Param: return paramKeys();
    case Section::Signal: return signalKeys();
    case Section::Io: return ioKeys();
    case Section::IoEntry: return ioEntryKeys();
    case Section::Page: return pageKeys(false);
    case Section::PageType: return pageKeys(true);
    case Section::Place: return placeKeys();
    case Section::Transition: return transitionKeys();
    case Section::Arc: return arcKeys();
    case Section::Instance: return instanceKeys();
    case Section::Scripts: return scriptsKeys();
    case Section::ScriptFile: return scriptFileKeys();
    case Section::Duration: return durationKeys();
    case Section::Part: return partKeys();
    case Section::PartIo: return partIoKeys();
    case Section::PartUse: return partUseKeys();
    case Section::Colour: return colourKeys();
    case Section::Continuous: return continuousKeys();
    case Section::Flow: return flowKeys();
    case Section::FlowRead: return flowReadKeys();
    case Section::Drive: return driveKeys();
  }
  return {};
}

/// A bound as the docs write it: whole numbers in full (1000000, not 1e+06).
std::string boundText(double x) {
  if (x == std::floor(x) && std::fabs(x) < 1e15) return std::to_string(static_cast<long long>(x));
  return core::formatDouble(x);
}

}  // namespace

std::string_view valueTypeName(ValueType type) {
  switch (type) {
    case ValueType::Integer: return "integer";
    case ValueType::Number: return "number";
    case ValueType::Text: return "text";
    case ValueType::Word: return "word";
    case ValueType::Name: return "name";
    case ValueType::Position: return "`[x, y]`";
    case ValueType::Vector: return "list of numbers";
    case ValueType::Script: return "script";
    case ValueType::Expression: return "expression";
    case ValueType::Inscription: return "inscription";
    case ValueType::Map: return "map";
    case ValueType::List: return "list";
  }
  return "?";
}

const std::vector<KeyDesc>& keys(Section section) {
  static const std::vector<std::vector<KeyDesc>> tables = [] {
    std::vector<std::vector<KeyDesc>> t;
    for (const Section s : kSections) t.push_back(build(s));
    return t;
  }();
  return tables[static_cast<std::size_t>(section)];
}

const std::vector<std::string>& keyNames(Section section) {
  static const std::vector<std::vector<std::string>> names = [] {
    std::vector<std::vector<std::string>> n;
    for (const Section s : kSections) {
      n.emplace_back();
      for (const auto& d : keys(s)) n.back().push_back(d.name);
    }
    return n;
  }();
  return names[static_cast<std::size_t>(section)];
}

std::vector<std::string> ioEntryKeyNames(IoTable table) {
  std::vector<std::string> names;
  for (const auto& d : keys(Section::IoEntry)) {
    if ((d.tables >> static_cast<unsigned>(table)) & 1U) names.push_back(d.name);
  }
  return names;
}

void inSchemaOrder(Section section, const std::vector<KeyWriter>& writers) {
  const auto& names = keyNames(section);
  std::vector<const KeyWriter*> by_key(names.size(), nullptr);
  for (const auto& w : writers) {
    const auto it = std::find(names.begin(), names.end(), w.key);
    GDPN_ASSERT(it != names.end(), "a writer writes only keys the schema describes");
    auto& slot = by_key[static_cast<std::size_t>(it - names.begin())];
    GDPN_ASSERT(slot == nullptr, "one writer per key");
    slot = &w;
  }
  for (const KeyWriter* w : by_key) {
    if (w != nullptr) w->write();
  }
}

const KeyDesc& key(Section section, std::string_view name) {
  for (const auto& d : keys(section)) {
    if (d.name == name) return d;
  }
  GDPN_ASSERT(false, "the schema describes every key the code names");
  std::abort();
}

double defaultNumber(Section section, std::string_view name) {
  const auto value = core::parseNumber(key(section, name).initial);
  GDPN_ASSERT(value.has_value(), "a numeric key's default is a number");
  return *value;
}

std::vector<double> defaultNumbers(Section section, std::string_view name) {
  const std::string& text = key(section, name).initial;
  GDPN_ASSERT(text.size() >= 2 && text.front() == '[' && text.back() == ']', "a list key's default is a list");
  std::vector<double> out;
  std::string_view rest = std::string_view(text).substr(1, text.size() - 2);
  while (!rest.empty()) {
    const auto comma = rest.find(',');
    std::string_view item = rest.substr(0, comma);
    while (!item.empty() && item.front() == ' ') item.remove_prefix(1);
    const auto value = core::parseNumber(item);
    GDPN_ASSERT(value.has_value(), "a list key's default is a list of numbers");
    out.push_back(*value);
    rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
  }
  return out;
}

bool inRange(const KeyDesc& key, double value) {
  if (!std::isfinite(value)) return false;
  const bool above = key.min_open ? value > key.min : value >= key.min;
  const bool below = key.max_open ? value < key.max : value <= key.max;
  return above && below;
}

std::string rangeText(const KeyDesc& key) {
  const bool low = std::isfinite(key.min), high = std::isfinite(key.max);
  if (low && high) {
    return std::string("in ") + (key.min_open ? "(" : "[") + boundText(key.min) + ", " +
           boundText(key.max) + (key.max_open ? ")" : "]");
  }
  if (low) return (key.min_open ? "> " : "≥ ") + boundText(key.min);
  if (high) return (key.max_open ? "< " : "≤ ") + boundText(key.max);
  return {};
}

std::string choiceList(const KeyDesc& key, std::string_view quote, std::string_view last) {
  std::string out;
  for (std::size_t i = 0; i < key.choices.size(); ++i) {
    out += std::string(i == 0 ? "" : i + 1 == key.choices.size() ? last : ", ") + std::string(quote) + key.choices[i] +
           std::string(quote);
  }
  return out;
}

std::string_view sectionName(Section section) {
  switch (section) {
    case Section::Model: return "model";
    case Section::Settings: return "settings";
    case Section::Param: return "param";
    case Section::Signal: return "signal";
    case Section::Io: return "io";
    case Section::IoEntry: return "io_entry";
    case Section::Page: return "page";
    case Section::PageType: return "page_type";
    case Section::Place: return "place";
    case Section::Transition: return "transition";
    case Section::Arc: return "arc";
    case Section::Instance: return "instance";
    case Section::Scripts: return "scripts";
    case Section::ScriptFile: return "script_file";
    case Section::Duration: return "duration";
    case Section::Part: return "part";
    case Section::PartIo: return "part_io";
    case Section::PartUse: return "part_use";
    case Section::Colour: return "colour";
    case Section::Continuous: return "continuous";
    case Section::Flow: return "flow";
    case Section::FlowRead: return "flow_read";
    case Section::Drive: return "drive";
  }
  return "?";
}

std::string schemaMarkdown(Section section) {
  std::string out = "| key | type | unit | default | meaning |\n| --- | --- | --- | --- | --- |\n";
  for (const auto& d : keys(section)) {
    std::string type = d.form.empty() ? std::string(valueTypeName(d.type)) : d.form;
    if (d.type == ValueType::Word && d.form.empty()) type = choiceList(d, "`");
    if (const std::string r = rangeText(d); !r.empty()) type += ", " + r;
    if (d.tables != 0 && section == Section::IoEntry) {
      // which tables take the key
      std::string of;
      for (unsigned t = 0; t < 4; ++t) {
        if ((d.tables >> t) & 1U) of += std::string(of.empty() ? "" : ", ") + "`" + ioTableKey(static_cast<IoTable>(t)) + "`";
      }
      if (d.tables != 0xF) type += " (" + of + ")";
    }
    out += "| `" + d.name + "` | " + core::markdownCell(type) + " | " + core::markdownCell(d.unit) + " | " +
           (d.initial.empty() ? std::string() : "`" + core::markdownCell(d.initial) + "`") + " | " + core::markdownCell(d.help) + " |\n";
  }
  return out;
}

}  // namespace gdpn::model::schema
