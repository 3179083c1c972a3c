// manifold_mesh.mjs — the meshing scenes of bench/scenes/mesh_*.scad built
// with manifold-3d at a stated tessellation, timed inside node (the WASM
// module's load is not counted; run.py times the whole process too).
//   node manifold_mesh.mjs cube_holes|spheres SEGMENTS [OUT.stl]
// Prints one JSON line: {scene, segments, ms, volume, triangles}; with
// OUT.stl also writes the mesh there (binary STL, after the timing).
import { writeFileSync } from 'node:fs';
import Module from 'manifold-3d';

const [scene, segArg, outPath] = process.argv.slice(2);
const segments = Number(segArg);
const wasm = await Module();
wasm.setup();
const { Manifold } = wasm;

function build() {
  if (scene === 'cube_holes') {
    const cyl = Manifold.cylinder(30, 6.5, 6.5, segments, true);
    return Manifold.cube([20, 20, 20], true)
      .subtract(Manifold.sphere(11, segments))
      .subtract(cyl)
      .subtract(cyl.rotate([90, 0, 0]))
      .subtract(cyl.rotate([0, 90, 0]));
  }
  if (scene === 'spheres') {
    return Manifold.sphere(10, segments).add(Manifold.sphere(10, segments).translate([10, 0, 0]));
  }
  throw new Error(`unknown scene ${scene}`);
}

const t0 = process.hrtime.bigint();
const m = build();
const triangles = m.numTri(); // booleans are lazy: this forces them
const mesh = m.getMesh();
const ms = Number(process.hrtime.bigint() - t0) / 1e6;
console.log(JSON.stringify({ scene, segments, ms, volume: m.volume(), triangles,
                             vertices: mesh.numVert }));
if (outPath) {
  const np = mesh.numProp, v = mesh.vertProperties, t = mesh.triVerts;
  const n = t.length / 3, buf = Buffer.alloc(84 + 50 * n);
  buf.writeUInt32LE(n, 80);
  for (let i = 0; i < n; i++)
    for (let c = 0; c < 3; c++)
      for (let k = 0; k < 3; k++)
        buf.writeFloatLE(v[np * t[3 * i + c] + k], 84 + 50 * i + 12 + 12 * c + 4 * k);
  writeFileSync(outPath, buf);
}
