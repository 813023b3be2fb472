// The document: the model being edited, its selection, its history, and reloading from disk.

#include "gdpn/ide/document.h"
#include "gdpn/ide/script_places.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <system_error>
#include <unordered_set>
#include <vector>

#include "gdpn/core/file.h"
#include "gdpn/core/output_file.h"
#include "gdpn/core/text.h"

namespace gdpn::ide {

namespace {

std::optional<std::filesystem::file_time_type> stampOf(const std::string& path) {
  std::error_code ec;
  auto t = std::filesystem::last_write_time(path, ec);
  if (ec) return std::nullopt;
  return t;
}

}  // namespace

std::unique_ptr<Document> Document::open(const std::string& path, core::Diagnostics& diags) {
  auto text = core::readFile(path, diags);
  if (!text) return nullptr;
  auto model = model::parseModel(*text, path, diags);
  if (!model) return nullptr;
  auto doc = std::make_unique<Document>(std::move(*model));
  doc->source_ = std::move(*text);
  doc->diagnostics_ = diags;
  return doc;
}

Document::Document(model::Model model) { adopt(std::move(model)); }

std::unique_ptr<Document> Document::create(const std::string& path) {
  return std::make_unique<Document>(model::emptyModel(path));
}

model::Model Document::exchange(model::Model model) {
  model::Model old;
  old.path = model_.path;
  old.description = std::move(model_.description);
  old.settings = model_.settings;
  old.params = std::move(model_.params);
  old.signals = std::move(model_.signals);
  old.io = std::move(model_.io);
  old.net = std::move(model_.net);
  old.type_scenes = std::move(model_.type_scenes);
  old.parts = std::move(model_.parts);
  old.scene = scene_;
  model_.description = std::move(model.description);
  model_.settings = model.settings;
  model_.params = std::move(model.params);
  model_.signals = std::move(model.signals);
  model_.io = std::move(model.io);
  model_.net = std::move(model.net);
  model_.type_scenes = std::move(model.type_scenes);
  model_.parts = std::move(model.parts);
  scene_ = model.scene ? std::shared_ptr<scene::Scene>(model.scene->clone()) : nullptr;
  model_.scene = scene_;
  touched();
  return old;
}

/// Puts another model's content in place of the document's (a restored autosave); undo puts
/// the old one back.
class ReplaceModelCommand final : public Command {
 public:
  ReplaceModelCommand(model::Model model, std::string label) : model_(std::move(model)), label_(std::move(label)) {}
  std::string apply(Document& doc) override {
    model_ = doc.exchange(std::move(model_));
    return {};
  }
  void revert(Document& doc) override { model_ = doc.exchange(std::move(model_)); }
  [[nodiscard]] std::string label() const override { return label_; }
  void absorb(const Command&) override {}

 private:
  model::Model model_;  // the content not in the document now
  std::string label_;
};

std::shared_ptr<scene::Scene> Document::swapScene(std::shared_ptr<scene::Scene> scene) {
  auto old = std::move(scene_);
  scene_ = std::move(scene);
  model_.scene = scene_;
  return old;
}

void Document::adopt(model::Model model) {
  model_ = std::move(model);
  // an editable copy of the scene, which the model then shares
  scene_.reset();
  if (model_.scene) scene_ = std::shared_ptr<scene::Scene>(model_.scene->clone());
  model_.scene = scene_;
  stamp_ = model_.path.empty() ? std::nullopt : stampOf(model_.path);
  script_stamps_ = scriptStamps();
  touched();
  saved_revision_ = revision_;
}

std::map<std::string, std::filesystem::file_time_type> Document::scriptStamps() const {
  std::map<std::string, std::filesystem::file_time_type> stamps;
  if (model_.path.empty()) return stamps;
  std::error_code ec;
  const auto dir = std::filesystem::path(model_.path).parent_path();
  for (std::filesystem::directory_iterator it(dir.empty() ? "." : dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->path().extension() != ".py") continue;
    if (auto t = stampOf(it->path().string())) stamps[it->path().string()] = *t;
  }
  return stamps;
}

bool Document::scriptsChanged() {
  auto now = scriptStamps();
  if (now == script_stamps_) return false;
  script_stamps_ = std::move(now);
  return true;
}

model::Model Document::snapshot() const {
  model::Model copy = model_;
  if (scene_) copy.scene = std::shared_ptr<const scene::Scene>(scene_->clone());
  // the scripts on the lines Save gives them: a run's error is placed at the file's line
  placeScripts(copy, text());
  return copy;
}

namespace {

/// Keeps the file at `path` as `path.~N~` (N one more than the highest kept, the oldest beyond
/// kBackups removed) before it is written over. "" or why it could not.
std::string keepBackup(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return {};
  const fs::path file(path);
  const std::string stem = file.filename().string() + ".~";
  std::vector<std::pair<long, fs::path>> kept;
  for (const auto& entry : fs::directory_iterator(file.parent_path().empty() ? fs::path(".") : file.parent_path(), ec)) {
    const std::string name = entry.path().filename().string();
    if (!name.starts_with(stem) || !name.ends_with("~") || name.size() <= stem.size() + 1) continue;
    const std::string digits = name.substr(stem.size(), name.size() - stem.size() - 1);
    if (!std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }) || digits.size() > 9) continue;
    kept.emplace_back(std::stol(digits), entry.path());
  }
  std::sort(kept.begin(), kept.end());
  const long next = kept.empty() ? 1 : kept.back().first + 1;
  const fs::path backup = file.parent_path() / (stem + std::to_string(next) + "~");
  fs::copy_file(file, backup, fs::copy_options::overwrite_existing, ec);
  if (ec) return "cannot keep a backup as " + backup.string() + ": " + ec.message();
  // the newest kBackups stay (the one just made among them)
  kept.emplace_back(next, backup);
  for (std::size_t i = 0; i + Document::kBackups < kept.size(); ++i) fs::remove(kept[i].second, ec);
  return {};
}

}  // namespace

bool Document::writeFile(const std::string& to, const std::string& text, core::Diagnostics& diags) {
  if (auto why = keepBackup(to); !why.empty()) {
    diags.error(core::SourceLoc{to, 0, 0}, why);
    return false;
  }
  if (std::string why; !core::writeOutput(to, text, why)) {
    diags.error({to, 0, 0}, why);
    return false;
  }
  return true;
}

bool Document::save(core::Diagnostics& diags, const std::string& path) {
  const auto& to = path.empty() ? model_.path : path;
  std::string written = text();
  if (!writeFile(to, written, diags)) return false;
  if (to == model_.path) {
    source_ = std::move(written);  // the next save keeps this file's layout
    stamp_ = stampOf(to);
    saved_revision_ = revision_;
    discardAutosave();
  }
  return true;
}

bool Document::saveAs(const std::string& path, core::Diagnostics& diags) {
  if (path.empty()) {
    diags.error({}, "Save As needs a file name");
    return false;
  }
  if (!path.ends_with(model::kModelSuffix)) {
    diags.error({path, 0, 0}, std::string("a model file's name ends in ") + model::kModelSuffix);
    return false;
  }
  std::string written = text();
  if (!writeFile(path, written, diags)) return false;
  discardAutosave();  // the old file's: its edits are in the new file
  model_.path = path;
  source_ = std::move(written);
  stamp_ = stampOf(path);
  saved_revision_ = revision_;
  script_stamps_ = scriptStamps();
  return true;
}

namespace {

/// The user's state folder for gdpn ($XDG_STATE_HOME/gdpn, else ~/.local/state/gdpn).
std::filesystem::path stateFolder() {
  if (const char* xdg = std::getenv("XDG_STATE_HOME"); xdg != nullptr && *xdg != '\0') {
    return std::filesystem::path(xdg) / "gdpn";
  }
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') {
    return std::filesystem::path(home) / ".local" / "state" / "gdpn";
  }
  return std::filesystem::temp_directory_path() / "gdpn-state";
}

std::optional<std::string> readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

std::string Document::autosavePath() const {
  std::error_code ec;
  auto absolute = std::filesystem::absolute(model_.path.empty() ? "untitled" : model_.path, ec).lexically_normal();
  const auto name = absolute.filename().string();
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(core::fnv1a(absolute.string())));
  return (stateFolder() / "autosave" / (name + "." + hash)).string();
}

bool Document::autosave(core::Diagnostics& diags) {
  const auto path = autosavePath();
  std::error_code ec;
  std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
  if (ec) {
    diags.error({path, 0, 0}, "cannot make the autosave folder: " + ec.message());
    return false;
  }
  return model::saveModel(model_, path, diags, source_);
}

bool Document::autosavePending() const {
  const auto path = autosavePath();
  const auto saved = stampOf(path);
  if (!saved) return false;
  const auto file = model_.path.empty() ? std::nullopt : stampOf(model_.path);
  if (file && *file > *saved) return false;
  const auto text = readText(path);
  return text && *text != this->text();
}

std::string Document::restoreAutosave() {
  const auto path = autosavePath();
  const auto text = readText(path);
  if (!text) return "there is no autosave of this model (" + path + ")";
  core::Diagnostics diags;
  // read as the model file itself, so that its relative files are found beside the model
  auto model = model::parseModel(*text, model_.path, diags);
  if (!model) {
    diagnostics_ = std::move(diags);
    return "the autosave " + path + " has errors";
  }
  return execute(std::make_unique<ReplaceModelCommand>(std::move(*model), "restore the autosave"));
}

void Document::discardAutosave() const {
  std::error_code ec;
  std::filesystem::remove(autosavePath(), ec);
}

std::string Document::execute(std::unique_ptr<Command> command) { return undo_.push(std::move(command), *this); }

bool Document::changedOnDisk() const {
  if (model_.path.empty()) return false;
  return stampOf(model_.path) != stamp_;
}

bool Document::reload() {
  core::Diagnostics diags;
  auto text = core::readFile(model_.path, diags);
  auto model = text ? model::parseModel(*text, model_.path, diags) : std::nullopt;
  if (!model) {
    // keep the old model; remember the new file's time so the errors are not read again and again
    stamp_ = stampOf(model_.path);
    diagnostics_ = std::move(diags);
    return false;
  }
  adopt(std::move(*model));
  source_ = std::move(*text);
  diagnostics_ = std::move(diags);
  undo_.clear();
  selectAll(stillNamed(*this, selections()));
  return true;
}

std::vector<Selection> Document::selections() const {
  if (!selection_.any()) return {};
  std::vector<Selection> out = also_;
  out.push_back(selection_);
  return out;
}

void Document::selectAll(const std::vector<Selection>& all) {
  select({});
  std::unordered_set<std::string> seen;  // kind and name: repeats are left out (a page's worth costs its size)
  for (const auto& one : all) {
    if (!one.any() || !seen.insert(char(static_cast<int>(one.kind) + '0') + one.name).second) continue;
    if (selection_.any()) also_.push_back(std::move(selection_));
    selection_ = one;
  }
}

void Document::toggleSelected(const Selection& one) {
  if (!one.any()) return;
  if (selection_ == one) {
    // the one added before it becomes the current one
    if (also_.empty()) {
      selection_ = {};
    } else {
      selection_ = std::move(also_.back());
      also_.pop_back();
    }
    return;
  }
  if (const auto it = std::find(also_.begin(), also_.end(), one); it != also_.end()) {
    also_.erase(it);
    return;
  }
  if (selection_.any()) also_.push_back(std::move(selection_));
  selection_ = one;
}

bool Document::isSelected(const Selection& one) const {
  return one.any() && (selection_ == one || std::find(also_.begin(), also_.end(), one) != also_.end());
}

}  // namespace gdpn::ide
