#pragma once
/// \file
/// A model: settings, the net (pages, page types and their scripts), and the scene section,
/// as read from and written to a `.gdpn.yaml` file (docs/format.md).

#include <cstdint>
#include <algorithm>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gdpn/core/diagnostics.h"
#include "gdpn/model/io.h"
#include "gdpn/model/param.h"
#include "gdpn/model/part.h"
#include "gdpn/model/signals.h"
#include "gdpn/net/spec.h"
#include "gdpn/scene/node.h"
#include "gdpn/sensors/hub.h"

namespace gdpn::model {

/// The `settings` section.
struct Settings {
  double dt = 1.0 / 60.0;            ///< step length, seconds
  bool dt_given = false;             ///< whether the file sets dt (kept on save)
  std::uint64_t seed = 1;            ///< seed of the model's random generator
  bool seed_given = false;           ///< whether the file sets seed (kept on save)
  std::optional<double> until;       ///< default end of a run, seconds
  /// the unit of the angles the file and the scripts write (the scene stores degrees)
  scene::AngleUnit angles = scene::AngleUnit::Degrees;
  /// `ties: random`: enabled transitions of equal priority that became enabled in the same
  /// step start in an order drawn from the generator; `ties: order` (the default): in
  /// declaration order
  bool random_ties = false;
  friend bool operator==(const Settings&, const Settings&) = default;
};

/// Everything a model file holds.
struct Model {
  std::string path;          ///< the file it was read from ("" when made in memory)
  std::string description;   ///< free text
  Settings settings;         ///< run settings
  std::vector<Param> params; ///< the `params` section, in file order
  std::vector<SignalSpec> signals;  ///< the `signals` section, in file order
  IoSpec io;                 ///< the `io` section: the plant and net as Modbus tables
  net::NetSpec net;          ///< pages and page types
  std::shared_ptr<const scene::Scene> scene;  ///< the `scene` section; null when the file has none
  /// The scene subtrees page types own (their `scene` sections), by page type name; each
  /// instance gets its own copy.
  std::map<std::string, std::shared_ptr<const scene::Scene>> type_scenes;
  /// The page types that are parts (they have `part`, `params` or `io`), by page type name.
  std::map<std::string, PartSpec> parts;

  /// Same content (the path and source locations are not compared).
  friend bool operator==(const Model& a, const Model& b) {
    return a.description == b.description && a.settings == b.settings && a.params == b.params && a.signals == b.signals && a.io == b.io && a.net == b.net && a.parts == b.parts &&
           sameScene(a.scene, b.scene) && a.type_scenes.size() == b.type_scenes.size() &&
           std::equal(a.type_scenes.begin(), a.type_scenes.end(), b.type_scenes.begin(),
                      [](const auto& x, const auto& y) { return x.first == y.first && sameScene(x.second, y.second); });
  }

  /// Both absent, or the same tree.
  static bool sameScene(const std::shared_ptr<const scene::Scene>& a, const std::shared_ptr<const scene::Scene>& b) {
    return a == b || (a && b && a->sameAs(*b));
  }
};

/// Drops from `fragment`'s fields the references to parameters that `declared` does not hold
/// (their values stay): what is pasted into another model names only that model's parameters.
void keepParamsOf(Model& fragment, const std::vector<Param>& declared);

/// The suffix of model files.
inline constexpr const char* kModelSuffix = ".gdpn.yaml";

/// Reads the model file at `path`; reports every problem found into `diags` (syntax, unknown
/// keys, wrong types) and returns nullopt when there was an error. Semantic checks (names,
/// slot kinds, balance) are compile()'s.
/// `params` set parameters of the `params` section to other values before any field reads
/// them (an unknown name or a value that is not a number is an error).
std::optional<Model> loadModel(const std::string& path, core::Diagnostics& diags,
                               const std::vector<ParamOverride>& params = {});

/// Parses model text; `file` names it in diagnostics.
std::optional<Model> parseModel(const std::string& text, const std::string& file, core::Diagnostics& diags,
                                const std::vector<ParamOverride>& params = {});

/// The canonical text of `model`: saving it and loading it back gives an equal model, and
/// writing that again gives the same bytes.
std::string writeModel(const Model& model);

/// The text of `model` written over `original`, the text of the file it was read from (as a
/// person wrote it): what the edits did not change keeps its bytes there (comments, key order,
/// layout, blank lines), what they changed is written canonically in its place, new entries
/// after their canonical predecessors (docs/format.md, "Saving"). The text always reads back
/// as the model that writeModel(model) reads back as; where the original's layout cannot give
/// that, it is writeModel(model). An empty `original` gives writeModel(model).
std::string writeModelOver(const Model& model, const std::string& original);

/// Writes `model` to `path` safely: a temporary file beside it, then a rename, so the old
/// file survives any failure. With `original` (the text the model was read from), the text is
/// writeModelOver(model, original), else writeModel(model). Returns false (with a diagnostic)
/// when it could not.
bool saveModel(const Model& model, const std::string& path, core::Diagnostics& diags, const std::string& original = {});

/// A model whose scene is the mesh file at `mesh` as a subtree (a Group named after the file,
/// holding a Material and a Mesh node per part), to be saved at `out`: the Mesh nodes refer
/// to the file relative to `out`'s folder. Nullopt with a diagnostic when the mesh cannot be
/// read.
std::optional<Model> meshModel(const std::string& mesh, const std::string& out, core::Diagnostics& diags);

/// Reads an input file for a headless run (`gdpn run --input`): a list of events
/// `{t: seconds, key: name, down: true}`, `{t: .., click: {from: [x,y,z], to: [x,y,z]}}` or
/// `{t: .., viewpoint: [x,y,z]}`, returned in time order. Mistakes are located in `diags`.
std::optional<std::vector<sensors::InputEvent>> loadInput(const std::string& path, core::Diagnostics& diags);

/// Resolves a command-line MODEL argument: a model file, or a folder holding exactly one.
std::optional<std::string> resolveModelPath(const std::string& arg, core::Diagnostics& diags);

/// True when `path` names a model file (*.gdpn.yaml) that is not there yet, or one that holds
/// nothing but blanks: the IDE and `gdpn parts --add` start a new model there (emptyModel).
bool startsNewModel(const std::string& path);

/// A new model to be saved at `path`: one empty page, main, and an empty scene.
Model emptyModel(const std::string& path);

/// A name in `folder` ("": the current one) for a new model that no file has yet: untitled.gdpn.yaml, else
/// untitled-2.gdpn.yaml, untitled-3.gdpn.yaml, ...
std::string untitledModelPath(const std::string& folder);

}  // namespace gdpn::model
