#pragma once
/// \file
/// Commands that edit the scene tree of a document: add a node of a type, delete a subtree,
/// rename a node, duplicate a subtree. A node the net's marking holds as a token (or reads as a
/// sensor) is the dissertation's hidden dependency: deleting it is refused with where it is
/// used, unless asked to take it out of the marking too; renaming it renames it there. Each
/// keeps the scene (and the net, when it changed) as they were, so that undo gives back the
/// save byte for byte.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gdpn/ide/command.h"
#include "gdpn/net/spec.h"
#include "gdpn/scene/node.h"

namespace gdpn::ide {

/// What a scene edit does.
enum class SceneEditKind {
  Add,        ///< a node of type `type` named `name` (a fresh name when empty) under `path`
  Delete,     ///< the node at `path` and its subtree
  Rename,     ///< the node at `path` to `name`
  Duplicate,  ///< a copy of the subtree at `path` beside it, named freshly after it
  Reparent,   ///< the subtree at `path` moved under the node at `name` ("" the root), last among its
              ///< children, its own fields kept; the net's marking follows
  Paste,      ///< copies of the top nodes of `fragment` under `path` ("" the root), renamed freshly
              ///< where a name is taken
};

/// One edit of the scene.
struct SceneEdit {
  SceneEditKind kind = SceneEditKind::Add;  ///< what to do
  std::string path;                         ///< Add: the parent ("" the root); else the node
  std::string type;                         ///< Add: the node type's name ("Cube", "Body", ...)
  std::string name;                         ///< Add: the new node's name; Rename: the new name; Reparent: the new parent
  bool with_marking = false;                ///< Delete: also take its nodes out of the net's markings
  std::shared_ptr<const scene::Scene> fragment;  ///< Paste: what to paste (a model file's scene, read)
};

/// Where the net's top-level pages use the subtree at `path`: "factory/P1 (b0)", one entry a
/// use (node tokens of the initial marking, sensor bindings).
std::vector<std::string> usesOf(const net::NetSpec& net, const std::string& path);

/// The command that performs a SceneEdit.
class SceneEditCommand final : public Command {
 public:
  explicit SceneEditCommand(SceneEdit edit);
  std::string apply(Document& doc) override;
  void revert(Document& doc) override;
  [[nodiscard]] std::string label() const override;
  void absorb(const Command&) override {}
  /// After apply(): the path of the node added, copied or renamed ("" for a delete).
  [[nodiscard]] const std::string& made() const { return made_; }

 private:
  SceneEdit edit_;
  std::string made_;
  std::shared_ptr<scene::Scene> before_;   // the scene as it was (null: the model had none)
  std::optional<net::NetSpec> net_before_;  // the net as it was, when the edit changed it
};

}  // namespace gdpn::ide
