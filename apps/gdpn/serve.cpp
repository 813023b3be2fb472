// `gdpn run --modbus / --realtime / --lockstep / --modbus-read-only`: the options; the
// serving itself is modbus::Serving.

#include "serve.h"

namespace gdpn::app {

void addServeOptions(CLI::App& run, ServeArgs& args) {
  auto* modbus = run.add_option("--modbus", args.modbus,
                                "serve the model's io section over Modbus TCP on [ADDRESS:]PORT (address "
                                "127.0.0.1 unless given, * for every interface; port 0: any free one), paced "
                                "to the wall clock unless --lockstep");
  run.add_flag("--realtime", args.realtime,
               "pace the run to the wall clock and report the real-time factor (with --modbus: the default)");
  run.add_flag("--lockstep", args.lockstep,
               "take steps only as the Modbus controller asks for them, through the io section's lockstep "
               "register: the same controller gives the same trace every run")
      ->needs(modbus)
      ->excludes("--realtime");
  run.add_flag("--modbus-read-only", args.read_only,
               "refuse every write from Modbus clients (exception 01): they read, nothing more")
      ->needs(modbus);
}

}  // namespace gdpn::app
