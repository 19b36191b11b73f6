// Pixels of a rendered row of spheres (radius 1, one per cell, orthographic, looking down -Z), as
// the pages read them back: RGBA floats, the bottom row first.

// Each covered pixel of the sphere in cell (column, row), row 0 at the top, whose centre lies within
// `rim` of the sphere's centre: its normal, its mirror direction and its colour. A cell spans ±`span`
// sphere radii (the pages' option of that name).
export function spherePixels(image, cell, column, row = 0, { span = 1, rim = 0.97 } = {}) {
  const bottom = image.height - (row + 1) * cell;
  const pixels = [];
  for (let py = 0; py < cell; py++)
    for (let px = 0; px < cell; px++) {
      const x = (((px + 0.5) / cell) * 2 - 1) * span, y = (((py + 0.5) / cell) * 2 - 1) * span;
      const r2 = x * x + y * y;
      if (r2 > rim * rim) continue;
      const normal = [x, y, Math.sqrt(1 - r2)];
      const reflected = [2 * normal[2] * normal[0], 2 * normal[2] * normal[1], 2 * normal[2] * normal[2] - 1];
      const offset = ((bottom + py) * image.width + column * cell + px) * 4;
      pixels.push({ normal, reflected, colour: image.pixels.slice(offset, offset + 3) });
    }
  return pixels;
}

export function luminance([r, g, b]) { return 0.2126 * r + 0.7152 * g + 0.0722 * b; }
