#!/usr/bin/env node
/* A PLC runtime for the sorting station (station.gdpn.yaml) that is itself an OPC UA server,
as many PLCs are: the plant is its client (gdpn run ... --opcua-client).

The PLC serves its I/O as variables of its own namespace (index 1) in the object PLC:

  ns=1;s=Eye     Boolean  input: a box breaks the beam
  ns=1;s=Height  Int16    input, mm: from the height sensor down to what is below it
  ns=1;s=Stroke  Int16    input, mm: how far the pusher is out
  ns=1;s=Belt    Boolean  output: the belt runs
  ns=1;s=Pusher  Boolean  output: the pusher goes out

The plant writes the inputs and subscribes to the outputs; the station's io section maps them
(`opcua: "ns=1;s=Eye"` on its entry eye, and so on). Every 10 ms the PLC runs one scan of
plc.py's program on the inputs as they were last written, and sets its outputs:

  RUN      belt on; a box at the eye: tall (its top nearer than 550 mm) -> PUSH, else -> PASS
  PUSH     belt off, pusher out, until it is 690 mm out -> RETRACT
  RETRACT  pusher in, until it is back within 10 mm -> RUN
  PASS     belt on; the eye clear again -> RUN

A step that waits for the pusher longer than 3 s stops the program (a stalled pusher): the
PLC says so, turns both outputs off and scans no more.

Start the PLC first, then the plant, in two terminals:

  node examples/commissioning/plc_server.js --port 4841
  gdpn run examples/commissioning/station.gdpn.yaml --opcua-client opc.tcp://127.0.0.1:4841

The PLC prints `plc: serving opc.tcp://127.0.0.1:PORT` once it listens (--port 0: any free
port), and the boxes it sorted when it is stopped (Ctrl-C, SIGTERM). Security policy None,
anonymous clients. The server keeps its certificate in node-opcua's default folder, or in
--pki DIR.

Needs node-opcua-server from the npm registry, which scripts/install-deps.sh installs into
scripts/node/node_modules (the program looks there, and in NODE_PATH).
*/
"use strict";
const { SCAN, Logic, PlcError, importPackage } = require("./plc_logic.js");
const path = require("path");

const NAMESPACE_URI = "urn:gdpn:example:plc";  // the PLC's own namespace, index 1

function parseArgs(argv) {
  const args = { host: "127.0.0.1", port: 4841, pki: null, quiet: false };
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    const value = () => {
      if (i + 1 >= argv.length) throw new PlcError(`${a} needs a value`);
      return argv[++i];
    };
    if (a === "--port") args.port = Number(value());
    else if (a === "--host") args.host = value();
    else if (a === "--pki") args.pki = path.resolve(value());
    else if (a === "--quiet" || a === "-q") args.quiet = true;
    else if (a === "--help" || a === "-h") {
      console.log("usage: plc_server.js [--port PORT] [--host ADDR] [--pki DIR] [-q]\n\n" +
                  "A PLC runtime for the sorting station that serves its I/O over OPC UA (port 0: any free one).");
      process.exit(0);
    } else throw new PlcError(`unknown option ${a}`);
  }
  if (!Number.isInteger(args.port) || args.port < 0 || args.port > 65535) throw new PlcError(`bad port ${args.port}`);
  return args;
}

async function main() {
  const args = parseArgs(process.argv.slice(2));
  process.env.NODEOPCUA_LOG_LEVEL ??= "2";  // node-opcua's own warnings off: this program says what went wrong
  const { OPCUAServer } = await importPackage("node-opcua-server");
  const { DataType, StatusCodes, Variant, MessageSecurityMode, SecurityPolicy } = await importPackage("node-opcua-client");
  const { OPCUACertificateManager } = await importPackage("node-opcua-certificate-manager");

  const server = new OPCUAServer({
    port: args.port,
    hostname: args.host,
    serverInfo: { applicationUri: NAMESPACE_URI, productUri: NAMESPACE_URI,
                  applicationName: { text: "gdpn example PLC (sorting station)" } },
    securityPolicies: [SecurityPolicy.None],
    securityModes: [MessageSecurityMode.None],
    allowAnonymous: true,
    ...(args.pki ? { serverCertificateManager: new OPCUACertificateManager({
      rootFolder: args.pki, automaticallyAcceptUnknownCertificate: true }) } : {}),
  });
  await server.initialize();
  const addressSpace = server.engine.addressSpace;
  const ns = addressSpace.getOwnNamespace();
  if (ns.index !== 1) throw new PlcError(`the PLC's namespace has index ${ns.index}, not 1`);
  const plc = ns.addObject({ organizedBy: addressSpace.rootFolder.objects, browseName: "PLC", nodeId: "s=PLC" });

  // the process image: inputs as the plant last wrote them, outputs as the last scan set them
  const image = { Eye: false, Height: 0, Stroke: 0, Belt: false, Pusher: false };
  const variables = {};
  const variable = (name, dataType, input, description) => {
    variables[name] = ns.addVariable({
      componentOf: plc, browseName: name, nodeId: `s=${name}`, dataType, description,
      accessLevel: input ? "CurrentRead | CurrentWrite" : "CurrentRead",
      userAccessLevel: input ? "CurrentRead | CurrentWrite" : "CurrentRead",
      minimumSamplingInterval: 10,
      value: new Variant({ dataType: DataType[dataType], value: image[name] }),
    });
    if (input) {
      variables[name].on("value_changed", (dataValue) => { image[name] = dataValue.value.value; });
    }
  };
  variable("Eye", "Boolean", true, "input: a box breaks the beam");
  variable("Height", "Int16", true, "input, mm: from the height sensor down to what is below it");
  variable("Stroke", "Int16", true, "input, mm: how far the pusher is out");
  variable("Belt", "Boolean", false, "output: the belt runs");
  variable("Pusher", "Boolean", false, "output: the pusher goes out");
  const setOutput = (name, on) => {
    if (image[name] === on) return;
    image[name] = on;
    variables[name].setValueFromSource(new Variant({ dataType: DataType.Boolean, value: on }), StatusCodes.Good);
  };

  await server.start();
  const port = server.endpoints[0].port;
  console.log(`plc: serving opc.tcp://${args.host}:${port}`);

  const logic = new Logic();
  let scans = 0, overruns = 0, status = 0;
  const start = performance.now() / 1000;
  let timer = null;
  const scan = () => {
    const now = performance.now() / 1000 - start;
    try {
      const [belt, pusher] = logic.scan(now, image.Eye, image.Height, image.Stroke);
      setOutput("Belt", belt);
      setOutput("Pusher", pusher);
    } catch (e) {
      console.error(`plc: error: ${e.message}; the program stops, its outputs off`);
      setOutput("Belt", false);
      setOutput("Pusher", false);
      status = 1;
      return;
    }
    scans += 1;
    const wait = start + scans * SCAN - performance.now() / 1000;
    if (wait < 0) overruns += 1;
    timer = setTimeout(scan, Math.max(0, wait * 1000));
  };
  scan();

  await new Promise((resolve) => {
    process.once("SIGTERM", resolve);
    process.once("SIGINT", resolve);
  });
  clearTimeout(timer);
  if (!args.quiet) {
    console.log(`plc: ${scans} scans; sorted ${logic.sorted.tall} tall and ${logic.sorted.short} short boxes; ` +
                `${overruns} overruns`);
  }
  await Promise.race([server.shutdown(0), new Promise((resolve) => setTimeout(resolve, 2000))]);
  return status;
}

main().then((status) => process.exit(status), (e) => {
  console.error(`plc: error: ${e.message}`);
  process.exit(1);
});
