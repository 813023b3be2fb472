#pragma once
// The hybrid nets' test models (tests/data/hybrid), as text for parseModel.

#include <fstream>
#include <sstream>
#include <string>

namespace gdpn::testing {

/// tests/data/hybrid/fill.gdpn.yaml: a pump fills a tank at 0.3 L/s until a level switch at 1 L stops it.
inline std::string fillModelText() {
  std::ifstream in(std::string(GDPN_SOURCE_DIR) + "/tests/data/hybrid/fill.gdpn.yaml");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace gdpn::testing
