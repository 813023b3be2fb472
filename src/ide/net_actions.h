#pragma once
// What the Edit and Net menus do to the net view's selection: select all, delete, copy,
// reverse an arc, align and distribute. Each edit is one undo step. Private to the ide module.

#include <string>
#include <utility>
#include <vector>

#include "gdpn/net/spec.h"

namespace gdpn::ide {

class App;

/// What is selected on the page the net view shows.
struct PageSelection {
  std::string page;                    ///< the page (or page type) edited
  std::string prefix;                  ///< the qualified names' prefix there
  /// The places, transitions and instances, by name, with where each is drawn, editor units.
  std::vector<std::pair<std::string, net::EditorPos>> constructs;
  std::vector<net::ArcSpec> arcs;      ///< the arcs, as the page declares them
  /// True when nothing of the page is selected.
  [[nodiscard]] bool empty() const { return constructs.empty() && arcs.empty(); }
};

/// The selection's items on the net view's page (laid out again first when the page changed).
[[nodiscard]] PageSelection netSelection(App& app);

/// Selects everything on the net view's page.
void selectAllOnPage(App& app);
/// Deletes the selected items of the net view's page as one step; "" or why not.
std::string deleteNetSelection(App& app);
/// The selected constructs of the net view's page and the arcs among them (and the selected
/// arcs whose two ends come along), as a page to paste; empty when none.
[[nodiscard]] net::PageSpec copyNetSelection(App& app);
/// Swaps the selected arc's ends (it stays selected); "" or why not.
std::string reverseSelectedArc(App& app);

/// Makes a page type of the selected constructs of the net view's page and puts an instance
/// of it in their place (page_from_selection.h); "" or why not.
std::string pageTypeFromSelection(App& app);
/// Shows the selected instance's page in the net view.
void openSelectedInstance(App& app);

/// How align and distribute place the selection.
enum class Arrange : std::uint8_t {
  Left,    ///< every centre on the leftmost one's x
  Top,     ///< every centre on the topmost one's y
  Across,  ///< evenly spaced in x from the leftmost to the rightmost, in their x order
  Down,    ///< evenly spaced in y from the topmost to the lowest
};
/// Arranges the selected constructs as `how` says, as one step; "" or why not.
std::string arrangeNetSelection(App& app, Arrange how);

}  // namespace gdpn::ide
