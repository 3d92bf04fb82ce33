// Checks `naming: ros2` with ROS 2's own message tools (tests/ecosystem/ros2_names.sh):
//   node ros2_check.mjs RUN.mcap ROS2_PACKAGE_DIR ECHO_DIR WIRE.json
// - @foxglove/rosmsg parses every msg/*.msg of the generated interface package (as ROS 2
//   definitions, each with the messages it uses appended, as rosbag2 stores them);
// - WIRE.json (`plexus topic list --json` in the default naming: the names on the wire) must
//   hold every topic as rt/<topic> with the type plexus_msgs::msg::dds_::<Type>_, which is
//   how rmw_fastrtps and rmw_cyclonedds name a ROS 2 topic and its type;
// - @foxglove/rosmsg2-serialization decodes the first samples of every channel of RUN.mcap
//   (recorded under naming ros2: the CDR exactly as it was on the wire) against the generated
//   definition of its type, and the values must equal `plexus topic echo --recording --json`
//   (ECHO_DIR/<topic with / as __>.jsonl).
// Exit 0 when everything matches; otherwise 1, with what differs.
import { McapIndexedReader } from "@mcap/core";
import { parse } from "@foxglove/rosmsg";
import { MessageReader } from "@foxglove/rosmsg2-serialization";
import zstd from "@foxglove/wasm-zstd";
import lz4 from "@foxglove/wasm-lz4";
import { open, readFile, readdir } from "node:fs/promises";
import { existsSync } from "node:fs";
import path from "node:path";
import { comparer, parseExact } from "./echo_compare.mjs";

const [file, pkgDir, echoDir, wireFile] = process.argv.slice(2);
if (!file || !pkgDir || !echoDir || !wireFile) {
  console.error("usage: node ros2_check.mjs RUN.mcap ROS2_PACKAGE_DIR ECHO_DIR WIRE.json");
  process.exit(2);
}
const failures = [];
const fail = (what) => {
  if (failures.length < 50) failures.push(what);
};

// The interface package: its name, and every .msg with the messages it uses appended.
const pkgXml = await readFile(path.join(pkgDir, "package.xml"), "utf8");
const pkg = /<name>([^<]+)<\/name>/.exec(pkgXml)?.[1];
if (pkg !== "plexus_msgs") fail(`package.xml names package ${pkg}, not plexus_msgs`);
const own = new Map();
for (const f of (await readdir(path.join(pkgDir, "msg"))).filter((f) => f.endsWith(".msg")))
  own.set(f.slice(0, -4), await readFile(path.join(pkgDir, "msg", f), "utf8"));
const usedTypes = (textOf) =>
  textOf
    .split("\n")
    .map((l) => l.replace(/#.*/, "").trim())
    .filter((l) => l && !l.includes("="))
    .map((l) => l.split(/\s+/)[0].replace(/\[.*$/, "").replace(/^plexus_msgs\//, ""))
    .filter((t) => own.has(t));
function fullDefinition(name) {
  const seen = new Set([name]);
  const order = [];
  const visit = (n) => {
    for (const t of usedTypes(own.get(n)))
      if (!seen.has(t)) {
        seen.add(t);
        order.push(t);
        visit(t);
      }
  };
  visit(name);
  return [own.get(name), ...order.map((t) => `${"=".repeat(80)}\nMSG: ${pkg}/${t}\n${own.get(t)}`)].join("\n");
}
const definitions = new Map();
for (const name of own.keys()) {
  try {
    definitions.set(name, parse(fullDefinition(name), { ros2: true }));
  } catch (e) {
    fail(`msg/${name}.msg does not parse: ${e.message}`);
  }
}

// The names on the wire.
const wire = JSON.parse(await readFile(wireFile, "utf8"));
const wireType = new Map();
for (const t of wire) {
  if (!t.topic.startsWith("rt/")) fail(`topic ${t.topic} on the wire is not a ROS 2 topic (rt/...)`);
  for (const ty of t.types) {
    const m = /^plexus_msgs::msg::dds_::([A-Za-z0-9]+)_$/.exec(ty);
    if (!m) fail(`${t.topic}: type ${ty} on the wire is not plexus_msgs::msg::dds_::<Type>_`);
    else if (!own.has(m[1])) fail(`${t.topic}: type ${ty} has no msg/${m[1]}.msg`);
    else wireType.set(t.topic, m[1]);
  }
}

// The recording: every channel decoded with its ROS 2 definition.
await zstd.isLoaded;
await lz4.isLoaded;
const handle = await open(file, "r");
const size = (await handle.stat()).size;
const reader = await McapIndexedReader.Initialize({
  readable: {
    size: async () => BigInt(size),
    read: async (offset, length) => {
      const buf = new Uint8Array(Number(length));
      await handle.read(buf, 0, Number(length), Number(offset));
      return buf;
    },
  },
  decompressHandlers: {
    zstd: (data, decompressedSize) => zstd.decompress(data, Number(decompressedSize)),
    lz4: (data, decompressedSize) => lz4(data, Number(decompressedSize)),
  },
});
const SAMPLE = 5;
const readers = new Map();
for (const [id, channel] of reader.channelsById) {
  const schema = reader.schemasById.get(channel.schemaId);
  const name = schema.name.replace(/^.*::/, "");
  const onWire = wireType.get(`rt/${channel.topic}`);
  if (onWire === undefined) fail(`${channel.topic}: not on the wire as rt/${channel.topic}`);
  else if (onWire !== name) fail(`${channel.topic}: type ${name} recorded, ${onWire} on the wire`);
  if (!definitions.has(name)) {
    fail(`${channel.topic}: no generated definition for ${schema.name}`);
    continue;
  }
  readers.set(id, new MessageReader(definitions.get(name)));
}
const samples = new Map();
for await (const m of reader.readMessages()) {
  const kept = samples.get(m.channelId) ?? [];
  if (kept.length >= SAMPLE || !readers.has(m.channelId)) continue;
  try {
    kept.push(readers.get(m.channelId).readMessage(m.data));
  } catch (e) {
    fail(`${reader.channelsById.get(m.channelId).topic}: does not decode as ROS 2 CDR: ${e.message}`);
  }
  samples.set(m.channelId, kept);
}
await handle.close();

const compare = comparer(fail);
let compared = 0;
// A channel the recorder opened for a writer it saw, but caught no sample of (plexus param's
// request: its writer lives a moment, and may have sent before the recorder's reader matched),
// has nothing to decode; the summary names such channels.
const counts = reader.statistics?.channelMessageCounts ?? new Map();
const empty = [];
for (const [id, channel] of reader.channelsById) {
  if (Number(counts.get(id) ?? 0n) === 0) {
    empty.push(channel.topic);
    continue;
  }
  const echoFile = path.join(echoDir, channel.topic.replaceAll("/", "__") + ".jsonl");
  if (!existsSync(echoFile)) {
    fail(`${channel.topic}: no ${echoFile}`);
    continue;
  }
  const lines = (await readFile(echoFile, "utf8")).split("\n").filter((l) => l.length > 0);
  const got = samples.get(id) ?? [];
  if (lines.length === 0 || lines.length !== got.length)
    fail(`${channel.topic}: echo printed ${lines.length} samples, ${got.length} decoded`);
  lines.forEach((line, i) => {
    compare(parseExact(line), got[i], `${channel.topic}#${i}`);
    compared++;
  });
}
if (reader.channelsById.size === 0) fail("the recording has no channels");
// The test's plexus param list under ROS 2 names: its reply was recorded and decoded above.
const replies = [...reader.channelsById].find(([, c]) => c.topic === "param/reply");
if (!replies || Number(counts.get(replies[0]) ?? 0n) === 0) fail("param/reply: no reply of plexus param list recorded");

console.log(
  `${own.size} .msg files parsed; ${wire.length} topics on the wire, all rt/...; ${reader.channelsById.size} channels ` +
    `decoded as ROS 2 CDR; ${compared} samples equal to plexus topic echo` +
    (empty.length ? `; no sample recorded on ${empty.join(", ")}` : ""),
);
if (failures.length > 0) {
  for (const f of failures) console.error(`MISMATCH ${f}`);
  process.exit(1);
}
