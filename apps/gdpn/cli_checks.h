#pragma once
/// \file
/// Checks of command-line values shared by gdpn's subcommands.

#include <CLI/CLI.hpp>

#include <charconv>
#include <cmath>
#include <string>
#include <string_view>
#include <type_traits>

namespace gdpn::app {

/// `text` in quotes for a message, cut to about 40 characters (a pasted 300-digit number
/// stays readable).
inline std::string quoteArg(const std::string& text) {
  constexpr std::size_t kMax = 40;
  if (text.size() <= kMax) return "'" + text + "'";
  return "'" + text.substr(0, kMax - 3) + "...' (" + std::to_string(text.size()) + " characters)";
}

/// A number on the command line: a whole number (integral T) or a finite decimal (floating
/// T) from `low` to `high`, above `low` when `above_low`. NaN, infinities, overflow, trailing
/// text and values out of range are refused before CLI11 converts the text; `what` names
/// the unit and range, in --help and in the message.
template <typename T>
CLI::Validator number(T low, T high, const std::string& what, bool above_low = false) {
  auto check = [=](std::string& text) -> std::string {
    const std::string_view digits = text.starts_with('+') ? std::string_view(text).substr(1) : std::string_view(text);
    T value{};
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    bool ok = !digits.empty() && ec == std::errc() && end == digits.data() + digits.size();
    if constexpr (std::is_floating_point_v<T>) ok = ok && std::isfinite(value);
    ok = ok && (above_low ? value > low : value >= low) && value <= high;
    return ok ? std::string() : "expected " + what + ", got " + quoteArg(text);
  };
  return CLI::Validator(check, what, "");
}

}  // namespace gdpn::app
