// scripts/rapier/peer.mjs - Rapier's shape queries (its WebAssembly build, f32) for `cdref peers`.
// src/peers/rapier.hpp runs it with node and talks to it a line at a time on its standard input
// and output: a request is an operation and its numbers (the case's columns rounded to float, as
// decimals that read back exactly), the reply the answer's numbers ("ok" first), or "error" and a
// message. The numbers are parsed as numbers and nothing else: no request text is evaluated.
//   rs s d c r          Ball(r) at c, castRayAndGetNormal(Ray(s, d), solid)  -> hit toi nx ny nz
//   rb s d c h          Cuboid(h) at c, the same                              -> hit toi nx ny nz
//   rt s d v0 v1 v2     Triangle(v0, v1, v2) at 0, the same                   -> hit toi nx ny nz
//   ss ca ra cb rb      Ball against Ball: intersectsShape, contactShape      -> hit distance
//   sb c r bc bh        Ball against Cuboid: the same                         -> hit distance
//   st c r v0 v1 v2     Ball against Triangle: the same                       -> hit distance
//   bb ca ha cb hb      Cuboid against Cuboid: intersectsShape                -> hit
//   tb v0 v1 v2 bc bh   Triangle against Cuboid: intersectsShape              -> hit
//   tt a0 a1 a2 b0 b1 b2  Triangle against Triangle: intersectsShape          -> hit
//   version             -> ok and Rapier's version
// contactShape is asked with a prediction of float's largest value, so it answers apart shapes
// too: its distance is negative when they overlap (the depth is its opposite).
import RAPIER from '@dimforge/rapier3d-compat';
import { createInterface } from 'node:readline';

await RAPIER.init();
const I = { w: 1, x: 0, y: 0, z: 0 };
const FAR = 3.4028234663852886e38;
const O = { x: 0, y: 0, z: 0 };
const v = (a, k) => ({ x: a[k], y: a[k + 1], z: a[k + 2] });
const widths = { rs: 10, rb: 12, rt: 15, ss: 8, sb: 10, st: 13, bb: 12, tb: 15, tt: 18, version: 0 };

function cast(shape, at, a) {
  const r = shape.castRayAndGetNormal(new RAPIER.Ray(v(a, 0), v(a, 3)), at, I, FAR, true);
  return r ? [1, r.timeOfImpact, r.normal.x, r.normal.y, r.normal.z] : [0, 0, 0, 0, 0];
}
function contact(s1, p1, s2, p2) {
  const hit = s1.intersectsShape(p1, I, s2, p2, I);
  const c = s1.contactShape(p1, I, s2, p2, I, FAR);
  return [hit ? 1 : 0, c ? c.distance : NaN];
}
const tri = (a, k) => new RAPIER.Triangle(v(a, k), v(a, k + 3), v(a, k + 6));
const cuboid = (a, k) => new RAPIER.Cuboid(a[k], a[k + 1], a[k + 2]);

function answer(op, a) {
  switch (op) {
    case 'rs': return cast(new RAPIER.Ball(a[9]), v(a, 6), a);
    case 'rb': return cast(cuboid(a, 9), v(a, 6), a);
    case 'rt': return cast(tri(a, 6), O, a);
    case 'ss': return contact(new RAPIER.Ball(a[3]), v(a, 0), new RAPIER.Ball(a[7]), v(a, 4));
    case 'sb': return contact(new RAPIER.Ball(a[3]), v(a, 0), cuboid(a, 7), v(a, 4));
    case 'st': return contact(new RAPIER.Ball(a[3]), v(a, 0), tri(a, 4), O);
    case 'bb': return [cuboid(a, 3).intersectsShape(v(a, 0), I, cuboid(a, 9), v(a, 6), I) ? 1 : 0];
    case 'tb': return [tri(a, 0).intersectsShape(O, I, cuboid(a, 12), v(a, 9), I) ? 1 : 0];
    case 'tt': return [tri(a, 0).intersectsShape(O, I, tri(a, 9), O, I) ? 1 : 0];
    case 'version': return [RAPIER.version()];
  }
  throw new Error(`unknown operation '${op}'`);
}

const lines = createInterface({ input: process.stdin, crlfDelay: Infinity });
for await (const line of lines) {
  let reply;
  try {
    const [op, ...rest] = line.trim().split(/\s+/);
    if (!(op in widths)) throw new Error(`unknown operation '${op}'`);
    if (rest.length !== widths[op]) throw new Error(`'${op}' takes ${widths[op]} numbers, not ${rest.length}`);
    const a = rest.map(Number);
    if (a.some((x) => !Number.isFinite(x))) throw new Error('a number is not finite');
    reply = 'ok ' + answer(op, a).join(' ');
  } catch (e) {
    reply = 'error ' + String(e && e.message ? e.message : e).replace(/\s+/g, ' ');
  }
  process.stdout.write(reply + '\n');
}
