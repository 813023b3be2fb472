// `gdpn convert`: a PNML net to a model file and back, or a mesh to a model holding it.

#include <filesystem>
#include <iostream>

#include "commands.h"
#include "gdpn/core/file.h"
#include "gdpn/core/output_file.h"
#include "gdpn/net/compile.h"
#include "gdpn/net/pnml.h"
#include "gdpn/scene/mesh.h"

namespace gdpn::app {

namespace {

namespace model = gdpn::model;
using gdpn::core::Diagnostics;

int convert(const std::string& in, const std::string& out) {
  // the format follows the output's extension; an input is never written over
  const bool to_pnml = out.ends_with(".pnml");
  if (!to_pnml && !out.ends_with(model::kModelSuffix)) {
    std::cerr << "error: OUT '" << out << "' must end in .pnml (a PNML net) or " << model::kModelSuffix
              << " (a model)\n";
    return 2;
  }
  const bool mesh = gdpn::scene::isMeshFile(in);
  if (mesh && to_pnml) {
    std::cerr << "error: a mesh converts to a model (" << model::kModelSuffix << "), not to PNML\n";
    return 2;
  }
  const std::string in_file = mesh || in.ends_with(".pnml") ? in : modelFile(in);
  if (overwritesInput("OUT", out, {{"the input file", in_file}})) return 2;
  Diagnostics diags;
  std::optional<model::Model> m;
  if (mesh) {
    m = model::meshModel(in, out, diags);
  } else if (in.ends_with(".pnml")) {
    // the net's name (its <name>, else its id) becomes the model's description
    std::string name;
    if (auto spec = gdpn::net::loadPnml(in, diags, &name); spec && gdpn::net::compile(*spec, diags)) {
      m.emplace();
      m->net = std::move(*spec);
      m->description = name.empty() ? "converted from " + std::filesystem::path(in).filename().string() : name;
    }
  } else if (auto path = model::resolveModelPath(in, diags)) {
    m = model::loadModel(*path, diags);
    if (m && !gdpn::net::compile(m->net, diags)) m.reset();
    // a model's files (scripts, meshes) are named relative to its folder
    const auto folder = [](const std::string& file) { return std::filesystem::absolute(file).parent_path().string(); };
    if (m && !to_pnml && !gdpn::core::sameFile(folder(*path), folder(out))) {
      diags.error({out, 0, 0}, "a model is rewritten only in its own folder (its files are named relative to it)");
      m.reset();
    }
  }
  if (m && to_pnml) {
    // what only gdpn reads back is said once per kind; the model beyond its net is not written
    std::string why;
    std::vector<gdpn::net::PnmlUnseen> unseen;
    auto text = gdpn::net::writePnml(m->net, why, m->description, &unseen);
    if (!text) {
      diags.error({in, 0, 0}, "cannot write PNML: " + why);
    } else if (!gdpn::core::writeOutput(out, *text, why)) {
      diags.error({out, 0, 0}, why);
    } else {
      for (const auto& u : unseen) {
        diags.note({out, 0, 0}, "only gdpn reads the net's " + std::to_string(u.count) + " " + u.what +
                                    " (other tools skip <toolspecific tool=\"gdpn\">)");
      }
      if (m->scene || !m->params.empty() || !m->signals.empty() || !m->io.empty()) {
        diags.note({out, 0, 0}, "PNML holds the net alone: the model's scene, parameters, signals, I/O and settings are not written");
      }
    }
  } else if (m) {
    model::saveModel(*m, out, diags);
  }
  diags.print(std::cerr);
  return diags.hasErrors() ? 1 : 0;
}

}  // namespace

Subcommand addConvert(CLI::App& app) {
  auto args = std::make_shared<std::pair<std::string, std::string>>();  // IN, OUT
  auto* convert_cmd = app.add_subcommand(
      "convert", "Convert a PNML net to a model file (and back), or a mesh file to a model holding it as a subtree");
  convert_cmd->add_option("IN", args->first, "a .pnml file, a .gdpn.yaml model, or a mesh (obj stl 3ds gltf glb dae ply wrl iv)")
      ->required();
  convert_cmd->add_option("OUT", args->second, "the .gdpn.yaml or .pnml to write")->required();
  setExamples(convert_cmd, {"gdpn convert net.pnml net.gdpn.yaml       # and back: net.gdpn.yaml net.pnml"});
  return {convert_cmd, [args] { return convert(args->first, args->second); }};
}

}  // namespace gdpn::app
