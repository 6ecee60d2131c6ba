#!/usr/bin/env node
// A small TopoJSON decoder (our own, for npm's `world-atlas`): one object of a topology to
// GeoJSON polygons and to our .xy rings.
//   node topojson_decode.js TOPOLOGY.json OBJECT OUT_PREFIX
// writes OUT_PREFIX.geojson (a FeatureCollection; every Polygon/MultiPolygon keeps its holes)
// and OUT_PREFIX.xy (the outer rings only, one block each, since .xy has no notion of holes).
//
// TopoJSON stores each shared border once as an "arc"; a ring lists the arcs it is made of,
// with ~i (= -i-1) meaning arc i walked backwards. With a "transform", arc positions are
// integers on a grid, each one a delta from the previous position of the same arc.
'use strict';
const fs = require('fs');

function decodeArcs(topology) {
  const t = topology.transform;
  return topology.arcs.map((arc) => {
    let x = 0, y = 0;
    return arc.map((p) => {
      if (!t) return [p[0], p[1]];
      x += p[0];
      y += p[1];
      return [x * t.scale[0] + t.translate[0], y * t.scale[1] + t.translate[1]];
    });
  });
}

// Consecutive arcs of a ring share their end point: keep it once.
function stitchRing(arcs, indices) {
  const ring = [];
  for (const i of indices) {
    const arc = i >= 0 ? arcs[i] : arcs[~i].slice().reverse();
    if (ring.length) ring.pop();
    for (const p of arc) ring.push(p);
  }
  return ring; // closed: first position == last, as GeoJSON wants
}

// Twice the signed area (shoelace); positive for counter-clockwise in the lon/lat plane.
function signedArea2(ring) {
  let a = 0;
  for (let i = 0; i + 1 < ring.length; i++) {
    a += ring[i][0] * ring[i + 1][1] - ring[i + 1][0] * ring[i][1];
  }
  return a;
}

// RFC 7946 §3.1.6: exterior rings counter-clockwise, holes clockwise. world-atlas follows
// d3's spherical convention (the opposite), so rings are re-oriented here.
function polygon(arcs, ringIndices) {
  return ringIndices.map((indices, k) => {
    const ring = stitchRing(arcs, indices);
    const ccw = signedArea2(ring) > 0;
    return ccw === (k === 0) ? ring : ring.reverse();
  });
}

function decodeObject(topology, name) {
  const object = topology.objects[name];
  if (!object) throw new Error(`no object "${name}" in the topology`);
  const arcs = decodeArcs(topology);
  const geometries = object.type === 'GeometryCollection' ? object.geometries : [object];
  const features = [];
  for (const g of geometries) {
    let geometry;
    if (g.type === 'Polygon') {
      geometry = { type: 'Polygon', coordinates: polygon(arcs, g.arcs) };
    } else if (g.type === 'MultiPolygon') {
      geometry = { type: 'MultiPolygon', coordinates: g.arcs.map((p) => polygon(arcs, p)) };
    } else {
      continue; // points, lines and null geometries are not polygons
    }
    features.push({ type: 'Feature', id: g.id, properties: g.properties || {}, geometry });
  }
  return { type: 'FeatureCollection', features };
}

function polygonsOf(feature) {
  const g = feature.geometry;
  return g.type === 'Polygon' ? [g.coordinates] : g.coordinates;
}

function main() {
  const [input, objectName, prefix] = process.argv.slice(2);
  if (!input || !objectName || !prefix) {
    console.error('usage: topojson_decode.js TOPOLOGY.json OBJECT OUT_PREFIX');
    process.exit(2);
  }
  const collection = decodeObject(JSON.parse(fs.readFileSync(input, 'utf8')), objectName);
  fs.writeFileSync(`${prefix}.geojson`, JSON.stringify(collection) + '\n');

  // .xy rings are closed implicitly: drop the repeated first position.
  const blocks = [];
  let polygons = 0, holes = 0, vertices = 0;
  for (const f of collection.features) {
    for (const rings of polygonsOf(f)) {
      polygons++;
      holes += rings.length - 1;
      for (const r of rings) vertices += r.length - 1;
      blocks.push(rings[0].slice(0, -1).map((p) => `${p[0]} ${p[1]}`).join('\n'));
    }
  }
  fs.writeFileSync(`${prefix}.xy`, blocks.join('\n\n') + '\n');
  console.log(`${objectName}: ${collection.features.length} features, ${polygons} polygons, ` +
    `${holes} holes, ${vertices} vertices -> ${prefix}.{geojson,xy}`);
}

main();
