// The model file's schema: its tables, the loader's checks drawn from it (every key accepted,
// every misspelling located with a suggestion), and every key through save and load.

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <map>
#include <set>

#include "gdpn/model/model.h"
#include "gdpn/model/schema.h"
#include "gdpn/net/script_kind.h"
#include "model/yaml.h"

namespace gdpn::model::schema {
namespace {

TEST(Schema, MarkdownOfTheSettingsIsKnown) {
  const std::string md = schemaMarkdown(Section::Settings);
  EXPECT_TRUE(md.starts_with("| key | type | unit | default | meaning |\n| --- | --- | --- | --- | --- |\n")) << md;
  EXPECT_NE(md.find("| `dt` | number, > 0 | s | `1/60` | the step |\n"), std::string::npos) << md;
  EXPECT_NE(md.find("| `seed` | integer, ≥ 0 |  | `1` | the seed of the model's random generator |\n"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| `angles` | `degrees` or `radians` |  | `degrees` | "), std::string::npos) << md;
  // one row per key, after the two of the heading
  EXPECT_EQ(std::count(md.begin(), md.end(), '\n'), 2 + 5);
}

TEST(Schema, MarkdownOfAnIoEntryNamesTheTablesOfEachKey) {
  const std::string md = schemaMarkdown(Section::IoEntry);
  EXPECT_NE(md.find("| `on` | number (`coils`) |  | `1` | "), std::string::npos) << md;
  EXPECT_NE(md.find("| `place` | name |  |  | "), std::string::npos) << md;
}

TEST(Schema, RangesAndDefaultsAreKnown) {
  const KeyDesc& probability = key(Section::Transition, "probability");
  EXPECT_EQ(rangeText(probability), "in (0, 1]");
  EXPECT_FALSE(inRange(probability, 0.0));
  EXPECT_TRUE(inRange(probability, 1.0));
  EXPECT_TRUE(inRange(probability, 1e-9));
  EXPECT_FALSE(inRange(probability, 1.5));
  const KeyDesc& dt = key(Section::Settings, "dt");
  EXPECT_FALSE(inRange(dt, 0.0));
  EXPECT_FALSE(inRange(dt, std::numeric_limits<double>::infinity()));
  EXPECT_FALSE(inRange(dt, std::numeric_limits<double>::quiet_NaN()));
  EXPECT_TRUE(inRange(dt, 0.001));
  EXPECT_EQ(rangeText(key(Section::Arc, "weight")), "in [1, 2147483647]");
  EXPECT_EQ(rangeText(key(Section::Transition, "servers")), "in [1, 1000000]");
  EXPECT_EQ(rangeText(key(Section::Transition, "priority")), "");
  EXPECT_EQ(defaultNumber(Section::Transition, "probability"), 1.0);
  EXPECT_EQ(defaultNumber(Section::Transition, "servers"), 1.0);
  EXPECT_EQ(defaultNumber(Section::IoEntry, "scale"), 1.0);
  EXPECT_EQ(key(Section::Arc, "kind").initial, "normal");
  EXPECT_EQ(defaultNumbers(Section::Instance, "rotation"), (std::vector<double>{0, 0, 1, 0}));
  EXPECT_EQ(defaultNumbers(Section::Instance, "translation"), (std::vector<double>{0, 0, 0}));
}

TEST(Schema, WordsComeFromTheirEnumsNames) {
  EXPECT_EQ(key(Section::Arc, "kind").choices, (std::vector<std::string>{"normal", "test", "inhibitor"}));
  EXPECT_EQ(choiceList(key(Section::Arc, "kind")), "normal, test or inhibitor");
  EXPECT_EQ(choiceList(key(Section::IoEntry, "type"), "", ", "), "Int16, UInt16, Int32, UInt32, Float, Double");
  EXPECT_EQ(key(Section::Place, "slots").form, "map slot → `control`, `node`, `sensor` or `value`");
  EXPECT_EQ(choiceList(key(Section::Settings, "ties"), "'"), "'order' or 'random'");
}

TEST(Schema, WritersRunInTheSchemasOrderWhateverTheirOwn) {
  std::string written;
  const auto w = [&](std::string_view k) { return KeyWriter{k, [&written, k] { written += std::string(k) + " "; }}; };
  inSchemaOrder(Section::Arc, {w("condition"), w("weight"), w("from"), w("to")});
  EXPECT_EQ(written, "from to weight condition ");
}

TEST(Schema, ScriptKeysAreTheScriptTables) {
  // each owner's scripts stand in its section, in the script table's order
  const std::pair<net::ScriptOwner, Section> owners[] = {{net::ScriptOwner::PlaceSlot, Section::Place},
                                                        {net::ScriptOwner::Transition, Section::Transition},
                                                        {net::ScriptOwner::Arc, Section::Arc}};
  for (const auto& [owner, section] : owners) {
    std::vector<std::string> scripts, described;
    for (const auto& k : net::kScriptKinds) {
      if (k.owner == owner) scripts.emplace_back(k.key);
    }
    for (const auto& d : keys(section)) {
      if (d.type == ValueType::Script || d.type == ValueType::Expression) described.push_back(d.name);
    }
    EXPECT_EQ(described, scripts) << sectionName(section);
  }
}

TEST(Schema, IoKeysAreTheFourTablesAfterLockstep) {
  EXPECT_EQ(keyNames(Section::Io),
            (std::vector<std::string>{"lockstep", ioTableKey(IoTable::DiscreteInputs), ioTableKey(IoTable::InputRegisters),
                                      ioTableKey(IoTable::Coils), ioTableKey(IoTable::HoldingRegisters)}));
  EXPECT_EQ(ioEntryKeyNames(IoTable::Coils),
            (std::vector<std::string>{"name", "place", "node", "part", "io", "field", "on", "off", "opcua"}));
  EXPECT_EQ(ioEntryKeyNames(IoTable::InputRegisters),
            (std::vector<std::string>{"name", "place", "value", "node", "part", "io", "of", "scale", "unit", "type", "opcua"}));
}

TEST(Schema, EveryKeyIsDescribed) {
  for (const Section s : kSections) {
    std::set<std::string> seen;
    for (const auto& d : keys(s)) {
      EXPECT_FALSE(d.help.empty()) << sectionName(s) << "." << d.name;
      EXPECT_TRUE(seen.insert(d.name).second) << sectionName(s) << "." << d.name << " stands twice";
      if (d.type == ValueType::Word) {
        EXPECT_FALSE(d.choices.empty()) << d.name;
        EXPECT_EQ(d.initial, d.choices.front()) << d.name;
      }
      EXPECT_EQ(d.tables != 0, s == Section::IoEntry) << sectionName(s) << "." << d.name;
    }
  }
}

/// Where a key of each section stands in a one-line model: the text before and after the
/// key, and how the loader names the map it is in.
struct Context {
  Section section;
  std::string before, after, what;
};

std::vector<Context> contexts() {
  return {
      {Section::Model, "", ": 1", "model file"},
      {Section::Settings, "settings: {", ": 1}", "settings"},
      {Section::Param, "params: {p: {", ": 1}}", "parameter 'p'"},
      {Section::Signal, "signals: {s: {", ": 1}}", "signal 's'"},
      {Section::Io, "io: {", ": 1}", "io"},
      {Section::Page, "pages: {main: {", ": 1}}", "page 'main'"},
      {Section::PageType, "page_types: {cell: {", ": 1}}", "page type 'cell'"},
      {Section::Place, "pages: {main: {places: {p: {", ": 1}}}}", "place"},
      {Section::Transition, "pages: {main: {transitions: {t: {", ": 1}}}}", "transition"},
      {Section::Arc, "pages: {main: {arcs: [{", ": 1}]}}", "arc"},
      {Section::Instance, "pages: {main: {instances: {i: {", ": 1}}}}", "instance"},
      {Section::Scripts, "scripts: {", ": 1}", "scripts"},
      {Section::ScriptFile, "scripts: {globals: {", ": 1}}", "globals"},
      {Section::Duration, "pages: {main: {transitions: {t: {duration: {", ": 1}}}}}", "duration"},
      {Section::Colour, "colours: {C: {", ": 1}}", "colour set 'C'"},
  };
}

/// The diagnostics of loading `text` as m.gdpn.yaml.
std::string diagnose(const std::string& text) {
  core::Diagnostics diags;
  (void)parseModel(text, "m.gdpn.yaml", diags);
  return diags.str();
}

TEST(SchemaLoad, EveryMisspeltKeyIsLocatedWithTheKeyItMeant) {
  // each key with an x after it: an unknown key, reported where it stands, naming the key
  const auto check = [](const std::string& before, const std::string& key, const std::string& after,
                        const std::string& what) {
    const std::string all = diagnose("gdpn: 1\n" + before + key + "x" + after + "\n");
    const std::string want = "m.gdpn.yaml:2:" + std::to_string(before.size() + 1) + ": error: unknown key '" + key +
                             "x' in " + what + " (did you mean '" + key + "'?)";
    EXPECT_NE(all.find(want), std::string::npos) << want << "\n" << all;
  };
  for (const auto& c : contexts()) {
    for (const auto& name : keyNames(c.section)) check(c.before, name, c.after, c.what);
  }
  for (unsigned t = 0; t < 4; ++t) {
    const auto table = static_cast<IoTable>(t);
    const std::string address = ioAddressName(table, 0);
    for (const auto& name : ioEntryKeyNames(table)) {
      check("io: {" + std::string(ioTableKey(table)) + ": {0: {", name, ": 1}}}", address);
    }
  }
}

TEST(SchemaLoad, EveryKeyIsAcceptedWhereItBelongs) {
  // a key in its place is never "unknown" (what its value must be is another matter)
  for (const auto& c : contexts()) {
    for (const auto& name : keyNames(c.section)) {
      const std::string all = diagnose("gdpn: 1\n" + c.before + name + c.after + "\n");
      EXPECT_EQ(all.find("unknown key"), std::string::npos) << sectionName(c.section) << "." << name << "\n" << all;
    }
  }
}

TEST(SchemaLoad, AValueOfTheWrongTypeIsRefusedWhereItStands) {
  // a map where a key of one plain type (a number, text, a word) is due
  const auto plain = [](const KeyDesc& d) {
    return d.form.empty() && (d.type == ValueType::Integer || d.type == ValueType::Number || d.type == ValueType::Text ||
                              d.type == ValueType::Name || d.type == ValueType::Word);
  };
  const auto check = [](const std::string& before, const std::string& key, const std::string& after) {
    const std::string all = diagnose("gdpn: 1\n" + before + key + ": {a: 1}" + after.substr(3) + "\n");
    const std::string at = "m.gdpn.yaml:2:" + std::to_string(before.size() + key.size() + 3) + ": error: ";
    const auto found = all.find(at);
    ASSERT_NE(found, std::string::npos) << key << ": " << at << "\n" << all;
    EXPECT_NE(all.find("expects", found), std::string::npos) << key << "\n" << all;
  };
  int checked = 0;
  for (const auto& c : contexts()) {
    for (const auto& d : keys(c.section)) {
      if (!plain(d) || (c.section == Section::Model && d.name == "gdpn")) continue;  // the first line's, below
      check(c.before, d.name, c.after);
      ++checked;
    }
  }
  for (unsigned t = 0; t < 4; ++t) {
    const auto table = static_cast<IoTable>(t);
    for (const auto& d : keys(Section::IoEntry)) {
      if (!plain(d) || ((d.tables >> t) & 1U) == 0) continue;
      check("io: {" + std::string(ioTableKey(table)) + ": {0: {", d.name, ": 1}}}");
      ++checked;
    }
  }
  EXPECT_GT(checked, 40);
  EXPECT_NE(diagnose("gdpn: {a: 1}\n").find("m.gdpn.yaml:1:7: error: 'gdpn' expects a whole number, got a map"),
            std::string::npos);
}

TEST(SchemaLoad, RangesComeFromTheSchemaWithTheirLocations) {
  EXPECT_NE(diagnose("gdpn: 1\nsettings: {dt: 0}\n").find("m.gdpn.yaml:2:16: error: dt must be a positive number of seconds"),
            std::string::npos);
  EXPECT_NE(diagnose("gdpn: 1\nsettings: {until: -1}\n").find("m.gdpn.yaml:2:19: error: until must be a time of at least 0 seconds"),
            std::string::npos);
  EXPECT_NE(diagnose("gdpn: 1\nsettings: {seed: -3}\n").find("m.gdpn.yaml:2:18: error: seed must not be negative"),
            std::string::npos);
  EXPECT_NE(diagnose("gdpn: 1\nsignals: {s: {place: p, every: 0}}\n")
                .find("m.gdpn.yaml:2:32: error: 'every' is a period of more than 0 seconds"),
            std::string::npos);
  EXPECT_NE(diagnose("gdpn: 1\nsettings: {ties: randum}\n").find("m.gdpn.yaml:2:18: error: ties are 'order'"),
            std::string::npos);
  EXPECT_NE(diagnose("gdpn: 1\npages: {main: {arcs: [{from: p, to: t, kind: tset}]}}\n")
                .find("m.gdpn.yaml:2:46: error: unknown arc kind 'tset' (did you mean 'test'?); expected normal, test "
                      "or inhibitor"),
            std::string::npos);
  EXPECT_NE(diagnose("gdpn: 1\npages: {main: {places: {p: {slots: {a1: sensr}}}}}\n")
                .find("m.gdpn.yaml:2:41: error: unknown slot kind 'sensr' (did you mean 'sensor'?); expected control, "
                      "node, sensor or value"),
            std::string::npos);
  EXPECT_NE(diagnose("gdpn: 1\nio: {input_registers: {0: {node: n, of: reading, type: int8}}}\n")
                .find("m.gdpn.yaml:2:56: error: 'type' is one of Int16, UInt16, Int32, UInt32, Float, Double, got 'int8'"),
            std::string::npos);
}

// A model that sets every key of every section to something other than its default.
const char* const kEveryKey = R"(gdpn: 1
description: "every key"
settings: {dt: 0.01, seed: 7, until: 60, angles: radians, ties: random}
params:
  speed: {value: 0.5, unit: m/s, description: "belt speed"}
  n: 3
signals:
  queue: {place: main/p, every: 0.5}
  firsts: {place: main/p, value: p1}
  height: {node: box, of: position}
  busy: {expression: "1 + 1"}
io:
  lockstep: 100
  discrete_inputs:
    0: {node: eye, of: active}
    1: {node: keys, key: g}
  input_registers:
    0: {name: height, node: mast, of: reading, scale: 1000, unit: mm, type: float32, opcua: "ns=1;s=Height"}
    2: {place: main/p, value: "p2"}
    3: {node: mast, of: reading, type: Double}
  coils:
    0: {node: belt, field: speed, on: 0.5, off: 0.25}
    1: {part: main/i, io: lamp}
  holding_registers:
    0: {place: main/p}
    2: {node: pusher, field: vel1, scale: 10, unit: mm/s, type: int32}
colours:
  B: bool
  Id: {range: [1, 5]}
  P: {enum: [p1, p2]}
  Phil: {cyclic: [ph1, ph2]}
  Pair: {product: [Id, P]}
  Rec: {record: {id: Id, flag: B}}
variables:
  x: P
pages:
  main:
    description: "the main page"
    places:
      p:
        description: "a place"
        fusion: pool
        slots: {a1: control, d0: node, c0: sensor, b0: value}
        colour: {b0: P}
        tokens: {a0: $n, d0: [box]}
        values: {b0: "all"}
        capacity: {a0: 5}
        sensors: {c0: eye}
        on_deposit: "x = 1"
        on_remove: "x = 2"
        on_enter: "x = 3"
        on_exit: "x = 4"
        on_sample: "x = 5"
        on_change: "x = 6"
        continuous: {amount: 2.5, capacity: 10, unit: L, drives: [{node: box, field: size.z, scale: 0.1, offset: 0.2}]}
        at: [1, 2]
    transitions:
      t:
        description: "a transition"
        continuous: {rate: "k * p", reads: {k: {node: box, of: angle}}}
        duration: {uniform: [1, $speed]}
        priority: 2
        probability: 0.5
        servers: 3
        when: "x <> p1"
        guard: "True"
        pre_fire: "x = 7"
        in_fire: {file: station.py, function: follow}
        post_fire: "x = 9"
        at: [3, 4]
      t2: {duration: {normal: [1, 0.1]}}
      t3: {duration: {exponential: 2}}
    instances:
      i: {type: cell, at: [5, 6], translation: [1, 2, 3], rotation: [0, 0, 1, 90], params: {w: 2}, part: j, uses: {eye: k}}
    arcs:
      - {from: p, to: t, kind: test, weight: {d0: 2}, inscription: {b0: x}, predicate: {d0: "token is not None"}, condition: {c0: "value > 0"}, via: [[1, 2]], label_at: [0, -0.5]}
page_types:
  cell:
    description: "a cell"
    references: [enter]
    places:
      enter: {tokens: 1}
    transitions:
      work: {}
    instances:
      inner: {type: other}
    arcs:
      - enter -> work
    scene:
      - Group: {name: g}
      - Cube: {name: c, size: [=w*2, 1, $w]}
      - Material: {name: m, shininess: $w}
    part: {version: 3, group: Cells, picture: cell.png, control: cell_control, controls: other}
    params:
      w: {value: 0.5, unit: m, description: "width"}
    io:
      lamp: {direction: output, signal: digital, unit: "-", description: "a lamp", node: m, field: emissive, on: [1, 0, =w], off: [0, 0, 0]}
      eye: {direction: input, signal: analog, node: c, of: reading}
    uses:
      eye: {io: [eye], optional: true, description: "an eye"}
fusion:
  pool: global
scene:
  - Group: {name: box}
scripts:
  globals: "x = 0"
)";

/// The keys of every map of each section in a saved model, in the order written.
std::map<Section, std::vector<std::vector<std::string>>> keysBySection(const std::string& text) {
  std::map<Section, std::vector<std::vector<std::string>>> out;
  const auto add = [&](Section s, const YAML::Node& map) {
    if (!map || !map.IsMap()) return;
    auto& keys = out[s].emplace_back();
    for (auto it = map.begin(); it != map.end(); ++it) keys.push_back(it->first.Scalar());
  };
  const YAML::Node root = YAML::Load(text);
  add(Section::Model, root);
  add(Section::Settings, root["settings"]);
  for (auto it = root["params"].begin(); it != root["params"].end(); ++it) add(Section::Param, it->second);
  for (auto it = root["signals"].begin(); it != root["signals"].end(); ++it) add(Section::Signal, it->second);
  add(Section::Io, root["io"]);
  add(Section::Scripts, root["scripts"]);
  for (auto it = root["colours"].begin(); it != root["colours"].end(); ++it) add(Section::Colour, it->second);
  for (unsigned t = 0; t < 4; ++t) {
    const YAML::Node table = root["io"][ioTableKey(static_cast<IoTable>(t))];
    for (auto it = table.begin(); it != table.end(); ++it) add(Section::IoEntry, it->second);
  }
  for (const auto& [pages, section] : {std::pair{"pages", Section::Page}, std::pair{"page_types", Section::PageType}}) {
    for (auto it = root[pages].begin(); it != root[pages].end(); ++it) {
      const YAML::Node page = it->second;
      add(section, page);
      for (auto p = page["places"].begin(); p != page["places"].end(); ++p) {
        add(Section::Place, p->second);
        if (const YAML::Node c = p->second["continuous"]; c && c.IsMap()) {
          add(Section::Continuous, c);
          for (const auto& d : c["drives"]) add(Section::Drive, d);
        }
      }
      for (auto t = page["transitions"].begin(); t != page["transitions"].end(); ++t) {
        const YAML::Node transition = t->second;
        add(Section::Transition, transition);
        add(Section::Duration, transition["duration"]);
        if (const YAML::Node flow = transition["continuous"]; flow && flow.IsMap()) {
          add(Section::Flow, flow);
          for (auto r = flow["reads"].begin(); r != flow["reads"].end(); ++r) add(Section::FlowRead, r->second);
        }
        for (auto s = transition.begin(); s != transition.end(); ++s) {
          if (s->second.IsMap() && s->second["file"]) add(Section::ScriptFile, s->second);
        }
      }
      for (auto i = page["instances"].begin(); i != page["instances"].end(); ++i) add(Section::Instance, i->second);
      add(Section::Part, page["part"]);
      for (auto i = page["io"].begin(); i != page["io"].end(); ++i) add(Section::PartIo, i->second);
      for (auto i = page["uses"].begin(); i != page["uses"].end(); ++i) add(Section::PartUse, i->second);
      for (const auto& a : page["arcs"]) add(Section::Arc, a);
    }
  }
  return out;
}

TEST(SchemaRoundTrip, EveryKeyIsWrittenInTheSchemasOrderAndReadBack) {
  core::Diagnostics diags;
  auto first = parseModel(kEveryKey, "every.gdpn.yaml", diags);
  ASSERT_TRUE(first) << diags.str();
  const std::string text = writeModel(*first);
  auto second = parseModel(text, "saved.gdpn.yaml", diags);
  ASSERT_TRUE(second) << diags.str() << "\n" << text;
  EXPECT_EQ(*first, *second) << text;
  EXPECT_EQ(writeModel(*second), text);
  // every key of every section is written, each map's keys in the schema's order
  const auto written = keysBySection(text);
  for (const Section s : kSections) {
    const auto& order = keyNames(s);
    std::set<std::string> all;
    const auto found = written.find(s);
    ASSERT_NE(found, written.end()) << sectionName(s) << "\n" << text;
    for (const auto& map : found->second) {
      std::size_t at = 0;
      for (const auto& k : map) {
        const auto pos = std::find(order.begin(), order.end(), k);
        ASSERT_NE(pos, order.end()) << sectionName(s) << ": '" << k << "' is not in the schema";
        const auto index = static_cast<std::size_t>(pos - order.begin());
        EXPECT_GE(index, at) << sectionName(s) << ": '" << k << "' is written out of the schema's order\n" << text;
        at = index;
        all.insert(k);
      }
    }
    EXPECT_EQ(all, std::set<std::string>(order.begin(), order.end())) << sectionName(s) << "\n" << text;
  }
}

TEST(SchemaRoundTrip, KeysAtTheirDefaultsAreLeftOut) {
  core::Diagnostics diags;
  auto m = parseModel(R"(gdpn: 1
settings: {angles: degrees, ties: order}
io:
  coils:
    0: {node: belt, field: speed, on: 1, off: 0}
  holding_registers:
    0: {name: set_speed, node: belt, field: speed, scale: 1, type: int16}
pages:
  main:
    places:
      p: {tokens: 1}
    transitions:
      t: {priority: 0, probability: 1, servers: 1}
    instances:
      i: {type: cell, translation: [0, 0, 0], rotation: [0, 0, 1, 0]}
    arcs:
      - {from: p, to: t, kind: normal}
)",
                      "defaults.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  const std::string text = writeModel(*m);
  for (const char* k : {"on:", "off:", "scale:", "type: int", "type: Int", "priority:", "probability:", "servers:", "kind:",
                        "translation:", "rotation:", "settings:", "angles:", "ties:"}) {
    EXPECT_EQ(text.find(k), std::string::npos) << k << "\n" << text;
  }
  EXPECT_NE(text.find("t: {}"), std::string::npos) << text;
  EXPECT_NE(text.find("i: {type: cell}"), std::string::npos) << text;
}

}  // namespace
}  // namespace gdpn::model::schema
