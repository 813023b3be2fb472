// User data on scene nodes: reading a datum written as text, and writing it back.

#include "gdpn/scene/user_data.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>

#include "gdpn/core/text.h"

namespace gdpn::scene {

namespace {

/// `text` without spaces at either end.
std::string_view trim(std::string_view text) {
  const auto first = text.find_first_not_of(' ');
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(' ') - first + 1);
}

/// A number written as text: a whole number as an int, else a finite double; nullopt otherwise.
std::optional<FieldValue> numberFromText(std::string_view text) {
  const char* first = text.data();
  const char* last = first + text.size();
  if (text.empty()) return std::nullopt;
  std::int64_t i = 0;
  if (auto [end, error] = std::from_chars(first, last, i); error == std::errc() && end == last) return i;
  double x = 0;
  if (auto [end, error] = std::from_chars(first, last, x); error == std::errc() && end == last && std::isfinite(x)) {
    return x;
  }
  return std::nullopt;
}

/// "[1, 2.5]" as a list of numbers; nullopt when it is not one.
std::optional<std::vector<double>> listFromText(std::string_view text) {
  if (text.size() < 2 || text.front() != '[' || text.back() != ']') return std::nullopt;
  std::vector<double> out;
  std::string_view rest = trim(text.substr(1, text.size() - 2));
  while (!rest.empty()) {
    const auto comma = rest.find(',');
    const auto word = trim(rest.substr(0, comma));
    const auto x = numberFromText(word);
    if (!x) return std::nullopt;
    out.push_back(std::holds_alternative<double>(*x) ? std::get<double>(*x) : static_cast<double>(std::get<std::int64_t>(*x)));
    if (comma == std::string_view::npos) break;
    rest = rest.substr(comma + 1);
    if (trim(rest).empty()) return std::nullopt;  // "[1, ]"
  }
  return out;
}

}  // namespace

FieldValue datumFromText(std::string_view text) {
  if (text == "true") return true;
  if (text == "false") return false;
  if (auto x = numberFromText(text)) return *x;
  if (auto list = listFromText(text)) return *list;
  return std::string(text);
}

std::string datumText(const FieldValue& value) {
  if (const auto* b = std::get_if<bool>(&value)) return *b ? "true" : "false";
  if (const auto* i = std::get_if<std::int64_t>(&value)) return std::to_string(*i);
  if (const auto* x = std::get_if<double>(&value)) {
    // a whole double keeps a point, so that it reads back as a number, not an int
    std::string s = core::formatDouble(*x);
    if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
    return s;
  }
  if (const auto* list = std::get_if<std::vector<double>>(&value)) {
    std::string s = "[";
    for (double x : *list) s += (s.size() > 1 ? ", " : "") + core::formatDouble(x);
    return s + "]";
  }
  if (const auto* s = std::get_if<std::string>(&value)) return *s;
  return {};
}

bool datumNeedsQuotes(const std::string& text) {
  return text.empty() || !std::holds_alternative<std::string>(datumFromText(text));
}

bool isDatumKind(const FieldValue& value) {
  return !std::holds_alternative<std::array<double, 3>>(value) && !std::holds_alternative<std::array<double, 4>>(value);
}

}  // namespace gdpn::scene
