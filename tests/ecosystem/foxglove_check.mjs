// A Foxglove WebSocket client (@foxglove/ws-protocol over `ws`) against foxglove_bridge
// (tests/ecosystem/foxglove_rfid.sh):
//   node foxglove_check.mjs URL SECONDS OUT.json TOPIC...
// (OUT.json.ready is written once every TOPIC has its first message.)
// Connects with subprotocol foxglove.websocket.v1, checks the server info (capability "time")
// and that every channel is advertised with an omgidl schema and cdr encoding; subscribes to
// the TOPICs, decodes every message with @foxglove/omgidl-parser and
// @foxglove/omgidl-serialization, and checks each decoded number against the @range of its
// member in the schema (and that it is finite). For SECONDS after each topic's first message
// it counts messages; OUT.json gets, per topic, the count, the rate from the messages'
// receive timestamps and the timestamps themselves (wall clock, ns), for the script to count
// over exactly the window `plexus topic hz` measured (a loaded machine's rate drifts). TOPIC "*": every
// advertised topic (tools/bench/foxglove_cost.sh). Exit 1 on a mismatch.
import foxgloveWs from "@foxglove/ws-protocol";
const { FoxgloveClient } = foxgloveWs;
import WebSocket from "ws";
import { parseIDL } from "@foxglove/omgidl-parser";
import { MessageReader } from "@foxglove/omgidl-serialization";
import { writeFile } from "node:fs/promises";
import { writeFileSync } from "node:fs";

const [url, secondsArg, outFile, ...topics] = process.argv.slice(2);
if (!url || !secondsArg || !outFile || topics.length === 0) {
  console.error("usage: node foxglove_check.mjs URL SECONDS OUT.json TOPIC...");
  process.exit(2);
}
const seconds = Number(secondsArg);
const failures = [];
const fail = (what) => failures.length < 50 && failures.push(what);

// @range(min=..., max=...) of each member of each struct in an IDL text: struct -> member -> [min, max].
function ranges(idl) {
  const out = new Map();
  let struct = null;
  let pending = null;
  for (const line of idl.split("\n")) {
    const s = /^\s*struct\s+(\w+)/.exec(line);
    if (s) {
      struct = new Map();
      out.set(s[1], struct);
      continue;
    }
    const r = /@range\(\s*min\s*=\s*([-+0-9.eE]+)\s*,\s*max\s*=\s*([-+0-9.eE]+)\s*\)/.exec(line);
    if (r) pending = [Number(r[1]), Number(r[2])];
    const m = /^\s*(?:@\w+(?:\([^)]*\))?\s*)*[\w:]+(?:\s+\w+)*\s+(\w+)\s*(?:\[\d+\])?\s*;/.exec(line);
    if (m && struct) {
      if (pending) struct.set(m[1], pending);
      pending = null;
    }
  }
  return out;
}

const client = new FoxgloveClient({ ws: new WebSocket(url, [FoxgloveClient.SUPPORTED_SUBPROTOCOL]) });
const wanted = new Map(); // subscription id -> {topic, reader, limits, first, last, n, window}
let serverInfo = null;
let readyWritten = false;
let times = 0;
const done = new Promise((resolve) => {
  setTimeout(resolve, (seconds + 20) * 1000); // at most: the topics' first messages come within 20 s
  client.on("serverInfo", (info) => {
    serverInfo = info;
  });
  client.on("time", () => times++);
  client.on("status", (s) => fail(`server status ${s.level}: ${s.message}`));
  client.on("error", (e) => fail(`client error: ${e.message}`));
  client.on("advertise", (channels) => {
    for (const c of channels) {
      if (c.encoding !== "cdr" || c.schemaEncoding !== "omgidl")
        fail(`${c.topic}: encoding ${c.encoding}, schema encoding ${c.schemaEncoding}`);
      const all = topics.length === 1 && topics[0] === "*";
      if ((!all && !topics.includes(c.topic)) || [...wanted.values()].some((w) => w.topic === c.topic)) continue;
      let reader, limits;
      try {
        reader = new MessageReader(c.schemaName, parseIDL(c.schema));
        limits = ranges(c.schema).get(c.schemaName.replace(/^.*::/, "")) ?? new Map();
      } catch (e) {
        fail(`${c.topic}: schema ${c.schemaName} does not parse: ${e.message}`);
        continue;
      }
      const id = client.subscribe(c.id);
      wanted.set(id, { topic: c.topic, reader, limits, first: null, last: null, n: 0, decoded: 0, times: [] });
    }
  });
  client.on("message", ({ subscriptionId, timestamp, data }) => {
    const w = wanted.get(subscriptionId);
    if (!w) return fail(`a message for subscription ${subscriptionId}, which the client never made`);
    const t = Number(timestamp) * 1e-9;
    if (w.first === null) {
      w.first = t;
      const everyWanted = topics[0] === "*" ? wanted.size > 0 : wanted.size === topics.length;
      if (!readyWritten && everyWanted && [...wanted.values()].every((x) => x.first !== null)) {
        readyWritten = true;
        writeFileSync(`${outFile}.ready`, "");
      }
    }
    if (t - w.first > seconds) {
      if ([...wanted.values()].every((x) => x.first !== null && x.last !== null && x.last - x.first >= seconds - 0.05))
        resolve();
      return;
    }
    w.last = t;
    w.n++;
    w.times.push(Number(timestamp));
    let value;
    try {
      value = w.reader.readMessage(new Uint8Array(data.buffer, data.byteOffset, data.byteLength));
    } catch (e) {
      return fail(`${w.topic}: message does not decode: ${e.message}`);
    }
    w.decoded++;
    for (const [field, v] of Object.entries(value)) {
      if (typeof v !== "number") continue;
      if (!Number.isFinite(v)) fail(`${w.topic}.${field}: ${v} is not finite`);
      const lim = w.limits.get(field);
      if (lim && (v < lim[0] || v > lim[1])) fail(`${w.topic}.${field}: ${v} outside its @range [${lim[0]}, ${lim[1]}]`);
    }
  });
});
await done;
client.close();

if (!serverInfo) fail("no serverInfo");
else if (!serverInfo.capabilities.includes("time")) fail(`capabilities ${serverInfo.capabilities}: no time`);
if (times === 0) fail("no time message");
const result = {};
const checked = topics.length === 1 && topics[0] === "*" ? [...wanted.values()].map((w) => w.topic) : topics;
for (const t of checked) {
  const w = [...wanted.values()].find((x) => x.topic === t);
  if (!w) {
    fail(`${t}: never advertised`);
    continue;
  }
  if (w.n < 2) {
    if (checked === topics) fail(`${t}: ${w.n} messages`);  // "*" takes slow topics as they come
    continue;
  }
  result[t] = {
    messages: w.n,
    decoded: w.decoded,
    span_s: w.last - w.first,
    rate_hz: (w.n - 1) / (w.last - w.first),
    receive_ns: checked === topics ? w.times : undefined,
  };
}
await writeFile(outFile, JSON.stringify(result, null, 1));
const brief = Object.fromEntries(Object.entries(result).map(([t, r]) => [t, { ...r, receive_ns: undefined }]));
console.log(`foxglove client: ${JSON.stringify(brief)}; ${times} time messages`);
if (failures.length > 0) {
  for (const f of failures) console.error(`MISMATCH ${f}`);
  process.exit(1);
}
