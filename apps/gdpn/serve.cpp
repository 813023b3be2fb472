// `gdpn run --modbus / --opcua / --opcua-client / --realtime / --lockstep / --read-only`: the
// options; the serving itself is link::Serving.

#include "serve.h"

namespace gdpn::app {

void addServeOptions(CLI::App& run, ServeArgs& args) {
  auto* modbus = run.add_option("--modbus", args.modbus,
                                "serve the model's io section over Modbus TCP on [ADDRESS:]PORT (address "
                                "127.0.0.1 unless given, * for every interface; port 0: any free one), paced "
                                "to the wall clock unless --lockstep");
  auto* opcua = run.add_option("--opcua", args.opcua,
                               "serve the model over OPC UA (opc.tcp, security None, anonymous) on "
                               "[ADDRESS:]PORT: its named I/O, parts, places, transitions, sensors, "
                               "parameters and a Step method (docs/opcua.md); paced to the wall clock "
                               "unless --lockstep");
  run.add_option("--opcua-client", args.opcua_client,
                 "let a PLC's own OPC UA server at opc.tcp://HOST:PORT drive the plant: its nodes named by "
                 "the io entries' `opcua` keys are read each step (outputs) and written (inputs)");
  run.add_flag("--realtime", args.realtime,
               "pace the run to the wall clock and report the real-time factor (with a server: the default)");
  run.add_flag("--lockstep", args.lockstep,
               "take steps only as a controller asks for them (Modbus: the io section's lockstep register; "
               "OPC UA: the Step method): the same controller gives the same trace every run")
      ->excludes("--realtime");
  run.add_flag("--read-only,--modbus-read-only", args.read_only,
               "the servers refuse every write (Modbus: exception 01; OPC UA: BadUserAccessDenied): "
               "clients read, nothing more");
  (void)modbus;
  (void)opcua;
}

}  // namespace gdpn::app
