// libFuzzer target: any bytes as a witness file (gdpn run --replay) must give a witness or
// located diagnostics naming the file, never a crash, a hang or a sanitizer report. A witness
// read names only the net's transitions and places.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#include "gdpn/model/witness.h"
#include "small_net.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const auto net = gdpn::fuzz::smallNet();
  static const std::string path = "/tmp/gdpn_witness_fuzz_" + std::to_string(::getpid()) + ".json";
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  gdpn::core::Diagnostics diags;
  const auto w = gdpn::model::loadWitness(*net, path, diags);
  if (!w) {
    if (!diags.hasErrors()) __builtin_trap();
    for (const auto& d : diags.all()) {
      if (d.loc.file != path) __builtin_trap();
    }
    return 0;
  }
  for (auto t : w->path) {
    if (t >= net->transitions().size()) __builtin_trap();
  }
  for (auto t : w->cycle) {
    if (t >= net->transitions().size()) __builtin_trap();
  }
  for (const auto& [place, n] : w->marking) {
    if (!net->findPlace(place)) __builtin_trap();
  }
  return 0;
}
