#pragma once
/// \file
/// Makes a page type from a selection of places and transitions on one page, as CPN Tools'
/// "Create subpage from selection": the selected constructs and the arcs between them move into
/// a new page type, one instance of it takes their place, and the arcs that cross the
/// selection's boundary reach the type's references (ports) as links `instance/place`. The net
/// compiled from the result is the one compiled before, up to the names that moved
/// (`line/x` becomes `line/inst/x`), and those names are followed wherever the model writes
/// them: scripts' string literals (`sim.place('line/x')`), guards, predicates, conditions, the
/// `io` section and the signals. No ImGui.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gdpn/core/diagnostics.h"
#include "gdpn/ide/command.h"
#include "gdpn/model/model.h"

namespace gdpn::ide {

/// What to make a page type from.
struct PageFromSelection {
  std::string page;                ///< the top-level page or page type the selection is on
  std::vector<std::string> names;  ///< the selected places and transitions, by their names on `page`
  std::string type;                ///< the new page type's name (an identifier no page type has)
  std::string instance;            ///< the instance that replaces the selection (an identifier free on `page`)
};

/// What making the page type did, besides the model.
struct PageFromSelectionResult {
  /// Every qualified name that moved, old to new (`line/x` to `line/inst/x`), in the order of
  /// the page's places then transitions; for a page type, once per instance of it. For the
  /// things kept outside the model that name constructs (breakpoints): followName().
  std::vector<std::pair<std::string, std::string>> renamed;
  /// Places not selected that moved in too: each sits between a selected transition and the
  /// rest of the net, so it becomes one of the type's references (the format has no binding
  /// of a reference to a place outside the instance).
  std::vector<std::string> pulled_in;
  /// The references the type publishes, in its places' order.
  std::vector<std::string> references;
};

/// `name` as it is after the move (`renamed`'s new name for an old one), or `name` itself.
[[nodiscard]] std::string followName(const PageFromSelectionResult& result, const std::string& name);

/// The model `model` becomes when the page type is made, or nullopt when it cannot be (each
/// reason a located error in `diags`: a name unknown on the page, an instance or fusion member
/// selected, a place that carries scene paths (node tokens, sensors: in a page type they are
/// relative to the instance), an arc to another instance's reference from a selected
/// transition, a name built at run time or written in a script file that cannot be followed).
/// Warnings (transitions that change their declaration order, which breaks ties) go to `diags`
/// too. `model` is not changed.
std::optional<model::Model> makePageFromSelection(const model::Model& model, const PageFromSelection& request,
                                                  core::Diagnostics& diags, PageFromSelectionResult* result = nullptr);

/// The undoable command: applies makePageFromSelection() to the document and selects the new
/// instance; revert gives the model back exactly as it was (its save then gives the same bytes).
class PageFromSelectionCommand final : public Command {
 public:
  /// A command that makes the page type `request` asks for.
  explicit PageFromSelectionCommand(PageFromSelection request) : request_(std::move(request)) {}
  /// "" when done; else the first error (all of them, located, in diagnostics()), the document
  /// unchanged.
  std::string apply(Document& doc) override;
  void revert(Document& doc) override;
  [[nodiscard]] std::string label() const override;
  void absorb(const Command&) override {}
  [[nodiscard]] bool changesScene() const override { return false; }
  /// The errors and warnings of the last apply().
  [[nodiscard]] const core::Diagnostics& diagnostics() const { return diags_; }
  /// What the last successful apply() did (names moved, places pulled in, references).
  [[nodiscard]] const PageFromSelectionResult& result() const { return result_; }

 private:
  PageFromSelection request_;
  core::Diagnostics diags_;
  PageFromSelectionResult result_;
  std::optional<model::Model> before_;  // the model's content as it was, for revert
};

}  // namespace gdpn::ide
