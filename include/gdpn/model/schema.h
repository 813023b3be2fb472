#pragma once
/// \file
/// The schema of the model file: every key of the top level, `settings`, `params`, `signals`,
/// `io`, pages, page types, places, transitions, arcs, instances, `scripts`, scripts in files,
/// duration laws and colour sets, described once (name,
/// type, default, range, unit, help), as builtin_nodes.cpp describes the scene's fields. The
/// loader takes its lists of allowed keys and its ranges from here, the writer its defaults
/// and its key order (a test checks the order), the IDE's contents view its help, and
/// docs/format.md its key tables (schemaMarkdown; a test fails when the docs lag).
///
/// A new key: describe it here (src/model/schema.cpp), read it in load.cpp, write it in
/// save.cpp, and set it in tests/model/schema_test.cpp's model of every key; the tests then
/// say what lags (the docs' table: GDPN_UPDATE_GOLDEN=1 model_test rewrites it).

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "gdpn/model/io.h"

namespace gdpn::model::schema {

/// The maps of a model file whose keys the schema describes.
enum class Section : std::uint8_t {
  Model,       ///< the top level
  Settings,    ///< `settings`
  Param,       ///< a parameter of `params` written as a map
  Signal,      ///< a signal of `signals`
  Io,          ///< `io`
  IoEntry,     ///< an address of one of `io`'s four tables
  Page,        ///< a page of `pages`
  PageType,    ///< a page type of `page_types`
  Place,       ///< a place of a page's `places`
  Transition,  ///< a transition of a page's `transitions`
  Arc,         ///< an arc of a page's `arcs`, written as a map
  Instance,    ///< an instance of a page's `instances`, written as a map
  Scripts,     ///< `scripts`
  ScriptFile,  ///< a script written as a function in a file
  Duration,    ///< a transition's `duration` written as a law (one key)
  Part,        ///< a page type's `part`: how the palette shows it
  PartIo,      ///< one of a page type's `io`: a part's named input or output
  PartUse,     ///< one of a page type's `uses`: a role a control pattern's instance fills with a part
  Colour,      ///< a colour set of `colours` written as a map (one key: what kind of set)
  Continuous,  ///< a place's `continuous` written as a map: its amount (hybrid nets)
  Flow,        ///< a transition's `continuous`: its rate (hybrid nets)
  FlowRead,    ///< one of a flow's `reads`: a number of the plant
  Drive,       ///< one of a continuous place's `drives`: a plant field its amount sets
};

/// Every section, in the order of the enum.
inline constexpr Section kSections[] = {Section::Model,   Section::Settings, Section::Param,      Section::Signal,
                                        Section::Io,      Section::IoEntry,  Section::Page,       Section::PageType,
                                        Section::Place,   Section::Transition, Section::Arc,      Section::Instance,
                                        Section::Scripts, Section::ScriptFile, Section::Duration,
                                        Section::Part,    Section::PartIo,   Section::PartUse,
                                        Section::Colour,  Section::Continuous, Section::Flow, Section::FlowRead,
                                        Section::Drive};

/// What a key's value is.
enum class ValueType : std::uint8_t {
  Integer,     ///< a whole number
  Number,      ///< a number
  Text,        ///< free text
  Word,        ///< one of the key's `choices`
  Name,        ///< a name: of a place, a transition, a node path, a page type
  Position,    ///< `[x, y]` in editor units
  Vector,      ///< a list of numbers
  Script,      ///< Python statements, inline or `{file, function}`
  Expression,  ///< a Python expression
  Inscription, ///< a text of the inscription language (net/inscription.h), not Python
  Map,         ///< a map (what it holds: the key's form and help)
  List,        ///< a list
};

/// The name of `type` as the docs write it ("integer", "number", "text").
std::string_view valueTypeName(ValueType type);

/// One key of a section.
struct KeyDesc {
  std::string name;                ///< as written in files
  ValueType type = ValueType::Text;  ///< what its value is
  std::string form;                ///< the docs' type column when `type` alone does not say it
  std::string initial;             ///< its default as a file writes it; empty: none
  double min = -std::numeric_limits<double>::infinity();  ///< the least value, in `unit`
  double max = std::numeric_limits<double>::infinity();   ///< the greatest value, in `unit`
  bool min_open = false;           ///< `min` itself is refused
  bool max_open = false;           ///< `max` itself is refused
  std::string unit;                ///< "s", "Hz", "" when none
  std::string help;                ///< one line or a few for the docs and the IDE
  /// the words a Word takes, the default first (a Map's: the words its values take)
  std::vector<std::string> choices;
  /// IoEntry keys: the tables (bit 1 << IoTable) whose entries take the key; 0 elsewhere
  std::uint8_t tables = 0;
};

/// What writes one key of a map (nothing, when its value is the default).
struct KeyWriter {
  std::string_view key;         ///< the key it writes
  std::function<void()> write;  ///< writes it
};
/// Runs `writers` in the order the schema lists the keys of `section`: the writer's key order
/// is the schema's. A writer for a key the schema lacks, or two for one key, is a programmer
/// error (asserted).
void inSchemaOrder(Section section, const std::vector<KeyWriter>& writers);

/// The keys of `section`, in the order the writer writes them (the canonical order).
const std::vector<KeyDesc>& keys(Section section);
/// The names of the keys of `section`, in order (what the loader allows).
const std::vector<std::string>& keyNames(Section section);
/// The names of the keys an io entry of `table` takes, in order.
std::vector<std::string> ioEntryKeyNames(IoTable table);
/// The key `name` of `section`; a name the schema lacks is a programmer error (asserted).
const KeyDesc& key(Section section, std::string_view name);
/// The default of numeric key `name` of `section` (asserted to be a number).
double defaultNumber(Section section, std::string_view name);
/// The default of list key `name` of `section`, "[a, b, c]" (asserted to be a list of numbers).
std::vector<double> defaultNumbers(Section section, std::string_view name);
/// True when `value` lies in the range of `key` (a NaN never does).
bool inRange(const KeyDesc& key, double value);
/// The range of `key` as the docs write it ("> 0", "in (0, 1]"); empty when unbounded.
std::string rangeText(const KeyDesc& key);
/// The words `key` takes, each between `quote`s, as a sentence lists them: "a, b or c" (the
/// last joined by `last`).
std::string choiceList(const KeyDesc& key, std::string_view quote = {}, std::string_view last = " or ");
/// The section's name as docs/format.md's markers write it (`places`, `io_entry`).
std::string_view sectionName(Section section);
/// The Markdown table of the keys of `section`, one line per row, each ending in '\n':
/// `| key | type | unit | default | meaning |`.
std::string schemaMarkdown(Section section);

}  // namespace gdpn::model::schema
