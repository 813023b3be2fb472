#pragma once
/// \file
/// A run served over OPC UA: the model's own namespace (`urn:gdpn:model:STEM`) with an object
/// for the model under Objects, holding its time, its Step method (lockstep), and folders of
/// its named I/O, its parts' I/O, its pages' places and transitions, its sensors and its
/// parameters (docs/opcua.md lists the NodeIds). Values are read from the run when asked;
/// writes go through the same checks as the I/O map's.
#include <memory>
#include <string>

#include "gdpn/model/io.h"
#include "gdpn/model/simulation.h"
#include "gdpn/opcua/address_space.h"

namespace gdpn::opcua {

/// The namespace URI of a model whose file is `path` (its name without `.gdpn.yaml`).
std::string modelNamespace(const std::string& path);

/// The address space of `sim`: the standard nodes and the model's. `io` (null: the model has
/// no io section) serves the named I/O; `client` names the writer in the trace. Both must
/// outlive the space.
std::unique_ptr<AddressSpace> modelAddressSpace(model::Simulation& sim, model::IoMap* io, const std::string& client);

}  // namespace gdpn::opcua
