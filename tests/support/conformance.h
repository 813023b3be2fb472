#pragma once
// Test support: the Model Checking Contest nets kept in tests/data/conformance/ (see the
// README.md there), read so that a missing file fails the test instead of crashing it.

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "gdpn/net/compile.h"
#include "gdpn/net/pnml.h"
#include "gdpn/net/query.h"
#include "gdpn/net/unfold.h"

namespace gdpn::testing {

/// The folder of the conformance nets and their reference answers.
inline const std::filesystem::path kConformanceDir =
    std::filesystem::path(GDPN_SOURCE_DIR) / "tests" / "data" / "conformance";

/// The PNML file of conformance net `model`.
inline std::filesystem::path conformanceFile(const std::string& model) { return kConformanceDir / (model + ".pnml"); }

/// The net of PNML file `file` read as a spec; nullopt after a failed expectation that names
/// the file and the loader's diagnostics.
inline std::optional<net::NetSpec> pnmlSpec(const std::filesystem::path& file) {
  core::Diagnostics diags;
  auto spec = net::loadPnml(file.string(), diags);
  EXPECT_TRUE(spec) << "net " << file << " could not be read:\n" << diags.str();
  return spec;
}

/// The net of PNML file `file`, compiled; null after a failed expectation.
inline std::shared_ptr<const net::Net> pnmlNet(const std::filesystem::path& file) {
  auto spec = pnmlSpec(file);
  if (!spec) return nullptr;
  core::Diagnostics diags;
  auto net = net::compile(*spec, diags);
  EXPECT_TRUE(net) << "net " << file << " did not compile:\n" << diags.str();
  return net;
}

/// Conformance net `model` read as a spec; nullopt after a failed expectation.
inline std::optional<net::NetSpec> conformanceSpec(const std::string& model) { return pnmlSpec(conformanceFile(model)); }

/// Conformance net `model`, compiled; null after a failed expectation.
inline std::shared_ptr<const net::Net> conformanceNet(const std::string& model) { return pnmlNet(conformanceFile(model)); }

/// The folder of the contest nets far beyond memory (one folder per model: model.pnml, the
/// seven property files, oracle-formulas.tsv).
inline const std::filesystem::path kLargeConformanceDir =
    std::filesystem::path(GDPN_SOURCE_DIR) / "tests" / "data" / "conformance-large";

/// An answer in the words of the contest's oracles: TRUE, FALSE, a number, or UNKNOWN.
inline std::string answerWord(const net::QueryAnswer& a) {
  switch (a.verdict) {
    case net::Verdict::True: return "TRUE";
    case net::Verdict::False: return "FALSE";
    case net::Verdict::Value: return std::to_string(a.value);
    case net::Verdict::Unknown: break;
  }
  return "UNKNOWN";
}

/// The folder of the coloured conformance nets (symmetric nets), one folder per model.
inline const std::filesystem::path kColourConformanceDir =
    std::filesystem::path(GDPN_SOURCE_DIR) / "tests" / "data" / "conformance-col";

/// A coloured conformance net unfolded and compiled, with the names its coloured places and
/// transitions stand for.
struct UnfoldedNet {
  std::shared_ptr<const net::Net> net;
  net::NameExpansion names;
};

/// Coloured conformance net `model` read, unfolded and compiled; a null net after a failed
/// expectation that names the file and the diagnostics.
inline UnfoldedNet colourConformanceNet(const std::string& model) {
  core::Diagnostics diags;
  const auto file = kColourConformanceDir / model / "model.pnml";
  auto spec = net::loadPnml(file.string(), diags);
  EXPECT_TRUE(spec) << "coloured net " << model << " could not be read:\n" << diags.str();
  if (!spec) return {};
  auto unfolded = net::unfold(*spec, diags);
  EXPECT_TRUE(unfolded) << "coloured net " << model << " could not be unfolded:\n" << diags.str();
  if (!unfolded) return {};
  auto net = net::compile(unfolded->net, diags);
  EXPECT_TRUE(net) << "coloured net " << model << " did not compile unfolded:\n" << diags.str();
  return {net, std::move(unfolded->names)};
}

}  // namespace gdpn::testing
