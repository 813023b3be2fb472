// `gdpn parts`: the parts library, a part's parameters and I/O, and a model's parts: added,
// mapped into its io section, updated.

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "commands.h"
#include "gdpn/core/text.h"
#include "gdpn/model/part_library.h"

namespace gdpn::app {

namespace {

namespace model = gdpn::model;
using gdpn::core::Diagnostics;

/// `gdpn parts`'s arguments.
struct PartsArgs {
  std::string part;                 ///< PART: show one part
  std::string model;                ///< --model
  std::string add;                  ///< --add PART
  std::string name;                 ///< --name
  std::vector<double> at;           ///< --at X Y Z
  double angle = 0;                 ///< --angle
  std::string page = "main";        ///< --page
  bool control = false;             ///< --control
  std::string pattern;              ///< --pattern NAME
  std::vector<std::string> uses;    ///< --use ROLE=PART (repeatable)
  std::string map;                  ///< --map INSTANCE
  bool update = false;              ///< --update
  std::string make;                 ///< --make NAME
  std::vector<std::string> from;    ///< --from PATH (repeatable)
  std::string group;                ///< --group
  std::string to;                   ///< --to FILE
};

/// "digital input", "analog output, m/s".
std::string ioKind(const model::PartIoSpec& io) {
  return std::string(model::ioSignalName(io.signal)) + " " + model::ioDirectionName(io.direction) +
         (io.unit.empty() ? "" : ", " + io.unit);
}

void listLibrary(const std::vector<model::LibraryPart>& parts, const std::vector<std::string>& path) {
  std::string group = "\x01";
  for (const auto& p : parts) {
    if (p.pattern) continue;
    if (p.spec.group != group) {
      group = p.spec.group;
      std::cout << (group.empty() ? "(no group)" : group) << "\n";
    }
    std::size_t in = 0, out = 0;
    for (const auto& io : p.spec.io) (io.direction == model::IoDirection::Input ? in : out)++;
    std::ostringstream line;
    line << "  " << std::left << std::setw(18) << p.name << " v" << std::setw(3) << p.spec.version << std::right
         << std::setw(2) << in << " in " << std::setw(2) << out << " out"
         << (p.spec.control.empty() ? "           " : "  + control") << "  " << p.description;
    std::string text = line.str();
    if (text.size() > 100) text = text.substr(0, 97) + "...";
    std::cout << text << "\n";
  }
  std::cout << "\nsearched, first first:";
  for (const auto& d : path) std::cout << "\n  " << d;
  std::cout << "\n";
}

void showPart(const model::LibraryPart& p, const std::vector<model::LibraryPart>& library) {
  std::cout << p.name << " (version " << p.spec.version << (p.spec.group.empty() ? "" : ", " + p.spec.group) << "): "
            << p.description << "\n  " << p.file << "\n";
  for (const auto& pattern : library) {
    if (!pattern.pattern || pattern.spec.controls != p.name) continue;
    const std::string head = "  control pattern " + pattern.name + (pattern.name == p.spec.control ? " (usual):" : ":");
    std::cout << head;
    core::writeWrapped(std::cout, head.size(), core::words(pattern.description), 4);
    std::cout << "\n";
    for (const auto& u : pattern.spec.uses) {
      std::string io;
      for (const auto& n : u.io) io += (io.empty() ? "" : ", ") + n;
      const std::string use = "    uses " + u.name + (u.optional ? " (optional)" : "") + ":";
      std::cout << use;
      core::writeWrapped(std::cout, use.size(), core::words("a part with " + io + (u.description.empty() ? "" : ": " + u.description)), 6);
      std::cout << "\n";
    }
  }
  if (!p.spec.params.empty()) std::cout << "\nparameter        value  unit   meaning\n";
  for (const auto& q : p.spec.params) {
    std::cout << "  " << std::left << std::setw(14) << q.name << std::right << std::setw(6)
              << core::formatDouble(q.declared) << "  " << std::left << std::setw(6) << q.unit << " " << q.description
              << std::right << "\n";
  }
  if (!p.spec.io.empty()) std::cout << "\nI/O              kind                       meaning\n";
  for (const auto& io : p.spec.io) {
    std::cout << "  " << std::left << std::setw(14) << io.name << " " << std::setw(26) << ioKind(io) << " "
              << io.description << std::right << "\n";
  }
}

int parts(const PartsArgs& args) {
  Diagnostics diags;
  std::optional<std::string> path;
  std::optional<model::Model> m;
  if (!args.model.empty()) {
    // a model file not there yet, with --add: a new model, written when the part is in it
    if (!args.add.empty() && model::startsNewModel(args.model)) {
      path = args.model;
      m = model::emptyModel(args.model);
    } else {
      path = model::resolveModelPath(args.model, diags);
      if (path) m = model::loadModel(*path, diags);
    }
    if (!m) {
      diags.print(std::cerr);
      return 1;
    }
  }
  const std::string dir = path ? std::filesystem::path(*path).parent_path().string() : std::string();
  const auto search = model::partSearchPath(path ? (dir.empty() ? "." : dir) : std::string());
  const auto library = model::scanParts(search, diags, path.value_or(""));
  diags.print(std::cerr);
  if (!m) {
    if (args.part.empty()) {
      listLibrary(library, search);
      return 0;
    }
    const auto* p = model::findLibraryPart(library, args.part);
    if (!p) {
      std::vector<std::string> names;
      for (const auto& l : library) names.push_back(l.name);
      std::cerr << "gdpn parts: error: no part '" << args.part << "' in the library" << core::didYouMean(args.part, names)
                << "\n";
      return 1;
    }
    showPart(*p, library);
    return 0;
  }
  bool changed = false;
  if (!args.add.empty()) {
    const auto* p = model::findLibraryPart(library, args.add);
    if (!p) {
      std::vector<std::string> names;
      for (const auto& l : library) names.push_back(l.name);
      std::cerr << "--add: error: no part '" << args.add << "' in the library" << core::didYouMean(args.add, names) << "\n";
      return 1;
    }
    std::string why;
    std::array<double, 3> at{0, 0, 0};
    for (std::size_t k = 0; k < args.at.size() && k < 3; ++k) at[k] = args.at[k];
    std::vector<net::InstanceSpec::Use> uses;
    for (const auto& u : args.uses) {
      const auto eq = u.find('=');
      if (eq == std::string::npos || eq == 0 || eq + 1 == u.size()) {
        std::cerr << "--use: error: '" << u << "' is not ROLE=PART (eye=diffuse_sensor1)\n";
        return 1;
      }
      uses.push_back({u.substr(0, eq), u.substr(eq + 1), {}});
    }
    const bool control = args.control || !args.pattern.empty() || !uses.empty();
    std::vector<std::string> names;
    if (control && uses.empty()) {
      names = model::placePart(*m, args.page, *p, at, args.angle, true, why, args.name, args.pattern);
    } else {
      names = model::placePart(*m, args.page, *p, at, args.angle, false, why, args.name);
      if (!names.empty() && control) {
        const auto c = model::addPartControl(*m, args.page, names.front(), why, args.pattern, uses);
        if (!c.empty()) names.push_back(c);
      }
    }
    if (names.empty() || (control && names.size() < 2)) {
      std::cerr << "--add: error: " << why << " (the model is left as it was)\n";
      return 1;
    }
    for (const auto& n : names) std::cout << "added " << args.page << "/" << n << "\n";
    changed = true;
  }
  if (!args.map.empty()) {
    std::string why;
    const auto added = model::mapPartIo(*m, args.page, args.map, why);
    if (!why.empty()) {
      std::cerr << "--map: error: " << why << "\n";
      return 1;
    }
    for (const auto& e : added) {
      std::cout << "mapped " << e.target << "." << e.io << " to " << model::ioAddressName(e.table, e.address) << "\n";
    }
    changed = changed || !added.empty();
  }
  if (!args.make.empty()) {
    // a new part from nodes of the model's scene, written to the user's library
    std::vector<const scene::Node*> nodes;
    for (const auto& p : args.from) {
      const scene::Node* n = m->scene ? m->scene->find(p) : nullptr;
      if (!n) {
        std::cerr << "--from: error: no node '" << p << "' in the scene of " << *path << "\n";
        return 1;
      }
      nodes.push_back(n);
    }
    std::string why;
    auto part = model::partFromNodes(nodes, args.make, args.group, m->params, why);
    if (!part) {
      std::cerr << "--make: error: " << why << "\n";
      return 1;
    }
    std::string to = args.to;
    if (to.empty()) {
      const auto& home = search.size() > 1 ? search[1] : search.front();
      std::error_code ec;
      std::filesystem::create_directories(home, ec);
      to = home + "/" + args.make + model::kModelSuffix;
    }
    Diagnostics saved;
    if (!model::saveModel(*part, to, saved)) {
      saved.print(std::cerr);
      return 1;
    }
    std::cout << "wrote part " << args.make << " to " << to << "\n";
    return 0;
  }
  const auto updates = model::partUpdates(*m, library);
  if (args.update) {
    for (const auto& u : updates) {
      std::vector<std::string> uses;
      std::string why;
      if (!model::applyPartUpdate(*m, u, uses, why)) {
        std::cerr << "--update: error: " << why << "\n";
        return 1;
      }
      std::cout << "updated " << u.name << " from version " << u.from << " to " << u.to << "\n";
      for (const auto& use : uses) std::cout << "  " << use << ": no longer there\n";
      changed = true;
    }
  } else if (args.add.empty() && args.map.empty()) {
    for (const auto& [name, spec] : m->parts) {
      if (!spec.listed || !spec.controls.empty()) continue;
      std::cout << name << " version " << spec.version;
      for (const auto& u : updates) {
        if (u.name != name) continue;
        std::cout << ": the library has version " << u.to << " (gdpn parts --model " << args.model << " --update)";
        const auto list = [](const char* what, const std::vector<std::string>& names) {
          if (names.empty()) return;
          std::cout << "\n  " << what << ":";
          for (const auto& n : names) std::cout << " " << n;
        };
        list("adds I/O", u.added);
        list("removes I/O", u.removed);
        list("changes I/O", u.changed);
        list("adds parameters", u.params_added);
        list("removes parameters", u.params_removed);
      }
      std::cout << "\n";
    }
  }
  if (changed) {
    Diagnostics saved;
    if (!model::saveModel(*m, *path, saved)) {
      saved.print(std::cerr);
      return 1;
    }
  }
  return 0;
}

}  // namespace

Subcommand addParts(CLI::App& app) {
  auto args = std::make_shared<PartsArgs>();
  auto* cmd = app.add_subcommand("parts", "List the parts library, show a part's parameters and I/O, or add, map and "
                                          "update the parts of a model");
  cmd->add_option("PART", args->part, "a part to show: its parameters and its I/O");
  cmd->add_option("--model", args->model, "a model: list its parts and the newer versions the library has");
  cmd->add_option("--add", args->add, "with --model: add an instance of this part and save the model (a model file not there "
                  "yet starts a new model)");
  cmd->add_option("--name", args->name, "with --add: the instance's name (default: the part's, numbered)");
  cmd->add_option("--at", args->at, "with --add: where it stands, X Y Z in m")->expected(3);
  cmd->add_option("--angle", args->angle, "with --add: turned by this many degrees about z");
  cmd->add_option("--page", args->page, "with --add and --map: the page (default main)");
  cmd->add_flag("--control", args->control, "with --add: also an instance of its usual control pattern, bound to it "
                                            "(its roles filled by the nearest parts that fit)");
  cmd->add_option("--pattern", args->pattern, "with --add: this control pattern of the part rather than its usual one");
  cmd->add_option("--use", args->uses, "with --add: ROLE=PART fills a role of the control pattern (repeatable)");
  cmd->add_option("--map", args->map, "with --model: map this part instance's I/O into the io section");
  cmd->add_flag("--update", args->update, "with --model: take the library's newer versions of its parts");
  cmd->add_option("--make", args->make, "with --model and --from: make a new part of this name from scene nodes");
  cmd->add_option("--from", args->from, "with --make: a node of the model's scene (its subtree goes too); repeatable");
  cmd->add_option("--group", args->group, "with --make: the palette's group");
  cmd->add_option("--to", args->to, "with --make: the part file to write (default: $XDG_DATA_HOME/gdpn/parts/NAME.gdpn.yaml)");
  setExamples(cmd, {"gdpn parts                                # the library, by group",
               "gdpn parts belt_conveyor                  # its parameters and its I/O",
               "gdpn parts --model line.gdpn.yaml --add belt_conveyor     # a new model with a belt",
               "gdpn parts --model line.gdpn.yaml --add pusher --at 1 0.5 0 --control   # and its control"});
  return {cmd, [args] { return parts(*args); }};
}

}  // namespace gdpn::app
