#!/usr/bin/env node
// Compares `flintstone check --json` with bench/peers/cgal_check on the same files and prints a
// Markdown summary and table (bench/workloads/check_mesh.sh writes it to
// bench/out/check_validation.md; docs/mesh.md, "Validation on real meshes", holds a copy).
//
//   node bench/mesh_check_compare.js OURS.jsonl CGAL.jsonl
//
// Each input line is "<file>\t<JSON>"; ours may be "<file>\tERROR\t<message>" when our reader
// rejected the file. A property is compared only where both sides define it the same way:
//  - counts (vertices, faces, edges, degenerate faces), closed, area: always (CGAL's figures
//    are from the soup, so every file that reads has them);
//  - manifold: CGAL's soup is manifold when no edge has three or more faces and
//    orient_polygon_soup did not have to duplicate a point (ours: no non-manifold edge or vertex);
//  - components, Euler characteristic, genus, self-intersections (PMP::self_intersections),
//    volume: when CGAL holds the soup as a Surface_mesh. Components must then agree although
//    the definitions differ: ours join triangles through shared vertices, CGAL's through shared
//    edges, and the two differ only at a non-manifold vertex, which a Surface_mesh cannot have.
//    When CGAL cannot, but the soup cut at its singular vertices is a mesh, ours must equal the
//    cut mesh's V - E + F minus the points added, and the cut mesh's components joined again
//    at the copied points; its components through edges alone may outnumber ours (marked as a
//    definition difference);
//  - self-intersections on the soup (the peer's soup_self_intersections): every file.
//  - genus and volume: ours are undefined (null) for a mesh that is not consistently oriented,
//    while CGAL reorients the soup first; such a pair is marked as a definition difference.
'use strict';
const fs = require('fs');

const REL_TOL = 1e-9;

// What each compared property is, as the summary table names it.
const LABELS = {
  vertices: 'vertices',
  faces: 'faces (after fan triangulation)',
  edges: 'edges',
  degenerate_faces: 'degenerate faces',
  closed: 'closed',
  manifold: 'manifold',
  nonmanifold_vertices: 'non-manifold vertices (CGAL: orient_polygon_soup)',
  oriented: 'oriented (manifold files)',
  area: 'area (rel. diff ≤ 1e-9)',
  self_intersections_soup: 'self-intersecting pairs (CGAL predicates on the soup)',
  pmp_vs_soup_self_intersections: 'CGAL consistency: PMP::self_intersections = soup count',
  mesh_closed: 'CGAL consistency: is_closed = closed soup',
  components: 'components',
  euler: 'Euler characteristic',
  genus: 'genus per component',
  self_intersections: 'self-intersecting pairs (PMP::self_intersections)',
  volume: 'volume (rel. diff ≤ 1e-9)',
  edge_components: 'components through edges only (CGAL cut mesh)',
}; // area and volume are floating-point sums in different orders

function readLines(path) {
  const out = new Map();
  for (const line of fs.readFileSync(path, 'utf8').split('\n')) {
    if (!line) continue;
    const [file, a, b] = line.split('\t');
    if (a === 'ERROR') out.set(file, { error: b.trim() });
    else if (!a) out.set(file, { error: 'no output (crashed?)' });
    else out.set(file, JSON.parse(a));
  }
  return out;
}

const relDiff = (a, b) => (a === b ? 0 : Math.abs(a - b) / Math.max(Math.abs(a), Math.abs(b)));
const genusList = (list) => (list || []).map((g) => (g === null ? 'open' : g)).sort().join(',');
const genusShown = (list) =>
  !list || list.length === 0 || list.some((g) => g === null) ? '–' : list.reduce((s, g) => s + g, 0);
const yn = (b) => (b ? 'yes' : 'no');
const short = (f) => f.replace(/^cgal\/data\/meshes\//, '').replace(/^cgal\/data\//, '');
const fmtRel = (r) => (r === 0 ? '0' : r.toExponential(0));

// One file: every property as {ours, cgal, status} with status 'ok', 'DIFF', 'def' (definition
// difference, explained), or 'n/a' (one side does not define it for this file).
function compare(o, c) {
  const p = {};
  const put = (key, ours, cgal, status) => (p[key] = { ours, cgal, status });
  const eq = (key, a, b) => put(key, a, b, a === b ? 'ok' : 'DIFF');
  for (const k of ['vertices', 'faces', 'edges', 'degenerate_faces']) eq(k, o[k], c[k]);
  eq('closed', o.closed, c.closed);
  const cgalManifold = c.nonmanifold_edges === 0 && (c.polygon_mesh_as_given || c.reoriented_without_split);
  if (c.repeated_index_faces > 0) {
    // The peer does not reorient such soups (see cgal_check.cpp), so CGAL says nothing here.
    put('manifold', o.manifold, null, 'n/a');
    put('nonmanifold_vertices', o.nonmanifold_vertices, null, 'n/a');
  } else {
    eq('manifold', o.manifold, cgalManifold);
    eq('nonmanifold_vertices', o.nonmanifold_vertices, c.nonmanifold_vertices);
  }
  if (o.manifold && cgalManifold) eq('oriented', o.oriented, c.polygon_mesh_as_given);
  const ca = c.area !== undefined ? c.area : c.soup_area; // PMP::area when CGAL has a mesh
  put('area', o.area, ca, relDiff(o.area, ca) <= REL_TOL ? 'ok' : 'DIFF');
  // Every file: CGAL's predicates on the soup, pairs decided as PMP decides them (the peer's
  // soup_self_intersections); where PMP::self_intersections ran too, the two must agree.
  eq('self_intersections_soup', o.self_intersections, c.soup_self_intersections);
  if (!c.surface_mesh) {
    // CGAL cut the soup at its singular vertices: the pieces' V - E + F is ours plus the points
    // it added; its components (through edges) may be more than ours (through vertices).
    // The relation holds when the cut is at vertices only, i.e. orient_polygon_soup did not also
    // cut along edges: no edge with three or more faces and an orientation it keeps.
    if (c.split_euler !== undefined && o.oriented && o.nonmanifold_edges === 0) {
      eq('euler', o.euler, c.split_euler - c.points_duplicated);
      eq('components', o.components, c.split_components_joined);
      put('edge_components', o.components, c.split_components, o.components === c.split_components ? 'ok' : 'def');
    } else {
      for (const k of ['components', 'euler']) put(k, o[k], null, 'n/a');
    }
    for (const k of ['genus', 'self_intersections', 'volume']) put(k, o[k], null, 'n/a');
    return p;
  }
  eq('pmp_vs_soup_self_intersections', c.self_intersections, c.soup_self_intersections);
  eq('mesh_closed', c.closed, c.mesh_closed);
  eq('components', o.components, c.components);
  eq('euler', o.euler, c.euler);
  const og = genusList(o.component_genus), cg = genusList(c.component_genus);
  if (og === cg) put('genus', og, cg, 'ok');
  else if (!o.oriented && c.reoriented_without_split) put('genus', og, cg, 'def');
  else put('genus', og, cg, 'DIFF');
  eq('self_intersections', o.self_intersections, c.self_intersections);
  if (o.volume === null && c.volume === null) put('volume', null, null, 'ok');
  else if (o.volume === null && !o.oriented && c.reoriented_without_split) put('volume', null, c.volume, 'def');
  else if (o.volume === null || c.volume === null) put('volume', o.volume, c.volume, 'DIFF');
  else {
    // CGAL's reorientation may flip the whole surface, so compare magnitudes only then.
    const ov = c.polygon_mesh_as_given ? o.volume : Math.abs(o.volume);
    const cv = c.polygon_mesh_as_given ? c.volume : Math.abs(c.volume);
    put('volume', o.volume, c.volume, relDiff(ov, cv) <= REL_TOL ? 'ok' : 'DIFF');
    p.volume.rel = relDiff(ov, cv);
  }
  return p;
}

function main() {
  const [oursPath, cgalPath] = process.argv.slice(2);
  const ours = readLines(oursPath), cgal = readLines(cgalPath);
  const rows = [], tally = new Map(), notes = [];
  let allAgree = 0, readErrors = 0;
  for (const [file, o] of ours) {
    const c = cgal.get(file) || { error: 'missing' };
    if (o.error || c.error) {
      readErrors++;
      rows.push(`| ${short(file)} | ${c.faces ?? '–'} | | | | | | | | read: ours ${o.error ? 'error' : 'ok'}, CGAL ${c.error ? 'error' : 'ok'} |`);
      notes.push(`- ${short(file)}: ours: ${o.error || 'read'}; CGAL: ${c.error || 'read'}`);
      continue;
    }
    const p = compare(o, c);
    for (const [k, v] of Object.entries(p)) {
      const t = tally.get(k) || { ok: 0, DIFF: 0, def: 0, 'n/a': 0 };
      t[v.status]++;
      tally.set(k, t);
    }
    const diffs = Object.keys(p).filter((k) => p[k].status === 'DIFF');
    const defs = Object.keys(p).filter((k) => p[k].status === 'def');
    const na = !c.surface_mesh;
    if (diffs.length === 0) allAgree++;
    let verdict = diffs.length ? `**no**: ${diffs.join(', ')}` : 'yes';
    if (defs.length) verdict += ` (definitions: ${defs.join(', ')})`;
    if (na) verdict += ' (CGAL: no Surface_mesh)';
    const pair = (k, f = (x) => x) => (p[k] ? `${f(p[k].ours)} / ${p[k].status === 'n/a' ? '–' : f(p[k].cgal)}` : '–');
    // Where CGAL has no Surface_mesh, its figures come from the soup or the cut mesh: marked *.
    const star = na ? '*' : '';
    const man = `${yn(o.manifold)} / ${p.manifold.status === 'n/a' ? '–' : yn(p.manifold.cgal)}`;
    const genus = na ? `${genusShown(o.component_genus)} / –` : `${genusShown(o.component_genus)} / ${genusShown(c.component_genus)}`;
    const vol = p.volume && p.volume.rel !== undefined ? fmtRel(p.volume.rel) : '–';
    const comps = p.edge_components && p.edge_components.status === 'def'
      ? `${pair('components')}* (${p.edge_components.cgal} through edges)` : `${pair('components')}${star}`;
    rows.push(`| ${short(file)} | ${o.faces} | ${pair('closed', yn)} | ${man} | ${comps} | ` +
      `${pair('euler')}${star} | ${genus} | ${pair('self_intersections_soup')}${star} | ${vol} | ${verdict} |`);
  }

  const total = ours.size;
  console.log(`${total} files; both read ${total - readErrors}; every compared property agrees on ${allAgree}.`);
  console.log('');
  console.log('| property | agree | differ | definition difference | not comparable |');
  console.log('|---|---:|---:|---:|---:|');
  for (const [k, t] of tally) console.log(`| ${LABELS[k] || k} | ${t.ok} | ${t.DIFF} | ${t.def} | ${t['n/a']} |`);
  console.log('');
  if (notes.length) {
    console.log('Files one side could not read:');
    console.log('');
    for (const n of notes) console.log(n);
    console.log('');
  }
  console.log('| file | faces | closed ours/CGAL | manifold ours/CGAL | components ours/CGAL | χ ours/CGAL | ' +
    'genus ours/CGAL | self-int. pairs ours/CGAL | volume rel. diff | agree? |');
  console.log('|---|---:|---|---|---|---|---|---|---:|---|');
  for (const r of rows) console.log(r);
}

main();
