#pragma once
/// \file
/// The editable description of a net: pages, page types, places, transitions, arcs and
/// instances, each with the source location it came from. Loaders (the model file, PNML)
/// fill it; `compile()` checks it and freezes it into a flat `Net`; savers write it back.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gdpn/core/diagnostics.h"
#include "gdpn/net/colour.h"
#include "gdpn/net/script_kind.h"
#include "gdpn/net/slot.h"

namespace gdpn::net {

using core::SourceLoc;

/// The law of a transition's duration and its parameters: what the kernel draws from (seconds).
struct DurationLaw {
  /// Which law the duration follows.
  enum class Law : std::uint8_t {
    Fixed,        ///< `a` seconds
    Uniform,      ///< uniform in [a, b) seconds
    Normal,       ///< normal with mean `a` and standard deviation `b` seconds, redrawn below 0
    Exponential,  ///< exponential with mean `a` seconds
    Immediate,    ///< no time at all: starts and completes within the firing phase (`duration: 0`)
  };
  Law law = Law::Fixed;  ///< the law
  double a = 0.0;        ///< first parameter, seconds
  double b = 0.0;        ///< second parameter, seconds (uniform, normal)

  /// True for a constant duration (an immediate one too: 0 s).
  [[nodiscard]] bool fixed() const { return law == Law::Fixed || law == Law::Immediate; }
};

/// A transition's duration as written: a constant or a distribution drawn at each start
/// (seconds), with where it was written and the model parameters it names.
struct Duration : DurationLaw {
  /// 0 s, fixed.
  Duration() = default;
  /// A duration of law `law` with parameters `a` and `b` (seconds), written at `where`.
  Duration(Law law_, double a_, double b_ = 0.0, SourceLoc where = {})
      : DurationLaw{law_, a_, b_}, loc(std::move(where)) {}
  SourceLoc loc;         ///< where it was written
  /// the model parameters `a` and `b` come from ("" for a number written as such)
  std::array<std::string, 2> params;

  friend bool operator==(const Duration& x, const Duration& y) {
    return x.law == y.law && x.a == y.a && x.b == y.b && x.params == y.params;
  }
};

/// A per-slot integer (a marking count, a capacity or an arc weight) with its location.
struct SlotCount {
  /// 0 tokens in a0.
  SlotCount() = default;
  /// `count` tokens in `slot_`, written at `where`, from parameter `from` ("" for none).
  SlotCount(SlotId slot_, std::int64_t count, SourceLoc where = {}, std::string from = {})
      : slot(slot_), value(count), loc(std::move(where)), param(std::move(from)) {}
  SlotId slot = kDefaultSlot;  ///< which slot
  std::int64_t value = 0;      ///< tokens
  SourceLoc loc;               ///< where it was written
  std::string param;           ///< the model parameter the value comes from ("" for none)
  friend bool operator==(const SlotCount& x, const SlotCount& y) {
    return x.slot == y.slot && x.value == y.value && x.param == y.param;
  }
};

/// Initial node tokens of one node slot: scene paths, in FIFO order.
struct SlotNodes {
  SlotId slot = kDefaultSlot;      ///< which slot
  std::vector<std::string> nodes;  ///< node paths, first to leave first
  SourceLoc loc;                   ///< where it was written
  friend bool operator==(const SlotNodes& x, const SlotNodes& y) {
    return x.slot == y.slot && x.nodes == y.nodes;
  }
};

/// An explicit slot kind declaration on a place.
struct SlotDecl {
  SlotId slot = kDefaultSlot;         ///< which slot
  SlotKind kind = SlotKind::Control;  ///< declared kind
  SourceLoc loc;                      ///< where it was written
  friend bool operator==(const SlotDecl& x, const SlotDecl& y) {
    return x.slot == y.slot && x.kind == y.kind;
  }
};

/// A script attached to a construct. The net only carries it; the script layer compiles and
/// runs it. Either inline code, or a function in a Python file beside the model.
struct ScriptSpec {
  std::string code;      ///< inline Python source (a statement block, or an expression for guards and predicates)
  std::string file;      ///< a .py file, relative to the model's folder (file form)
  std::string function;  ///< the function in that file (file form; a globals file needs none)
  SourceLoc loc;         ///< where the code's first character is (inline) or where the script is named (file form)
  int indent = 0;        ///< columns the code's lines are indented by in the model file (inline block form)
  /// The model file's line of each line of `code`, where they do not follow one another from
  /// `loc.line` (a folded `>` block, a quoted string spread over lines or holding `\n`); empty
  /// when they do (a `|` block, one line).
  std::vector<int> lines;

  /// True when no script is attached.
  [[nodiscard]] bool empty() const { return code.empty() && file.empty(); }
  friend bool operator==(const ScriptSpec& x, const ScriptSpec& y) {
    return x.code == y.code && x.file == y.file && x.function == y.function;
  }
};

/// Scripts of one place slot.
struct SlotScripts {
  SlotId slot = kDefaultSlot;  ///< which slot
  ScriptSpec on_deposit;       ///< runs per token deposited: `on_deposit(token)`
  ScriptSpec on_remove;        ///< runs per token removed: `on_remove(token)`
  ScriptSpec on_enter;         ///< sensor slot (Region): per item that entered: `items`, `item`
  ScriptSpec on_exit;          ///< sensor slot (Region): per item that left: `items`, `item`
  ScriptSpec on_sample;        ///< sensor slot: every step while the sensor reports anything
  ScriptSpec on_change;        ///< sensor slot (not a Region): when the value changes: `value`
  friend bool operator==(const SlotScripts&, const SlotScripts&) = default;
};

/// The script of kind `kind` (one of kSlotScripts) of a place slot.
const ScriptSpec& scriptOf(const SlotScripts& s, ScriptKind kind);
/// The same, to change.
inline ScriptSpec& scriptOf(SlotScripts& s, ScriptKind kind) {
  return const_cast<ScriptSpec&>(scriptOf(static_cast<const SlotScripts&>(s), kind));
}

/// A sensor slot of a place, bound to a sensor node of the scene.
struct SensorBinding {
  SlotId slot = kDefaultSlot;  ///< which slot
  std::string path;            ///< the sensor node's path (relative to the instance in a page type)
  SourceLoc loc;               ///< where it was written
  friend bool operator==(const SensorBinding& x, const SensorBinding& y) {
    return x.slot == y.slot && x.path == y.path;
  }
};

/// A predicate of an arc on one node slot: which tokens are eligible.
struct SlotPredicate {
  SlotId slot = kDefaultSlot;  ///< which slot
  ScriptSpec expression;       ///< a Python expression over `token` (and `self`, the transition)
  friend bool operator==(const SlotPredicate&, const SlotPredicate&) = default;
};

/// A text of the inscription language on one slot (a place's colour set or initial values, an
/// arc's inscription), with where it was written: its first character's line and column.
struct SlotText {
  SlotId slot = kDefaultSlot;  ///< which slot
  std::string text;            ///< as written
  SourceLoc loc;               ///< where its first character is
  /// Where each character of `text` (and its end) stands in the file, line and column, where
  /// that is not simply one after another from `loc` (a block over several lines, a quoted text
  /// with escapes); empty otherwise. Layout only: not compared.
  std::vector<std::pair<int, int>> layout{};
  /// Where the place `in_text` of the text (its lines and columns from 1) stands in the file.
  [[nodiscard]] SourceLoc where(const SourceLoc& in_text) const;
  friend bool operator==(const SlotText& x, const SlotText& y) { return x.slot == y.slot && x.text == y.text; }
};

/// A field of the plant that a continuous place's amount drives (hybrid nets): after every step
/// the node's number field is set to `offset + scale * amount` (a tank's fill as a shape's height).
struct FluidDrive {
  std::string node;     ///< the node's path (relative to the instance in a page type)
  std::string field;    ///< its number field (`size.z` for one component of a vector field)
  double scale = 1.0;   ///< field units per unit of amount
  double offset = 0.0;  ///< the field's value at amount 0, field units
  SourceLoc loc;        ///< where it was written
  friend bool operator==(const FluidDrive& x, const FluidDrive& y) {
    return x.node == y.node && x.field == y.field && x.scale == y.scale && x.offset == y.offset;
  }
};

/// What makes a place continuous (hybrid nets, semantics: *Continuous places*): it holds a
/// non-negative real amount rather than tokens.
struct FluidSpec {
  double amount = 0.0;                ///< the initial amount, in `unit` (>= 0)
  std::optional<double> capacity{};   ///< the most it holds, in `unit` (none: unbounded)
  std::string unit{};                 ///< for people: `L`, `kg`, `Ah`
  SourceLoc loc{};                    ///< where `continuous` was written
  std::vector<FluidDrive> drives{};   ///< plant fields its amount sets
  friend bool operator==(const FluidSpec& x, const FluidSpec& y) {
    return x.amount == y.amount && x.capacity == y.capacity && x.unit == y.unit && x.drives == y.drives;
  }
};

/// A number of the plant a flow's rate reads (hybrid nets): what a signal's `node` and `of` read.
struct FlowRead {
  std::string name;  ///< the name the rate uses
  std::string node;  ///< the node's path (relative to the instance in a page type)
  std::string of;    ///< what of it: `reading`, `angle`, a field, ... (docs/format.md, Signals)
  SourceLoc loc;     ///< where it was written
  friend bool operator==(const FlowRead& x, const FlowRead& y) {
    return x.name == y.name && x.node == y.node && x.of == y.of;
  }
};

/// What makes a transition continuous (hybrid nets, semantics: *Continuous transitions*): it
/// flows at a rate instead of firing.
struct FlowSpec {
  /// The rate, units of amount per second per unit of arc weight: an expression (core
  /// expression syntax) over the amounts of the continuous places on its page (by name), its
  /// `reads` and the model's parameters.
  SlotText rate{};
  std::vector<FlowRead> reads{};  ///< numbers of the plant the rate names
  /// The model's parameters (name, value), filled by the loader: the rate may name them.
  std::vector<std::pair<std::string, double>> params{};
  SourceLoc loc{};                ///< where `continuous` was written
  friend bool operator==(const FlowSpec& x, const FlowSpec& y) { return x.rate == y.rate && x.reads == y.reads; }
};

/// A 2D position in the net editor (editor units, for the IDE and PNML graphics).
using EditorPos = std::array<double, 2>;

/// A place: per slot an initial marking and a capacity.
struct PlaceSpec {
  std::string name;                    ///< unique on its page
  SourceLoc loc;                       ///< where the place is declared
  std::string description;             ///< free text kept for the user
  std::vector<SlotDecl> kinds;         ///< explicit slot kinds
  std::vector<SlotCount> tokens;       ///< initial control tokens per slot
  std::vector<SlotNodes> nodes;        ///< initial node tokens per slot
  std::vector<SlotCount> capacity;     ///< capacity per slot (unbounded when absent)
  std::vector<SlotScripts> scripts;    ///< per-slot scripts
  std::vector<SensorBinding> sensors;  ///< sensor slots and the sensors they read
  std::optional<EditorPos> position;   ///< where the editor draws it
  std::string fusion{};                ///< the fusion set it is a member of ("" for none)
  SourceLoc fusion_loc{};              ///< where the set is named
  std::vector<SlotText> colours{};     ///< value slots: the colour set each holds, by name (`colour:`)
  std::vector<SlotText> values{};      ///< value slots: the initial values, a multiset inscription (`values:`)
  std::optional<FluidSpec> fluid{};    ///< set for a continuous place (hybrid nets): its amount
  /// True when it is a continuous place.
  [[nodiscard]] bool continuous() const { return fluid.has_value(); }
  /// True when it declares anything a fusion set's members share: slot kinds, tokens,
  /// capacities, scripts or sensors.
  [[nodiscard]] bool declares() const {
    return !kinds.empty() || !tokens.empty() || !nodes.empty() || !capacity.empty() || !scripts.empty() ||
           !sensors.empty() || !colours.empty() || !values.empty() || fluid;
  }
  /// True when `x` and `y` declare the same slot kinds, tokens, capacities, scripts and sensors.
  friend bool sameDeclarations(const PlaceSpec& x, const PlaceSpec& y) {
    return x.kinds == y.kinds && x.tokens == y.tokens && x.nodes == y.nodes && x.capacity == y.capacity &&
           x.scripts == y.scripts && x.sensors == y.sensors && x.colours == y.colours && x.values == y.values &&
           x.fluid == y.fluid;
  }
  friend bool operator==(const PlaceSpec& x, const PlaceSpec& y) {
    return x.name == y.name && x.description == y.description && sameDeclarations(x, y) &&
           x.position == y.position && x.fusion == y.fusion;
  }
};

/// A transition's servers when any number of its occurrences may run at once.
inline constexpr std::int64_t kUnlimitedServers = 0;
/// The most servers a transition may have when they are limited.
inline constexpr std::int64_t kMostServers = 1'000'000;

/// A timed transition.
struct TransitionSpec {
  std::string name;                   ///< unique on its page
  SourceLoc loc;                      ///< where the transition is declared
  std::string description;            ///< free text kept for the user
  Duration duration;                  ///< occurrence duration, seconds
  std::int64_t priority = 0;          ///< higher starts first
  double probability = 1.0;           ///< chance to start in a step while enabled, in (0, 1]
  SourceLoc probability_loc;          ///< where the probability was written
  std::string priority_param;         ///< the model parameter the priority comes from ("" for none)
  std::string probability_param;      ///< the model parameter the probability comes from ("" for none)
  std::int64_t servers = 1;           ///< occurrences that may run at once; kUnlimitedServers for no limit
  SourceLoc servers_loc;              ///< where the servers were written
  std::string servers_param;          ///< the model parameter the servers come from ("" for none)
  ScriptSpec guard;                   ///< a Python expression; the transition may start only while it is true
  ScriptSpec pre_fire;                ///< runs when an occurrence starts
  ScriptSpec in_fire;                 ///< runs every step while occurring (self.elapsed, self.progress)
  ScriptSpec post_fire;               ///< runs when an occurrence completes, before its deposits
  std::optional<EditorPos> position;  ///< where the editor draws it
  /// The condition on its variables in the inscription language (`when:`; text "" for none):
  /// a binding occurs only where it is true. Not a Python guard: the analysis reads it.
  SlotText when{};
  std::optional<FlowSpec> flow{};     ///< set for a continuous transition (hybrid nets): its rate

  /// True when it is a continuous transition.
  [[nodiscard]] bool continuous() const { return flow.has_value(); }
  /// True when any script is attached.
  [[nodiscard]] bool scripted() const {
    return !guard.empty() || !pre_fire.empty() || !in_fire.empty() || !post_fire.empty();
  }
  /// True when it has a condition in the inscription language.
  [[nodiscard]] bool conditioned() const { return !when.text.empty(); }
  friend bool operator==(const TransitionSpec& x, const TransitionSpec& y) {
    return x.name == y.name && x.description == y.description && x.duration == y.duration &&
           x.priority == y.priority && x.probability == y.probability && x.guard == y.guard &&
           x.priority_param == y.priority_param && x.probability_param == y.probability_param &&
           x.servers == y.servers && x.servers_param == y.servers_param &&
           x.pre_fire == y.pre_fire && x.in_fire == y.in_fire && x.post_fire == y.post_fire &&
           x.position == y.position && x.when == y.when && x.flow == y.flow;
  }
};

/// The script of kind `kind` (one of kTransitionScripts) of a transition.
const ScriptSpec& scriptOf(const TransitionSpec& t, ScriptKind kind);
/// The same, to change.
inline ScriptSpec& scriptOf(TransitionSpec& t, ScriptKind kind) {
  return const_cast<ScriptSpec&>(scriptOf(static_cast<const TransitionSpec&>(t), kind));
}

/// How an input arc acts on its place.
enum class ArcKind : std::uint8_t {
  Normal,     ///< takes `w` tokens (output arcs are always normal)
  Test,       ///< needs `w` tokens, takes none
  Inhibitor,  ///< allows the transition only while the place holds fewer than `w`
};

/// "normal", "test" or "inhibitor".
const char* arcKindName(ArcKind kind);

/// An arc between a place (or a link `instance/reference`) and a transition, either way.
struct ArcSpec {
  std::string from;                ///< source: a place, link or transition name on the page
  std::string to;                  ///< target: a transition, place or link name on the page
  ArcKind kind = ArcKind::Normal;  ///< normal, test or inhibitor
  std::vector<SlotCount> weights;  ///< per-slot weights; empty means a0 with weight 1
  std::vector<SlotPredicate> predicates;  ///< per node slot: which tokens are eligible (input arcs)
  std::vector<SlotPredicate> conditions;  ///< per sensor slot: the arc allows its transition while true
  std::vector<SlotText> inscriptions{};   ///< per value slot: the multiset it takes or puts (`inscription:`)
  SourceLoc loc;                   ///< where the arc is declared
  SourceLoc from_loc;              ///< where `from` is written
  SourceLoc to_loc;                ///< where `to` is written
  /// Its route in the editor: bend points from source to target, editor units (as a place's
  /// position); empty for a straight arc (or Graphviz's route). Layout, not semantics: the
  /// compiler ignores it, and it compares as positions do.
  std::vector<EditorPos> via{};
  /// Where its inscription stands: an offset from the middle of its drawn path (half its
  /// length along it), editor units; none: beside the path where it fits.
  std::optional<EditorPos> label_at{};
  /// On an arc with a continuous place: its weight, a real number in the place's unit (none:
  /// 1); `weight: 2.5` fills it, and `weights` with the whole number where it is one.
  std::optional<double> amount{};
  std::string amount_param{};  ///< the model parameter `amount` comes from ("" for none)
  friend bool operator==(const ArcSpec& x, const ArcSpec& y) {
    return x.from == y.from && x.to == y.to && x.kind == y.kind && x.weights == y.weights &&
           x.predicates == y.predicates && x.conditions == y.conditions && x.via == y.via &&
           x.label_at == y.label_at && x.inscriptions == y.inscriptions && x.amount == y.amount &&
           x.amount_param == y.amount_param;
  }
};

/// An instance of a page type on a page.
struct InstanceSpec {
  std::string name;                   ///< unique on its page; qualifies the names inside
  std::string type;                   ///< the page type it instantiates
  SourceLoc loc;                      ///< where the instance is declared
  SourceLoc type_loc;                 ///< where the type is named
  std::optional<EditorPos> position;  ///< where the editor draws it
  std::array<double, 3> translation{0, 0, 0};     ///< where its copy of the type's scene stands, m
  std::array<double, 4> rotation{0, 0, 1, 0};     ///< how it is turned: axis and degrees
  /// A number the type declares as a parameter, set for this instance (`params: {length: 3}`).
  struct Param {
    std::string name;   ///< the type's parameter
    double value = 0;   ///< its value here, in the parameter's unit
    SourceLoc loc;      ///< where it is set
    friend bool operator==(const Param& a, const Param& b) { return a.name == b.name && a.value == b.value; }
  };
  std::vector<Param> params{};  ///< the parameters set here, in file order (the others keep the type's)
  std::string part{};         ///< a control pattern's: the part instance on its page it controls
  SourceLoc part_loc{};       ///< where `part` is written
  /// A control pattern's: the part instance on its page that fills one of its roles (`uses`).
  struct Use {
    std::string role;   ///< the pattern's role (`eye`)
    std::string part;   ///< the part instance on this page that fills it
    SourceLoc loc;      ///< where it is written
    friend bool operator==(const Use& a, const Use& b) { return a.role == b.role && a.part == b.part; }
  };
  std::vector<Use> uses{};    ///< the roles filled here, in file order
  friend bool operator==(const InstanceSpec& x, const InstanceSpec& y) {
    return x.name == y.name && x.type == y.type && x.position == y.position && x.translation == y.translation &&
           x.rotation == y.rotation && x.params == y.params && x.part == y.part && x.uses == y.uses;
  }
};

/// A published place of a page type (a port), seen from outside as a link.
struct ReferenceSpec {
  std::string place;  ///< the referenced place, which also names the link
  SourceLoc loc;      ///< where it was written
  friend bool operator==(const ReferenceSpec& x, const ReferenceSpec& y) {
    return x.place == y.place;
  }
};

/// A page (top level) or page type: a net with optional references and instances.
struct PageSpec {
  std::string name;                          ///< unique among pages (or among page types)
  SourceLoc loc;                             ///< where it is declared
  std::string description;                   ///< free text kept for the user
  std::vector<ReferenceSpec> references;     ///< published places (page types only)
  std::vector<PlaceSpec> places;             ///< in declaration order
  std::vector<TransitionSpec> transitions;   ///< in declaration order
  std::vector<ArcSpec> arcs;                 ///< in declaration order
  std::vector<InstanceSpec> instances;       ///< in declaration order
  friend bool operator==(const PageSpec& x, const PageSpec& y) {
    return x.name == y.name && x.description == y.description && x.references == y.references &&
           x.places == y.places && x.transitions == y.transitions && x.arcs == y.arcs &&
           x.instances == y.instances;
  }
};

/// How far a fusion set reaches.
enum class FusionScope : std::uint8_t {
  Global,    ///< its members are one place for the whole net
  Instance,  ///< its members (all on one page or page type) are one place per instance of it
};

/// "global" or "instance".
const char* fusionScopeName(FusionScope scope);
/// The scope called `word` ("global", "instance"), if any.
std::optional<FusionScope> parseFusionScope(std::string_view word);

/// A fusion set: places, each named by its member's `fusion`, that are one place.
struct FusionSpec {
  std::string name;                           ///< unique among fusion sets
  FusionScope scope = FusionScope::Global;    ///< one place for the net, or one per instance
  SourceLoc loc;                              ///< where it is declared
  friend bool operator==(const FusionSpec& x, const FusionSpec& y) {
    return x.name == y.name && x.scope == y.scope;
  }
};

/// The whole net of a model: top-level pages and the page types they instantiate.
struct NetSpec {
  std::vector<PageSpec> pages;       ///< top-level pages; names qualify their constructs
  std::vector<PageSpec> page_types;  ///< reusable pages, instantiated by name
  std::vector<FusionSpec> fusions;   ///< fusion sets, in declaration order
  ScriptSpec globals;                ///< model-wide script run once at load; its names are seen by every script
  std::vector<ColourSetSpec> colours{};   ///< colour sets of value tokens (`colours:`), in declaration order
  std::vector<VariableSpec> variables{};  ///< variables of the inscriptions (`variables:`), in declaration order
  friend bool operator==(const NetSpec&, const NetSpec&) = default;
};

}  // namespace gdpn::net
