// An independent decoder for the LAZ files octopoint writes (tests/support/laz_encoder.h):
// laz-perf (hobuinc/laz-perf, WebAssembly, from npm: scripts/fetch-laz-perf) decodes LAZ and every
// record must equal the record of the LAS file written from the same points.
// usage: node laz_perf_decode.cjs NODE_MODULES FILE.laz FILE.las
// Exits 0 when every record is equal, 1 with one line saying where they differ, 77 (a skip) when
// laz-perf is not installed.
'use strict';
const fs = require('fs');
const path = require('path');

const [modules, lazPath, lasPath] = process.argv.slice(2);
let createLazPerf;
try {
  ({ createLazPerf } = require(path.join(modules, 'laz-perf')));
} catch (error) {
  console.error(`laz-perf is not installed in ${modules} (scripts/fetch-laz-perf)`);
  process.exit(77);
}

// The LAS file's records, from its header (point offset, record length; the count of LAS 1.4,
// 64-bit, whose legacy 32-bit count is 0 for point formats 6 to 10).
function lasRecords(bytes) {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const offset = view.getUint32(96, true);
  const length = view.getUint16(105, true);
  const minor = view.getUint8(25);
  const count = minor >= 4 ? Number(view.getBigUint64(247, true)) : view.getUint32(107, true);
  return { offset, length, count, bytes };
}

(async () => {
  const lazPerf = await createLazPerf();
  const laz = fs.readFileSync(lazPath);
  const las = lasRecords(fs.readFileSync(lasPath));
  const filePointer = lazPerf._malloc(laz.length);
  lazPerf.HEAPU8.set(laz, filePointer);
  const reader = new lazPerf.LASZip();
  reader.open(filePointer, laz.length);
  const count = reader.getCount();
  const length = reader.getPointLength();
  if (count !== las.count || length !== las.length) {
    console.error(`${lazPath}: laz-perf reads ${count} points of ${length} bytes, ` +
                  `${lasPath} has ${las.count} of ${las.length}`);
    process.exit(1);
  }
  const point = lazPerf._malloc(length);
  for (let i = 0; i < count; ++i) {
    reader.getPoint(point);
    const decoded = lazPerf.HEAPU8.subarray(point, point + length);
    const start = las.offset + i * length;
    const expected = las.bytes.subarray(start, start + length);
    if (Buffer.compare(Buffer.from(decoded), expected) !== 0) {
      console.error(`${lazPath}: laz-perf decodes point ${i} as ${Buffer.from(decoded).toString('hex')}, ` +
                    `${lasPath} has ${expected.toString('hex')}`);
      process.exit(1);
    }
  }
  console.log(`${lazPath}: laz-perf decodes all ${count} points of ${length} bytes as in ${lasPath}`);
  process.exit(0);
})();
