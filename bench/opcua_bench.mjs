/* The client side of bench/opcua_bench.py: node-opcua-client (npm, pinned in scripts/node), a
real OPC UA client no one here wrote, against `gdpn run ... --opcua`. Prints one JSON object on
its last line; everything else it says goes to stderr.

  realtime URL READS SECONDS
      (the run paced to the wall clock)
      1. READS sequential Reads of ns=1;s=time and READS of 10 variables a request (time,
         steps and 8 places), in turns: each round trip in ms;
      2. a subscription (publishing interval 50 ms, queue 100) on 100 variables that change
         (the model's places, transitions and sensor readings in browse order, then time and
         steps), sampling interval 0 (every step), for SECONDS: the data changes received, and
         for each its latency, from its ServerTimestamp (wall clock when the server sampled it)
         to its arrival here (same machine, same clock).
  lockstep URL STEPS_PER_CALL CALLS ITEMS
      (the run in lockstep) ITEMS (0 or 100) monitored as above, then CALLS calls of
      Step(STEPS_PER_CALL) back to back, timed; the data changes received meanwhile.
      The run is left to its end by the caller (it is started with --until one call further).

usage: node bench/opcua_bench.mjs MODE URL ARGS...
*/
import { createRequire } from "node:module";
import path from "node:path";
import { fileURLToPath } from "node:url";

const here = path.dirname(fileURLToPath(import.meta.url));

/** node-opcua-client from NODE_PATH or scripts/node/node_modules (scripts/install-deps.sh). */
function loadClient() {
  const places = (process.env.NODE_PATH || "").split(path.delimiter).filter(Boolean);
  places.push(path.join(here, "..", "scripts", "node", "node_modules"));
  for (const folder of places) {
    try {
      return createRequire(path.join(folder, "..", "package.json"))("node-opcua-client");
    } catch {
      /* the next place */
    }
  }
  throw new Error("node-opcua-client is missing: scripts/install-deps.sh installs it into scripts/node/node_modules");
}

const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));
const within = (promise, ms, what) => Promise.race([
  promise, sleep(ms).then(() => { throw new Error(`${what}: no answer in ${ms} ms`); })]);
const nowMs = () => Number(process.hrtime.bigint()) / 1e6;
/** Wall clock in ms since 1970, below the millisecond (as the server's timestamps are). */
const wallMs = () => performance.timeOrigin + performance.now();

/** Median, 99th percentile, mean and count of `values` (ms). */
function stats(values) {
  const v = [...values].sort((a, b) => a - b);
  if (v.length === 0) return { n: 0 };
  return { n: v.length, median: v[Math.floor(v.length / 2)], p99: v[Math.floor(v.length * 0.99)],
           mean: v.reduce((s, x) => s + x, 0) / v.length, max: v[v.length - 1] };
}

async function main() {
  process.env.NODEOPCUA_LOG_LEVEL ??= "2";
  const ua = loadClient();
  const { OPCUAClient, AttributeIds, DataType, BrowseDirection, TimestampsToReturn, StatusCodes,
          ClientMonitoredItemGroup, MessageSecurityMode, SecurityPolicy, NodeClass } = ua;
  const [mode, endpoint, ...args] = process.argv.slice(2);
  const client = OPCUAClient.create({
    applicationName: "gdpn bench", securityMode: MessageSecurityMode.None, securityPolicy: SecurityPolicy.None,
    endpointMustExist: false, keepSessionAlive: false,
    connectionStrategy: { maxRetry: 2, initialDelay: 100, maxDelay: 200 },
  });
  await within(client.connect(endpoint), 20000, "connect");
  const session = await within(client.createSession(), 10000, "create a session");
  const names = (await session.read({ nodeId: "i=2255", attributeId: AttributeIds.Value })).value.value;
  const ns = names.findIndex((n) => n.startsWith("urn:gdpn:model:"));
  const node = (id) => `ns=${ns};s=${id}`;

  // every variable under a folder, depth first in browse order
  const variables = async (nodeId, into = []) => {
    const r = await within(session.browse({ nodeId, browseDirection: BrowseDirection.Forward,
      referenceTypeId: "HierarchicalReferences", includeSubtypes: true, resultMask: 63 }), 10000, `browse ${nodeId}`);
    for (const ref of r.references) {
      if (ref.nodeClass === NodeClass.Variable) into.push(ref.nodeId.toString());
      await variables(ref.nodeId, into);
    }
    return into;
  };
  const idOf = (s) => s.replace(/^ns=\d+;s=/, "");
  const net = await variables(node("net"));
  const places = net.filter((id) => idOf(id).startsWith("place/"));
  const transitions = net.filter((id) => idOf(id).startsWith("transition/") && !idOf(id).endsWith("/enabled"));
  const sensorVariables = await variables(node("sensors"));
  const sensors = sensorVariables.filter((id) => !/\/(active|count)$/.test(idOf(id)));
  const sensorFlags = sensorVariables.filter((id) => /\/active$/.test(idOf(id)));
  const watched = [...places, ...transitions, ...sensors, ...sensorFlags].slice(0, 98).concat([node("time"), node("steps")]);
  if (watched.length !== 100) throw new Error(`only ${watched.length} variables to monitor: ${places.length} places, ${transitions.length} transitions, ${sensors.length} sensors`);

  let changes = 0;
  const seen = new Set();
  const latencies = [];
  const subscribe = async () => {
    const subscription = await within(session.createSubscription2({
      requestedPublishingInterval: 50, requestedLifetimeCount: 6000, requestedMaxKeepAliveCount: 20,
      maxNotificationsPerPublish: 0, publishingEnabled: true, priority: 1 }), 10000, "CreateSubscription");
    const group = await within(ClientMonitoredItemGroup.create(subscription,
      watched.map((nodeId) => ({ nodeId, attributeId: AttributeIds.Value })),
      { samplingInterval: 0, queueSize: 100, discardOldest: true }, TimestampsToReturn.Both), 10000, "CreateMonitoredItems");
    // (the group's items keep no status of their own: every item's first value is the proof)
    group.on("changed", (item, dv) => {
      changes += 1;
      seen.add(item);
      if (dv.serverTimestamp) latencies.push(wallMs() - (dv.serverTimestamp.getTime() + (dv.serverPicoseconds || 0) / 1e9));
    });
    for (let k = 0; k < 100 && seen.size < watched.length; k++) await sleep(20);
    if (seen.size < watched.length) throw new Error(`${watched.length - seen.size} monitored items sent no first value`);
    return { subscription, revised: subscription.publishingInterval };
  };

  const out = { items: watched.length, watched };
  if (mode === "realtime") {
    const [reads, seconds] = args.map(Number);
    const one = { nodeId: node("time"), attributeId: AttributeIds.Value };
    const ten = [node("time"), node("steps"), ...places.slice(0, 8)].map((nodeId) => ({ nodeId, attributeId: AttributeIds.Value }));
    // the two kinds in turns, so that both see the same machine
    const check = (r) => {
      if ((Array.isArray(r) ? r : [r]).some((dv) => dv.statusCode.value !== StatusCodes.Good.value)) {
        throw new Error("a Read was not Good");
      }
    };
    const timeReads = async () => {
      for (let k = 0; k < 100; k++) check(await session.read(k % 2 ? ten : one));  // warm up
      const times = { one: [], ten: [] };
      for (let k = 0; k < reads; k++) {
        for (const [key, what] of [["one", one], ["ten", ten]]) {
          const t0 = nowMs();
          const r = await session.read(what);
          times[key].push(nowMs() - t0);
          check(r);
        }
      }
      return times;
    };
    const times = await within(timeReads(), 300000, "the Reads");
    out.read1 = stats(times.one);
    out.read10 = stats(times.ten);
    const t0 = (await session.read(one)).value.value;
    const { subscription, revised } = await subscribe();
    await sleep(500);
    const c0 = changes;
    latencies.length = 0;
    const w0 = nowMs();
    await sleep(seconds * 1000);
    const elapsed = (nowMs() - w0) / 1000;
    out.changes = changes - c0;
    out.seconds = elapsed;
    out.rate = out.changes / elapsed;
    out.latency = stats(latencies);
    out.publishing_interval = revised;
    out.model_seconds = (await session.read(one)).value.value - t0;
    await within(subscription.terminate(), 10000, "DeleteSubscriptions").catch(() => {});
  } else if (mode === "lockstep") {
    const [perCall, calls, items] = args.map(Number);
    if (items) await subscribe();
    await sleep(200);
    const c0 = changes;
    const t0 = nowMs();
    for (let k = 0; k < calls; k++) {
      const answer = await within(session.call({ objectId: node("model"), methodId: node("step"),
        inputArguments: [{ dataType: DataType.UInt32, value: perCall }] }), 30000, "Step");
      if (answer.statusCode !== StatusCodes.Good) throw new Error(`Step: ${answer.statusCode.toString()}`);
    }
    out.seconds = (nowMs() - t0) / 1000;
    out.steps = perCall * calls;
    await sleep(300);  // the last notifications
    out.changes = changes - c0;
    // the run's last call, which ends it: its answer may not come
    session.call({ objectId: node("model"), methodId: node("step"),
      inputArguments: [{ dataType: DataType.UInt32, value: perCall }] }).catch(() => {});
    await sleep(300);
  } else {
    throw new Error(`no mode ${mode}`);
  }
  await within(client.disconnect(), 3000, "disconnect").catch(() => {});
  console.log(JSON.stringify(out));
}

main().then(() => process.exit(0), (e) => {
  console.error(`opcua_bench.mjs: ${e.message}`);
  process.exit(1);
});
