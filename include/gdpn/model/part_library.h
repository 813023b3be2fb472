#pragma once
/// \file
/// The parts library: part files found along a search path, copied into models that use
/// them, and offered again when the library holds a newer version. The IDE's palette, `gdpn
/// parts` and the Python module all call these.
///
/// A part file is a model file (`*.gdpn.yaml`) whose page types include parts (page types with
/// a `part` section); it may hold a demo page, which is never copied. A model keeps a copy of
/// every part type it uses (with its version), so it opens and runs without the library.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "gdpn/core/diagnostics.h"
#include "gdpn/model/model.h"

namespace gdpn::model {

/// A part the library offers.
struct LibraryPart {
  std::string name;         ///< its page type's name: `belt_conveyor`
  std::string file;         ///< the part file that holds it
  std::string description;  ///< its page type's description
  std::string picture;      ///< its picture's path ("" when the file names none or it is missing)
  PartSpec spec;            ///< version, group, parameters, I/O
  bool pattern = false;     ///< a control pattern (the palette lists parts, not patterns)
};

/// The folders parts are looked for in, first first: `model_dir` (the model's own folder, when
/// not empty), `$XDG_DATA_HOME/gdpn/parts` (`~/.local/share/gdpn/parts`), each of
/// `$XDG_DATA_DIRS` + `/gdpn/parts` (`/usr/local/share:/usr/share`), the install prefix's
/// `share/gdpn/parts`, then the source tree's `parts/` (the build's own library).
std::vector<std::string> partSearchPath(const std::string& model_dir);

/// Every part in the part files of `path` (a folder named `parts` searched with its
/// subfolders, any other, such as a model's own folder, without descending), sorted by group
/// then name; where two
/// files hold a part of one name, the higher version wins, and of one version the earlier
/// folder's (a model beside the model holds copies of the parts it uses: an older copy never
/// hides the library's newer version). A file that does not load is a
/// warning in `diags` and skipped. `skip` is a file not to read (the model itself).
std::vector<LibraryPart> scanParts(const std::vector<std::string>& path, core::Diagnostics& diags,
                                   const std::string& skip = {});

/// The part named `name` in `parts`, or null.
const LibraryPart* findLibraryPart(const std::vector<LibraryPart>& parts, const std::string& name);

/// Copies page type `name` of `part`'s file into `model`, with its control pattern and every
/// page type they instantiate, unless the model holds them already. False with `why` when the
/// file does not load, or when the model holds a different page type of one of these names
/// that is not an older version of the same part (update it first).
bool copyPartType(Model& model, const LibraryPart& part, std::string& why);

/// A free instance name on `page` for a new instance of `type`: `type` with the first number
/// from 1 not yet taken (`belt_conveyor1`), or `prefix` + number when given.
std::string freeInstanceName(const Model& model, const std::string& page, const std::string& prefix);

/// Adds part `part` to page `page` of `model` (a new page when there is none of that name):
/// its type copied in (copyPartType), an instance named `name` (or a free name after the part)
/// standing at `translation` (m) turned by `angle` degrees about z, and, with `control`, an
/// instance of its control pattern bound to it (addPartControl with `pattern`). Returns the new
/// instances' names, the part's first; with `why` when it cannot (the part alone when only the
/// control pattern could not be added).
std::vector<std::string> placePart(Model& model, const std::string& page, const LibraryPart& part,
                                   const std::array<double, 3>& translation, double angle, bool control,
                                   std::string& why, const std::string& name = {}, const std::string& pattern = {});

/// The control patterns of part type `type` in `model`: the one it names as `control` first,
/// then the page types that say they `control` it, in the file's order.
std::vector<std::string> controlPatterns(const Model& model, const std::string& type);

/// Why part instance `candidate` cannot fill role `role` of a control pattern's instance that
/// controls `controlled` (on the same page): it is no part, a control pattern, the controlled
/// part itself, or lacks some of the role's I/O. "" when it can.
std::string roleRefusal(const Model& model, const net::InstanceSpec& candidate, const std::string& controlled,
                        const PartUse& role);

/// The parts that fill the roles (`uses`) of control pattern `pattern` for an instance that
/// controls part instance `instance` on `page`: those `given`, and for each other role the part
/// instance nearest `instance` (m, between their translations; the first of equals) whose part
/// fits (roleRefusal). An optional role no part fills is left out. Empty with `why` when a
/// role is unknown or given twice, a given part does not fit, or a required role has no part
/// to fill it.
std::vector<net::InstanceSpec::Use> fillRoles(const Model& model, const std::string& page, const std::string& instance,
                                              const std::string& pattern,
                                              const std::vector<net::InstanceSpec::Use>& given, std::string& why);

/// Adds to page `page` of `model` an instance of control pattern `pattern` (empty: the usual
/// one, the first of controlPatterns) of part instance `instance` (it must be in the model, as
/// copyPartType leaves it), bound to it with `part:`, its roles filled by fillRoles from
/// `uses`, and named after it (`pusher1_control` for the usual pattern; `pusher1_sort` for
/// pattern `pusher_sort`; a free name after that when taken). Returns the new instance's name;
/// "" with `why` when there is no such part instance or pattern, a role cannot be filled, or
/// an instance on the page controls it already.
std::string addPartControl(Model& model, const std::string& page, const std::string& instance, std::string& why,
                           const std::string& pattern = {}, const std::vector<net::InstanceSpec::Use>& uses = {});

/// Maps every I/O of part instance `instance` (its name on `page`) into the `io` section at
/// the first free addresses of their tables (a digital input in `discrete_inputs`, an analogue
/// one in `input_registers` as a Float, a digital output in `coils`, an analogue one in
/// `holding_registers` as a Float), skipping those already mapped. Returns the entries
/// added; empty with `why` when there is no such part instance.
std::vector<IoEntry> mapPartIo(Model& model, const std::string& page, const std::string& instance, std::string& why);

/// What a newer version of a part changes for a model that uses an older one.
struct PartUpdate {
  std::string name;                   ///< the part type
  int from = 0;                       ///< the model's version
  int to = 0;                         ///< the library's
  std::string file;                   ///< the library's file
  std::vector<std::string> added;     ///< I/O the new version adds
  std::vector<std::string> removed;   ///< I/O it no longer has
  std::vector<std::string> changed;   ///< I/O whose direction, signal, unit or binding changed
  std::vector<std::string> params_added;    ///< parameters it adds
  std::vector<std::string> params_removed;  ///< parameters it no longer has
};

/// The parts of `model` the library holds in a newer version.
std::vector<PartUpdate> partUpdates(const Model& model, const std::vector<LibraryPart>& parts);

/// Replaces `model`'s copy of the part type `update.name` (and its control pattern) by the
/// library's; instance parameters the new version lacks are dropped. Uses of removed I/O (in
/// the `io` section) become errors at their location in `diags` when the model is checked;
/// their list is returned in `uses` ("io.coils.3: pusher1.extend"). False with `why` when the
/// library's file does not load.
bool applyPartUpdate(Model& model, const PartUpdate& update, std::vector<std::string>& uses, std::string& why);

/// A part file holding page type `name` (a part of `group`, version 1) whose machine is a copy
/// of `nodes` (scene nodes, each with its subtree; where the first is a Transform, its place is
/// the part's origin and the Transforms among them move by as much), with a demo page placing
/// one instance: what the IDE's "Save as Part" writes. The
/// nodes keep their fields' parameter references only where `params` declares them. Nullopt
/// with `why` when `name` is no identifier or `nodes` is empty.
std::optional<Model> partFromNodes(const std::vector<const scene::Node*>& nodes, const std::string& name,
                                   const std::string& group, const std::vector<Param>& params, std::string& why);

/// docs/parts.md's catalogue of `parts` (patterns under the part they control): per part its
/// picture (linked relative to `docs_dir`), description, parameters and I/O, as Markdown
/// between the markers `<!-- parts: from gdpn::model::partsMarkdown() -->` and
/// `<!-- end of parts -->` (a test fails when the docs lag).
std::string partsMarkdown(const std::vector<LibraryPart>& parts, const std::string& docs_dir);

}  // namespace gdpn::model
