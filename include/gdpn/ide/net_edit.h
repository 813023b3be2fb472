#pragma once
/// \file
/// Commands that edit the net of a document: add, move, rename and delete places and
/// transitions; add and delete arcs and set their kind and weight. Each checks what it is asked
/// (names are identifiers, unique on their page; an arc joins a place and a transition of its
/// page) and refuses with a reason, leaving the document as it was. Each keeps the page as it
/// was before, so that undo gives it back exactly, declaration order included.

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gdpn/ide/command.h"
#include "gdpn/net/spec.h"

namespace gdpn::ide {

/// What a net edit does to its page.
enum class NetEditKind {
  AddPlace,       ///< a place `name` at `at`
  AddTransition,  ///< a transition `name` at `at`
  Move,           ///< place or transition `name` to `at` (a drag's moves merge into one step)
  Rename,         ///< place or transition `name` to `new_name`, its arcs following
  Delete,         ///< place or transition `name` and every arc that touches it
  AddArc,         ///< an arc from `name` to `new_name` of kind `arc_kind` and weight `weight`
  DeleteArc,      ///< the arc from `name` to `new_name` of kind `arc_kind`
  SetArcWeight,   ///< that arc's weight on its first slot (a0 when it has none)
  SetPlace,       ///< place `name` becomes `place` (its slots, marking, capacities, sensors, scripts)
  SetTransition,  ///< transition `name` becomes `transition` (duration, priority, probability, scripts)
  Paste,          ///< the places, transitions and arcs of `fragment` added (a name taken gets a number;
                  ///< arcs kept where both ends come along; positions half a unit down and right)
  MoveMany,       ///< each of `moves` to its point (a group's drag, align, distribute: one step)
  DeleteMany,     ///< the places, transitions and instances `names` with every arc touching them,
                  ///< and the arcs `arcs` (by source, target and kind)
  SetArc,         ///< the arc from `name` to `new_name` of kind `arc_kind` becomes `arc` (its kind,
                  ///< weights, predicates, conditions; its ends swapped: reversed)
  AddInstance,    ///< an instance `name` of page type `new_name` at `at`
};

/// One edit of one page's net (a top-level page or a page type, by name).
struct NetEdit {
  NetEditKind kind = NetEditKind::AddPlace;  ///< what to do
  std::string page;                          ///< the page or page type
  std::string name;                          ///< the construct (AddArc, DeleteArc, SetArcWeight: the arc's source)
  std::string new_name;                      ///< Rename: the new name; arcs: the arc's target
  net::EditorPos at{0, 0};                   ///< AddPlace, AddTransition, Move: editor units
  net::ArcKind arc_kind = net::ArcKind::Normal;  ///< arcs: normal, test or inhibitor
  std::int64_t weight = 1;                   ///< AddArc, SetArcWeight: tokens, 1 to 10^9
  std::uint64_t drag = 0;                    ///< Move: the drag it belongs to (0: a single move)
  /// Move on a page laid out by Graphviz (some construct without a position): where each
  /// construct is drawn now, by name, so that the page keeps its look with one node moved.
  std::vector<std::pair<std::string, net::EditorPos>> pins;
  /// SetPlace: the place as it is to be (same name; its position is kept from the page).
  std::optional<net::PlaceSpec> place;
  /// SetTransition: the transition as it is to be (same name; its position is kept).
  std::optional<net::TransitionSpec> transition;
  /// Paste: what to paste (a page of a model file, read).
  std::optional<net::PageSpec> fragment;
  /// MoveMany: each construct's name and where it goes, editor units.
  std::vector<std::pair<std::string, net::EditorPos>> moves;
  /// DeleteMany: the places, transitions and instances to delete.
  std::vector<std::string> names;
  /// DeleteMany: the arcs to delete (their source, target and kind say which).
  std::vector<net::ArcSpec> arcs;
  /// SetArc: the arc as it is to be.
  std::optional<net::ArcSpec> arc;
};

/// A NetEdit of `kind` on `page`: construct `name` (and `second`: a new name, or an arc's
/// target), at `at`; the other members as they start.
NetEdit makeNetEdit(NetEditKind kind, std::string page, std::string name, std::string second = {},
                    net::EditorPos at = {0, 0});

/// The command that performs a NetEdit.
class NetEditCommand final : public Command {
 public:
  explicit NetEditCommand(NetEdit edit);
  std::string apply(Document& doc) override;
  void revert(Document& doc) override;
  [[nodiscard]] std::string label() const override;
  [[nodiscard]] std::uint64_t mergeKey() const override;
  void absorb(const Command& next) override;
  [[nodiscard]] bool changesScene() const override { return false; }
  /// After apply(): the name of the first construct a Paste added ("" otherwise).
  [[nodiscard]] const std::string& made() const { return made_; }
  /// After apply(): what a Paste added, under the names it got (empty otherwise).
  [[nodiscard]] const net::PageSpec& pasted() const { return pasted_; }

 private:
  NetEdit edit_;
  std::string made_;
  net::PageSpec pasted_;
  std::optional<net::PageSpec> before_;  // the page as it was, for revert
  /// Where a move found the page's constructs and bends (a move changes nothing else: the page
  /// is not copied, so that a drag on a large page costs what it moves).
  struct Positions {
    std::vector<std::optional<net::EditorPos>> places, transitions, instances;  ///< by index
    std::vector<std::vector<net::EditorPos>> via;                                ///< each arc's bends
  };
  std::optional<Positions> positions_;   // a move's page as it was, for revert
  std::optional<std::pair<std::size_t, net::ArcSpec>> arc_before_;  // an arc's route changed alone: it as it was, by index
  bool type_ = false;                    // the page is a page type
};

/// Sets the model's globals script (run once at load; every script sees its names) to inline
/// `code` ("" removes it).
class SetGlobalsCommand final : public Command {
 public:
  explicit SetGlobalsCommand(std::string code) : code_(std::move(code)) {}
  std::string apply(Document& doc) override;
  void revert(Document& doc) override;
  [[nodiscard]] std::string label() const override { return "edit the model's globals"; }
  void absorb(const Command&) override {}
  [[nodiscard]] bool changesScene() const override { return false; }

 private:
  std::string code_;
  net::ScriptSpec before_;
};

/// The page or page type `name` of `net`; null when there is none.
net::PageSpec* findPage(net::NetSpec& net, const std::string& name, bool* is_type = nullptr);
/// findPage() in a net that is only read.
const net::PageSpec* findPage(const net::NetSpec& net, const std::string& name, bool* is_type = nullptr);

// Changes to a place's slots, for the contents view: each keeps the place in the form the
// model file would have read (empty entries dropped), so that a save reads back the same.

/// What slot `slot` of `p` is: sensor when bound to a sensor, else as declared, else node
/// when it holds node tokens, else control.
net::SlotKind slotKindOf(const net::PlaceSpec& p, net::SlotId slot);
/// Makes slot `slot` of `p` a slot of `kind` (a sensor slot reading the node at `sensor`):
/// what the old kind held there (tokens, nodes, capacity, the binding) goes.
void setSlotKind(net::PlaceSpec& p, net::SlotId slot, net::SlotKind kind, const std::string& sensor = {});
/// Sets the count of `slot` in `counts` (a place's tokens or capacities); nullopt removes it.
void setSlotCount(std::vector<net::SlotCount>& counts, net::SlotId slot, std::optional<std::int64_t> value);
/// The entry of `slot` in `counts`; null when it has none.
const net::SlotCount* slotEntry(const std::vector<net::SlotCount>& counts, net::SlotId slot);
/// The count of `slot` in `counts`; nullopt when it has none.
std::optional<std::int64_t> slotCount(const std::vector<net::SlotCount>& counts, net::SlotId slot);
/// Puts the node at `path` last into node slot `slot` of `p` (the slot becomes a node slot).
void addNodeToken(net::PlaceSpec& p, net::SlotId slot, const std::string& path);
/// Takes the node at `path` out of slot `slot` of `p`; false when it was not there.
bool removeNodeToken(net::PlaceSpec& p, net::SlotId slot, const std::string& path);
/// Makes `script` the inline code `code` ("" none), keeping where it stood in the model file (or
/// taking `owner`, its construct's place, for a new one) so that a compile error stays located.
void setInlineCode(net::ScriptSpec& script, const std::string& code, const core::SourceLoc& owner);
/// Sets the inline script of kind `kind` of slot `slot` of `p` to `code` ("" removes it).
void setSlotScript(net::PlaceSpec& p, net::SlotId slot, net::ScriptKind kind, const std::string& code);

/// Where a construct of the compiled net is written: the page (or page type) and its name there.
struct ConstructAt {
  std::string page;  ///< the page or page type
  std::string name;  ///< the place's or transition's name on it
};

/// The page and name behind the qualified name `qualified` ("main/buffer", or
/// "main/cell1/buffer" inside instance cell1, which is written in cell1's page type);
/// nullopt when no page or instance leads there.
std::optional<ConstructAt> locateConstruct(const net::NetSpec& net, const std::string& qualified);

}  // namespace gdpn::ide
