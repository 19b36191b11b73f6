// Environments whose every texel the engine tests know, written as the kit reads them.
import { mkdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { faceNames, texelCentre } from './cube.mjs';

// Radiance RGBE, flat scanlines (each pixel's first byte is its largest channel's mantissa, >= 128,
// so no reader takes a scanline for run-length encoded).
function rgbe([r, g, b]) {
  const largest = Math.max(r, g, b);
  if (largest < 1e-32) return [0, 0, 0, 0];
  const exponent = Math.floor(Math.log2(largest)) + 1; // frexp's: largest = m 2^exponent, m in [0.5, 1)
  const scale = 256 / 2 ** exponent;
  return [Math.floor(r * scale), Math.floor(g * scale), Math.floor(b * scale), exponent + 128];
}

function writeHdr(file, width, height, colourAt) {
  const header = `#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y ${height} +X ${width}\n`;
  const pixels = Buffer.alloc(width * height * 4);
  for (let row = 0; row < height; row++)
    for (let column = 0; column < width; column++) pixels.set(rgbe(colourAt(column, row)), (row * width + column) * 4);
  writeFileSync(file, Buffer.concat([Buffer.from(header, 'latin1'), pixels]));
}

// The white furnace: radiance 1 everywhere.
export function writeFurnace(folder) {
  mkdirSync(folder, { recursive: true });
  const file = path.join(folder, 'furnace.hdr');
  writeHdr(file, 64, 32, () => [1, 1, 1]);
  return file;
}

// A panorama of 6 bands of latitude by 8 sectors of longitude, each patch its own colour between
// 0.2 and 2: edges at every scale a prefiltered mip blurs, and no texel bright enough to be taken
// out as a light, so that where a renderer reads the wrong mip its spheres show it.
export function writePatches(folder) {
  mkdirSync(folder, { recursive: true });
  const file = path.join(folder, 'patches.hdr');
  const width = 256, height = 128;
  writeHdr(file, width, height, (column, row) => {
    const band = Math.floor((row / height) * 6), sector = Math.floor((column / width) * 8);
    const hue = (band * 8 + sector) * 0.6180339887;
    return [0, 1, 2].map((channel) => 0.2 + 1.8 * (0.5 + 0.5 * Math.cos(2 * Math.PI * (hue + channel / 3))));
  });
  return file;
}

// A dim sky of 0.1 and a small sun of 20000 (about 6° across) 36° above the horizon, from the left
// and a little in front of spheres seen from +Z (the light's direction about (-0.77, 0.59, 0.25)):
// bright enough that the bake takes it out as a light, and beside the spheres, so that their lit
// sides, terminators and shadowed sides all show.
export function writeSunBeside(folder) {
  mkdirSync(folder, { recursive: true });
  const file = path.join(folder, 'sun.hdr');
  const width = 256, height = 128, sun = { column: 0.2 * width, row: 0.3 * height, radius: 1.5 };
  writeHdr(file, width, height, (column, row) => {
    const latitude = Math.PI * (0.5 - (row + 0.5) / height);
    const dx = (column + 0.5 - sun.column) * Math.cos(latitude), dy = row + 0.5 - sun.row;
    return Math.hypot(dx, dy) <= sun.radius ? [20000, 20000, 20000] : [0.1, 0.1, 0.1];
  });
  return file;
}

// Each face its own colour, and one texel 8 times as bright off the face's centre and off its
// diagonals, so that a swapped face, a mirrored face or a turned face each move it.
export const orientation = {
  size: 16,
  hotColumn: 3,
  hotRow: 4,
  hotGain: 8,
  colours: [[1, 0.25, 0.25], [0.25, 1, 1], [0.25, 1, 0.25], [1, 0.25, 1], [0.25, 0.25, 1], [1, 1, 0.25]],
  hotDirection(face) { return texelCentre(face, this.hotColumn, this.hotRow, this.size); },
};

export function writeOrientationCube(folder) {
  const cube = path.join(folder, 'orientation');
  mkdirSync(cube, { recursive: true });
  faceNames.forEach((name, face) => {
    const colour = orientation.colours[face];
    writeHdr(path.join(cube, `${name}.hdr`), orientation.size, orientation.size, (column, row) =>
      column === orientation.hotColumn && row === orientation.hotRow ? colour.map((c) => c * orientation.hotGain) : colour);
  });
  return cube;
}
