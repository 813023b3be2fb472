// Editing the scene tree: each edit works on a copy of the scene (and of the net when the
// marking follows) and puts it in place when every check passes; the old ones are kept for undo.

#include "gdpn/ide/scene_edit.h"

#include <algorithm>
#include <cctype>

#include "gdpn/core/text.h"
#include "gdpn/ide/document.h"

namespace gdpn::ide {

namespace {

/// True when `p` is `path` or lies below it.
bool within(const std::string& p, const std::string& path) {
  return p == path || (p.size() > path.size() && p.starts_with(path) && p[path.size()] == '/');
}

/// Calls `f(page, place, slot name, path)` for every node path the top-level pages' markings
/// and sensor bindings hold, the path by reference.
template <typename Net, typename F>
void eachPath(Net& net, F&& f) {
  for (auto& page : net.pages) {
    for (auto& place : page.places) {
      for (auto& slot : place.nodes) {
        for (auto& p : slot.nodes) f(page, place, net::slotName(slot.slot), p);
      }
      for (auto& sensor : place.sensors) f(page, place, net::slotName(sensor.slot), sensor.path);
    }
  }
}

std::string nameProblem(const std::string& name) {
  if (!core::isIdentifier(name)) return "'" + name + "' is not a name (letters, digits and _, not starting with a digit)";
  return {};
}

}  // namespace

std::vector<std::string> usesOf(const net::NetSpec& net, const std::string& path) {
  std::vector<std::string> uses;
  eachPath(net, [&](const auto& page, const auto& place, const std::string& slot, const std::string& p) {
    if (within(p, path)) uses.push_back(page.name + "/" + place.name + " (" + slot + ")");
  });
  return uses;
}

SceneEditCommand::SceneEditCommand(SceneEdit edit) : edit_(std::move(edit)) {}

std::string SceneEditCommand::apply(Document& doc) {
  made_.clear();
  const scene::Scene* current = doc.scene();
  if (current == nullptr && !((edit_.kind == SceneEditKind::Add || edit_.kind == SceneEditKind::Paste) && edit_.path.empty())) {
    return "the model has no scene";
  }
  std::shared_ptr<scene::Scene> edited = current ? std::shared_ptr<scene::Scene>(current->clone())
                                                 : std::make_shared<scene::Scene>();
  net::NetSpec net = doc.model().net;
  bool net_changed = false;
  const bool at_root = (edit_.kind == SceneEditKind::Add || edit_.kind == SceneEditKind::Paste) && edit_.path.empty();
  scene::Node* node = at_root ? &edited->root() : edited->find(edit_.path);
  if (node == nullptr) return "no node '" + edit_.path + "'";
  const bool root = node == &edited->root();
  switch (edit_.kind) {
    case SceneEditKind::Add: {
      const scene::NodeType* type = edited->types().find(edit_.type);
      if (type == nullptr) return "no node type '" + edit_.type + "'";
      std::string name = edit_.name;
      if (name.empty()) {
        std::string base = type->name;
        for (auto& c : base) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        name = edited->freshName(*node, base);
      }
      if (auto why = nameProblem(name); !why.empty()) return why;
      const scene::Node* made = edited->create(*type, name, *node);
      if (made == nullptr) {
        return node->child(name) != nullptr ? "'" + edit_.path + "' has a child '" + name + "' already"
                                            : "a " + node->type().name + " holds no other nodes";
      }
      made_ = made->path();
      break;
    }
    case SceneEditKind::Delete: {
      if (root) return "the scene's root stays";
      const auto uses = usesOf(net, edit_.path);
      if (!uses.empty() && !edit_.with_marking) {
        std::string list;
        for (const auto& u : uses) list += (list.empty() ? "" : ", ") + u;
        return "'" + edit_.path + "' is used by the net: " + list + "; delete it with its marking to take it out there too";
      }
      for (auto& page : net.pages) {
        for (auto& place : page.places) {
          for (auto& slot : place.nodes) {
            std::erase_if(slot.nodes, [&](const std::string& p) { return within(p, edit_.path); });
          }
          std::erase_if(place.nodes, [](const net::SlotNodes& s) { return s.nodes.empty(); });
          std::erase_if(place.sensors, [&](const net::SensorBinding& b) { return within(b.path, edit_.path); });
        }
      }
      net_changed = !uses.empty();
      edited->destroy(*node);
      break;
    }
    case SceneEditKind::Rename: {
      if (root) return "the scene's root has no name";
      if (auto why = nameProblem(edit_.name); !why.empty()) return why;
      const std::string parent = node->parent() == &edited->root() ? std::string() : node->parent()->path();
      const std::string renamed = parent.empty() ? edit_.name : parent + "/" + edit_.name;
      if (!edited->rename(*node, edit_.name)) return "'" + edit_.name + "' is taken beside it";
      made_ = renamed;
      // the marking follows the nodes
      eachPath(net, [&](auto&, auto&, const std::string&, std::string& p) {
        if (!within(p, edit_.path)) return;
        p = renamed + p.substr(edit_.path.size());
        net_changed = true;
      });
      break;
    }
    case SceneEditKind::Paste: {
      if (!edit_.fragment || edit_.fragment->root().children().empty()) return "nothing to paste";
      if (!root && !node->type().has_children) return "a " + node->type().name + " holds no other nodes";
      for (const auto& top : edit_.fragment->root().children()) {
        // an unnamed node stays unnamed; a name taken there gets a number
        const bool free = top->name().empty() || node->child(top->name()) == nullptr;
        const std::string name = free ? top->name() : edited->freshName(*node, top->name());
        const scene::Node* copy = edited->copy(*top, *node, name);
        if (copy == nullptr) return "'" + top->name() + "' cannot be pasted there";
        if (made_.empty()) made_ = copy->path();
      }
      break;
    }
    case SceneEditKind::Reparent: {
      if (root) return "the scene's root has no parent";
      scene::Node* parent = edit_.name.empty() ? &edited->root() : edited->find(edit_.name);
      if (parent == nullptr) return "no node '" + edit_.name + "'";
      if (parent != &edited->root() && within(edit_.name, edit_.path)) return "a node cannot go under itself";
      if (parent == node->parent()) return "'" + edit_.path + "' is there already";
      if (parent != &edited->root() && !parent->type().has_children) return "a " + parent->type().name + " holds no other nodes";
      if (parent->child(node->name()) != nullptr) {
        return "'" + (edit_.name.empty() ? std::string("the scene") : edit_.name) + "' has a child '" + node->name() + "' already";
      }
      const scene::Node* moved = edited->copy(*node, *parent);
      if (moved == nullptr) return "it cannot be moved there";
      const std::string to = moved->path();
      edited->destroy(*node);
      // the marking follows the nodes
      eachPath(net, [&](auto&, auto&, const std::string&, std::string& p) {
        if (!within(p, edit_.path)) return;
        p = to + p.substr(edit_.path.size());
        net_changed = true;
      });
      made_ = to;
      break;
    }
    case SceneEditKind::Duplicate: {
      if (root) return "the scene's root cannot be copied beside itself";
      scene::Node& parent = *node->parent();
      const scene::Node* copy = edited->copy(*node, parent, edited->freshName(parent, node->name()));
      if (copy == nullptr) return "it cannot be copied";
      made_ = copy->path();
      break;
    }
  }
  before_ = doc.swapScene(std::move(edited));
  net_before_.reset();
  if (net_changed) {
    net_before_ = std::move(doc.editableNet());
    doc.editableNet() = std::move(net);
  }
  doc.touched();
  return {};
}

void SceneEditCommand::revert(Document& doc) {
  (void)doc.swapScene(before_);
  if (net_before_) doc.editableNet() = *net_before_;
  doc.touched();
}

std::string SceneEditCommand::label() const {
  switch (edit_.kind) {
    case SceneEditKind::Add: return "add a " + edit_.type + " under " + (edit_.path.empty() ? "the scene" : edit_.path);
    case SceneEditKind::Delete: return "delete " + edit_.path;
    case SceneEditKind::Rename: return "rename " + edit_.path + " to " + edit_.name;
    case SceneEditKind::Duplicate: return "duplicate " + edit_.path;
    case SceneEditKind::Paste: return "paste under " + (edit_.path.empty() ? std::string("the scene") : edit_.path);
    case SceneEditKind::Reparent: return "move " + edit_.path + " under " + (edit_.name.empty() ? "the scene" : edit_.name);
  }
  return "edit the scene";
}

}  // namespace gdpn::ide
