// Witness files read back for `gdpn run --replay`: the JSON that `gdpn analyze --witness`
// writes, its names resolved against the net, its mistakes located in the file.

#include "gdpn/model/witness.h"

#include <nlohmann/json.hpp>

#include "gdpn/core/file.h"

namespace gdpn::model {
namespace {

/// The line and column of byte `at` of `text`, counted from 1.
core::SourceLoc locationOf(const std::string& file, const std::string& text, std::size_t at) {
  core::SourceLoc loc{file, 1, 1};
  for (std::size_t i = 0; i < std::min(at, text.size()); ++i) {
    if (text[i] == '\n') {
      ++loc.line;
      loc.column = 1;
    } else {
      ++loc.column;
    }
  }
  return loc;
}

}  // namespace

std::optional<Witness> loadWitness(const net::Net& net, const std::string& file, core::Diagnostics& diags) {
  const auto text = core::readFile(file, diags);
  if (!text) return std::nullopt;
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(*text);
  } catch (const nlohmann::json::parse_error& e) {
    // the library's message begins with its own "[json.exception...] parse error at ..." prefix
    std::string why = e.what();
    if (const auto colon = why.find(": ", why.find("parse error")); colon != std::string::npos) why = why.substr(colon + 2);
    diags.error(locationOf(file, *text, e.byte == 0 ? 0 : e.byte - 1), "not JSON: " + why);
    return std::nullopt;
  } catch (const nlohmann::json::exception& e) {
    // a number past what a double holds, and the like: no place in the file is known
    std::string why = e.what();
    if (const auto bracket = why.find("] "); bracket != std::string::npos) why = why.substr(bracket + 2);
    diags.error({file, 0, 0}, "not JSON gdpn can read: " + why);
    return std::nullopt;
  }
  // a name's place in the file: its first quoted occurrence after `key`
  auto where = [&](const std::string& key, const std::string& name) {
    const std::size_t k = text->find("\"" + key + "\"");
    const std::size_t at = text->find(nlohmann::json(name).dump(), k == std::string::npos ? 0 : k);
    return locationOf(file, *text, at == std::string::npos ? (k == std::string::npos ? 0 : k) : at);
  };
  if (!j.is_object() || !j.contains("path") || !j["path"].is_array()) {
    diags.error({file, 1, 1}, "not a witness: a JSON object with a \"path\" list of transition names is expected "
                               "(what gdpn analyze --witness writes)");
    return std::nullopt;
  }
  Witness w;
  if (j.contains("query") && j["query"].is_string()) w.query = j["query"].get<std::string>();
  auto transitions = [&](const char* key, std::vector<net::TransitionId>& out) {
    for (const auto& x : j[key]) {
      const auto t = x.is_string() ? net.findTransition(x.get<std::string>()) : std::nullopt;
      if (!t) {
        const std::string name = x.is_string() ? x.get<std::string>() : x.dump();
        diags.error(where(key, name), "the net has no transition '" + name + "'");
        continue;
      }
      out.push_back(*t);
    }
  };
  transitions("path", w.path);
  if (j.contains("cycle")) {
    if (j["cycle"].is_array()) {
      w.lasso = true;
      transitions("cycle", w.cycle);
    } else {
      diags.error(where("cycle", ""), "\"cycle\" must be a list of transition names");
    }
  }
  if (j.contains("marking")) {
    if (!j["marking"].is_object()) {
      diags.error(where("marking", ""), "\"marking\" must map place names to token counts");
    } else {
      for (const auto& [place, n] : j["marking"].items()) {
        const bool known = net.findPlace(place).has_value();
        if (!known) diags.error(where("marking", place), "the net has no place '" + place + "'");
        if (!n.is_number_integer()) diags.error(where("marking", place), "the tokens of '" + place + "' must be a whole number");
        if (known && n.is_number_integer()) w.marking.emplace_back(place, n.get<std::int64_t>());
      }
    }
  }
  if (diags.hasErrors()) return std::nullopt;
  return w;
}

std::string witnessMismatch(const net::Net& net, const net::Kernel& kernel, const Witness& witness) {
  std::vector<std::int64_t> expected(net.places().size(), 0);
  for (const auto& [place, n] : witness.marking) expected[*net.findPlace(place)] = n;
  std::string out;
  for (net::PlaceId p{0}; p < net.places().size(); ++p) {
    const std::int64_t has = kernel.placeTokens(p);
    if (has == expected[p]) continue;
    out += (out.empty() ? "" : "; ") + std::string("'") + net.placeName(p) + "' holds " + std::to_string(has) +
           ", the witness says " + std::to_string(expected[p]);
  }
  return out;
}

}  // namespace gdpn::model
