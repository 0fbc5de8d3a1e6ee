// mcap_decoders.mjs: rodshape's MCAP files read by the decoders Foxglove uses (issue 49, item 2):
// @mcap/core (the stream reader with its CRC checks, and the indexed reader through the summary,
// the chunk indexes and the message indexes), @foxglove/rosmsg (the ros2msg schemas) and
// @foxglove/rosmsg2-serialization (CDR), with fzstd for zstd chunks. For each output directory
// given (one of `rodshape plan|validate --mcap`), its plan.mcap or validation.mcap:
//   - the header's profile is ros2, every schema is ros2msg and parses, every channel is cdr;
//   - both readers see the same messages, as many as the statistics count, per channel too; the
//     data section's CRC (Data End) is that of the bytes before it;
//   - every message deserialises, with no byte left over, and serialises back to the same bytes;
//   - /rodshape/joint_trajectory (with joint_trajectory.csv) equals the CSV to the digits written
//     (12 significant), its times to the nanosecond, and /joint_states has a message per sample;
//     likewise /rodshape/base_joint_trajectory, base_joint_trajectory.csv, /base_arm/joint_states;
//   - /rodshape/rod has the initial shape and each step's, whose rod points equal plan.json's
//     shapes (initial.nodes.position, steps[k].configuration.nodes.position) exactly;
//   - validation.mcap: /camera/points clouds are whole (data = width × point_step bytes).
// Usage: node mcap_decoders.mjs --modules PREFIX OUTDIR...   (PREFIX/node_modules holds the
// packages: npm install --prefix PREFIX @mcap/core @foxglove/rosmsg @foxglove/rosmsg2-serialization
// fzstd). Exit 0: all good; 1: a check failed; 77: the packages are missing (ctest's skip).
import { readFileSync, existsSync } from "node:fs";
import { createRequire } from "node:module";
import { join, basename } from "node:path";

const args = process.argv.slice(2);
const at = args.indexOf("--modules");
if (at < 0 || at + 1 >= args.length || args.length < 3) {
  console.error("usage: node mcap_decoders.mjs --modules PREFIX OUTDIR...");
  process.exit(2);
}
const prefix = args[at + 1];
const directories = args.filter((_, i) => i !== at && i !== at + 1);
const packages = ["@mcap/core", "@foxglove/rosmsg", "@foxglove/rosmsg2-serialization", "fzstd"];
const require = createRequire(join(prefix, "node_modules", "resolver.js"));
const loaded = {};
for (const name of packages) {
  try {
    loaded[name] = require(name);
  } catch {
    console.log(
      `SKIP: npm package ${name} is not installed in ${prefix}/node_modules; install the ` +
        `decoders with: npm install --prefix ${prefix} ${packages.join(" ")}`,
    );
    process.exit(77);
  }
}
const { McapStreamReader, McapIndexedReader } = loaded["@mcap/core"];
const { parse } = loaded["@foxglove/rosmsg"];
const { MessageReader, MessageWriter } = loaded["@foxglove/rosmsg2-serialization"];
const { decompress } = loaded["fzstd"];
const crc32 = require("@foxglove/crc").crc32; // @mcap/core's own dependency

let failures = 0;
function check(condition, where, what) {
  if (!condition) {
    failures += 1;
    console.error(`FAIL ${where}: ${what}`);
  }
  return condition;
}

const decompressHandlers = {
  zstd: (data, size) => decompress(data, new Uint8Array(Number(size))),
};

function sameBytes(a, b) {
  if (a.byteLength !== b.byteLength) return false;
  for (let i = 0; i < a.byteLength; i++) if (a[i] !== b[i]) return false;
  return true;
}

/// Number(value) as C++'s ostream prints it with setprecision(12): 12 significant digits.
const digits12 = (value) => Number(value.toPrecision(12));

function readCsv(path) {
  const lines = readFileSync(path, "utf8").trim().split("\n");
  return { header: lines[0].split(","), rows: lines.slice(1).map((l) => l.split(",").map(Number)) };
}

async function checkFile(directory) {
  const name = existsSync(join(directory, "validation.mcap")) ? "validation.mcap" : "plan.mcap";
  const path = join(directory, name);
  const where = `${basename(directory)}/${name}`;
  if (!check(existsSync(path), where, "no MCAP file")) return;
  const bytes = new Uint8Array(readFileSync(path));

  // The stream reader: every record in file order, chunk CRCs checked.
  const stream = new McapStreamReader({ validateCrcs: true, decompressHandlers });
  stream.append(bytes);
  const schemas = new Map();
  const channels = new Map();
  const streamed = [];
  let header;
  let footer;
  let compression = "";
  for (let record; (record = stream.nextRecord()); ) {
    if (record.type === "Header") header = record;
    else if (record.type === "Schema") schemas.set(record.id, record);
    else if (record.type === "Channel") channels.set(record.id, record);
    else if (record.type === "Message") streamed.push(record);
    else if (record.type === "Footer") footer = record;
    else if (record.type === "DataEnd") {
      // Data End is the last record before the summary: 1 + 8 + 4 bytes.
      const dataEnd = Number(footerStart(bytes)) - 13;
      check(record.dataSectionCrc === crc32(bytes.subarray(0, dataEnd)), where,
            `data section CRC ${record.dataSectionCrc} is not that of its ${dataEnd} bytes`);
    }
  }
  check(stream.done(), where, "the stream reader did not reach the end");
  check(header?.profile === "ros2", where, `profile ${header?.profile}`);
  check(header?.library.startsWith("rodshape"), where, `library ${header?.library}`);
  check(footer && footer.summaryStart > 0n, where, "no summary section");

  // The indexed reader: the summary (its CRC checked), chunk indexes and message indexes.
  const indexed = await McapIndexedReader.Initialize({
    readable: {
      size: async () => BigInt(bytes.byteLength),
      read: async (offset, size) => bytes.subarray(Number(offset), Number(offset + size)),
    },
    decompressHandlers,
  });
  const viaIndex = [];
  for await (const message of indexed.readMessages()) viaIndex.push(message);
  const stats = indexed.statistics;
  check(stats && stats.messageCount === BigInt(streamed.length), where,
        `statistics count ${stats?.messageCount} messages, the stream has ${streamed.length}`);
  check(viaIndex.length === streamed.length, where,
        `the indexes reach ${viaIndex.length} messages, the stream has ${streamed.length}`);
  for (const [id, count] of stats?.channelMessageCounts ?? []) {
    const seen = viaIndex.filter((m) => m.channelId === id).length;
    check(BigInt(seen) === count, where, `channel ${id}: ${seen} messages indexed, ${count} counted`);
  }
  for (const chunk of indexed.chunkIndexes) compression = chunk.compression || "none";
  check(indexed.schemasById.size === schemas.size && indexed.channelsById.size === channels.size,
        where, "the summary's schemas or channels differ from the data section's");

  // Every schema parses; every message deserialises whole and serialises back to its bytes.
  const codecs = new Map();
  for (const [id, schema] of schemas) {
    check(schema.encoding === "ros2msg", where, `schema ${schema.name}: encoding ${schema.encoding}`);
    try {
      const definitions = parse(new TextDecoder().decode(schema.data), { ros2: true });
      codecs.set(id, { reader: new MessageReader(definitions), writer: new MessageWriter(definitions) });
    } catch (error) {
      check(false, where, `schema ${schema.name} does not parse: ${error.message}`);
    }
  }
  const byTopic = new Map();
  for (const message of streamed) {
    const channel = channels.get(message.channelId);
    check(channel.messageEncoding === "cdr", where, `${channel.topic}: ${channel.messageEncoding}`);
    const codec = codecs.get(channel.schemaId);
    if (!codec) continue;
    let decoded;
    try {
      decoded = codec.reader.readMessage(message.data);
    } catch (error) {
      check(false, where, `${channel.topic} at ${message.logTime}: ${error.message}`);
      continue;
    }
    check(!codec.reader.lastReadHadTrailingBytes(), where,
          `${channel.topic} at ${message.logTime}: bytes left after the message`);
    check(sameBytes(codec.writer.writeMessage(decoded), message.data), where,
          `${channel.topic} at ${message.logTime}: serialised back, the bytes differ`);
    if (!byTopic.has(channel.topic)) byTopic.set(channel.topic, []);
    byTopic.get(channel.topic).push({ time: message.logTime, message: decoded });
  }
  for (const topic of ["/tf", "/rodshape/rod"])
    check(byTopic.has(topic), where, `no ${topic} messages`);

  // The joint trajectories against joint_trajectory.csv (base_joint_trajectory.csv), to the
  // digits written, and a joint state per sample.
  const notes = [];
  for (const [file, topic, states] of [
    ["joint_trajectory.csv", "/rodshape/joint_trajectory", "/joint_states"],
    ["base_joint_trajectory.csv", "/rodshape/base_joint_trajectory", "/base_arm/joint_states"],
  ]) {
    const csvPath = join(directory, file);
    if (!existsSync(csvPath)) {
      check(!byTopic.has(topic), where, `${topic} without ${file}`);
      continue;
    }
    const csv = readCsv(csvPath);
    const trajectories = byTopic.get(topic) ?? [];
    if (!check(trajectories.length === 1, where, `${trajectories.length} messages on ${topic}`))
      continue;
    const trajectory = trajectories[0].message;
    check(JSON.stringify(trajectory.joint_names) === JSON.stringify(csv.header.slice(1)), where,
          `${topic}: joint names ${trajectory.joint_names} against ${file}'s ${csv.header.slice(1)}`);
    check(trajectory.points.length === csv.rows.length, where,
          `${topic}: ${trajectory.points.length} points, ${file} has ${csv.rows.length} rows`);
    const t0 = csv.rows[0][0];
    let worst = 0;
    trajectory.points.forEach((point, i) => {
      const row = csv.rows[i] ?? [];
      const t = point.time_from_start.sec + point.time_from_start.nanosec * 1e-9 + t0;
      worst = Math.max(worst, Math.abs(t - row[0]));
      check(Math.abs(t - row[0]) <= 1e-9 + 1e-12 * Math.abs(row[0]), where,
            `${topic} point ${i}: time ${t} against ${file}'s ${row[0]}`);
      point.positions.forEach((q, j) =>
        check(digits12(q) === row[j + 1], where,
              `${topic} point ${i}, ${csv.header[j + 1]}: ${q} against ${file}'s ${row[j + 1]}`));
    });
    const stateCount = (byTopic.get(states) ?? []).length;
    check(stateCount === csv.rows.length, where,
          `${stateCount} messages on ${states} for ${csv.rows.length} samples`);
    notes.push(`${topic} = ${file} (${csv.rows.length} samples, times within ` +
               `${worst.toExponential(1)} s)`);
  }

  // The rod's shapes against plan.json's.
  const plan = JSON.parse(readFileSync(join(directory, "plan.json"), "utf8"));
  const shapes = [plan.initial.nodes.position,
                  ...plan.steps.map((step) => step.configuration.nodes.position)];
  const rods = byTopic.get("/rodshape/rod") ?? [];
  check(rods.length === shapes.length, where,
        `${rods.length} rod messages, plan.json has ${shapes.length} shapes`);
  rods.forEach(({ message }, k) => {
    const rod = message.markers.find((m) => m.ns === "rod");
    if (!check(rod, where, `rod message ${k} has no "rod" marker`)) return;
    const expected = shapes[k] ?? [];
    check(rod.points.length === expected.length, where,
          `shape ${k}: ${rod.points.length} points, plan.json has ${expected.length}`);
    rod.points.forEach((p, i) =>
      check(p.x === expected[i]?.[0] && p.y === expected[i]?.[1] && p.z === expected[i]?.[2], where,
            `shape ${k}, node ${i}: (${p.x}, ${p.y}, ${p.z}) against plan.json's ${expected[i]}`));
  });
  notes.push(`${rods.length} rod shapes = plan.json's`);

  for (const { message } of byTopic.get("/camera/points") ?? [])
    check(message.data.length === message.width * message.point_step, where,
          `a cloud of ${message.width} points has ${message.data.length} bytes`);
  if (name === "validation.mcap")
    check(byTopic.has("/camera/points") || byTopic.has("/rodshape/markers_measured"), where,
          "a validation without /camera/points or /rodshape/markers_measured");

  const topics = [...byTopic.entries()].map(([topic, list]) => `${topic} ${list.length}`);
  console.log(`${where}: ${schemas.size} schemas parsed, ${streamed.length} messages decoded ` +
              `(${compression}; ${topics.join(", ")}); ${notes.join("; ")}`);
}

/// The footer's summary_start: the footer is the 29 bytes before the closing 8-byte magic.
function footerStart(bytes) {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  return view.getBigUint64(bytes.byteLength - 8 - 20, true);
}

for (const directory of directories) {
  try {
    await checkFile(directory);
  } catch (error) {
    check(false, directory, error.stack ?? String(error));
  }
}
if (failures > 0) {
  console.error(`mcap_decoders: ${failures} check(s) failed`);
  process.exit(1);
}
console.log(`mcap_decoders: ${directories.length} MCAP file(s) decoded, every check passed`);
