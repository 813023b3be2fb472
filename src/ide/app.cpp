// The IDE's frame: the run advances, the views draw in their places, the splitters move, and
// replay actions are performed through the same document and run controls the views use.

#include "app.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iterator>
#include <string_view>
#include <utility>

#include "action_run.h"
#include "detail/picture_texture.h"
#include "detail/world_texture.h"
#include "net_actions.h"
#include "gdpn/ide/net_edit.h"
#include "gdpn/ide/scene_edit.h"
#include "gdpn/ide/set_field.h"
#include "gdpn/scene/actions.h"
#include "gdpn/ide/actions.h"
#include "gdpn/session/breakpoint_syntax.h"
#include "views.h"
#include "views/net_view_state.h"
#include "views/palette_state.h"

namespace gdpn::ide {

namespace {

/// `path` made absolute and normal ("a/../b.yaml" from /w: "/w/b.yaml"); as given when it cannot be.
std::string absolutePath(const std::string& path) {
  std::error_code ec;
  const auto a = std::filesystem::absolute(path, ec);
  return ec ? path : a.lexically_normal().string();
}

constexpr const char* kRegularFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr const char* kBoldFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf";
constexpr float kFontSize = 15.0F;

nlohmann::json rectJson(const Rect& r) { return {r.x, r.y, r.w, r.h}; }

}  // namespace

Fonts loadFonts() {
  auto& io = ImGui::GetIO();
  Fonts f;
  // Latin-1, and the dashes and arrows the views write (an em dash for no value, an arrow for
  // a force waiting for the next step)
  static const ImWchar kRanges[] = {0x0020, 0x00FF, 0x2010, 0x2027, 0x2190, 0x2193, 0};
  if (std::filesystem::exists(kRegularFont)) f.regular = io.Fonts->AddFontFromFileTTF(kRegularFont, kFontSize, nullptr, kRanges);
  if (f.regular == nullptr) f.regular = io.Fonts->AddFontDefault();
  if (std::filesystem::exists(kBoldFont)) f.bold = io.Fonts->AddFontFromFileTTF(kBoldFont, kFontSize, nullptr, kRanges);
  if (f.bold == nullptr) f.bold = f.regular;
  return f;
}

App::App(std::unique_ptr<Document> doc, session::SessionOptions options)
    : doc_(std::move(doc)), options_(options), net_view_(std::make_unique<NetViewState>()),
      palette_(std::make_unique<PaletteState>()) {
  core::Diagnostics diags;
  (void)run_.open(*doc_, diags, std::move(options));
  if (std::filesystem::exists(doc_->model().path)) recent = withRecent(recent, absolutePath(doc_->model().path));
  // the world view starts where the scene's first Camera looks (or a view that frames it)
  if (auto* s = doc_->scene()) {
    scene::updateTransforms(s->root());
    std::string error;
    world.orbit = OrbitCamera::from(render::chooseCamera(*s, "", 0.0, error));
  }
  const auto names = run_.transitions();
  if (!names.empty()) toolbar.fire_target = names.front();
  restore_offered = doc_->autosavePending();
  autosaved_revision = doc_->revision();
}

App::~App() {
  std::string why;
  if (movie) (void)movie->close(why);  // a movie being filmed when the IDE closes is kept
}

void App::toggleMovie() {
  if (!movie) {
    movie = std::make_unique<capture::MovieWriter>();  // opened by filmFrame, which knows the size
    movie_path = "gdpn-ide-" + std::to_string(++movies) + ".mp4";
    message = "filming " + movie_path;
    return;
  }
  std::string why;
  const auto frames = movie->frames();
  message = movie->frames() == 0 ? "no frames filmed"
            : movie->close(why)  ? "saved " + movie_path + " (" + std::to_string(frames) + " frames)"
                                 : movie_path + ": " + why;
  movie.reset();
}

void App::filmFrame(int width, int height, const std::vector<std::uint8_t>& rgb) {
  if (!movie) return;
  const int w = width & ~1, h = height & ~1;
  std::string why;
  if (movie->frames() == 0 && !movie->open(movie_path, w, h, std::clamp(std::round(fps), 10.0, 60.0), why)) {
    message = movie_path + ": " + why;
    movie.reset();
    return;
  }
  std::vector<std::uint8_t> even(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3);
  for (int y = 0; y < h; ++y) {
    std::copy_n(rgb.begin() + static_cast<std::ptrdiff_t>(y) * width * 3, static_cast<std::size_t>(w) * 3,
                even.begin() + static_cast<std::ptrdiff_t>(y) * w * 3);
  }
  if (!movie->write(even)) {
    (void)movie->close(why);
    message = movie_path + ": " + why;
    movie.reset();
  }
}

void App::initGraphics(Fonts f) {
  fonts = f;
  const auto dir = std::filesystem::path(doc_->model().path).parent_path().string();
  world.renderer = std::make_unique<render::Renderer>(dir);
  world.texture = std::make_unique<WorldTexture>();
}

scene::Scene* App::shownScene() const {
  if (run_.mode() != RunMode::Edit && run_.session() != nullptr) return run_.session()->simulation().plant();
  if (palette_->edit_scene) return palette_->edit_scene.get();
  return doc_->scene();
}

void App::selectNode(const std::string& path) {
  doc_->select(Selection::node(path));
  tree.reveal = true;
}

bool App::selectByName(const std::string& name) {
  auto* s = shownScene();
  if (s != nullptr && s->find(name) != nullptr) {
    selectNode(name);
    return true;
  }
  // an arc, as arcName() writes it ("main: a -> t")
  if (const Selection arc{SelectionKind::Arc, name}; parseArcName(name) && namesSomething(*doc_, arc)) {
    doc_->select(arc);
    return true;
  }
  if (run_.session() == nullptr) return false;
  const auto& net = run_.session()->simulation().net();
  if (net.findPlace(name)) {
    doc_->select({SelectionKind::Place, name});
    return true;
  }
  if (net.findTransition(name)) {
    doc_->select({SelectionKind::Transition, name});
    toolbar.fire_target = name;
    return true;
  }
  // an instance: a prefix of qualified names
  const auto prefix = name + "/";
  for (net::PlaceId p{0}; p < net.places().size(); ++p) {
    if (net.placeName(p).starts_with(prefix)) {
      doc_->select({SelectionKind::Instance, name});
      return true;
    }
  }
  return false;
}

void App::frameSelection() {
  auto* s = shownScene();
  if (s == nullptr) return;
  scene::updateTransforms(s->root());
  const auto& sel = doc_->selection();
  auto* node = sel.kind == SelectionKind::Node ? s->find(sel.name) : nullptr;
  world.orbit.frame(scene::boundingBox(node != nullptr ? *node : s->root()));
  world.camera_node.clear();
}

void App::undo() {
  if (!doc_->undo()) message = "nothing to undo";
  else message = "undone";
}

void App::redo() {
  if (!doc_->redo()) message = "nothing to redo";
  else message = "redone";
}

void App::save() {
  if (untitled_) {  // a new model has no file yet: its name first
    browse(BrowseFor::SaveAs);
    return;
  }
  core::Diagnostics diags;
  message = doc_->save(diags) ? "saved " + doc_->model().path : diags.str();
}

void App::deleteSelection() {
  if (run_.mode() != RunMode::Edit) {
    message = "the run's plant and net are not edited: Reset to edit the model";
    return;
  }
  const auto sel = doc_->selection();
  std::string why;
  if (sel.kind == SelectionKind::Node) {
    why = doc_->execute(std::make_unique<SceneEditCommand>(SceneEdit{SceneEditKind::Delete, sel.name, {}, {}, false, {}}));
  } else if (sel.kind == SelectionKind::None) {
    return;
  } else if (!netSelection(*this).empty()) {
    // what is selected on the net view's page, as one step
    why = deleteNetSelection(*this);
    if (!why.empty()) message = why;
    return;
  } else if (sel.kind == SelectionKind::Place || sel.kind == SelectionKind::Transition) {
    // chosen in the tree on a page the net view does not show
    const auto at = locateConstruct(doc_->model().net, sel.name);
    why = at ? doc_->execute(std::make_unique<NetEditCommand>(makeNetEdit(NetEditKind::Delete, at->page, at->name)))
             : "'" + sel.name + "' is not written on a page";
  } else {
    message = "show " + sel.name + "'s page in the net view to delete it";
    return;
  }
  message = why.empty() ? "deleted " + sel.name : why;
  if (why.empty()) doc_->select({});
}

const TokenTypes& App::tokenTypes() {
  if (token_types_revision_ == doc_->revision()) return token_types_;
  const auto& m = doc_->model();
  token_types_ = propagateTokenTypes(m.net, [&](const std::string& page, const std::string& path) -> const scene::NodeType* {
    const auto it = m.type_scenes.find(page);
    const scene::Scene* s = it != m.type_scenes.end() ? it->second.get() : doc_->scene();
    const auto* node = s != nullptr ? s->find(path) : nullptr;
    return node != nullptr ? &node->type() : nullptr;
  });
  token_types_revision_ = doc_->revision();
  return token_types_;
}

bool App::copySelection() {
  // the clipboard holds a model file: the node's subtree as its scene, or the place or
  // transition on a page; it pastes into any model, and reads as text anywhere else
  const auto& sel = doc_->selection();
  model::Model m;
  if (sel.kind == SelectionKind::Node) {
    const auto* s = doc_->scene();
    const auto* node = s != nullptr ? s->find(sel.name) : nullptr;
    if (node == nullptr) return false;
    auto fragment = std::make_shared<scene::Scene>(s->types());
    fragment->copy(*node, fragment->root());
    m.scene = fragment;
  } else if (const auto net_selected = netSelection(*this); std::any_of(
                 net_selected.constructs.begin(), net_selected.constructs.end(), [&](const auto& c) {
                   const auto* page = findPage(doc_->model().net, net_selected.page);
                   return page != nullptr && std::any_of(page->instances.begin(), page->instances.end(),
                                                         [&](const auto& i) { return i.name == c.first; });
                 })) {
    message = "an instance is not copied: select places and transitions (with the arcs among them) to copy";
    return false;
  } else if (auto many = copyNetSelection(*this); !many.places.empty() || !many.transitions.empty()) {
    // the net view's selection, with the arcs among it
    m.net.pages.push_back(std::move(many));
  } else if (sel.kind == SelectionKind::Place || sel.kind == SelectionKind::Transition) {
    const auto at = locateConstruct(doc_->model().net, sel.name);
    auto* page = at ? findPage(doc_->editableNet(), at->page) : nullptr;
    if (page == nullptr) return false;
    net::PageSpec fragment;
    fragment.name = at->page;
    for (const auto& p : page->places) {
      if (p.name == at->name) fragment.places.push_back(p);
    }
    for (const auto& t : page->transitions) {
      if (t.name == at->name) fragment.transitions.push_back(t);
    }
    m.net.pages.push_back(std::move(fragment));
  } else {
    message = "select a node, a place or a transition to copy";
    return false;
  }
  // the parameters its fields name go with it, so that it reads back
  m.params = doc_->model().params;
  copied = model::writeModel(m);
  ImGui::SetClipboardText(copied.c_str());
  const auto count = m.net.pages.empty() ? 1 : m.net.pages.front().places.size() + m.net.pages.front().transitions.size();
  message = count > 1 ? "copied " + std::to_string(count) + " places and transitions (as a model file)"
                      : "copied " + sel.name + " (as a model file)";
  return true;
}

void App::paste() {
  if (run_.mode() != RunMode::Edit) {
    message = "the run's plant is not edited: Reset to edit the model";
    return;
  }
  // an empty clipboard (or one holding no text) is nothing to paste: nothing happens
  const char* text = ImGui::GetClipboardText();
  if (text == nullptr || std::string_view(text).find_first_not_of(" \t\r\n") == std::string_view::npos) return;
  core::Diagnostics diags;
  auto m = model::parseModel(text, "<clipboard>", diags);
  // a field that names a parameter this model does not declare keeps its value alone
  if (m) model::keepParamsOf(*m, doc_->model().params);
  // a model file's places and transitions go into the net view's page
  const net::PageSpec* constructs = nullptr;
  if (m) {
    for (const auto& page : m->net.pages) {
      if (!page.places.empty() || !page.transitions.empty()) constructs = &page;
    }
  }
  if (constructs != nullptr) {
    auto e = makeNetEdit(NetEditKind::Paste, net_view_->layout.page, {});
    e.fragment = *constructs;
    auto command = std::make_unique<NetEditCommand>(std::move(e));
    const auto* edit = command.get();  // kept on the undo stack when it succeeds
    const auto why = doc_->execute(std::move(command));
    message = why.empty() ? "pasted " + edit->made() + " into " + net_view_->layout.page : why;
    if (why.empty()) {
      // everything pasted is selected, ready to be moved as one
      const auto& prefix = net_view_->view.prefix.empty() ? net_view_->layout.page : net_view_->view.prefix;
      std::vector<Selection> made;
      for (const auto& p : edit->pasted().places) made.push_back({SelectionKind::Place, prefix + "/" + p.name});
      for (const auto& t : edit->pasted().transitions) made.push_back({SelectionKind::Transition, prefix + "/" + t.name});
      for (const auto& a : edit->pasted().arcs) made.push_back({SelectionKind::Arc, arcName(prefix, a.from, a.to, a.kind)});
      doc_->selectAll(made);
    }
    return;
  }
  if (!m || !m->scene || m->scene->root().children().empty()) {
    message = "the clipboard holds no scene nodes, places or transitions of a model file";
    return;
  }
  std::string made;
  const auto why = pasteScene(m->scene, made);
  message = why.empty() ? "pasted " + made : why;
}

std::string App::pasteScene(std::shared_ptr<const scene::Scene> fragment, std::string& made) {
  // under the selected node when it takes children, else beside it, else at the top
  const auto& sel = doc_->selection();
  const auto* s = doc_->scene();
  const auto* node = sel.kind == SelectionKind::Node && s != nullptr ? s->find(sel.name) : nullptr;
  std::string parent;
  if (node != nullptr) parent = node->type().has_children ? sel.name : (node->parent() == &s->root() ? "" : node->parent()->path());
  auto command = std::make_unique<SceneEditCommand>(SceneEdit{SceneEditKind::Paste, parent, {}, {}, false, std::move(fragment)});
  const auto* edit = command.get();  // kept on the undo stack when it succeeds
  const auto why = doc_->execute(std::move(command));
  if (why.empty()) {
    made = edit->made();
    doc_->select(Selection::node(made));
    tree.reveal = true;
  }
  return why;
}

void App::importMeshes(const std::string& files) {
  if (run_.mode() != RunMode::Edit) {
    message = "the run's plant is not edited: Reset to edit the model";
    return;
  }
  // the files, separated by ';' or new lines; a relative name is looked for beside the model
  // first, then in the current folder
  namespace fs = std::filesystem;
  const auto& model_path = doc_->model().path;
  const fs::path folder = fs::path(model_path).parent_path();
  auto fragment = std::make_shared<scene::Scene>(doc_->scene() != nullptr ? doc_->scene()->types() : scene::builtinTypes());
  std::string errors;
  int read = 0;
  std::size_t start = 0;
  while (start <= files.size()) {
    auto end = files.find_first_of(";\n", start);
    if (end == std::string::npos) end = files.size();
    std::string name = files.substr(start, end - start);
    start = end + 1;
    name.erase(0, name.find_first_not_of(" \t"));
    name.erase(name.find_last_not_of(" \t") + 1);
    if (name.empty()) continue;
    std::error_code ec;
    const fs::path beside = folder / name;
    const std::string path = fs::path(name).is_relative() && fs::exists(beside, ec) ? beside.string() : name;
    core::Diagnostics diags;
    const auto m = model::meshModel(path, model_path.empty() ? "untitled.gdpn.yaml" : model_path, diags);
    if (!m || !m->scene) {
      errors += (errors.empty() ? "" : "; ") + diags.str();
      continue;
    }
    for (const auto& top : m->scene->root().children()) {
      const bool free = fragment->root().child(top->name()) == nullptr;
      fragment->copy(*top, fragment->root(), free ? std::string() : fragment->freshName(fragment->root(), top->name()));
    }
    ++read;
  }
  if (read == 0) {
    message = errors.empty() ? "no mesh files named" : errors;
    return;
  }
  // one step for all of them, under the selected node (beside it, or at the top)
  std::string made;
  const auto why = pasteScene(fragment, made);
  message = !why.empty() ? why
                         : "imported " + std::to_string(read) + (read == 1 ? " mesh file" : " mesh files") +
                               (errors.empty() ? std::string() : "; not read: " + errors);
}

void App::saveAs(const std::string& path) {
  core::Diagnostics diags;
  if (!doc_->saveAs(path, diags)) {
    message = diags.str();
    return;
  }
  message = "saved as " + path;
  untitled_ = false;
  recent = withRecent(recent, absolutePath(path));
  // a question waited for this save (a new model saved before it is closed)
  if (question.then != AfterQuestion::None) {
    const auto waiting = std::exchange(question, {});
    proceed(waiting.then, waiting.path);
  }
}

void App::newModel() {
  if (!askFirst(AfterQuestion::New, {})) proceed(AfterQuestion::New, {});
}

void App::openModel(const std::string& path) {
  if (!askFirst(AfterQuestion::Open, path)) proceed(AfterQuestion::Open, path);
}

void App::closeModel() {
  if (!askFirst(AfterQuestion::Close, {})) proceed(AfterQuestion::Close, {});
}

void App::quit() {
  if (!askFirst(AfterQuestion::Quit, {})) proceed(AfterQuestion::Quit, {});
}

bool App::askFirst(AfterQuestion then, const std::string& path) {
  if (!doc_->modified()) return false;
  question = {then, path};
  return true;
}

void App::answer(SaveAnswer a) {
  if (question.then == AfterQuestion::None) return;
  switch (a) {
    case SaveAnswer::Cancel: question = {}; return;
    case SaveAnswer::DontSave: break;
    case SaveAnswer::Save:
      if (untitled_) {  // Save As first; the question goes on once it is saved
        browse(BrowseFor::SaveAs);
        return;
      }
      save();
      if (doc_->modified()) {  // the save failed: the message says why, the model stays
        question = {};
        return;
      }
      break;
  }
  const auto waiting = std::exchange(question, {});
  proceed(waiting.then, waiting.path);
}

void App::proceed(AfterQuestion then, const std::string& path) {
  switch (then) {
    case AfterQuestion::None: return;
    case AfterQuestion::Quit: quit_requested_ = true; return;
    case AfterQuestion::New:
    case AfterQuestion::Close: {
      // a name beside the old model's that no file has yet
      const auto folder = std::filesystem::path(doc_->model().path).parent_path();
      replaceDocument(Document::create(model::untitledModelPath(folder.string())), true);
      message = then == AfterQuestion::New ? "a new model: Save gives it a name" : "closed; a new model took its place";
      return;
    }
    case AfterQuestion::Open: {
      core::Diagnostics diags;
      auto doc = Document::open(path, diags);
      if (!doc) {
        message = "cannot open " + path + ": " + (diags.all().empty() ? std::string("no such model") : diags.all().front().str());
        return;
      }
      replaceDocument(std::move(doc), false);
      recent = withRecent(recent, absolutePath(path));
      message = "opened " + path;
      return;
    }
  }
}

void App::replaceDocument(std::unique_ptr<Document> doc, bool untitled) {
  doc_ = std::move(doc);
  untitled_ = untitled;
  core::Diagnostics diags;
  (void)run_.open(*doc_, diags, options_);
  run_.setPlantOnly(false);
  net_view_ = std::make_unique<NetViewState>();
  palette_ = std::make_unique<PaletteState>();  // the new model's parts are scanned for at the next frame
  token_types_revision_ = ~std::uint64_t{0};
  io_list.rows.clear();  // the list is found again for the new model (its tab stays chosen)
  io_list.revision = ~std::uint64_t{0};
  io_list.typed.clear();
  part_updates = {};  // found again for the new model
  save_part = {};
  inspector.scripts = {};
  world.manipulating = {};
  world.camera_node.clear();
  toolbar.fire_target.clear();
  const auto names = run_.transitions();
  if (!names.empty()) toolbar.fire_target = names.front();
  world.orbit = OrbitCamera{};
  if (auto* s = doc_->scene()) {
    scene::updateTransforms(s->root());
    std::string error;
    world.orbit = OrbitCamera::from(render::chooseCamera(*s, "", 0.0, error));
  }
  restore_offered = doc_->autosavePending();
  autosaved_revision = doc_->revision();
  quiet_revision = followed_revision = 0;
  world.key = {};
  if (world.renderer) world.renderer = std::make_unique<render::Renderer>(std::filesystem::path(doc_->model().path).parent_path().string());
}

void App::browse(BrowseFor mode) {
  browser.open = true;
  browser.mode = mode;
  browser.error.clear();
  browser.replacing.clear();
  const auto path = std::filesystem::path(absolutePath(doc_->model().path));
  browser.folder = path.parent_path().string();
  browser.name = mode == BrowseFor::SaveAs ? path.filename().string() : std::string();
}

std::string App::title() const {
  return (doc_->modified() ? "*" : "") + std::filesystem::path(doc_->model().path).filename().string() + " - gdpn ide";
}

void App::openGuide() {
  // the installed docs (PREFIX/share/doc/gdpn beside PREFIX/bin), else the sources' of a build
  // tree the program runs from
  std::error_code ec;
  const auto exe = std::filesystem::canonical("/proc/self/exe", ec);
  std::vector<std::filesystem::path> candidates;
  if (!ec) {
    candidates.push_back(exe.parent_path().parent_path() / "share" / "doc" / "gdpn" / "ide.md");
    for (auto dir = exe.parent_path(); dir.has_relative_path(); dir = dir.parent_path()) {
      candidates.push_back(dir / "docs" / "ide.md");
    }
  }
  for (const auto& c : candidates) {
    if (!std::filesystem::exists(c, ec)) continue;
    message = "the guide: " + c.string();
    const bool quotable = c.string().find('\'') == std::string::npos;  // the shell line quotes it
    if (quotable && (std::getenv("DISPLAY") != nullptr || std::getenv("WAYLAND_DISPLAY") != nullptr)) {
      const std::string command = "xdg-open '" + c.string() + "' >/dev/null 2>&1 &";
      if (std::system(command.c_str()) != 0) message += " (xdg-open could not show it)";
    }
    return;
  }
  message = "the guide (docs/ide.md) is not installed here";
}

void App::restoreAutosave() {
  restore_offered = false;
  const auto why = doc_->restoreAutosave();
  message = why.empty() ? "restored the edits of the autosave: Save keeps them, Undo drops them" : why;
}

void App::discardAutosave() {
  restore_offered = false;
  doc_->discardAutosave();
  message = "the autosave was removed";
}

void App::checkAutosave(double wall_seconds) {
  // edits wait autosave_seconds before they are written; each new edit does not restart the wait
  if (autosave_seconds <= 0 || !doc_->modified() || doc_->revision() == autosaved_revision) {
    autosave_clock = 0;
    return;
  }
  autosave_clock += wall_seconds;
  if (autosave_clock < autosave_seconds) return;
  autosave_clock = 0;
  autosaved_revision = doc_->revision();
  core::Diagnostics diags;
  if (!doc_->autosave(diags)) message = "autosave failed: " + diags.str();
}

void App::followEdits(double wall_seconds) {
  // in edit mode the run follows the edited model a quarter of a second after the edits stop
  // (not while a field or a handle is held): the net view shows the marking as edited and the
  // Diagnostics view what the compiler says of it
  if (doc_->revision() != quiet_revision) {
    quiet_revision = doc_->revision();
    edit_quiet = 0;
  }
  edit_quiet += wall_seconds;
  if (run_.mode() != RunMode::Edit || run_.revision() == doc_->revision() || edit_quiet < 0.25) return;
  if (ImGui::IsAnyItemActive() || world.manipulating.handle != Handle::None) return;
  if (followed_revision == doc_->revision()) return;  // tried already: it did not compile
  followed_revision = doc_->revision();
  core::Diagnostics diags;
  (void)run_.reset(diags);
}

void App::drawRestoreOffer(nlohmann::json& report) {
  constexpr const char* kTitle = "Unsaved edits found";
  report = {{"offered", restore_offered}};
  if (!restore_offered) return;
  if (!ImGui::IsPopupOpen(kTitle)) ImGui::OpenPopup(kTitle);
  const auto& io = ImGui::GetIO();
  ImGui::SetNextWindowPos({io.DisplaySize.x / 2, io.DisplaySize.y / 2}, ImGuiCond_Always, {0.5F, 0.5F});
  if (!ImGui::BeginPopupModal(kTitle, nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove)) return;
  const auto autosave = doc_->autosavePath();
  ImGui::TextUnformatted("The IDE ended without saving edits to this model. An autosave of them is newer than");
  ImGui::TextUnformatted("the model file:");
  ImGui::TextDisabled("%s", autosave.c_str());
  ImGui::Spacing();
  nlohmann::json buttons;
  const auto button = [&](const char* label) {
    const bool pressed = ImGui::Button(label, {200, 0});
    noteItem(label, buttons);
    return pressed;
  };
  if (button("Restore the edits")) restoreAutosave();
  ImGui::SameLine();
  if (button("Discard the autosave")) discardAutosave();
  if (!restore_offered) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
  report["autosave"] = autosave;
  report["buttons"] = buttons;
}

void App::reset() {
  core::Diagnostics diags;
  if (!run_.reset(diags)) {
    message = "the edited model does not compile: see Diagnostics";
    return;
  }
  message = "reset";
}

void App::checkReload() {
  // twice a second at 60 frames a second is enough
  if (++frames_ % 30 != 0) return;
  if (!doc_->changedOnDisk()) {
    if (doc_->scriptsChanged()) {
      reset();
      if (run_.buildDiagnostics().all().empty()) message = "a script changed: the run was reset with it";
    }
    return;
  }
  if (!doc_->reload()) {
    message = "the model file changed and has errors: the old model stays";
    return;
  }
  message = "reloaded " + std::filesystem::path(doc_->model().path).filename().string();
  // the run takes the new model at once
  reset();
}

bool App::perform(const Action& a, std::string& error) {
  switch (a.kind) {
    case ActionKind::Select:
      if (!selectByName(a.text)) error = "nothing is called '" + a.text + "'";
      break;
    case ActionKind::Press:
      if (const auto id = findAction(a.text)) error = performAction(*this, *id);
      else error = "no action is called '" + a.text + "' (" + actionNames() + ")";
      break;
    case ActionKind::Fire: {
      const auto names = run_.transitions();
      if (std::find(names.begin(), names.end(), a.text) == names.end()) {
        error = "the net has no transition '" + a.text + "'";
        break;
      }
      toolbar.fire_target = a.text;
      (void)run_.fire(a.text);
      message = run_.message();
      break;
    }
    case ActionKind::RunFor: run_.runFor(a.number); break;
    case ActionKind::Steps: run_.runSteps(static_cast<std::int64_t>(a.number)); break;
    case ActionKind::Set: {
      auto* s = doc_->scene();
      const auto* node = s ? s->find(a.text) : nullptr;
      if (node == nullptr) {
        error = "no node '" + a.text + "'";
        break;
      }
      // besides the fields: the template mark and user data (`data.order`), as the file has them
      if (a.field == "template") {
        if (a.list || a.value.size() != 1 || (a.value[0] != "true" && a.value[0] != "false")) {
          error = "'template' expects true or false";
          break;
        }
        error = doc_->execute(std::make_unique<SetTemplateCommand>(a.text, a.value[0] == "true"));
        inspector.error = error;
        break;
      }
      if (a.field.starts_with("data.")) {
        std::optional<scene::FieldValue> datum;
        if (a.list) {
          // the list as the file's text rule reads it: "[1, 2.5]"
          std::string text = "[";
          for (const auto& w : a.value) text += (text.size() > 1 ? ", " : "") + w;
          datum = scene::datumFromText(text + "]");
          if (!std::holds_alternative<std::vector<double>>(*datum)) {
            error = "a datum's list holds numbers only";
            break;
          }
        } else if (a.value.size() == 1) {
          datum = a.quoted ? scene::FieldValue(a.value[0]) : scene::datumFromText(a.value[0]);
        }
        error = doc_->execute(std::make_unique<SetDatumCommand>(a.text, a.field.substr(5), std::move(datum)));
        inspector.error = error;
        break;
      }
      const int i = node->type().fieldIndex(a.field);
      if (i < 0) {
        error = "a " + node->type().name + " has no field '" + a.field + "'";
        break;
      }
      auto value = fieldValueFromWords(*node->type().fields[static_cast<std::size_t>(i)], a.value, a.list, error);
      if (!value) break;
      error = doc_->execute(std::make_unique<SetFieldCommand>(a.text, a.field, std::move(*value)));
      inspector.error = error;
      break;
    }
    case ActionKind::View: {
      if (auto v = parseStandardView(a.text)) {
        world.orbit.look(*v);
        world.camera_node.clear();
      } else if (a.text == "frame") {
        frameSelection();
      } else if (a.text == "all") {
        if (auto* s = shownScene()) {
          scene::updateTransforms(s->root());
          world.orbit.frame(scene::boundingBox(s->root()));
          world.camera_node.clear();
        }
      } else {
        auto* s = shownScene();
        auto* node = s ? s->find(a.text) : nullptr;
        if (node == nullptr || node->kind() != scene::NodeKind::Camera) {
          error = "'" + a.text + "' is no standard view (front, back, left, right, top, iso, frame, all) and no Camera node";
          break;
        }
        world.camera_node = a.text;
      }
      break;
    }
    case ActionKind::Break: {
      session::Breakpoint bp;
      if (a.field == "written") {
        // in gdpn run --break's syntax, checked by the replay's reader already
        auto written = session::parseBreakpoint(a.text);
        if (!written) {
          error = written.error().message;
          break;
        }
        bp = std::move(*written);
      } else if (a.field == "starts") bp = session::Breakpoint::starts(a.text);
      else if (a.field == "completes") bp = session::Breakpoint::completes(a.text);
      else if (a.field == "place")
        bp = session::Breakpoint::marking(a.text, session::Compare::GreaterEqual, static_cast<std::int64_t>(a.number));
      else bp = session::Breakpoint::predicate(a.text);
      error = run_.addBreakpoint(std::move(bp));
      break;
    }
    case ActionKind::Key:
    case ActionKind::Type:
    case ActionKind::Click:
    case ActionKind::Drag:
    case ActionKind::Wheel:
    case ActionKind::Frames:
    case ActionKind::Screenshot:
      error = "this action needs the platform";
      break;
  }
  return error.empty();
}

namespace {
/// The world view's resolution steps while running (share of each side).
constexpr double kWorldScales[] = {1.0, 0.85, 0.7, 0.6, 0.5};
constexpr int kWorldLevels = static_cast<int>(std::size(kWorldScales));
}  // namespace

bool App::busy() const {
  // only a run that goes on: an edit (a handle or a field dragged, a field typed in) with nothing
  // running keeps the whole resolution, however slow the frames
  return run_.mode() == RunMode::Running;
}

double App::worldScale() const { return busy() ? kWorldScales[world.level] : 1.0; }

void App::frame(float width, float height, double wall_seconds) {
  // the frame time smoothed (not the rate: one very short frame, such as the first, would
  // read thousands of frames a second and take many frames to fade)
  if (wall_seconds > 0) fps = 1.0 / (fps == 0 ? wall_seconds : 0.9 / fps + 0.1 * wall_seconds);
  // a software renderer cannot fill a large world view 30 times a second: while running (and
  // only then), its resolution follows the frame rate, a step every half second at most (a
  // headless frame stands for 1/60 s and never lowers it, unless a replay says it is slower)
  world.level_age += wall_seconds;
  if (busy() && world.level_age >= 0.5) {
    if (fps < 30 && world.level + 1 < kWorldLevels) {
      ++world.level;
      world.level_age = 0;
    } else if (fps > 45 && world.level > 0) {
      --world.level;
      world.level_age = 0;
    }
  }
  checkReload();
  checkAutosave(wall_seconds);
  followEdits(wall_seconds);
  refreshEditScene(*this);
  refreshPartUpdates(*this);
  run_.advance(wall_seconds);

  // the actions' shortcuts, everywhere
  auto& io = ImGui::GetIO();
  handleShortcuts(*this);

  const auto layout = Layout::of(splitters_, width, height);
  ImGui::SetNextWindowPos({0, 0});
  ImGui::SetNextWindowSize({width, height});
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, {0, 0});
  ImGui::PushStyleVar(ImGuiStyleVar_WindowRounding, 0);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0);
  ImGui::Begin("gdpn ide", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoScrollWithMouse);
  ImGui::PopStyleVar(3);

  nlohmann::json report;
  drawToolbar(*this, layout.toolbar, report["toolbar"], report["menu"]);
  // a view filling the window leaves the others out
  if (layout.tree.w > 0) drawTreeView(*this, layout.tree, report["tree"]);
  if (layout.palette.w > 0) drawPalette(*this, layout.palette, report["palette"]);
  else report["palette"] = {{"shown", false}};
  if (layout.world.w > 0) drawWorldView(*this, layout.world, report["world"]);
  if (layout.net.w > 0) drawNetView(*this, layout.net, report["net_view"]);
  if (layout.inspector.w > 0) {
    // the inspector shares its panel with the I/O list, a tab each
    const Rect below = drawInspectorTabs(*this, layout.inspector, report["inspector_tabs"]);
    if (io_list.shown) drawIoList(*this, below, report["io_list"]);
    else if (colour_sets.shown) drawColourSets(*this, below, report["colour_sets"]);
    else drawInspector(*this, below, report["inspector"]);
  }
  if (layout.diagnostics.w > 0) drawDiagnostics(*this, layout.diagnostics, report["diagnostics"], report["breakpoints"]);
  drawStatusBar(*this, layout.status, report["status"]);

  // the splitters: drag a handle to move it
  for (int i = 0; i < static_cast<int>(std::size(layout.handles)); ++i) {
    const auto& h = layout.handles[i];
    if (h.w <= 0 || h.h <= 0) continue;
    ImGui::SetCursorScreenPos({h.x, h.y});
    ImGui::PushID(i);
    ImGui::InvisibleButton("##splitter", {std::max(h.w, 1.0F), std::max(h.h, 1.0F)});
    ImGui::PopID();
    const bool vertical = h.w < h.h;
    if (ImGui::IsItemHovered() || ImGui::IsItemActive()) {
      ImGui::SetMouseCursor(vertical ? ImGuiMouseCursor_ResizeEW : ImGuiMouseCursor_ResizeNS);
      ImGui::GetWindowDrawList()->AddRectFilled({h.x, h.y}, {h.x + h.w, h.y + h.h},
                                                ImGui::GetColorU32(ImGuiCol_SeparatorHovered));
    }
    if (ImGui::IsItemActive()) {
      const auto d = io.MouseDelta;
      switch (static_cast<Splitter>(i)) {
        case Splitter::Tree: splitters_.tree_width += d.x; break;
        case Splitter::Bottom: splitters_.bottom_height -= d.y; break;
        case Splitter::Net: splitters_.net_width -= d.x; break;
        case Splitter::Diagnostics: splitters_.diagnostics_width -= d.x; break;
        case Splitter::Palette: splitters_.palette_height -= d.y; break;
      }
    }
  }
  ImGui::End();
  // over the world view, in a window of its own so that it stays on top and can be moved
  if (layout.world.w > 0) drawMiniView(*this, layout.world, report["mini_view"]);
  drawDropOffer(*this, report["palette"]);
  drawPartUpdates(*this, report["parts_update"]);
  drawSaveAsPart(*this, report["save_as_part"]);
  drawRestoreOffer(report["restore"]);
  drawFileBrowser(*this, report["file_browser"]);
  drawSaveQuestion(*this, report["save_changes"]);
  drawKeys(*this, report["keys"]);

  // what the frame showed, for tests and scripts
  const auto& sel = doc_->selection();
  report["selection"] = {{"kind", selectionKindName(sel.kind)}, {"name", sel.name}, {"count", doc_->selectedCount()}};
  if (doc_->selectedCount() > 1 && doc_->selectedCount() <= 500) {
    nlohmann::json all = nlohmann::json::array();
    for (const auto& one : doc_->selections()) all.push_back(one.name);
    report["selection"]["all"] = all;
  }
  report["run"] = {{"mode", runModeName(run_.mode())},
                   {"speed", runSpeedName(run_.speed())},
                   {"time", run_.time()},
                   {"steps", run_.steps()},
                   {"plant_only", run_.plantOnly()},
                   {"breakpoints", run_.breakpoints()},
                   {"message", run_.message()}};
  report["undo"] = {{"depth", doc_->history().depth()}, {"can_redo", doc_->history().canRedo()},
                    {"label", doc_->history().undoLabel()}};
  report["document"] = {{"path", doc_->model().path}, {"modified", doc_->modified()}, {"title", title()},
                        {"untitled", untitled_}, {"recent", recent},
                        {"autosaved_revision", autosaved_revision}, {"revision", doc_->revision()}};
  report["layout"] = {{"toolbar", rectJson(layout.toolbar)}, {"tree", rectJson(layout.tree)},
                      {"world", rectJson(layout.world)},     {"net", rectJson(layout.net)},
                      {"inspector", rectJson(layout.inspector)}, {"diagnostics", rectJson(layout.diagnostics)},
                      {"status", rectJson(layout.status)}, {"palette", rectJson(layout.palette)}};
  report["splitters"] = {{"tree_width", splitters_.tree_width},
                         {"bottom_height", splitters_.bottom_height},
                         {"net_width", splitters_.net_width},
                         {"diagnostics_width", splitters_.diagnostics_width},
                         {"palette_height", splitters_.palette_height},
                         {"show_palette", splitters_.show_palette},
                         {"swapped", splitters_.swapped},
                         {"full", splitters_.full == FullView::World ? "world" : splitters_.full == FullView::Net ? "net" : "none"}};
  report["message"] = message;
  report["copied"] = copied;
  report_ = std::move(report);
}

void beginPanel(const char* id, const Rect& at, const char* heading) {
  ImGui::SetCursorScreenPos({at.x, at.y});
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, {6, 4});
  ImGui::BeginChild(id, {at.w, at.h}, true, ImGuiWindowFlags_AlwaysUseWindowPadding);
  ImGui::PopStyleVar();
  if (heading != nullptr && *heading != '\0') {
    ImGui::TextColored({0.62F, 0.72F, 0.86F, 1.0F}, "%s", heading);
    ImGui::Separator();
  }
}

void endPanel() { ImGui::EndChild(); }

void noteItem(const std::string& label, nlohmann::json& positions) {
  const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
  positions[label] = {std::lround((lo.x + hi.x) / 2), std::lround((lo.y + hi.y) / 2)};
}

bool beginMenu(const char* label, nlohmann::json& positions) {
  const ImVec2 at = ImGui::GetCursorScreenPos();
  const float w = ImGui::GetContentRegionAvail().x, h = ImGui::GetTextLineHeight();
  positions[label] = {std::lround(at.x + w / 2), std::lround(at.y + h / 2)};
  return ImGui::BeginMenu(label);
}

bool menuItem(const char* label, nlohmann::json& positions) {
  const bool chosen = ImGui::MenuItem(label);
  noteItem(label, positions);
  return chosen;
}

}  // namespace gdpn::ide
