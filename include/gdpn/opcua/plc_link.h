#pragma once
/// \file
/// The plant as a PLC's OPC UA client (`gdpn run MODEL --opcua-client opc.tcp://HOST:PORT`):
/// every `io` entry with an `opcua: NODEID` key is linked to that node of the PLC. The plant's
/// outputs to the PLC (discrete inputs, input registers: sensors) are written to their nodes;
/// the PLC's outputs to the plant (coils, holding registers: actuators) are subscribed to and
/// applied to the plant. It runs between the run's steps, single-threaded, and never waits
/// there: exchange() handles what the PLC has sent by then and sends what changed.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "gdpn/core/diagnostics.h"
#include "gdpn/model/io.h"
#include "gdpn/opcua/client.h"

namespace gdpn::opcua {

/// What a link has done so far (for the run's closing summary).
struct PlcLinkStats {
  std::uint64_t reads = 0;          ///< attributes read from the PLC (when connecting)
  std::uint64_t writes = 0;         ///< sensor values written to the PLC
  std::uint64_t notifications = 0;  ///< PLC output values received
  std::uint64_t applied = 0;        ///< PLC output values applied to the plant
};

/// The link of one run's `io` section to a PLC's nodes.
class PlcLink {
 public:
  /// Parses each point's `opcua` node, connects to `url`, reads each node's DataType,
  /// AccessLevel and value (a node the PLC lacks, of a type that does not fit its point's, or
  /// a sensor's node it will not let be written is a located error in `diags`), applies the
  /// PLC's outputs as they are now and subscribes to them. Null on failure: with errors in
  /// `diags` when the model is at fault (`model_path` locates "no entry is linked"), else
  /// with `why` (the connection, the PLC's answers).
  static std::unique_ptr<PlcLink> connect(const std::string& url, model::IoMap& io, const std::string& model_path,
                                          core::Diagnostics& diags, std::string& why, const ClientOptions& options = {});
  ~PlcLink();
  PlcLink(const PlcLink&) = delete;
  PlcLink& operator=(const PlcLink&) = delete;

  /// Once per step, before it: handles what the PLC sent (the newest value of each output
  /// applied to the plant, written by client "plc"), and sends one Write of the sensors that
  /// changed since they were last sent (held while an earlier Write is unanswered). Never
  /// waits. False with `why` when the connection is lost or broken, the PLC refuses a write,
  /// or the plant refuses a value: the run must stop.
  bool exchange(std::string& why);
  /// Closes the session and the connection.
  void close();

  /// Points linked that the plant writes to the PLC (sensors).
  [[nodiscard]] std::size_t inputs() const { return inputs_.size(); }
  /// Points linked that the PLC writes to the plant (actuators).
  [[nodiscard]] std::size_t outputs() const { return outputs_.size(); }
  /// What it has done so far.
  [[nodiscard]] const PlcLinkStats& stats() const { return stats_; }

 private:
  /// One point linked to a PLC node.
  struct Linked {
    std::size_t point = 0;   // its index in io.points()
    NodeId node;             // the PLC's node
    BuiltinType plc_type = BuiltinType::Null;  // the node's data type
    bool sent = false;       // a value was sent (sensors)
    double last = 0;         // the value last sent (sensors) or applied (actuators)
    bool fresh = false;      // a value came that is not applied yet (actuators)
    double newest = 0;       // that value
  };
  PlcLink(model::IoMap& io, std::unique_ptr<Client> client) : io_(io), client_(std::move(client)) {}
  bool apply(Linked& out, double value, std::string& why);
  model::IoMap& io_;
  std::unique_ptr<Client> client_;
  std::vector<Linked> inputs_, outputs_;
  PlcLinkStats stats_;
};

/// Whether every value of `from` is a value of `to` (Boolean only to Boolean; integers within
/// range; Float and Double hold the integers they hold exactly).
bool typeHolds(BuiltinType from, BuiltinType to);

/// The built-in type of an I/O point's data type.
BuiltinType builtinOfPoint(model::IoDataType type);

}  // namespace gdpn::opcua
