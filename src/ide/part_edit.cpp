// Part instances edited: placed from the library, given their control, their parameters and
// placement set; the library's newer versions taken; a scene node saved as a new part.

#include "gdpn/ide/part_edit.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <set>

#include "gdpn/core/text.h"
#include "gdpn/ide/document.h"

namespace gdpn::ide {

namespace {

net::PageSpec* pageOf(net::NetSpec& net, const std::string& name) {
  const auto it = std::find_if(net.pages.begin(), net.pages.end(), [&](const auto& p) { return p.name == name; });
  return it == net.pages.end() ? nullptr : &*it;
}

net::InstanceSpec* instanceOf(net::NetSpec& net, const PartInstanceAt& at) {
  auto* page = pageOf(net, at.page);
  if (page == nullptr) return nullptr;
  const auto it = std::find_if(page->instances.begin(), page->instances.end(), [&](const auto& i) { return i.name == at.name; });
  return it == page->instances.end() ? nullptr : &*it;
}

/// The part state of `doc`'s model, moved out (the document keeps empty ones until `restore`).
PartTypesState takeState(Document& doc) {
  auto& m = doc.editableModel();
  return {std::move(m.net), std::move(m.type_scenes), std::move(m.parts)};
}

void putState(Document& doc, PartTypesState state) {
  auto& m = doc.editableModel();
  m.net = std::move(state.net);
  m.type_scenes = std::move(state.type_scenes);
  m.parts = std::move(state.parts);
}

/// The words of `text` that could name a parameter (letters, digits and _, not starting with a
/// digit): a binding's parameter, or the names in its expression ("=length/2").
void wordsOf(const std::string& text, std::set<std::string>& words) {
  const auto part = [&](std::size_t i) { return std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '_'; };
  std::size_t i = 0;
  while (i < text.size()) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (std::isdigit(c)) {
      // a number, with what its digits run into (2e3, 0.5): no name
      while (i < text.size() && (part(i) || text[i] == '.')) ++i;
      continue;
    }
    if (!std::isalpha(c) && c != '_') {
      ++i;
      continue;
    }
    const std::size_t start = i;
    while (i < text.size() && part(i)) ++i;
    words.insert(text.substr(start, i - start));
  }
}

/// The names the fields of `node` and its subtree take their values from.
void namedParams(const scene::Node& node, std::set<std::string>& words) {
  for (const auto& b : node.params) wordsOf(b.text, words);
  for (const auto& c : node.children()) namedParams(*c, words);
}

}  // namespace

std::optional<PartInstanceAt> findPartInstance(const model::Model& model, const std::string& name) {
  const auto slash = name.find('/');
  const std::string page = slash == std::string::npos ? std::string() : name.substr(0, slash);
  const std::string own = slash == std::string::npos ? name : name.substr(slash + 1);
  for (const auto& p : model.net.pages) {
    if (!page.empty() && p.name != page) continue;
    for (const auto& i : p.instances) {
      if (i.name == own && model.parts.contains(i.type)) return PartInstanceAt{p.name, i.name};
    }
  }
  return std::nullopt;
}

const net::InstanceSpec* instanceAt(const model::Model& model, const PartInstanceAt& at) {
  return instanceOf(const_cast<net::NetSpec&>(model.net), at);
}

std::string controllerOf(const model::Model& model, const PartInstanceAt& at) {
  for (const auto& p : model.net.pages) {
    if (p.name != at.page) continue;
    for (const auto& i : p.instances) {
      if (i.part == at.name) return i.name;
    }
  }
  return {};
}

PlacePartCommand::PlacePartCommand(model::LibraryPart part, std::string page, std::array<double, 3> translation,
                                   double angle, bool control)
    : part_(std::move(part)), page_(std::move(page)), translation_(translation), angle_(angle), control_(control) {}

std::string PlacePartCommand::apply(Document& doc) {
  if (other_) {
    // a redo: exactly what the first apply made
    auto before = takeState(doc);
    putState(doc, std::move(*other_));
    other_ = std::move(before);
    return {};
  }
  const auto& m = doc.model();
  PartTypesState before{m.net, m.type_scenes, m.parts};
  std::string why;
  made_ = model::placePart(doc.editableModel(), page_, part_, translation_, angle_, control_, why);
  if (made_.empty() || !why.empty()) {
    putState(doc, std::move(before));
    made_.clear();
    return why.empty() ? "'" + part_.name + "' cannot be placed" : why;
  }
  other_ = std::move(before);
  return {};
}

void PlacePartCommand::revert(Document& doc) {
  auto now = takeState(doc);
  putState(doc, std::move(*other_));
  other_ = std::move(now);
}

std::string PlacePartCommand::label() const {
  return "place " + (made_.empty() ? part_.name : made_.front()) + " (" + part_.name + ")";
}

AddPartControlCommand::AddPartControlCommand(PartInstanceAt at, std::string pattern)
    : at_(std::move(at)), pattern_(std::move(pattern)) {}

std::string AddPartControlCommand::apply(Document& doc) {
  auto* page = pageOf(doc.editableNet(), at_.page);
  if (page == nullptr) return "no page '" + at_.page + "'";
  if (other_) {
    std::swap(*page, *other_);
    return {};
  }
  net::PageSpec before = *page;
  std::string why;
  made_ = model::addPartControl(doc.editableModel(), at_.page, at_.name, why, pattern_);
  if (made_.empty()) return why;
  other_ = std::move(before);
  return {};
}

void AddPartControlCommand::revert(Document& doc) {
  if (auto* page = pageOf(doc.editableNet(), at_.page); page != nullptr && other_) std::swap(*page, *other_);
}

std::string AddPartControlCommand::label() const { return "add the control of " + at_.name; }

std::unique_ptr<SetInstanceCommand> SetInstanceCommand::param(PartInstanceAt at, std::string param, double value) {
  std::unique_ptr<SetInstanceCommand> c(new SetInstanceCommand());
  c->at_ = std::move(at);
  c->param_ = std::move(param);
  c->value_ = value;
  return c;
}

std::unique_ptr<SetInstanceCommand> SetInstanceCommand::placement(PartInstanceAt at, std::array<double, 3> translation,
                                                                  std::array<double, 4> rotation, std::uint64_t merge) {
  std::unique_ptr<SetInstanceCommand> c(new SetInstanceCommand());
  c->at_ = std::move(at);
  c->translation_ = translation;
  c->rotation_ = rotation;
  c->merge_ = merge;
  return c;
}

std::string SetInstanceCommand::apply(Document& doc) {
  auto* inst = instanceOf(doc.editableNet(), at_);
  if (inst == nullptr) return "no instance '" + at_.name + "' on page '" + at_.page + "'";
  if (after_) {  // a redo
    *inst = *after_;
    return {};
  }
  net::InstanceSpec next = *inst;
  if (param_.empty()) {
    for (const double v : translation_) {
      if (!std::isfinite(v)) return "a translation is three finite numbers (m)";
    }
    // whole nanometres, as the file will say them (a drag's steps add up to 3.3499999...)
    const auto tidy = [](double v) {
      const double r = std::round(v * 1e9) / 1e9;
      return r == 0 ? 0.0 : r;
    };
    for (std::size_t i = 0; i < 3; ++i) next.translation[i] = tidy(translation_[i]);
    for (std::size_t i = 0; i < 4; ++i) next.rotation[i] = tidy(rotation_[i]);
  } else {
    const auto spec = doc.model().parts.find(inst->type);
    const auto* declared = spec == doc.model().parts.end() ? nullptr : [&]() -> const model::Param* {
      for (const auto& p : spec->second.params) {
        if (p.name == param_) return &p;
      }
      return nullptr;
    }();
    if (declared == nullptr) return "part '" + inst->type + "' has no parameter '" + param_ + "'";
    if (!std::isfinite(value_)) return "'" + param_ + "' is a number";
    if (declared->integer && std::floor(value_) != value_) {
      return "'" + param_ + "' is a whole number; " + core::formatDouble(value_) + " is not";
    }
    // set here, or written anew in the type's order of declaration
    auto it = std::find_if(next.params.begin(), next.params.end(), [&](const auto& p) { return p.name == param_; });
    if (it != next.params.end()) {
      it->value = value_;
    } else {
      net::InstanceSpec::Param p;
      p.name = param_;
      p.value = value_;
      next.params.push_back(std::move(p));
      std::stable_sort(next.params.begin(), next.params.end(), [&](const auto& a, const auto& b) {
        const auto order = [&](const std::string& n) {
          const auto& ps = spec->second.params;
          return std::find_if(ps.begin(), ps.end(), [&](const auto& x) { return x.name == n; }) - ps.begin();
        };
        return order(a.name) < order(b.name);
      });
    }
  }
  if (next == *inst) return "'" + at_.name + "' has that already";
  before_ = *inst;
  *inst = next;
  after_ = std::move(next);
  return {};
}

void SetInstanceCommand::revert(Document& doc) {
  if (auto* inst = instanceOf(doc.editableNet(), at_); inst != nullptr && before_) *inst = *before_;
}

std::string SetInstanceCommand::label() const {
  return param_.empty() ? "move " + at_.name : "set " + at_.name + "." + param_ + " = " + core::formatDouble(value_);
}

void SetInstanceCommand::absorb(const Command& next) {
  const auto& n = static_cast<const SetInstanceCommand&>(next);
  after_ = n.after_;
  translation_ = n.translation_;
  rotation_ = n.rotation_;
}

std::vector<std::string> removedIoUses(const model::Model& model, const std::vector<model::PartUpdate>& updates,
                                       std::string& why) {
  // applied to a copy: the copy shares the scenes, which the updates replace and never edit
  model::Model copy = model;
  std::vector<std::string> uses;
  for (const auto& u : updates) {
    if (!model::applyPartUpdate(copy, u, uses, why)) return {};
  }
  return uses;
}

UpdatePartsCommand::UpdatePartsCommand(std::vector<model::PartUpdate> updates) : updates_(std::move(updates)) {}

std::string UpdatePartsCommand::apply(Document& doc) {
  if (other_) {
    // a redo: exactly what the first apply made
    auto before = takeState(doc);
    putState(doc, std::move(*other_));
    other_ = std::move(before);
    return {};
  }
  if (updates_.empty()) return "no part has a newer version in the library";
  const auto& m = doc.model();
  PartTypesState before{m.net, m.type_scenes, m.parts};
  std::vector<std::string> uses;
  for (const auto& u : updates_) {
    std::string why;
    if (!model::applyPartUpdate(doc.editableModel(), u, uses, why)) {
      putState(doc, std::move(before));
      return "'" + u.name + "' cannot be updated: " + why;
    }
  }
  uses_ = std::move(uses);
  other_ = std::move(before);
  return {};
}

void UpdatePartsCommand::revert(Document& doc) {
  auto now = takeState(doc);
  putState(doc, std::move(*other_));
  other_ = std::move(now);
}

std::string UpdatePartsCommand::label() const {
  if (updates_.size() == 1) return "update " + updates_[0].name + " to version " + std::to_string(updates_[0].to);
  return "update " + std::to_string(updates_.size()) + " parts";
}

std::string userPartsFolder() {
  const auto var = [](const char* name) {
    const char* v = std::getenv(name);
    return v != nullptr ? std::string(v) : std::string();
  };
  // as model::partSearchPath reads them: an empty variable is no variable
  std::string data = var("XDG_DATA_HOME");
  if (data.empty() && !var("HOME").empty()) data = var("HOME") + "/.local/share";
  return data.empty() ? std::string() : data + "/gdpn/parts";
}

SavedPart savePartOfNode(const model::Model& model, const std::string& node, const std::string& name,
                         const std::string& group, const std::string& folder, bool replace) {
  namespace fs = std::filesystem;
  SavedPart out;
  const scene::Node* n = model.scene ? model.scene->find(node) : nullptr;
  if (n == nullptr) {
    out.error = "the model's scene has no node '" + node + "' (a part placed from the library is one already)";
    return out;
  }
  // the model's parameters that the subtree's fields name become the part's
  std::set<std::string> named;
  namedParams(*n, named);
  std::vector<model::Param> params;
  for (const auto& p : model.params) {
    if (named.contains(p.name)) params.push_back(p);
  }
  std::string why;
  const auto part = model::partFromNodes({n}, name, group, params, why);
  if (!part) {
    out.error = why;
    return out;
  }
  if (folder.empty()) {
    out.error = "neither $XDG_DATA_HOME nor $HOME is set: there is no parts folder of the user's to save to";
    return out;
  }
  out.file = (fs::path(folder) / (name + model::kModelSuffix)).string();
  std::error_code ec;
  if (!replace && fs::exists(out.file, ec)) {
    out.exists = true;
    out.error = name + model::kModelSuffix + " exists in " + folder + ": Save again to replace it";
    return out;
  }
  fs::create_directories(folder, ec);
  if (ec) {
    out.error = "cannot make " + folder + ": " + ec.message();
    return out;
  }
  core::Diagnostics diags;
  if (!model::saveModel(*part, out.file, diags)) out.error = diags.str();
  return out;
}

}  // namespace gdpn::ide
