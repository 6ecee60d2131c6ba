#!/usr/bin/env node
// Differential test of `flintstone check` against bench/peers/cgal_check on random triangle
// soups on a small integer grid, where shared, repeated, collinear and coplanar vertices are
// the rule (docs/mesh.md, "Validation on real meshes"). Not part of bench/run.sh.
//
//   node bench/tools/check_random_soups.js FLINTSTONE CGAL_CHECK FIRST_SEED COUNT GRID MAX_TRIANGLES
//
// Prints the seeds whose answers differ (the soup is kept as soup-<seed>.off in the current
// folder) and a summary line. Compared: faces, edges, degenerate faces, closed, self-intersecting
// pairs (CGAL's soup count), non-manifold vertices (unless a face repeats an index: the peer
// does not reorient those), and where CGAL makes a Surface_mesh, components, Euler
// characteristic and genus per component. Genus differs by definition when our answer is
// "not oriented" and CGAL's reorientation succeeded; such seeds are counted apart.
'use strict';
const fs = require('fs');
const { execFileSync } = require('child_process');

const [fl, peer, first, count, grid, maxTri] = process.argv.slice(2);
if (!maxTri) {
  console.error('usage: check_random_soups.js FLINTSTONE CGAL_CHECK FIRST_SEED COUNT GRID MAX_TRIANGLES');
  process.exit(2);
}

function soup(seed) {
  let s = seed; // a small LCG: the same seed gives the same soup everywhere
  const rnd = () => (s = (s * 1103515245 + 12345) % 2147483648) / 2147483648;
  const ri = (n) => Math.floor(rnd() * n);
  const nv = 6 + ri(14), nt = 2 + ri(+maxTri), repeats = rnd() < 0.3;
  const v = [], t = [];
  for (let i = 0; i < nv; i++) v.push([ri(+grid), ri(+grid), ri(+grid)]);
  for (let i = 0; i < nt; i++) {
    let f;
    do f = [ri(nv), ri(nv), ri(nv)];
    while (!repeats && (f[0] === f[1] || f[1] === f[2] || f[0] === f[2]));
    t.push(f);
  }
  return `OFF\n${nv} ${nt} 0\n${v.map((p) => p.join(' ')).join('\n')}\n${t.map((f) => '3 ' + f.join(' ')).join('\n')}\n`;
}

const genusList = (l) => JSON.stringify(l.map((g) => (g === null ? 'open' : g)).sort());

function differences(o, c) {
  const d = [];
  const eq = (k, a, b) => a !== b && d.push(`${k} ${a}/${b}`);
  eq('faces', o.faces, c.faces);
  eq('edges', o.edges, c.edges);
  eq('degenerate', o.degenerate_faces, c.degenerate_faces);
  eq('closed', o.closed, c.closed);
  eq('self_intersections', o.self_intersections, c.soup_self_intersections);
  if (!c.repeated_index_faces) eq('nonmanifold_vertices', o.nonmanifold_vertices, c.nonmanifold_vertices);
  if (c.surface_mesh) {
    eq('components', o.components, c.components);
    eq('euler', o.euler, c.euler);
    eq('pmp_self_intersections', c.self_intersections, c.soup_self_intersections);
    eq('genus', genusList(o.component_genus), genusList(c.component_genus));
  }
  return d;
}

let differ = 0, byDefinition = 0, meshes = 0;
for (let seed = +first; seed < +first + +count; seed++) {
  const path = `soup-${seed}.off`;
  fs.writeFileSync(path, soup(seed));
  const run = (cmd, args) => JSON.parse(execFileSync(cmd, args, { timeout: 30000 }).toString());
  const o = run(fl, ['check', path, '--json']);
  const c = run(peer, [path]);
  meshes += c.surface_mesh ? 1 : 0;
  const d = differences(o, c);
  if (d.length === 1 && d[0].startsWith('genus') && !o.oriented && c.reoriented_without_split) {
    byDefinition++;
    fs.unlinkSync(path);
  } else if (d.length) {
    differ++;
    console.log(`seed ${seed}: ${d.join(', ')}`);
  } else {
    fs.unlinkSync(path);
  }
}
console.log(`${count} soups (grid ${grid}, up to ${+maxTri + 1} triangles): ${differ} differ, ` +
  `${byDefinition} differ only in genus by definition (not oriented), ${meshes} were CGAL Surface_meshes`);
process.exit(differ ? 1 : 0);
