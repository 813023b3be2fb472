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

namespace gdpn::testing {

/// The folder of the conformance nets and their reference answers.
inline const std::filesystem::path kConformanceDir =
    std::filesystem::path(GDPN_SOURCE_DIR) / "tests" / "data" / "conformance";

/// The PNML file of conformance net `model`.
inline std::filesystem::path conformanceFile(const std::string& model) { return kConformanceDir / (model + ".pnml"); }

/// Conformance net `model` read as a spec; nullopt after a failed expectation that names the
/// file and the loader's diagnostics.
inline std::optional<net::NetSpec> conformanceSpec(const std::string& model) {
  core::Diagnostics diags;
  auto spec = net::loadPnml(conformanceFile(model).string(), diags);
  EXPECT_TRUE(spec) << "conformance net " << model << " could not be read:\n" << diags.str();
  return spec;
}

/// Conformance net `model`, compiled; null after a failed expectation.
inline std::shared_ptr<const net::Net> conformanceNet(const std::string& model) {
  auto spec = conformanceSpec(model);
  if (!spec) return nullptr;
  core::Diagnostics diags;
  auto net = net::compile(*spec, diags);
  EXPECT_TRUE(net) << "conformance net " << model << " did not compile:\n" << diags.str();
  return net;
}

}  // namespace gdpn::testing
