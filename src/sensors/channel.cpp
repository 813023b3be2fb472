// A reading's channels: their names, their empty values, and reading them by name.

#include "gdpn/sensors/channel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gdpn/core/assert.h"

namespace gdpn::sensors {

std::string_view channelTypeName(ChannelType type) {
  switch (type) {
    case ChannelType::Number: return "number";
    case ChannelType::Flag: return "flag";
    case ChannelType::Vector: return "vector";
    case ChannelType::Numbers: return "numbers";
    case ChannelType::Items: return "items";
    case ChannelType::Node: return "node";
    case ChannelType::Text: return "text";
    case ChannelType::Texts: return "texts";
  }
  return "number";
}

Value emptyValue(ChannelType type) {
  switch (type) {
    case ChannelType::Number: return 0.0;
    case ChannelType::Flag: return false;
    case ChannelType::Vector: return core::Vec3{};
    case ChannelType::Numbers: return std::vector<double>{};
    case ChannelType::Items: return std::vector<scene::NodeHandle>{};
    case ChannelType::Node: return Value(std::in_place_index<5>, scene::NodeHandle{0});
    case ChannelType::Text: return std::string{};
    case ChannelType::Texts: return std::vector<std::string>{};
  }
  return 0.0;
}

std::string numberText(double x, int digits) {
  char text[64];
  if (std::isfinite(x) && std::abs(x) < 1e15 && x == std::floor(x)) {
    std::snprintf(text, sizeof text, "%.0f", x == 0 ? 0.0 : x);  // no "-0"
  } else {
    std::snprintf(text, sizeof text, "%.*g", digits, x);
  }
  return text;
}

std::string_view shownUnit(const Channel& c, bool degrees) { return c.angular && degrees ? "deg/s" : c.unit; }

std::string channelText(const Channel& c, const Value& v, const std::function<std::string(scene::NodeHandle)>& name_of,
                        bool degrees) {
  const double scale = c.angular && degrees ? core::degrees(1.0) : 1.0;
  const std::string_view unit = shownUnit(c, degrees);
  const auto withUnit = [&](std::string text) { return unit.empty() ? text : text + " " + std::string(unit); };
  const auto words = [](const std::vector<std::string>& list) {
    std::string out;
    for (std::size_t i = 0; i < list.size() && i < 8; ++i) out += (out.empty() ? "" : ", ") + list[i];
    if (list.size() > 8) out += ", ...";
    return list.empty() ? std::string("none") : out;
  };
  switch (c.type) {
    case ChannelType::Number: return withUnit(numberText(std::get<double>(v) * scale, c.digits));
    case ChannelType::Flag: return std::get<bool>(v) ? "yes" : "no";
    case ChannelType::Vector: {
      const core::Vec3 x = std::get<core::Vec3>(v) * scale;
      return withUnit("(" + numberText(x.x, c.digits) + ", " + numberText(x.y, c.digits) + ", " + numberText(x.z, c.digits) + ")");
    }
    case ChannelType::Numbers: {
      const auto& x = std::get<std::vector<double>>(v);
      if (x.empty()) return "none";
      const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
      return withUnit(std::to_string(x.size()) + (x.size() == 1 ? " value, " : " values, ") + numberText(*lo * scale, c.digits) +
                      " to " + numberText(*hi * scale, c.digits));
    }
    case ChannelType::Items: {
      std::vector<std::string> names;
      for (auto h : std::get<std::vector<scene::NodeHandle>>(v)) names.push_back(name_of(h));
      return words(names);
    }
    case ChannelType::Node: {
      const auto h = std::get<scene::NodeHandle>(v);
      return h != 0 ? name_of(h) : "none";
    }
    case ChannelType::Text: {
      const auto& word = std::get<std::string>(v);
      return word.empty() ? "none" : word;
    }
    case ChannelType::Texts: return words(std::get<std::vector<std::string>>(v));
  }
  return {};
}

Reading::Reading(std::span<const Channel> channels) : channels_(channels) {
  values_.reserve(channels.size());
  for (const auto& c : channels) values_.push_back(emptyValue(c.type));
}

int Reading::find(std::string_view name) const {
  for (std::size_t i = 0; i < channels_.size(); ++i) {
    if (channels_[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

const Value& Reading::named(std::string_view name, ChannelType type) const {
  const int i = find(name);
  GDPN_ASSERT(i >= 0 && channels_[static_cast<std::size_t>(i)].type == type, "no channel of that name and type");
  return values_[static_cast<std::size_t>(i)];
}

double Reading::number(std::string_view name) const { return std::get<double>(named(name, ChannelType::Number)); }

core::Vec3 Reading::vector(std::string_view name) const {
  return std::get<core::Vec3>(named(name, ChannelType::Vector));
}

const std::vector<double>& Reading::numbers(std::string_view name) const {
  return std::get<std::vector<double>>(named(name, ChannelType::Numbers));
}

scene::NodeHandle Reading::node(std::string_view name) const {
  return std::get<scene::NodeHandle>(named(name, ChannelType::Node));
}

const std::vector<scene::NodeHandle>& Reading::items() const {
  static const std::vector<scene::NodeHandle> none;
  for (std::size_t i = 0; i < channels_.size(); ++i) {
    if (channels_[i].type == ChannelType::Items) return std::get<std::vector<scene::NodeHandle>>(values_[i]);
  }
  return none;
}

}  // namespace gdpn::sensors
