// libFuzzer target: any bytes as a model file must give diagnostics or a model, never a crash,
// a hang or a sanitizer report. A model that compiles is also written back and reloaded.

#include <cstddef>
#include <cstdint>
#include <string>

#include "gdpn/model/model.h"
#include "gdpn/net/compile.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  gdpn::core::Diagnostics diags;
  auto model = gdpn::model::parseModel(text, "fuzz.gdpn.yaml", diags);
  if (!model) return 0;
  if (!gdpn::net::compile(model->net, diags)) return 0;
  // a valid model must read back the same from what the writer makes of it
  gdpn::core::Diagnostics again;
  auto reread = gdpn::model::parseModel(gdpn::model::writeModel(*model), "fuzz2.gdpn.yaml", again);
  if (!reread || !(*reread == *model)) __builtin_trap();
  return 0;
}
