// The kit's render as the engine tests compare with it: its grid and its split-sum image.
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { FloatType } from 'three';
import { EXRLoader } from 'three/addons/loaders/EXRLoader.js';

// A cell of the kit's grid spans ±1/0.9 sphere radii (hlsl/Common/SphereGrid.fxh's SPHERE_RADIUS).
export const kitSpan = 1 / 0.9;

// { grid, image: { width, height, pixels } } with the pixels bottom row first, as the pages read back.
export function readKitRender(folder) {
  const grid = JSON.parse(readFileSync(path.join(folder, 'errors.json'), 'utf8')).grid;
  const loader = new EXRLoader();
  loader.setDataType(FloatType);
  const bytes = readFileSync(path.join(folder, 'splitsum.exr'));
  const exr = loader.parse(bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength));
  return { grid, image: { width: exr.width, height: exr.height, pixels: exr.data } };
}

// The grid's opaque spheres as the pages take them.
export function opaqueSpheres(grid) {
  const spheres = [];
  grid.rows.forEach((material, row) => {
    if (material.transmittance > 0) return;
    grid.roughness.forEach((roughness, column) =>
      spheres.push({ color: material.albedo, metalness: material.metalness, roughness, column, row, material: material.name }));
  });
  return spheres;
}
