// laz-perf's decoding speed (hobuinc/laz-perf, WebAssembly from npm: scripts/fetch-laz-perf) on a
// LAZ file, for docs/preparer.md's comparison with octopoint's decoder (prepare_bench
// BM_DecodeLandscape writes the same landscape files). One run, one thread; laz-perf's API decodes
// a point per JavaScript call, which is counted in.
// usage: node bench/laz_perf_speed.cjs build/node/node_modules FILE.laz
'use strict';
const fs = require('fs');
const path = require('path');

const [modules, lazPath] = process.argv.slice(2);
const { createLazPerf } = require(path.join(modules, 'laz-perf'));

(async () => {
  const lazPerf = await createLazPerf();
  const laz = fs.readFileSync(lazPath);
  const filePointer = lazPerf._malloc(laz.length);
  lazPerf.HEAPU8.set(laz, filePointer);
  const start = process.hrtime.bigint();
  const reader = new lazPerf.LASZip();
  reader.open(filePointer, laz.length);
  const count = reader.getCount();
  const point = lazPerf._malloc(reader.getPointLength());
  for (let i = 0; i < count; ++i) reader.getPoint(point);
  const seconds = Number(process.hrtime.bigint() - start) / 1e9;
  console.log(`${lazPath}: laz-perf decodes ${count} points in ${seconds.toFixed(2)} s, ` +
              `${(count / seconds / 1e6).toFixed(2)} M points/s`);
})();
