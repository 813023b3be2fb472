#pragma once
/// \file
/// `gdpn run`'s options of its outside links (link::ServeRequest): `--modbus [ADDR:]PORT`,
/// `--opcua [ADDR:]PORT`, `--opcua-client URL`, `--realtime`, `--lockstep`, `--read-only`.

#include <CLI/CLI.hpp>

#include "gdpn/link/serving.h"

namespace gdpn::app {

/// The options, as gdpn run reads them.
using ServeArgs = link::ServeRequest;

/// Adds the options to `run`.
void addServeOptions(CLI::App& run, ServeArgs& args);

}  // namespace gdpn::app
