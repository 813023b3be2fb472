// Every kind of sensor describes its channels, and the docs' table of them is the kinds' own.

#include <gtest/gtest.h>

#include <cctype>
#include <fstream>
#include <set>
#include <sstream>

#include "gdpn/scene/types.h"
#include "gdpn/sensors/sensor_kind.h"

namespace gdpn::sensors {
namespace {

bool lowerIdentifier(std::string_view name) {
  if (name.empty() || !std::islower(static_cast<unsigned char>(name[0]))) return false;
  for (char c : name) {
    if (!std::islower(static_cast<unsigned char>(c)) && !std::isdigit(static_cast<unsigned char>(c)) && c != '_') return false;
  }
  return true;
}

TEST(SensorChannels, EveryNodeTypeOfTheSensorCategoryIsAKindWithChannels) {
  std::size_t sensors = 0;
  for (const scene::NodeType* type : scene::builtinTypes().all()) {
    const SensorKind* kind = sensorKind(type->kind);
    EXPECT_EQ(kind != nullptr, type->category == scene::Category::Sensor) << type->name;
    if (kind == nullptr) continue;
    ++sensors;
    EXPECT_EQ(kind->node_kind, type->kind) << type->name;
    EXPECT_FALSE(kind->channels.empty()) << type->name;
    EXPECT_FALSE(kind->active.empty()) << type->name << ": what `active` means";
  }
  EXPECT_EQ(sensors, sensorKinds().size());
}

TEST(SensorChannels, EachChannelIsNamedTypedAndExplained) {
  for (const SensorKind* kind : sensorKinds()) {
    const std::string type = scene::builtinTypes().find(kind->node_kind)->name;
    std::set<std::string_view> names;
    int items = 0;
    for (const Channel& c : kind->channels) {
      EXPECT_TRUE(lowerIdentifier(c.name)) << type << ": '" << c.name << "' is no lower-case identifier";
      EXPECT_TRUE(names.insert(c.name).second) << type << ": '" << c.name << "' twice";
      // the names every sensor has in scripts are not channels
      EXPECT_NE(c.name, "value") << type;
      EXPECT_NE(c.name, "active") << type;
      EXPECT_NE(c.name, "image") << type;
      EXPECT_FALSE(c.help.empty()) << type << "." << c.name;
      if (c.angular) {
        EXPECT_EQ(c.unit, "rad/s") << type << "." << c.name;
      }
      if (c.per_item) {
        EXPECT_EQ(c.type, ChannelType::Numbers) << type << "." << c.name;
      }
      items += c.type == ChannelType::Items ? 1 : 0;
    }
    // the main number; at most one Items channel (whose changes are enter and exit events)
    ASSERT_LT(kind->primary, kind->channels.size()) << type;
    EXPECT_EQ(kind->channels[kind->primary].type, ChannelType::Number) << type;
    EXPECT_LE(items, 1) << type;
    // a Contact's forces stand beside its items
    for (const Channel& c : kind->channels) {
      if (c.per_item) {
        EXPECT_EQ(items, 1) << type << "." << c.name << " is per item, but of which items?";
      }
    }
    EXPECT_EQ(kind->sampling == Sampling::Rate, sampled(kind->node_kind)) << type;
  }
}

TEST(SensorChannels, AnEmptyReadingHoldsEachChannelsTypeOfValue) {
  for (const SensorKind* kind : sensorKinds()) {
    const Reading r(kind->channels);
    ASSERT_EQ(r.channels().size(), kind->channels.size());
    EXPECT_FALSE(r.active);
    for (std::size_t i = 0; i < kind->channels.size(); ++i) {
      EXPECT_EQ(r.value(i).index(), static_cast<std::size_t>(kind->channels[i].type)) << kind->channels[i].name;
      EXPECT_EQ(r.find(kind->channels[i].name), static_cast<int>(i));
    }
    EXPECT_EQ(r.find("no_such_channel"), -1);
  }
}

TEST(SensorChannels, ChannelTextGivesUnitsAndDegreesWhereAsked) {
  const auto name_of = [](scene::NodeHandle h) { return "#" + std::to_string(h); };
  const Channel distance{"distance", ChannelType::Number, "m", "to the first hit"};
  EXPECT_EQ(channelText(distance, 0.4215, name_of, true), "0.4215 m");
  EXPECT_EQ(channelText(distance, 3.0, name_of, true), "3 m");
  const Channel spin{"angular_velocity", ChannelType::Vector, "rad/s", "spin", true};
  EXPECT_EQ(channelText(spin, core::Vec3{0, 0, 3.14159265358979}, name_of, true), "(0, 0, 180) deg/s");
  EXPECT_EQ(channelText(spin, core::Vec3{0, 0, 1}, name_of, false), "(0, 0, 1) rad/s");
  const Channel ranges{"ranges", ChannelType::Numbers, "m", "rays"};
  EXPECT_EQ(channelText(ranges, std::vector<double>{4, 0.5, 2}, name_of, true), "3 values, 0.5 to 4 m");
  EXPECT_EQ(channelText(ranges, std::vector<double>{}, name_of, true), "none");
  const Channel hit{"hit", ChannelType::Node, "", "what it sees"};
  EXPECT_EQ(channelText(hit, Value(std::in_place_index<5>, scene::NodeHandle{7}), name_of, true), "#7");
  EXPECT_EQ(channelText(hit, emptyValue(ChannelType::Node), name_of, true), "none");
  const Channel keys{"keys", ChannelType::Texts, "", "held"};
  EXPECT_EQ(channelText(keys, std::vector<std::string>{"a", "space"}, name_of, true), "a, space");
}

TEST(SensorChannels, TheDocsTableIsTheKindsOwn) {
  std::ifstream in(std::string(GDPN_SOURCE_DIR) + "/docs/format.md");
  ASSERT_TRUE(in) << "docs/format.md";
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  const std::string begin = "<!-- sensor channels: from gdpn::sensors::channelsMarkdown() -->\n";
  const std::string end = "<!-- end of sensor channels -->";
  const auto from = doc.find(begin);
  ASSERT_NE(from, std::string::npos) << "docs/format.md lacks the marker " << begin;
  const auto to = doc.find(end, from);
  ASSERT_NE(to, std::string::npos) << "docs/format.md lacks the marker " << end;
  EXPECT_EQ(doc.substr(from + begin.size(), to - from - begin.size()), channelsMarkdown())
      << "docs/format.md's table of sensor channels differs from the kinds' descriptions; paste this:\n"
      << channelsMarkdown();
}

}  // namespace
}  // namespace gdpn::sensors
