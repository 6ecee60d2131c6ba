#!/usr/bin/env node
// Converts npm's `bunny` package (the Stanford bunny as JS arrays: `positions` [[x,y,z],...]
// and `cells` [[i,j,k],...], 0-based) into our formats:
//   node bunny_convert.js PACKAGE_DIR OUT_PREFIX
// writes OUT_PREFIX.off, OUT_PREFIX.ply (binary little endian, double coordinates) and
// OUT_PREFIX.xyz (the vertices alone, a point set).
'use strict';
const fs = require('fs');
const path = require('path');

const [pkgDir, prefix] = process.argv.slice(2);
if (!pkgDir || !prefix) {
  console.error('usage: bunny_convert.js PACKAGE_DIR OUT_PREFIX');
  process.exit(2);
}
const { positions, cells } = require(path.resolve(pkgDir));
for (const c of cells) {
  if (c.length !== 3 || c.some((i) => !(i >= 0 && i < positions.length))) {
    throw new Error(`bunny: face ${JSON.stringify(c)} is not a triangle of valid indices`);
  }
}

// Numbers are written with JS's shortest round-trip formatting, so the text files hold exactly
// the doubles the package holds.
const xyzLines = positions.map((p) => p.join(' '));
fs.writeFileSync(`${prefix}.xyz`, xyzLines.join('\n') + '\n');
fs.writeFileSync(`${prefix}.off`, [`OFF`, `${positions.length} ${cells.length} 0`,
  ...xyzLines, ...cells.map((c) => `3 ${c.join(' ')}`)].join('\n') + '\n');

const header = Buffer.from(['ply', 'format binary_little_endian 1.0',
  'comment Stanford bunny from the npm package `bunny`',
  `element vertex ${positions.length}`,
  'property double x', 'property double y', 'property double z',
  `element face ${cells.length}`, 'property list uchar int vertex_indices', 'end_header', ''].join('\n'));
const body = Buffer.alloc(positions.length * 24 + cells.length * 13);
let o = 0;
for (const p of positions) for (const x of p) { body.writeDoubleLE(x, o); o += 8; }
for (const c of cells) {
  body.writeUInt8(3, o); o += 1;
  for (const i of c) { body.writeInt32LE(i, o); o += 4; }
}
fs.writeFileSync(`${prefix}.ply`, Buffer.concat([header, body]));
console.log(`bunny: ${positions.length} vertices, ${cells.length} triangles -> ${prefix}.{off,ply,xyz}`);
