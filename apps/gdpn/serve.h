#pragma once
/// \file
/// `gdpn run`'s options of its outside links (modbus::ServeRequest): `--modbus [ADDR:]PORT`,
/// `--realtime`, `--lockstep`, `--modbus-read-only`.

#include <CLI/CLI.hpp>

#include "gdpn/modbus/serving.h"

namespace gdpn::app {

/// The options, as gdpn run reads them.
using ServeArgs = modbus::ServeRequest;

/// Adds the options to `run`.
void addServeOptions(CLI::App& run, ServeArgs& args);

}  // namespace gdpn::app
