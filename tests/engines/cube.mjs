// The Vulkan / OpenGL cube map convention (Vulkan spec, "Cube Map Face Selection"), written out
// here on its own so that the tests do not borrow the kit's.
export const faceNames = ['px', 'nx', 'py', 'ny', 'pz', 'nz'];

// The unit direction through the centre of texel (column, row) of `face`.
export function texelCentre(face, column, row, size) {
  const s = ((column + 0.5) / size) * 2 - 1;
  const t = ((row + 0.5) / size) * 2 - 1;
  const d = [[1, -t, -s], [-1, -t, s], [s, 1, t], [s, -1, -t], [s, -t, 1], [-s, -t, -1]][face];
  return normalize(d);
}

// The face a direction selects.
export function faceOf([x, y, z]) {
  const ax = Math.abs(x), ay = Math.abs(y), az = Math.abs(z);
  if (ax >= ay && ax >= az) return x > 0 ? 0 : 1;
  if (ay >= az) return y > 0 ? 2 : 3;
  return z > 0 ? 4 : 5;
}

// How far a direction is from its face's edges: its major coordinate over the next largest.
export function marginOf([x, y, z]) {
  const sorted = [Math.abs(x), Math.abs(y), Math.abs(z)].sort((a, b) => b - a);
  return sorted[0] / Math.max(sorted[1], 1e-12);
}

export function normalize([x, y, z]) {
  const length = Math.hypot(x, y, z);
  return [x / length, y / length, z / length];
}

export function angleBetween(a, b) {
  const cosine = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  return Math.acos(Math.min(1, Math.max(-1, cosine)));
}
