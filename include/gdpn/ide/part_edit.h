#pragma once
/// \file
/// Commands that edit a document's part instances: a part placed from the palette (with the
/// page types it brings), its control pattern added, an instance's parameter or placement set,
/// the library's newer versions of its parts taken. Each of the library's edits is one library
/// call (model/part_library.h); every command keeps what it changed, so that undo gives the
/// model back exactly and redo puts the same result back. Also "Save as Part": a scene node
/// written to the user's library as a new part.

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gdpn/ide/command.h"
#include "gdpn/model/model.h"
#include "gdpn/model/part_library.h"

namespace gdpn::ide {

/// Where a part instance is written: an instance of a part type on a top-level page.
struct PartInstanceAt {
  std::string page;  ///< the page ("main")
  std::string name;  ///< the instance ("belt_conveyor1")
  friend bool operator==(const PartInstanceAt&, const PartInstanceAt&) = default;
};

/// The part instance `name` names: by its own name (which is also the path of the Transform
/// that holds its machine in the plant) or qualified by its page (`main/belt_conveyor1`).
/// Nullopt when no page has an instance of a part type by that name.
[[nodiscard]] std::optional<PartInstanceAt> findPartInstance(const model::Model& model, const std::string& name);
/// The instance `at` names, or null.
[[nodiscard]] const net::InstanceSpec* instanceAt(const model::Model& model, const PartInstanceAt& at);
/// The name of the instance on `at`'s page that controls it (its `part:` names it); "" when none.
[[nodiscard]] std::string controllerOf(const model::Model& model, const PartInstanceAt& at);

/// What a part edit changes: the net and the page types' scenes and part sections.
struct PartTypesState {
  net::NetSpec net;  ///< pages and page types
  std::map<std::string, std::shared_ptr<const scene::Scene>> type_scenes;  ///< by page type
  std::map<std::string, model::PartSpec> parts;  ///< by page type
};

/// Places library part `part` on `page` (model::placePart, once): its types copied in when the
/// model lacks them, an instance at `translation` (m) turned `angle` degrees about z, and with
/// `control` its control pattern bound to it. Undo removes what it added.
class PlacePartCommand final : public Command {
 public:
  /// The drop of `part` on `page` at `translation` (world, m), turned `angle` degrees about z.
  PlacePartCommand(model::LibraryPart part, std::string page, std::array<double, 3> translation, double angle,
                   bool control = false);
  std::string apply(Document& doc) override;
  void revert(Document& doc) override;
  [[nodiscard]] std::string label() const override;
  void absorb(const Command&) override {}
  /// The new instances' names, the part's first (empty until applied).
  [[nodiscard]] const std::vector<std::string>& made() const { return made_; }

 private:
  model::LibraryPart part_;
  std::string page_;
  std::array<double, 3> translation_;
  double angle_;
  bool control_;
  std::vector<std::string> made_;
  std::optional<PartTypesState> other_;  // the state not in the document now (after apply: the one before)
};

/// Adds an instance of a control pattern of part instance `at`, bound to it and its roles
/// filled by the nearest parts that fit (model::addPartControl, once). Undo removes it.
class AddPartControlCommand final : public Command {
 public:
  /// The control of part instance `at`: control pattern `pattern` (empty: its usual one).
  explicit AddPartControlCommand(PartInstanceAt at, std::string pattern = {});
  std::string apply(Document& doc) override;
  void revert(Document& doc) override;
  [[nodiscard]] std::string label() const override;
  void absorb(const Command&) override {}
  [[nodiscard]] bool changesScene() const override { return false; }
  /// The new instance's name (empty until applied).
  [[nodiscard]] const std::string& made() const { return made_; }

 private:
  PartInstanceAt at_;
  std::string pattern_;
  std::string made_;
  std::optional<net::PageSpec> other_;  // the page not in the document now
};

/// Sets one parameter of a part instance, or its placement. A parameter the part does not
/// declare, a fraction for a whole-number one or a value that is not finite is refused.
class SetInstanceCommand final : public Command {
 public:
  /// Parameter `param` of instance `at` becomes `value` (in the parameter's unit).
  static std::unique_ptr<SetInstanceCommand> param(PartInstanceAt at, std::string param, double value);
  /// Instance `at` stands at `translation` (m) turned by `rotation` (axis and degrees); the
  /// moves of one drag (`merge` not 0) are one step.
  static std::unique_ptr<SetInstanceCommand> placement(PartInstanceAt at, std::array<double, 3> translation,
                                                       std::array<double, 4> rotation, std::uint64_t merge = 0);
  std::string apply(Document& doc) override;
  void revert(Document& doc) override;
  [[nodiscard]] std::string label() const override;
  [[nodiscard]] std::uint64_t mergeKey() const override { return merge_; }
  void absorb(const Command& next) override;
  [[nodiscard]] bool changesScene() const override { return false; }

 private:
  SetInstanceCommand() = default;
  PartInstanceAt at_;
  std::string param_;  // "" for a placement
  double value_ = 0;
  std::array<double, 3> translation_{0, 0, 0};
  std::array<double, 4> rotation_{0, 0, 1, 0};
  std::uint64_t merge_ = 0;
  std::optional<net::InstanceSpec> before_;  // the instance before the first apply
  std::optional<net::InstanceSpec> after_;   // and after the last
};

/// The io section's uses of the I/O that `updates` remove, as they will be located once the
/// updates are applied ("m.gdpn.yaml:4:5: discrete input 0 uses main/lamp1.seen"): each update
/// applied (model::applyPartUpdate) to a copy of `model`. Empty with `why` when a library file
/// does not load.
[[nodiscard]] std::vector<std::string> removedIoUses(const model::Model& model,
                                                     const std::vector<model::PartUpdate>& updates, std::string& why);

/// Takes the library's newer versions of parts the model uses (model::applyPartUpdate, once for
/// each update, in order) as one step: their page types, scenes and part sections replaced,
/// instance parameters the new versions lack dropped. The io section is left as it is: its uses
/// of removed I/O become located errors when the model is checked. Undo gives the model back
/// exactly.
class UpdatePartsCommand final : public Command {
 public:
  /// The updates found by model::partUpdates.
  explicit UpdatePartsCommand(std::vector<model::PartUpdate> updates);
  std::string apply(Document& doc) override;
  void revert(Document& doc) override;
  [[nodiscard]] std::string label() const override;
  void absorb(const Command&) override {}
  /// The io section's uses of removed I/O, located, found by the first apply.
  [[nodiscard]] const std::vector<std::string>& uses() const { return uses_; }

 private:
  std::vector<model::PartUpdate> updates_;
  std::vector<std::string> uses_;
  std::optional<PartTypesState> other_;  // the state not in the document now (after apply: the one before)
};

/// The user's own parts folder, where "Save as Part" writes: `$XDG_DATA_HOME/gdpn/parts`, else
/// `$HOME/.local/share/gdpn/parts` (the folder model::partSearchPath looks in after the
/// model's own); "" when neither variable is set.
[[nodiscard]] std::string userPartsFolder();

/// What saving a scene node as a part did.
struct SavedPart {
  std::string file;     ///< the part file: written, or the one that exists already
  std::string error;    ///< why nothing was written ("" when it was)
  bool exists = false;  ///< refused only because `file` exists (saving again with `replace` replaces it)
};

/// Writes the part `name` (of the palette's group `group`, version 1) made of node `node` of
/// `model`'s scene and its subtree (model::partFromNodes; the model's parameters that its
/// fields name become the part's) to `folder`/`name`.gdpn.yaml, the folder made when missing:
/// written beside the file and renamed when complete. A file there is replaced only with
/// `replace`. Nothing is written when `name` is no identifier or the scene has no such node.
[[nodiscard]] SavedPart savePartOfNode(const model::Model& model, const std::string& node, const std::string& name,
                                       const std::string& group, const std::string& folder, bool replace);

}  // namespace gdpn::ide
