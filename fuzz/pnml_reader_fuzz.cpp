// libFuzzer target: any bytes as a PNML file must give diagnostics or a net, never a crash,
// a hang or a sanitizer report. A net that compiles is also written back and read again.

#include <cstddef>
#include <cstdint>
#include <string>

#include "gdpn/net/compile.h"
#include "gdpn/net/pnml.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  gdpn::core::Diagnostics diags;
  auto spec = gdpn::net::parsePnml(text, "fuzz.pnml", diags);
  if (!spec || !gdpn::net::compile(*spec, diags)) return 0;
  std::string why;
  auto again = gdpn::net::writePnml(*spec, why);
  if (!again) return 0;
  gdpn::core::Diagnostics diags2;
  auto reread = gdpn::net::parsePnml(*again, "fuzz2.pnml", diags2);
  if (!reread || !(*reread == *spec)) __builtin_trap();
  return 0;
}
