/* The sorting station's control program (plc.py's, in JavaScript), shared by the two OPC UA
controllers of the commissioning example: plc_opcua.js (a soft PLC, the plant's client) and
plc_server.js (a PLC runtime that is itself a server, the plant its client).
*/
"use strict";
const path = require("path");
const url = require("url");

const SCAN = 0.010;              // s, the scan period
const TALL_BELOW_MM = 550;       // a tall box's top (750 mm) is 450 mm below the sensor, a short one's 650
const OUT_MM = 690, IN_MM = 10;  // the pusher's stroke when out (of 700) and when back
const STALL_TIME = 3.0;          // s, the longest the pusher may take

/** The control program: inputs in, outputs out, once per scan. `now` is the PLC's clock (s). */
class Logic {
  constructor() {
    this.step = "RUN";
    this.since = 0.0;
    this.sorted = { tall: 0, short: 0 };
  }

  scan(now, eye, heightMm, strokeMm) {
    const go = (step) => { this.step = step; this.since = now; };
    if ((this.step === "PUSH" || this.step === "RETRACT") && now - this.since > STALL_TIME) {
      throw new PlcError(`the pusher stalled in ${this.step} at ${strokeMm} mm`);
    }
    if (this.step === "RUN" && eye) {
      const tall = heightMm < TALL_BELOW_MM;
      this.sorted[tall ? "tall" : "short"] += 1;
      go(tall ? "PUSH" : "PASS");
    } else if (this.step === "PUSH" && strokeMm >= OUT_MM) {
      go("RETRACT");
    } else if (this.step === "RETRACT" && strokeMm <= IN_MM) {
      go("RUN");
    } else if (this.step === "PASS" && !eye) {
      go("RUN");
    }
    const belt = this.step === "RUN" || this.step === "PASS";
    const pusher = this.step === "PUSH";
    return [belt, pusher];
  }
}

/** A refusal, a mistake on the command line, a missing package, a stall. */
class PlcError extends Error {}

/** Imports an npm package from scripts/node/node_modules (beside this repository's examples) or NODE_PATH. */
async function importPackage(name) {
  const places = (process.env.NODE_PATH || "").split(path.delimiter).filter(Boolean);
  places.push(path.join(__dirname, "..", "..", "scripts", "node", "node_modules"));
  for (const folder of places) {
    let file;
    try {
      file = require.resolve(name, { paths: [path.dirname(folder)] });
    } catch {
      continue;
    }
    return import(url.pathToFileURL(file).href);
  }
  throw new PlcError(`${name} is missing: scripts/install-deps.sh installs it into scripts/node/node_modules`);
}

module.exports = { SCAN, TALL_BELOW_MM, OUT_MM, IN_MM, STALL_TIME, Logic, PlcError, importPackage };
