#pragma once
/// \file
/// Where a server listens, as users write it: `[ADDRESS:]PORT` (Modbus TCP, OPC UA).
#include <cstdint>
#include <string>

namespace gdpn::core {

/// "[ADDR:]PORT" taken apart: a dotted IPv4 address (or `*` for every interface, 0.0.0.0) and
/// a port from 0 to 65535 (0: any free one). `address` is left as it was when none is written.
/// False with `why` when it is neither.
bool parseListenAddress(const std::string& text, std::string& address, std::uint16_t& port, std::string& why);

}  // namespace gdpn::core
