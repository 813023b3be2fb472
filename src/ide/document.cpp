// The document: the model being edited, its selection, its history, and reloading from disk.

#include "gdpn/ide/document.h"

#include <algorithm>
#include <system_error>
#include <vector>

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
  auto model = model::loadModel(path, diags);
  if (!model) return nullptr;
  auto doc = std::make_unique<Document>(std::move(*model));
  doc->diagnostics_ = diags;
  return doc;
}

Document::Document(model::Model model) { adopt(std::move(model)); }

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
  ++revision_;
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

bool Document::save(core::Diagnostics& diags, const std::string& path) {
  const auto& to = path.empty() ? model_.path : path;
  if (auto why = keepBackup(to); !why.empty()) {
    diags.error(core::SourceLoc{to, 0, 0}, why);
    return false;
  }
  if (!model::saveModel(model_, to, diags)) return false;
  if (to == model_.path) stamp_ = stampOf(to);
  return true;
}

std::string Document::execute(std::unique_ptr<Command> command) { return undo_.push(std::move(command), *this); }

bool Document::changedOnDisk() const {
  if (model_.path.empty()) return false;
  return stampOf(model_.path) != stamp_;
}

bool Document::reload() {
  core::Diagnostics diags;
  auto model = model::loadModel(model_.path, diags);
  if (!model) {
    // keep the old model; remember the new file's time so the errors are not read again and again
    stamp_ = stampOf(model_.path);
    diagnostics_ = std::move(diags);
    return false;
  }
  adopt(std::move(*model));
  diagnostics_ = std::move(diags);
  undo_.clear();
  if (selection_.kind == SelectionKind::Node && (!scene_ || scene_->find(selection_.name) == nullptr)) {
    selection_ = {};
  }
  return true;
}

}  // namespace gdpn::ide
