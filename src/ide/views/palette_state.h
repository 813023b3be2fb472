#pragma once
// What the parts palette keeps between frames: the library's parts and their pictures, the
// search, the part being dragged and where it would land, the control offered after a drop,
// and the scene the views show in edit mode (the document's scene with the part instances'
// machines). Private to the ide module.

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gdpn/core/diagnostics.h"
#include "gdpn/ide/part_edit.h"
#include "gdpn/ide/part_snap.h"
#include "gdpn/model/part_library.h"
#include "gdpn/scene/node.h"

namespace gdpn::ide {

class PictureTexture;

/// A library part's machine at its type's parameters, for the ghost and for snapping.
struct PartMachine {
  std::shared_ptr<const scene::Scene> scene;  ///< its type's scene (null: it brings none)
  core::Aabb box;                             ///< its shapes in its own frame, m
  bool loose = false;                         ///< an item (its shapes all in bodies): it may go on top of a part
  std::string error;                          ///< why its file did not load ("" when it did)
};

/// One control pattern offered after a drop.
struct OfferedPattern {
  std::string name;         ///< its page type (`pusher_sort`)
  std::string description;  ///< its page type's description
  std::string uses;         ///< the parts that would fill its roles ("eye: diffuse_sensor1, belt: belt_conveyor1")
  std::string unfilled;     ///< why it cannot be added now (a role no part fills); "" when it can
};

/// The control patterns offered after a drop: "Add a control for pusher1?", one button each.
struct DropOffer {
  bool open = false;      ///< shown
  bool appearing = false; ///< opened this frame: the popup is placed at the drop
  PartInstanceAt at;      ///< the part just placed
  std::vector<OfferedPattern> patterns;  ///< its control patterns, the usual one first
  float x = 0, y = 0;     ///< where it was dropped, window pixels
};

/// The parts palette's own state, and the edit scene it adds to the views.
struct PaletteState {
  std::vector<model::LibraryPart> parts;   ///< the library's parts (patterns left out), by group then name
  std::vector<std::string> folders;        ///< the search path scanned
  std::vector<std::string> warnings;       ///< part files skipped, and why
  std::optional<std::string> scanned_for;  ///< the model file the parts were scanned for (none: not yet)
  std::uint64_t scans = 0;                 ///< grows with every scan (what the part updates were found with)
  std::string search;                      ///< the search field: name, group or description
  std::map<std::string, std::unique_ptr<PictureTexture>> pictures;  ///< by part name (null: none or unreadable)
  std::map<std::string, PartMachine> machines;  ///< by part name, loaded at its first drag

  std::string dragged;                 ///< the part being dragged over the world view ("" : none)
  std::optional<DropPlace> ghost;      ///< where it would land now
  double drag_turn = 0;                ///< degrees the user turned it while dragging (Turn a Quarter), 0 to 270
  std::unique_ptr<scene::Scene> ghost_scene;  ///< the edit scene with the ghost, drawn while dragging
  std::uint64_t ghost_builds = ~std::uint64_t{0};    ///< `builds` when it was made
  std::uint64_t ghost_revision = ~std::uint64_t{0};  ///< the document's scene revision then
  std::string ghost_part;              ///< the part the ghost scene shows
  scene::NodeHandle ghost_node = 0;    ///< the ghost's Transform in it
  DropOffer offer;                     ///< the control offered after a drop

  /// The document's scene with each part instance's machine under a Transform named after the
  /// instance, as the run places it (null: the views show the document's scene itself).
  std::unique_ptr<scene::Scene> edit_scene;
  std::uint64_t generation = 0;        ///< grows whenever what the world view shows changes (the ghost too)
  std::uint64_t builds = 0;            ///< grows whenever the edit scene is made again or dropped
  std::uint64_t built_revision = ~std::uint64_t{0};  ///< the document's revision it was made from
  std::uint64_t built_run = ~std::uint64_t{0};       ///< the run's revision then
  const void* built_session = nullptr;               ///< and its session
  bool built_with_ghost = false;                     ///< made while a part was dragged
  std::string followed;                ///< the part instances (types, parameters) the run was last reset for
  std::map<std::string, PartInstanceAt> frames;  ///< part instances by their Transform's path in it
};

}  // namespace gdpn::ide
