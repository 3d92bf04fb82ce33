// Compares a value a third-party decoder produced with what `plexus topic echo --json`
// printed for the same sample (tests/ecosystem: mcap_check.mjs, ros2_check.mjs).
//   const compare = comparer(fail); compare(parseExact(line), decoded, "r1/position#0");
// 64-bit integers are kept exact (as strings on plexus's side, BigInt on the decoder's);
// char[N] prints as a string on plexus's side and decodes as bytes; everything else must be
// equal, field names and order included.

/** One line of `topic echo --json`, with its 64-bit integers as strings. */
export const parseExact = (line) => JSON.parse(line.replace(/([:\[,]\s*)(-?\d{16,})(?=\s*[,\]}])/g, '$1"$2"'));

/** A char[N] or uint8[N] as the text up to its first NUL. */
export const text = (v) => {
  const bytes = Array.from(v);
  const end = bytes.indexOf(0);
  return new TextDecoder().decode(Uint8Array.from(end < 0 ? bytes : bytes.slice(0, end)));
};

/** compare(expected, actual, where): calls fail(what) for every difference. */
export function comparer(fail) {
  const compare = (expected, actual, where) => {
    if (typeof expected === "string") {
      if (typeof actual === "bigint") return String(actual) === expected || fail(`${where}: ${actual} != ${expected}`);
      if (typeof actual === "string") return actual === expected || fail(`${where}: "${actual}" != "${expected}"`);
      if (actual && typeof actual.length === "number")
        return text(actual) === expected || fail(`${where}: "${text(actual)}" != "${expected}"`);
      return fail(`${where}: ${typeof actual} where plexus has a string`);
    }
    if (typeof expected === "number") {
      const a = typeof actual === "bigint" ? Number(actual) : actual;
      return a === expected || (Number.isNaN(a) && Number.isNaN(expected)) || fail(`${where}: ${actual} != ${expected}`);
    }
    if (Array.isArray(expected)) {
      if (!actual || actual.length !== expected.length)
        return fail(`${where}: ${actual?.length} elements, plexus ${expected.length}`);
      expected.forEach((e, i) => compare(e, actual[i], `${where}[${i}]`));
      return;
    }
    if (expected && typeof expected === "object") {
      const keys = Object.keys(expected);
      const got = Object.keys(actual ?? {});
      if (keys.join() !== got.join()) return fail(`${where}: fields ${got.join()} != plexus ${keys.join()}`);
      for (const k of keys) compare(expected[k], actual[k], `${where}.${k}`);
      return;
    }
    return expected === actual || fail(`${where}: ${actual} != ${expected}`);
  };
  return compare;
}
