// Reads a plexus MCAP recording with third-party readers and compares it with plexus's own
// view of it (tests/ecosystem/mcap_main_job.sh):
//   node mcap_check.mjs RUN.mcap INFO.json ECHO_DIR
// - @mcap/core's McapIndexedReader opens it through its summary (footer, summary CRC, chunk
//   and message indexes) and reads every message (chunk CRCs checked); its McapStreamReader
//   reads the file again record by record, every CRC checked (chunks, data section, summary);
// - @foxglove/omgidl-parser parses every channel's schema, @foxglove/omgidl-serialization
//   decodes every message against it (root: the schema name);
// - the channel and message counts, per channel too, must equal `plexus record info --json`
//   (INFO.json), and the decoded fields of the first samples of every topic must equal
//   `plexus topic echo TOPIC --recording RUN.mcap --json` (ECHO_DIR/<topic with / as __>.jsonl).
// Exit 0 when everything matches; otherwise 1, with what differs.
import { McapIndexedReader, McapStreamReader } from "@mcap/core";
import { parseIDL } from "@foxglove/omgidl-parser";
import { MessageReader } from "@foxglove/omgidl-serialization";
import zstd from "@foxglove/wasm-zstd";
import lz4 from "@foxglove/wasm-lz4";
import { open, readFile } from "node:fs/promises";
import { existsSync } from "node:fs";
import path from "node:path";
import { comparer, parseExact } from "./echo_compare.mjs";

const [file, infoFile, echoDir] = process.argv.slice(2);
if (!file || !infoFile || !echoDir) {
  console.error("usage: node mcap_check.mjs RUN.mcap INFO.json ECHO_DIR");
  process.exit(2);
}

const failures = [];
const fail = (what) => {
  if (failures.length < 50) failures.push(what);
};

await zstd.isLoaded;
await lz4.isLoaded;
const handle = await open(file, "r");
const size = (await handle.stat()).size;
const readable = {
  size: async () => BigInt(size),
  read: async (offset, length) => {
    const buf = new Uint8Array(Number(length));
    const { bytesRead } = await handle.read(buf, 0, Number(length), Number(offset));
    if (bytesRead !== Number(length)) throw new Error(`short read at ${offset}`);
    return buf;
  },
};
const reader = await McapIndexedReader.Initialize({
  readable,
  decompressHandlers: {
    zstd: (data, decompressedSize) => zstd.decompress(data, Number(decompressedSize)),
    lz4: (data, decompressedSize) => lz4(data, Number(decompressedSize)),
  },
});
if (!reader.statistics) fail("no statistics record in the summary");

// Every channel's schema parsed, a reader for its root type.
const decoders = new Map();
for (const [id, channel] of reader.channelsById) {
  const schema = reader.schemasById.get(channel.schemaId);
  if (!schema) {
    fail(`channel ${id} (${channel.topic}): no schema`);
    continue;
  }
  if (schema.encoding !== "omgidl") fail(`${channel.topic}: schema encoding ${schema.encoding}, not omgidl`);
  if (channel.messageEncoding !== "cdr") fail(`${channel.topic}: message encoding ${channel.messageEncoding}, not cdr`);
  try {
    const definitions = parseIDL(new TextDecoder().decode(schema.data));
    decoders.set(id, new MessageReader(schema.name, definitions));
  } catch (e) {
    fail(`${channel.topic}: schema ${schema.name} does not parse: ${e.message}`);
  }
}

// Every message decoded; the first ones of each topic kept for the comparison.
const SAMPLE = 25;
const counts = new Map();
const samples = new Map();
let total = 0;
for await (const m of reader.readMessages()) {
  total++;
  counts.set(m.channelId, (counts.get(m.channelId) ?? 0) + 1);
  const decoder = decoders.get(m.channelId);
  if (!decoder) continue;
  let value;
  try {
    value = decoder.readMessage(m.data);
  } catch (e) {
    fail(`${reader.channelsById.get(m.channelId).topic}: message ${m.sequence} does not decode: ${e.message}`);
    continue;
  }
  const kept = samples.get(m.channelId) ?? [];
  if (kept.length < SAMPLE) kept.push(value);
  samples.set(m.channelId, kept);
  if (m.publishTime !== value.header.publish_time_ns) fail(`${reader.channelsById.get(m.channelId).topic}: publish_time ${m.publishTime} is not the header's ${value.header.publish_time_ns}`);
}
await handle.close();

// The whole file record by record, as a streaming reader sees it.
const handlers = {
  zstd: (data, decompressedSize) => zstd.decompress(data, Number(decompressedSize)),
  lz4: (data, decompressedSize) => lz4(data, Number(decompressedSize)),
};
const stream = new McapStreamReader({ validateCrcs: true, decompressHandlers: handlers });
stream.append(await readFile(file));
let streamed = 0;
for (let record; (record = stream.nextRecord()); ) if (record.type === "Message") streamed++;
if (!stream.done()) fail("McapStreamReader: the file does not end with a footer and the magic");
if (streamed !== total) fail(`McapStreamReader read ${streamed} messages, McapIndexedReader ${total}`);

// Counts against `plexus record info --json`.
const info = JSON.parse(await readFile(infoFile, "utf8"));
if (reader.channelsById.size !== info.topics) fail(`channels: McapIndexedReader ${reader.channelsById.size}, plexus ${info.topics}`);
if (BigInt(total) !== BigInt(info.messages)) fail(`messages: read ${total}, plexus ${info.messages}`);
if (reader.statistics && reader.statistics.messageCount !== BigInt(info.messages))
  fail(`statistics record: ${reader.statistics.messageCount} messages, plexus ${info.messages}`);
const byTopic = new Map([...reader.channelsById].map(([id, c]) => [c.topic, id]));
for (const c of info.channels) {
  const id = byTopic.get(c.topic);
  if (id === undefined) fail(`${c.topic}: no such channel`);
  else if ((counts.get(id) ?? 0) !== Number(c.messages)) fail(`${c.topic}: read ${counts.get(id) ?? 0}, plexus ${c.messages}`);
}

// Decoded values against `plexus topic echo --json` (echo_compare.mjs).
const compare = comparer(fail);
let compared = 0;
for (const [topic, id] of byTopic) {
  const echoFile = path.join(echoDir, topic.replaceAll("/", "__") + ".jsonl");
  if (!existsSync(echoFile)) {
    fail(`${topic}: no ${echoFile}`);
    continue;
  }
  const lines = (await readFile(echoFile, "utf8")).split("\n").filter((l) => l.length > 0);
  const got = samples.get(id) ?? [];
  if (lines.length !== Math.min(SAMPLE, counts.get(id) ?? 0)) fail(`${topic}: echo printed ${lines.length} samples`);
  lines.forEach((line, i) => {
    compare(parseExact(line), got[i], `${topic}#${i}`);
    compared++;
  });
}

console.log(
  `${file}: ${reader.channelsById.size} channels, ${reader.schemasById.size} schemas, ${reader.chunkIndexes.length} chunks, ` +
    `${total} messages decoded; ${compared} samples compared with plexus topic echo`,
);
if (failures.length > 0) {
  for (const f of failures) console.error(`MISMATCH ${f}`);
  process.exit(1);
}
