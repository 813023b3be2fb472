// The parts library: part files found along a search path, copied into models, updated.

#include "gdpn/model/part_library.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <map>
#include <set>

#include "gdpn/core/text.h"
#include "gdpn/scene/fields.h"

namespace gdpn::model {
namespace fs = std::filesystem;

namespace {

/// `$name`, or `fallback` when it is unset or empty.
std::string env(const char* name, const std::string& fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::string(v) : fallback;
}

/// The part files in `dir` (with its subfolders when `deep`), in path order.
std::vector<fs::path> partFiles(const fs::path& dir, bool deep) {
  std::vector<fs::path> out;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return out;
  const auto take = [&](const fs::directory_entry& e) {
    const std::string name = e.path().filename().string();
    std::error_code ignored;
    if (e.is_regular_file(ignored) && name.size() > std::string_view(kModelSuffix).size() &&
        name.ends_with(kModelSuffix)) {
      out.push_back(e.path());
    }
  };
  if (deep) {
    for (fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec), end;
         !ec && it != end; it.increment(ec)) {
      take(*it);
    }
  } else {
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) take(*it);
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// The page type `name` of `model`, or null.
const net::PageSpec* pageType(const Model& model, const std::string& name) {
  for (const auto& t : model.net.page_types) {
    if (t.name == name) return &t;
  }
  return nullptr;
}

/// The page types of `file` that part `name` brings: itself, its control patterns, and what
/// they instantiate, in the file's order.
std::vector<std::string> typesOf(const Model& file, const std::string& name) {
  std::set<std::string> want;
  std::function<void(const std::string&)> add = [&](const std::string& type) {
    const net::PageSpec* t = pageType(file, type);
    if (!t || !want.insert(type).second) return;
    for (const auto& i : t->instances) add(i.type);
  };
  add(name);
  for (const auto& [type, spec] : file.parts) {
    if (spec.controls == name) add(type);
  }
  if (const auto it = file.parts.find(name); it != file.parts.end() && !it->second.control.empty()) {
    add(it->second.control);
  }
  std::vector<std::string> out;
  for (const auto& t : file.net.page_types) {
    if (want.contains(t.name)) out.push_back(t.name);
  }
  return out;
}

/// Copies page type `name` (its net, scene and part section) from `from` into `to`, replacing
/// one of that name.
void copyType(Model& to, const Model& from, const std::string& name) {
  const net::PageSpec* t = pageType(from, name);
  auto it = std::find_if(to.net.page_types.begin(), to.net.page_types.end(),
                         [&](const net::PageSpec& p) { return p.name == name; });
  if (it != to.net.page_types.end()) *it = *t;
  else to.net.page_types.push_back(*t);
  if (auto s = from.type_scenes.find(name); s != from.type_scenes.end()) to.type_scenes[name] = s->second;
  else to.type_scenes.erase(name);
  if (auto p = from.parts.find(name); p != from.parts.end()) to.parts[name] = p->second;
  else to.parts.erase(name);
}

/// Loads a part file; nullopt and `why` (its first error) when it does not load.
std::optional<Model> loadPartFile(const std::string& file, std::string& why) {
  core::Diagnostics diags;
  auto m = loadModel(file, diags);
  if (!m) {
    why = diags.all().empty() ? file + ": cannot be read" : diags.all().front().str();
    return std::nullopt;
  }
  return m;
}

/// Part file `file` and, in `types`, the page types its part `name` brings (typesOf);
/// nullopt and `why` when it does not load or has no such part.
std::optional<Model> loadPartTypes(const std::string& file, const std::string& name, std::vector<std::string>& types,
                                   std::string& why) {
  auto m = loadPartFile(file, why);
  if (!m) return std::nullopt;
  types = typesOf(*m, name);
  if (types.empty()) {
    why = file + " holds no page type '" + name + "'";
    return std::nullopt;
  }
  return m;
}

}  // namespace

std::vector<std::string> partSearchPath(const std::string& model_dir) {
  std::vector<std::string> out;
  if (!model_dir.empty()) out.push_back(model_dir);
  const std::string home = env("HOME", "");
  const std::string data_home = env("XDG_DATA_HOME", home.empty() ? std::string() : home + "/.local/share");
  if (!data_home.empty()) out.push_back(data_home + "/gdpn/parts");
  const std::string dirs = env("XDG_DATA_DIRS", "/usr/local/share:/usr/share");
  std::size_t begin = 0;
  while (begin <= dirs.size()) {
    const auto end = dirs.find(':', begin);
    const std::string d = dirs.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
    if (!d.empty()) out.push_back(d + "/gdpn/parts");
    if (end == std::string::npos) break;
    begin = end + 1;
  }
#ifdef GDPN_PARTS_INSTALL_DIR
  out.emplace_back(GDPN_PARTS_INSTALL_DIR);
#endif
#ifdef GDPN_PARTS_SOURCE_DIR
  out.emplace_back(GDPN_PARTS_SOURCE_DIR);
#endif
  // each folder once, at its first place
  std::vector<std::string> unique;
  for (auto& d : out) {
    if (std::find(unique.begin(), unique.end(), d) == unique.end()) unique.push_back(std::move(d));
  }
  return unique;
}

std::vector<LibraryPart> scanParts(const std::vector<std::string>& path, core::Diagnostics& diags,
                                   const std::string& skip) {
  std::vector<LibraryPart> out;
  std::map<std::string, std::size_t> seen;  // a part's name -> its index in out
  std::error_code ec;
  const fs::path skipped = skip.empty() ? fs::path() : fs::weakly_canonical(skip, ec);
  for (std::size_t k = 0; k < path.size(); ++k) {
    // a library folder (`.../parts`) is searched with its subfolders; any other, a model's
    // own folder, only itself: a model in a home folder must not read the whole home
    const bool deep = fs::path(path[k]).filename() == "parts";
    for (const auto& file : partFiles(path[k], deep)) {
      if (!skipped.empty() && fs::weakly_canonical(file, ec) == skipped) continue;
      core::Diagnostics mine;
      auto m = loadModel(file.string(), mine);
      if (!m) {
        const auto& first = mine.all().empty() ? core::Diagnostic{} : mine.all().front();
        diags.warning(first.loc.line > 0 ? first.loc : core::SourceLoc{file.string(), 0, 0},
                      "part file skipped: " + first.message);
        continue;
      }
      for (const auto& [name, spec] : m->parts) {
        if (!spec.listed) continue;
        // a name met before keeps its first file, unless this one is newer (a model's stale
        // copy beside the model never hides the library's newer version), or as new and it
        // has the picture the first lacks (a saved model's copy beside the model)
        const auto before = seen.find(name);
        const fs::path pic = spec.picture.empty() ? fs::path() : file.parent_path() / spec.picture;
        const bool pictured = !pic.empty() && fs::is_regular_file(pic, ec);
        if (before != seen.end()) {
          const LibraryPart& first = out[before->second];
          if (first.spec.version > spec.version) continue;
          if (first.spec.version == spec.version && (!first.picture.empty() || !pictured)) continue;
        }
        LibraryPart p;
        p.name = name;
        p.file = file.string();
        p.spec = spec;
        p.pattern = !spec.controls.empty();
        if (const net::PageSpec* t = pageType(*m, name)) p.description = t->description;
        if (pictured) p.picture = pic.string();
        if (before != seen.end()) {
          out[before->second] = std::move(p);
        } else {
          seen.emplace(name, out.size());
          out.push_back(std::move(p));
        }
      }
    }
  }
  std::stable_sort(out.begin(), out.end(), [](const LibraryPart& a, const LibraryPart& b) {
    return a.spec.group != b.spec.group ? a.spec.group < b.spec.group : a.name < b.name;
  });
  return out;
}

const LibraryPart* findLibraryPart(const std::vector<LibraryPart>& parts, const std::string& name) {
  for (const auto& p : parts) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

bool copyPartType(Model& model, const LibraryPart& part, std::string& why) {
  std::vector<std::string> types;
  const auto file = loadPartTypes(part.file, part.name, types, why);
  if (!file) return false;
  std::vector<std::string> missing;
  for (const auto& t : types) {
    const net::PageSpec* mine = pageType(model, t);
    if (!mine) {
      missing.push_back(t);
      continue;
    }
    const auto theirs = file->parts.find(t);
    const auto ours = model.parts.find(t);
    if (theirs == file->parts.end() || ours == model.parts.end()) {
      why = "the model has a page type '" + t + "' of its own: rename it to use part '" + part.name + "'";
      return false;
    }
    if (ours->second.version < theirs->second.version) {
      why = "the model uses version " + std::to_string(ours->second.version) + " of '" + t + "'; the library has " +
            std::to_string(theirs->second.version) + ": update it first";
      return false;
    }
  }
  for (const auto& t : missing) copyType(model, *file, t);
  return true;
}

namespace {

/// Whether `page` has an instance, place or transition named `name`.
bool nameTaken(const net::PageSpec& page, const std::string& name) {
  const auto named = [&](const auto& list) {
    return std::any_of(list.begin(), list.end(), [&](const auto& x) { return x.name == name; });
  };
  return named(page.instances) || named(page.places) || named(page.transitions);
}

}  // namespace

std::string freeInstanceName(const Model& model, const std::string& page, const std::string& prefix) {
  std::set<std::string> taken;
  for (const auto* pages : {&model.net.pages, &model.net.page_types}) {
    for (const auto& p : *pages) {
      if (p.name != page) continue;
      for (const auto& i : p.instances) taken.insert(i.name);
      for (const auto& pl : p.places) taken.insert(pl.name);
      for (const auto& t : p.transitions) taken.insert(t.name);
    }
  }
  for (int n = 1;; ++n) {
    std::string name = prefix + std::to_string(n);
    if (!taken.contains(name)) return name;
  }
}

std::vector<std::string> placePart(Model& model, const std::string& page, const LibraryPart& part,
                                   const std::array<double, 3>& translation, double angle, bool control,
                                   std::string& why, const std::string& name, const std::string& pattern) {
  if (part.pattern) {
    why = "'" + part.name + "' is a control pattern: place the part it controls (" + part.spec.controls + ")";
    return {};
  }
  if (!copyPartType(model, part, why)) return {};
  auto target = std::find_if(model.net.pages.begin(), model.net.pages.end(),
                             [&](const net::PageSpec& p) { return p.name == page; });
  if (target == model.net.pages.end()) {
    net::PageSpec fresh;
    fresh.name = page;
    model.net.pages.push_back(std::move(fresh));
    target = std::prev(model.net.pages.end());
  }
  std::vector<std::string> out;
  net::InstanceSpec inst;
  inst.name = name.empty() ? freeInstanceName(model, page, part.name) : name;
  if (!core::isIdentifier(inst.name) || nameTaken(*target, inst.name)) {
    why = "'" + inst.name + "' is taken on page '" + page + "' or is no name";
    return {};
  }
  inst.type = part.name;
  inst.translation = translation;
  inst.rotation = {0, 0, 1, angle};
  target->instances.push_back(inst);
  out.push_back(inst.name);
  if (control) {
    const std::string c = addPartControl(model, page, inst.name, why, pattern);
    if (!c.empty()) out.push_back(c);
  }
  return out;
}

std::vector<std::string> controlPatterns(const Model& model, const std::string& type) {
  std::vector<std::string> out;
  const auto spec = model.parts.find(type);
  if (spec != model.parts.end() && !spec->second.control.empty() && pageType(model, spec->second.control)) {
    out.push_back(spec->second.control);
  }
  for (const auto& t : model.net.page_types) {
    const auto s = model.parts.find(t.name);
    if (s != model.parts.end() && s->second.controls == type && std::find(out.begin(), out.end(), t.name) == out.end()) {
      out.push_back(t.name);
    }
  }
  return out;
}

std::string roleRefusal(const Model& model, const net::InstanceSpec& candidate, const std::string& controlled,
                        const PartUse& role) {
  const auto s = model.parts.find(candidate.type);
  if (s == model.parts.end()) return "'" + candidate.name + "' is a " + candidate.type + ", no part";
  if (!s->second.controls.empty()) return "'" + candidate.name + "' is a control pattern (" + candidate.type + "), not a part";
  if (candidate.name == controlled) return "'" + candidate.name + "' is the part the pattern controls";
  std::string missing;
  for (const auto& n : role.io) {
    if (s->second.findIo(n) == nullptr) missing += (missing.empty() ? "" : ", ") + n;
  }
  return missing.empty() ? std::string() : "'" + candidate.name + "' is a " + candidate.type + ", which has no " + missing;
}

std::vector<net::InstanceSpec::Use> fillRoles(const Model& model, const std::string& page, const std::string& instance,
                                              const std::string& pattern,
                                              const std::vector<net::InstanceSpec::Use>& given, std::string& why) {
  const auto target = std::find_if(model.net.pages.begin(), model.net.pages.end(),
                                   [&](const net::PageSpec& p) { return p.name == page; });
  const auto spec = model.parts.find(pattern);
  if (target == model.net.pages.end() || spec == model.parts.end()) {
    why = "no page '" + page + "', or no control pattern '" + pattern + "'";
    return {};
  }
  const auto named = [&](const std::string& name) -> const net::InstanceSpec* {
    for (const auto& i : target->instances) {
      if (i.name == name) return &i;
    }
    return nullptr;
  };
  const net::InstanceSpec* self = named(instance);
  if (self == nullptr) {
    why = "no part instance '" + instance + "' on page '" + page + "'";
    return {};
  }
  const auto needs = [](const PartUse& role) {
    std::string out;
    for (const auto& n : role.io) out += (out.empty() ? "" : ", ") + n;
    return out;
  };
  // what is given: known roles, each once, filled by parts that fit
  for (std::size_t k = 0; k < given.size(); ++k) {
    const auto& u = given[k];
    const PartUse* role = spec->second.findUse(u.role);
    if (role == nullptr) {
      why = "'" + pattern + "' has no role '" + u.role + "'";
      return {};
    }
    for (std::size_t j = 0; j < k; ++j) {
      if (given[j].role == u.role) {
        why = "role '" + u.role + "' is given twice";
        return {};
      }
    }
    const net::InstanceSpec* part = named(u.part);
    const std::string refusal = part ? roleRefusal(model, *part, instance, *role) : "no instance '" + u.part + "' on page '" + page + "'";
    if (!refusal.empty()) {
      why = refusal + ": role '" + u.role + "' of '" + pattern + "' needs a part with " + needs(*role);
      return {};
    }
  }
  std::vector<net::InstanceSpec::Use> out;
  for (const auto& role : spec->second.uses) {
    const auto set = std::find_if(given.begin(), given.end(), [&](const auto& u) { return u.role == role.name; });
    if (set != given.end()) {
      out.push_back(*set);
      continue;
    }
    // the nearest part instance that fits (the first of equals)
    const net::InstanceSpec* best = nullptr;
    double best_d = 0;
    for (const auto& i : target->instances) {
      if (!roleRefusal(model, i, instance, role).empty()) continue;
      const double d = std::hypot(i.translation[0] - self->translation[0], i.translation[1] - self->translation[1],
                                  i.translation[2] - self->translation[2]);
      if (!std::isfinite(d)) continue;
      if (best == nullptr || d < best_d) {
        best = &i;
        best_d = d;
      }
    }
    if (best != nullptr) {
      out.push_back({role.name, best->name, {}});
    } else if (!role.optional) {
      why = "'" + pattern + "' needs a part with " + needs(role) + " for its role '" + role.name + "'" +
            (role.description.empty() ? "" : " (" + role.description + ")") + ": place one on page '" + page + "' first";
      return {};
    }
  }
  return out;
}

std::string addPartControl(Model& model, const std::string& page, const std::string& instance, std::string& why,
                           const std::string& pattern_wanted, const std::vector<net::InstanceSpec::Use>& uses) {
  auto target = std::find_if(model.net.pages.begin(), model.net.pages.end(),
                             [&](const net::PageSpec& p) { return p.name == page; });
  const net::InstanceSpec* inst = nullptr;
  if (target != model.net.pages.end()) {
    for (const auto& i : target->instances) {
      if (i.name == instance) inst = &i;
    }
  }
  const auto spec = inst ? model.parts.find(inst->type) : model.parts.end();
  if (!inst || spec == model.parts.end()) {
    why = "no part instance '" + instance + "' on page '" + page + "'";
    return {};
  }
  const auto patterns = controlPatterns(model, inst->type);
  if (patterns.empty()) {
    why = "'" + inst->type + "' comes with no control pattern in the model";
    return {};
  }
  const std::string pattern = pattern_wanted.empty() ? patterns.front() : pattern_wanted;
  if (std::find(patterns.begin(), patterns.end(), pattern) == patterns.end()) {
    std::string list;
    for (const auto& p : patterns) list += (list.empty() ? "" : ", ") + p;
    why = "'" + pattern + "' is no control pattern of '" + inst->type + "' (it has: " + list + ")";
    return {};
  }
  for (const auto& i : target->instances) {
    if (i.part == instance) {
      why = "'" + i.name + "' controls '" + instance + "' already";
      return {};
    }
  }
  std::string unfilled;
  auto filled = fillRoles(model, page, instance, pattern, uses, unfilled);
  if (!unfilled.empty()) {
    why = unfilled;
    return {};
  }
  net::InstanceSpec c;
  const bool usual = pattern == spec->second.control || (spec->second.control.empty() && pattern == patterns.front());
  // named after the part and what the pattern does (`pusher1_control`, `pusher1_sort`)
  std::string suffix = "_control";
  if (!usual && pattern.starts_with(inst->type + "_")) suffix = pattern.substr(inst->type.size());
  const std::string wanted = instance + suffix;
  c.name = nameTaken(*target, wanted) ? freeInstanceName(model, page, wanted) : wanted;
  c.type = pattern;
  c.part = instance;
  c.uses = std::move(filled);
  target->instances.push_back(std::move(c));
  return target->instances.back().name;
}

std::vector<IoEntry> mapPartIo(Model& model, const std::string& page, const std::string& instance, std::string& why) {
  const net::InstanceSpec* inst = nullptr;
  for (const auto& p : model.net.pages) {
    if (p.name != page) continue;
    for (const auto& i : p.instances) {
      if (i.name == instance) inst = &i;
    }
  }
  const auto spec = inst ? model.parts.find(inst->type) : model.parts.end();
  if (!inst || spec == model.parts.end()) {
    why = "no part instance '" + instance + "' on page '" + page + "'";
    return {};
  }
  const std::string target = page + "/" + instance;
  std::vector<IoEntry> added;
  for (const auto& io : spec->second.io) {
    const bool input = io.direction == IoDirection::Input;
    const bool digital = io.signal == IoSignal::Digital;
    const IoTable table = input ? (digital ? IoTable::DiscreteInputs : IoTable::InputRegisters)
                                : (digital ? IoTable::Coils : IoTable::HoldingRegisters);
    const bool mapped = std::any_of(model.io.entries.begin(), model.io.entries.end(), [&](const IoEntry& e) {
      return e.source == IoEntry::Source::Part && e.io == io.name &&
             (e.target == target || e.target == instance);
    });
    if (mapped) continue;
    // the first address from which the entry's words are free
    const int width = digital ? 1 : 2;
    std::uint32_t address = 0;
    for (bool moved = true; moved;) {
      moved = false;
      for (const auto& e : model.io.entries) {
        if (e.table != table) continue;
        const int w = (table == IoTable::InputRegisters || table == IoTable::HoldingRegisters) ? ioWidth(e.type) : 1;
        const bool overlap = address < e.address + static_cast<std::uint32_t>(w) &&
                             e.address < address + static_cast<std::uint32_t>(width);
        const bool lockstep = table == IoTable::HoldingRegisters && model.io.lockstep &&
                              address <= *model.io.lockstep && *model.io.lockstep < address + static_cast<std::uint32_t>(width);
        if (overlap || lockstep) {
          address = std::max(address + 1, overlap ? e.address + static_cast<std::uint32_t>(w) : address + 1);
          moved = true;
        }
      }
    }
    if (address + static_cast<std::uint32_t>(width) - 1 > 65535) {
      why = "the " + std::string(ioTableKey(table)) + " table is full";
      return added;
    }
    IoEntry e;
    e.table = table;
    e.address = static_cast<std::uint16_t>(address);
    e.source = IoEntry::Source::Part;
    e.target = target;
    e.io = io.name;
    if (!digital) {
      e.type = IoDataType::Float;
      e.unit = io.unit;
    }
    model.io.entries.push_back(e);
    added.push_back(e);
  }
  std::stable_sort(model.io.entries.begin(), model.io.entries.end(), [](const IoEntry& a, const IoEntry& b) {
    return a.table != b.table ? a.table < b.table : a.address < b.address;
  });
  return added;
}

std::vector<PartUpdate> partUpdates(const Model& model, const std::vector<LibraryPart>& parts) {
  std::vector<PartUpdate> out;
  for (const auto& [name, ours] : model.parts) {
    if (!ours.listed || !ours.controls.empty()) continue;
    const LibraryPart* lib = findLibraryPart(parts, name);
    if (!lib || lib->spec.version <= ours.version) continue;
    PartUpdate u;
    u.name = name;
    u.from = ours.version;
    u.to = lib->spec.version;
    u.file = lib->file;
    for (const auto& io : lib->spec.io) {
      const PartIoSpec* old = ours.findIo(io.name);
      if (!old) u.added.push_back(io.name);
      else if (!(*old == io)) u.changed.push_back(io.name);
    }
    for (const auto& io : ours.io) {
      if (!lib->spec.findIo(io.name)) u.removed.push_back(io.name);
    }
    const auto has = [](const std::vector<Param>& ps, const std::string& n) {
      return std::any_of(ps.begin(), ps.end(), [&](const Param& p) { return p.name == n; });
    };
    for (const auto& p : lib->spec.params) {
      if (!has(ours.params, p.name)) u.params_added.push_back(p.name);
    }
    for (const auto& p : ours.params) {
      if (!has(lib->spec.params, p.name)) u.params_removed.push_back(p.name);
    }
    out.push_back(std::move(u));
  }
  return out;
}

bool applyPartUpdate(Model& model, const PartUpdate& update, std::vector<std::string>& uses, std::string& why) {
  std::vector<std::string> types;
  const auto file = loadPartTypes(update.file, update.name, types, why);
  if (!file) return false;
  for (const auto& t : types) copyType(model, *file, t);
  const PartSpec& now = model.parts.at(update.name);
  // instances keep the parameters the new version still has
  std::set<std::string> instances;  // the part's instances, by name on their page
  for (auto* pages : {&model.net.pages, &model.net.page_types}) {
    for (auto& page : *pages) {
      for (auto& inst : page.instances) {
        if (inst.type != update.name) continue;
        instances.insert(inst.name);
        std::erase_if(inst.params, [&](const net::InstanceSpec::Param& p) {
          return std::none_of(now.params.begin(), now.params.end(), [&](const Param& d) { return d.name == p.name; });
        });
      }
    }
  }
  // the io section's uses of removed I/O stay, to be reported where they are written
  for (const auto& e : model.io.entries) {
    if (e.source != IoEntry::Source::Part) continue;
    const auto slash = e.target.rfind('/');
    const std::string inst = e.target.substr(slash == std::string::npos ? 0 : slash + 1);
    if (instances.contains(inst) && !now.findIo(e.io)) {
      uses.push_back(e.loc.str() + ": " + ioAddressName(e.table, e.address) + " uses " + e.target + "." + e.io);
    }
  }
  return true;
}

std::optional<Model> partFromNodes(const std::vector<const scene::Node*>& nodes, const std::string& name,
                                   const std::string& group, const std::vector<Param>& params, std::string& why) {
  if (!core::isIdentifier(name)) {
    why = "a part's name is a word of letters, digits and _ (not starting with a digit), got '" + name + "'";
    return std::nullopt;
  }
  if (nodes.empty()) {
    why = "nothing is selected to make a part of";
    return std::nullopt;
  }
  Model m;
  m.description = "the part " + name;
  auto scene = std::make_shared<scene::Scene>();
  for (const scene::Node* n : nodes) {
    if (!scene->copy(*n, scene->root())) {
      why = "two selected nodes are named '" + n->name() + "': rename one";
      return std::nullopt;
    }
  }
  // the first node's place is the part's origin: its Transforms are moved by as much
  if (nodes.front()->kind() == scene::NodeKind::Transform) {
    const auto origin = nodes.front()->vec3(scene::field::Transform::Translation);
    for (const auto& c : scene->root().children()) {
      if (c->kind() != scene::NodeKind::Transform) continue;
      const auto t = c->vec3(scene::field::Transform::Translation);
      c->setValue(scene::field::Transform::Translation, std::array<double, 3>{t.x - origin.x, t.y - origin.y, t.z - origin.z});
      std::erase_if(c->params, [](const scene::Node::Binding& b) { return b.field == static_cast<std::uint32_t>(scene::field::Transform::Translation); });
    }
  }
  // references the part does not declare keep their values alone
  Model fragment;
  fragment.scene = scene;
  keepParamsOf(fragment, params);
  net::PageSpec type;
  type.name = name;
  type.description = "made from " + core::counted(nodes.size(), "node") + " of a scene";
  m.net.page_types.push_back(type);
  m.type_scenes[name] = fragment.scene;
  PartSpec part;
  part.listed = true;
  part.group = group;
  part.params = params;
  m.parts[name] = part;
  net::PageSpec demo;
  demo.name = "main";
  net::InstanceSpec inst;
  inst.name = name + "1";
  inst.type = name;
  demo.instances.push_back(inst);
  m.net.pages.push_back(demo);
  return m;
}

namespace {

/// `|` in a table cell would end it.
std::string cell(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '|') out += '\\';
    out += c == '\n' ? ' ' : c;
  }
  return out;
}

/// A Markdown table of `params` (nothing when there are none).
void paramsTable(std::string& out, const std::vector<Param>& params) {
  if (params.empty()) return;
  out += "| parameter | default | unit | meaning |\n| --- | --- | --- | --- |\n";
  for (const auto& q : params) {
    out += "| `" + q.name + "` | " + core::formatDouble(q.declared) + " | " + cell(q.unit) + " | " + cell(q.description) +
           " |\n";
  }
  out += "\n";
}

}  // namespace

std::string partsMarkdown(const std::vector<LibraryPart>& parts, const std::string& docs_dir) {
  std::string out = "<!-- parts: from gdpn::model::partsMarkdown() -->\n";
  std::string group = "\x01";
  for (const auto& p : parts) {
    if (p.pattern) continue;
    if (p.spec.group != group) {
      group = p.spec.group;
      out += "\n### " + (group.empty() ? std::string("Other") : group) + "\n";
    }
    out += "\n#### `" + p.name + "` (version " + std::to_string(p.spec.version) + ")\n\n";
    if (!p.picture.empty()) {
      std::error_code ec;
      const auto rel = fs::relative(p.picture, docs_dir, ec);
      out += "![" + p.name + "](" + (ec ? p.picture : rel.generic_string()) + ")\n\n";
    }
    if (!p.description.empty()) out += p.description + "\n\n";
    paramsTable(out, p.spec.params);
    if (!p.spec.io.empty()) {
      out += "| I/O | kind | unit | meaning |\n| --- | --- | --- | --- |\n";
      for (const auto& io : p.spec.io) {
        out += "| `" + io.name + "` | " + ioSignalName(io.signal) + " " + ioDirectionName(io.direction) + " | " +
               cell(io.unit) + " | " + cell(io.description) + " |\n";
      }
      out += "\n";
    }
    for (const auto& c : parts) {
      if (c.pattern && c.spec.controls == p.name) {
        out += "Control pattern `" + c.name + "`" + (c.name == p.spec.control ? " (its usual one)" : "") +
               (c.description.empty() ? "" : ": " + c.description) + "\n\n";
        paramsTable(out, c.spec.params);
        if (!c.spec.uses.empty()) {
          out += "| uses | a part with | meaning |\n| --- | --- | --- |\n";
          for (const auto& u : c.spec.uses) {
            std::string io;
            for (const auto& n : u.io) io += (io.empty() ? "`" : ", `") + n + "`";
            out += "| `" + u.name + "`" + (u.optional ? " (optional)" : "") + " | " + io + " | " + cell(u.description) +
                   " |\n";
          }
          out += "\n";
        }
      }
    }
  }
  return out + "<!-- end of parts -->\n";
}

}  // namespace gdpn::model
