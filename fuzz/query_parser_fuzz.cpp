// libFuzzer target: any bytes as a query (the text form) and as a contest property file (XML)
// must give a located mistake or formulas, never a crash, a hang or a sanitizer report. A
// formula read is printed, read again to the same text, and answered on a small net within a
// few markings.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "gdpn/core/diagnostics.h"
#include "gdpn/net/query.h"
#include "small_net.h"


extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const auto net = gdpn::fuzz::smallNet();
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<gdpn::net::Formula> formulas;
  gdpn::net::QueryError error;
  if (auto f = gdpn::net::parseQuery(*net, text, error)) {
    formulas.push_back(std::move(*f));
  } else if (error.message.empty() || error.column < 1 || error.column > text.size() + 1) {
    __builtin_trap();
  }
  gdpn::core::Diagnostics diags;
  if (auto properties = gdpn::net::readMccProperties(*net, text, "fuzz.xml", diags)) {
    for (auto& p : *properties) formulas.push_back(std::move(p.formula));
  } else if (!diags.hasErrors()) {
    __builtin_trap();  // refused without saying why
  }
  for (const auto& f : formulas) {
    const std::string printed = gdpn::net::formulaText(*net, f);
    const auto again = gdpn::net::parseQuery(*net, printed, error);
    if (!again || gdpn::net::formulaText(*net, *again) != printed) __builtin_trap();
  }
  gdpn::net::ExploreOptions limits;
  limits.max_states = 64;
  (void)gdpn::net::answerQueries(*net, formulas, limits);
  return 0;
}
