#!/usr/bin/env node
/* A soft PLC for the sorting station (station.gdpn.yaml), over OPC UA: plc.py's program, as an
OPC UA client of the plant.

It does what a PLC does: every 10 ms it reads its inputs (the photo-eye, the height sensor,
the pusher's stroke), runs its logic once, and writes its outputs (the belt, the pusher).
The logic is a sequence of four steps, as the net on the station's page net_control, except
that the PLC waits for the pusher's stroke where the net waits fixed times:

  RUN      belt on; a box at the eye: tall (its top nearer than 550 mm) -> PUSH, else -> PASS
  PUSH     belt off, pusher out, until it is 690 mm out -> RETRACT
  RETRACT  pusher in, until it is back within 10 mm -> RUN
  PASS     belt on; the eye clear again -> RUN

A step that waits for the pusher longer than 3 s stops the program with an error (a stalled
pusher: try writing a force of 5 N to io/push_force).

The plant's I/O are the variables of its IO folder, ns=1;s=io/<name> (io/eye, io/height,
io/stroke read; io/belt, io/pusher written), where namespace 1 is the model's own
(urn:gdpn:model:station): the program finds its index in the server's NamespaceArray.

Run the station first, then this, in two terminals:

  gdpn run examples/commissioning/station.gdpn.yaml --opcua 4840
  node examples/commissioning/plc_opcua.js --port 4840

With --lockstep (and gdpn run ... --lockstep) each scan calls the model's Step method for
2 steps (10 ms of model time) instead of waiting 10 ms of wall clock: the run is as fast as
the two can go, and the same every time. The program ends when the plant closes the
connection (the run is over), or with Ctrl-C.

Needs node-opcua-client from the npm registry, which scripts/install-deps.sh installs into
scripts/node/node_modules (the program looks there, and in NODE_PATH).
*/
"use strict";
const { SCAN, Logic, PlcError, importPackage } = require("./plc_logic.js");

// the station's io section (station.gdpn.yaml): its variables in the model's namespace
const MODEL_URI = "urn:gdpn:model:station";
const EYE = "io/eye";            // a box breaks the beam
const HEIGHT = "io/height";      // mm: from the sensor down to what is below it
const STROKE = "io/stroke";      // mm: how far the pusher is out
const BELT = "io/belt";          // the belt runs
const PUSHER = "io/pusher";      // the pusher goes out
const PUSH_SPEED = "io/push_speed";  // mm/s: the pusher's top speed

const STEPS_PER_SCAN = 2;        // the station's dt is 5 ms

/** The plant closed the connection: its run is over. */
class PlantGone extends Error {}

function parseArgs(argv) {
  const args = { url: null, host: "127.0.0.1", port: 4840, lockstep: false, quiet: false, namespace: MODEL_URI };
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    const value = () => {
      if (i + 1 >= argv.length) throw new PlcError(`${a} needs a value`);
      return argv[++i];
    };
    if (a === "--url") args.url = value();
    else if (a === "--host") args.host = value();
    else if (a === "--port") args.port = Number(value());
    else if (a === "--namespace") args.namespace = value();
    else if (a === "--lockstep") args.lockstep = true;
    else if (a === "--quiet" || a === "-q") args.quiet = true;
    else if (a === "--help" || a === "-h") {
      console.log("usage: plc_opcua.js [--port PORT | --url opc.tcp://HOST:PORT] [--host HOST] [--lockstep] [--namespace URI] [-q]\n\n" +
                  "A soft PLC for the sorting station over OPC UA. --lockstep: call the model's Step method for each\n" +
                  "scan's 10 ms instead of waiting for the wall clock.");
      process.exit(0);
    } else throw new PlcError(`unknown option ${a}`);
  }
  if (!args.url) {
    if (!Number.isInteger(args.port) || args.port < 1 || args.port > 65535) throw new PlcError(`bad port ${args.port}`);
    args.url = `opc.tcp://${args.host}:${args.port}`;
  }
  return args;
}

const sleep = (s) => new Promise((resolve) => setTimeout(resolve, s * 1000));

async function main() {
  const args = parseArgs(process.argv.slice(2));
  process.env.NODEOPCUA_LOG_LEVEL ??= "2";  // node-opcua's own warnings off: this program says what went wrong
  const ua = await importPackage("node-opcua-client");
  const { OPCUAClient, AttributeIds, DataType, MessageSecurityMode, SecurityPolicy, StatusCodes } = ua;

  const client = OPCUAClient.create({
    applicationName: "gdpn soft PLC",
    securityMode: MessageSecurityMode.None,
    securityPolicy: SecurityPolicy.None,
    endpointMustExist: false,
    keepSessionAlive: false,
    connectionStrategy: { maxRetry: 50, initialDelay: 100, maxDelay: 200 },  // the plant may still be starting
  });
  // once connected, a lost connection is the end of the run: no reconnecting
  let gone = null;
  const goneSignal = new Promise((resolve) => { gone = resolve; });
  const plantGone = () => gone(new PlantGone());
  client.on("connection_lost", plantGone);
  client.on("close", plantGone);
  // every request races the plant's going
  const ask = async (what, promise) => {
    const result = await Promise.race([promise, goneSignal]);
    if (result instanceof PlantGone) throw result;
    return result;
  };

  try {
    await client.connect(args.url);
  } catch (e) {
    console.error(`plc: error: no OPC UA server at ${args.url} (${e.message})`);
    return 1;
  }
  client.connectionStrategy = { maxRetry: 0, initialDelay: 10, maxDelay: 20 };

  const logic = new Logic();
  let scans = 0, overruns = 0, worst = 0.0;
  let session = null;
  let status = 0;
  const stop = () => plantGone();
  process.on("SIGINT", stop);
  try {
    session = await ask("open a session", client.createSession());
    const names = await ask("read the namespaces", session.read({ nodeId: "i=2255", attributeId: AttributeIds.Value }));
    const ns = (names.value.value || []).indexOf(args.namespace);
    if (ns < 0) throw new PlcError(`the server has no namespace ${args.namespace}`);
    const node = (name) => `ns=${ns};s=${name}`;
    const check = (code, what) => {
      if (code !== StatusCodes.Good) throw new PlcError(`${what}: ${code.toString()}`);
    };
    const value = (dataValue, what) => {
      check(dataValue.statusCode, what);
      return dataValue.value.value;
    };
    const writeItem = (name, dataType, v) => ({ nodeId: node(name), attributeId: AttributeIds.Value,
                                                 value: { value: { dataType, value: v } } });
    const inputs = [EYE, HEIGHT, STROKE].map((name) => ({ nodeId: node(name), attributeId: AttributeIds.Value }));
    const step = { objectId: node("model"), methodId: node("step"),
                   inputArguments: [{ dataType: DataType.UInt32, value: STEPS_PER_SCAN }] };

    check((await ask("set the pusher's speed", session.write(writeItem(PUSH_SPEED, DataType.Int16, 800)))),
          "set the pusher's speed");
    const start = performance.now() / 1000;
    for (;;) {
      const began = performance.now() / 1000;
      const now = args.lockstep ? scans * SCAN : began - start;
      const [eye, height, stroke] = await ask("read the inputs", session.read(inputs));
      const [belt, pusher] = logic.scan(now, value(eye, "read the eye"), value(height, "read the height"),
                                        value(stroke, "read the stroke"));
      const written = await ask("write the outputs", session.write([writeItem(BELT, DataType.Boolean, belt),
                                                                    writeItem(PUSHER, DataType.Boolean, pusher)]));
      written.forEach((code) => check(code, "write the outputs"));
      scans += 1;
      if (args.lockstep) {
        check((await ask("ask for a scan's steps", session.call(step))).statusCode, "ask for a scan's steps");
        continue;
      }
      const took = performance.now() / 1000 - began;
      worst = Math.max(worst, took);
      const wait = start + scans * SCAN - performance.now() / 1000;
      if (wait > 0) await ask("wait for the next scan", sleep(wait));
      else overruns += 1;
    }
  } catch (e) {
    if (e instanceof PlcError) {  // a request refused (the address space and this program disagree), a stall
      console.error(`plc: error: ${e.message}`);
      status = 1;
    } else if (!(e instanceof PlantGone) && !/closed|disconnect|socket|ECONN|EPIPE|BadSecureChannel|BadSession|BadConnection|BadCommunication|BadServerHalted|BadShutdown/i.test(e.message)) {
      console.error(`plc: error: ${e.message}`);
      status = 1;
    }  // else the run is over and the plant has gone
  } finally {
    process.off("SIGINT", stop);
    await Promise.race([client.disconnect().catch(() => {}), sleep(2)]);
  }
  if (status === 0 && !args.quiet) {
    console.log(`plc: ${scans} scans; sorted ${logic.sorted.tall} tall and ${logic.sorted.short} short boxes` +
                (args.lockstep ? "" : `; slowest scan ${(worst * 1000).toFixed(1)} ms, ${overruns} overruns`));
  }
  return status;
}

main().then((status) => process.exit(status), (e) => {
  console.error(`plc: error: ${e.message}`);
  process.exit(1);
});
