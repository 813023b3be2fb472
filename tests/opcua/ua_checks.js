/* node-opcua's client against `gdpn run examples/commissioning/station.gdpn.yaml --opcua 0 --lockstep`:
one part of tests/opcua/clients_check.py, which starts the run and reads this program's lines.

  browse     NamespaceArray, ServerStatus.State, the station's folders and their names, BrowseNext
             with 3 references a time, TranslateBrowsePathsToNodeIds, RegisterNodes
  readwrite  io/height and its EngineeringUnits, writes that move the pusher and set its speed,
             BadNotWritable on inputs and places, BadTypeMismatch on a wrong data type
  subscribe  io/eye's changes as the first box passes (model-time source timestamps), an
             absolute deadband on io/height
  call       Step(10) advances the model by 10 x dt

Each check prints `ok    WHAT` or `FAIL  WHAT`; the status is 1 when one failed. Every part ends by
calling Step until the run is over (the run is started with --until). Every wait has a timeout.

usage: node ua_checks.js PART opc.tcp://127.0.0.1:PORT UNTIL
*/
"use strict";
const path = require("path");
const url = require("url");

const [PART, URL, UNTIL_TEXT] = process.argv.slice(2);
const UNTIL = Number(UNTIL_TEXT);           // s, the run's --until
const MODEL_URI = "urn:gdpn:model:station";
const DT = 0.005;                            // s, the station's step
const EPOCH = Date.UTC(2000, 0, 1);          // model time 0 as a source timestamp
const IO_NAMES = ["eye", "boxes_to_come", "height", "stroke", "tall_bin", "short_bin",
                  "belt", "pusher", "push_speed", "stock", "push_force"];
let failures = 0;

function check(ok, what) {
  console.log((ok ? "ok    " : "FAIL  ") + what);
  if (!ok) failures += 1;
  return ok;
}

async function importPackage(name) {
  const places = (process.env.NODE_PATH || "").split(path.delimiter).filter(Boolean);
  places.push(path.join(__dirname, "..", "..", "scripts", "node", "node_modules"));
  for (const folder of places) {
    try {
      return import(url.pathToFileURL(require.resolve(name, { paths: [path.dirname(folder)] })).href);
    } catch {
      /* the next place */
    }
  }
  throw new Error(`${name} is missing: scripts/install-deps.sh installs it into scripts/node/node_modules`);
}

const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));
const within = (promise, ms, what) => Promise.race([
  promise, sleep(ms).then(() => { throw new Error(`${what}: no answer in ${ms} ms`); })]);

async function main() {
  process.env.NODEOPCUA_LOG_LEVEL ??= "2";
  const ua = await importPackage("node-opcua-client");
  const { OPCUAClient, AttributeIds, DataType, StatusCodes, BrowseDirection, makeBrowsePath,
          TimestampsToReturn, DataChangeFilter, DataChangeTrigger, DeadbandType, ClientMonitoredItem,
          MessageSecurityMode, SecurityPolicy } = ua;
  const client = OPCUAClient.create({
    applicationName: "gdpn tests", securityMode: MessageSecurityMode.None, securityPolicy: SecurityPolicy.None,
    endpointMustExist: false, keepSessionAlive: false,
    connectionStrategy: { maxRetry: 2, initialDelay: 100, maxDelay: 200 },
  });
  await within(client.connect(URL), 20000, "connect");
  const session = await within(client.createSession(), 10000, "create a session");
  const read = async (nodeId, attributeId = AttributeIds.Value) =>
    within(session.read({ nodeId, attributeId }), 10000, `read ${nodeId}`);

  const names = (await read("i=2255")).value.value || [];
  const ns = names.indexOf(MODEL_URI);
  const node = (id) => `ns=${ns};s=${id}`;
  const step = async (n) => within(session.call({ objectId: node("model"), methodId: node("step"),
    inputArguments: [{ dataType: DataType.UInt32, value: n }] }), 30000, `Step(${n})`);
  const browseNames = async (nodeId, extra = {}) => {
    const result = await within(session.browse({ nodeId, browseDirection: BrowseDirection.Forward,
      referenceTypeId: "HierarchicalReferences", includeSubtypes: true, resultMask: 63, ...extra }), 10000,
    `browse ${nodeId}`);
    return result;
  };
  const write = async (nodeId, dataType, value) => within(session.write({ nodeId, attributeId: AttributeIds.Value,
    value: { value: { dataType, value } } }), 10000, `write ${nodeId}`);

  if (PART === "browse") {
    check(ns > 0, `NamespaceArray has ${MODEL_URI} (index ${ns}): ${JSON.stringify(names)}`);
    const state = await read("i=2259");
    check(state.statusCode === StatusCodes.Good && state.value.value === 0, `ServerStatus.State is Running (0): ${state.value.value}`);
    const objects = await browseNames("i=85");
    const station = objects.references.find((r) => r.browseName.name === "station");
    check(station && station.browseName.namespaceIndex === ns && station.nodeId.toString() === node("model"),
          `Objects has ${ns}:station, ${node("model")}`);
    const model = await browseNames(node("model"));
    const seen = model.references.map((r) => r.browseName.name).sort();
    check(["IO", "Net", "Parameters", "Parts", "Sensors", "Step", "Steps", "Time"].every((n) => seen.includes(n)),
          `station has IO, Parts, Net, Sensors, Parameters, Time, Steps, Step: ${seen.join(" ")}`);
    const want = {
      IO: "io", Parts: "parts", Net: "net", Sensors: "sensors", Parameters: "params", Time: "time", Steps: "steps", Step: "step" };
    check(Object.entries(want).every(([n, id]) => model.references.some((r) => r.browseName.name === n && r.nodeId.toString() === node(id))),
          "their NodeIds are ns=1;s=io, parts, net, sensors, params, time, steps, step (namespace 1 by its URI)");
    const io = await browseNames(node("io"));
    const ioNames = io.references.map((r) => r.browseName.name);
    check(JSON.stringify([...ioNames].sort()) === JSON.stringify([...IO_NAMES].sort()), `IO has the station's 11 entries: ${ioNames.join(" ")}`);
    check(io.references.every((r) => r.nodeId.toString() === node("io/" + r.browseName.name)), "each is ns=1;s=io/<name>");
    // BrowseNext: 3 references a time
    const views = await within(session.browse({ nodeId: node("io"), browseDirection: BrowseDirection.Forward,
      referenceTypeId: "HierarchicalReferences", includeSubtypes: true, resultMask: 63 }), 10000, "browse");
    session.requestedMaxReferencesPerNode = 3;
    const paged = [];
    let cp = null;
    {
      const r = await within(session.browse({ nodeId: node("io"), browseDirection: BrowseDirection.Forward,
        referenceTypeId: "HierarchicalReferences", includeSubtypes: true, resultMask: 63 }), 10000, "browse 3 a time");
      paged.push(r.references.length);
      check(r.references.length === 3 && r.continuationPoint && r.continuationPoint.length > 0,
            `browse IO 3 at a time: 3 references and a continuation point (${r.references.length})`);
      cp = r.continuationPoint;
      const got = r.references.map((x) => x.browseName.name);
      for (let k = 0; k < 10 && cp && cp.length; k++) {
        const next = await within(session.browseNext(cp, false), 10000, "BrowseNext");
        got.push(...next.references.map((x) => x.browseName.name));
        paged.push(next.references.length);
        cp = next.continuationPoint;
      }
      check(JSON.stringify(got) === JSON.stringify(views.references.map((x) => x.browseName.name)),
            `BrowseNext brings the rest, in order: pages of ${paged.join(", ")}`);
    }
    session.requestedMaxReferencesPerNode = 10000;
    const paths = await within(session.translateBrowsePath([
      makeBrowsePath("i=85", `/${ns}:station/${ns}:IO/${ns}:height`),
      makeBrowsePath("i=85", `/${ns}:station/${ns}:IO/${ns}:no_such_thing`)]), 10000, "TranslateBrowsePathsToNodeIds");
    check(paths[0].statusCode === StatusCodes.Good && paths[0].targets.length === 1 &&
          paths[0].targets[0].targetId.toString() === node("io/height"),
          `TranslateBrowsePathsToNodeIds: /1:station/1:IO/1:height is ${node("io/height")}`);
    check(paths[1].statusCode === StatusCodes.BadNoMatch, `a path to nothing: BadNoMatch (${paths[1].statusCode.toString()})`);
    const registered = await within(session.registerNodes([node("io/height"), node("time")]), 10000, "RegisterNodes");
    check(registered.length === 2, "RegisterNodes: two NodeIds back");
    const direct = await read(node("io/height"));
    const viaRegistered = await read(registered[0]);
    check(viaRegistered.statusCode === StatusCodes.Good && viaRegistered.value.value === direct.value.value,
          `a registered NodeId reads as the node (${viaRegistered.value.value} mm)`);
    await within(session.unregisterNodes(registered), 10000, "UnregisterNodes");
    const net = await browseNames(node("net"));
    check(net.references.some((r) => r.nodeId.toString() === node("page/feeder")), "Net has the page feeder, ns=1;s=page/feeder");
    const stock = await read(node("place/feeder/stock"));
    check(stock.value.dataType === DataType.Int32 && stock.value.value === 7,
          `place feeder/stock: Int32, 7 tokens once the first box is fed (${stock.value.value})`);
    const sensors = await browseNames(node("sensors"));
    check(sensors.references.some((r) => r.nodeId.toString() === node("sensor/station/mast/height")),
          "Sensors has ns=1;s=sensor/station/mast/height");
    const boxes = await read(node("param/boxes"));
    check(boxes.value.dataType === DataType.Double && boxes.value.value === 8, `param/boxes: Double 8 (${boxes.value.value})`);
  } else if (PART === "readwrite") {
    const height = await read(node("io/height"));
    check(height.value.dataType === DataType.Int16 && height.value.value === 850,
          `io/height: Int16, 850 mm from the sensor (1.2 m up) to the belt's top (0.35 m) (${height.value.value})`);
    const dataType = await read(node("io/height"), AttributeIds.DataType);
    check(dataType.value.value.toString() === "ns=0;i=4", `io/height's DataType attribute is Int16, i=4 (${dataType.value.value})`);
    const props = await within(session.browse({ nodeId: node("io/height"), browseDirection: BrowseDirection.Forward,
      referenceTypeId: "HasProperty", includeSubtypes: true, resultMask: 63 }), 10000, "browse properties");
    const eu = props.references.find((r) => r.browseName.name === "EngineeringUnits");
    if (check(eu !== undefined, "io/height has the property EngineeringUnits")) {
      const info = (await read(eu.nodeId)).value.value;
      check(info && info.displayName && info.displayName.text === "mm", `its EUInformation says mm (${info && JSON.stringify(info.displayName)})`);
    }
    const belt0 = await read(node("io/belt"));
    check(belt0.value.value === false, "io/belt reads false at first");
    check((await write(node("io/belt"), DataType.Boolean, true)) === StatusCodes.Good, "io/belt written true: Good");
    check((await read(node("io/belt"))).value.value === true, "io/belt reads back true");
    check((await write(node("io/push_speed"), DataType.Int16, 500)) === StatusCodes.Good, "io/push_speed written 500 mm/s: Good");
    check((await read(node("io/push_speed"))).value.value === 500, "io/push_speed reads back 500");
    check((await write(node("io/pusher"), DataType.Boolean, true)) === StatusCodes.Good, "io/pusher written true: Good");
    const answer = await step(200);
    check(answer.statusCode === StatusCodes.Good, "Step(200): 1 s of model time");
    const stroke = (await read(node("io/stroke"))).value.value;
    check(stroke >= 470 && stroke <= 510, `io/stroke: the pusher went out about 500 mm in 1 s at 500 mm/s (${stroke} mm)`);
    const notWritable = await write(node("io/height"), DataType.Int16, 100);
    check(notWritable === StatusCodes.BadNotWritable, `io/height written: BadNotWritable (${notWritable.toString()})`);
    const place = await write(node("place/feeder/stock"), DataType.Int32, 1);
    check(place === StatusCodes.BadNotWritable, `place feeder/stock written: BadNotWritable (${place.toString()})`);
    const mismatch = await write(node("io/belt"), DataType.Int16, 0);
    check(mismatch === StatusCodes.BadTypeMismatch, `io/belt written an Int16: BadTypeMismatch (${mismatch.toString()})`);
    check((await read(node("io/belt"))).value.value === true, "io/belt is still true");
    check((await read(node("io/height"))).value.value !== 100, "io/height did not take 100");
  } else if (PART === "subscribe") {
    check((await write(node("io/belt"), DataType.Boolean, true)) === StatusCodes.Good, "io/belt written true");
    const subscription = await within(session.createSubscription2({
      requestedPublishingInterval: 20, requestedLifetimeCount: 1000, requestedMaxKeepAliveCount: 20,
      maxNotificationsPerPublish: 0, publishingEnabled: true, priority: 1 }), 10000, "CreateSubscription");
    const changes = { eye: [], coarse: [], fine: [] };
    const monitor = async (key, id, filter) => {
      const item = await within(ClientMonitoredItem.create(subscription, { nodeId: node(id), attributeId: AttributeIds.Value },
        { samplingInterval: 0, queueSize: 100, discardOldest: true, ...(filter ? { filter } : {}) },
        TimestampsToReturn.Both).on("changed", (dv) => changes[key].push(dv)), 10000, `monitor ${id}`);
      return item;
    };
    const deadband = (value) => new DataChangeFilter({ trigger: DataChangeTrigger.StatusValue,
      deadbandType: DeadbandType.Absolute, deadbandValue: value });
    await monitor("eye", "io/eye");
    await monitor("coarse", "io/height", deadband(1000));
    await monitor("fine", "io/height", deadband(1));
    await sleep(200);
    let answers = 0;
    for (let k = 0; k < 24; k++) {  // 6 s of model time, 0.25 s a call
      if ((await step(50)).statusCode !== StatusCodes.Good) break;
      answers += 1;
      await sleep(40);
    }
    check(answers === 24, `Step(50) 24 times, 6 s of model time, each Good (${answers})`);
    await sleep(500);
    const eye = changes.eye.map((dv) => dv.value.value);
    check(JSON.stringify(eye) === "[false,true,false]", `io/eye: false, then true, then false as the first box passes (${JSON.stringify(eye)})`);
    if (changes.eye.length === 3) {
      const on = (changes.eye[1].sourceTimestamp.getTime() - EPOCH) / 1000;
      const off = (changes.eye[2].sourceTimestamp.getTime() - EPOCH) / 1000;
      check(on > 3.5 && on < 4.7, `the eye sees the box at model time ${on} s (from x = -1.7 m to 0.4 m at 0.5 m/s: about 4 s)`);
      check(off - on > 0.3 && off - on < 0.6, `and is clear ${(off - on).toFixed(3)} s later (a 0.2 m box at 0.5 m/s: 0.4 s)`);
    }
    const coarse = changes.coarse.map((dv) => dv.value.value);
    const fine = changes.fine.map((dv) => dv.value.value);
    check(coarse.length === 1 && coarse[0] === 850, `io/height with an absolute deadband of 1000: only its first value (${JSON.stringify(coarse)})`);
    check(fine.length >= 3 && fine[0] === 850 && fine.some((h) => h < 700) && fine[fine.length - 1] === 850,
          `io/height with a deadband of 1: 850, the box's top, 850 again (${JSON.stringify(fine)})`);
    await within(subscription.terminate(), 10000, "DeleteSubscriptions");
  } else if (PART === "call") {
    const t0 = (await read(node("time"))).value.value;
    const s0 = (await read(node("steps"))).value.value;
    const answer = await step(10);
    check(answer.statusCode === StatusCodes.Good, `Step(10): Good (${answer.statusCode.toString()})`);
    const t1 = answer.outputArguments && answer.outputArguments[0] ? answer.outputArguments[0].value : NaN;
    check(Math.abs(t1 - t0 - 10 * DT) < 1e-12, `Step(10) answers the time ${t1} s, ${t0} s + 10 x 0.005 s`);
    check((await read(node("time"))).value.value === t1, "ns=1;s=time reads the same");
    const s1 = (await read(node("steps"))).value.value;
    const asNumber = (v) => (Array.isArray(v) ? v[0] * 2 ** 32 + v[1] : Number(v));
    check(asNumber(s1) - asNumber(s0) === 10, `ns=1;s=steps went up by 10 (${JSON.stringify(s0)} -> ${JSON.stringify(s1)})`);
    const missing = await within(session.call({ objectId: node("model"), methodId: node("step"), inputArguments: [] }), 10000, "Step()");
    check(missing.statusCode === StatusCodes.BadArgumentsMissing, `Step with no argument: BadArgumentsMissing (${missing.statusCode.toString()})`);
  } else if (PART === "call-realtime") {
    const answer = await step(10);
    check(answer.statusCode === StatusCodes.BadInvalidState, `Step in a run in real time: BadInvalidState (${answer.statusCode.toString()})`);
  } else {
    throw new Error(`no part ${PART}`);
  }

  // the rest of the run, so that it ends (a lockstep run); the last answer may not come
  if (PART !== "call-realtime") {
    for (let k = 0; k < 100; k++) {
      let t;
      try {
        t = (await read(node("time"))).value.value;
      } catch {
        break;
      }
      if (!(t < UNTIL - 1e-9)) break;
      try {
        await within(step(Math.round((UNTIL - t) / DT)), 30000, "the rest of the run");
      } catch {
        break;
      }
    }
  }
  await within(client.disconnect(), 5000, "disconnect").catch(() => {});
}

const watchdog = setTimeout(() => {
  check(false, `${PART}: still not done after 120 s`);
  process.exit(1);
}, 120000);
main().then(() => {
  clearTimeout(watchdog);
  process.exit(failures ? 1 : 0);
}, (e) => {
  check(false, `${PART}: ${e.message}`);
  process.exit(1);
});
