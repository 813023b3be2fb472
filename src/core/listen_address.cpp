// `[ADDRESS:]PORT` taken apart.

#include "gdpn/core/listen_address.h"

#include <arpa/inet.h>

#include <charconv>

namespace gdpn::core {

bool parseListenAddress(const std::string& text, std::string& address, std::uint16_t& port, std::string& why) {
  const auto colon = text.rfind(':');
  std::string host = colon == std::string::npos ? "" : text.substr(0, colon);
  const std::string digits = colon == std::string::npos ? text : text.substr(colon + 1);
  unsigned value = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (digits.empty() || ec != std::errc() || end != digits.data() + digits.size() || value > 65535) {
    why = "expected [ADDRESS:]PORT with a port from 0 to 65535 (0: any free one), got '" + text + "'";
    return false;
  }
  if (host == "*") host = "0.0.0.0";
  in_addr parsed{};
  if (!host.empty() && inet_pton(AF_INET, host.c_str(), &parsed) != 1) {
    why = "'" + host + "' is no IPv4 address (write 127.0.0.1, 0.0.0.0 or * for every interface)";
    return false;
  }
  if (!host.empty()) address = host;
  port = static_cast<std::uint16_t>(value);
  return true;
}

}  // namespace gdpn::core
