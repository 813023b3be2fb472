// libFuzzer target: any bytes as an input-event file must give events or located diagnostics,
// never a crash, a hang or a sanitizer report. Events come back in time order.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#include "gdpn/model/model.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string path = "/tmp/gdpn_input_fuzz_" + std::to_string(::getpid()) + ".input.yaml";
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  gdpn::core::Diagnostics diags;
  const auto events = gdpn::model::loadInput(path, diags);
  if (!events) {
    // every error names the file, and a place in it unless the file as a whole is at fault
    if (!diags.hasErrors()) __builtin_trap();
    for (const auto& d : diags.all()) {
      if (d.loc.file != path) __builtin_trap();
    }
    return 0;
  }
  for (std::size_t i = 1; i < events->size(); ++i) {
    if ((*events)[i].t < (*events)[i - 1].t) __builtin_trap();
  }
  return 0;
}
