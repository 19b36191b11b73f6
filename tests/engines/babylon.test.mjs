// Babylon.js 9 reads `iblkit bake --profile babylon` and renders spheres in Debian's chromium.
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { EngineSession, assertDeparturesWithin, assertSomeDepartureBeyond, describe, orientationFailures, shaderSh,
         testSunAsTheEnginesLight } from './checks.mjs';

const session = new EngineSession('babylon', 'babylon');
before(() => session.open());
after(() => session.close());

test("white furnace: every white metal is 1; white dielectrics within Babylon.js's own bound", async () => {
  for (const sphere of await session.furnaceDepartures()) {
    // Measured: metals within 6e-8 of 1 at every roughness. Babylon.js's dielectric is not energy
    // conserving at grazing angles (its specular is added over a diffuse it does not lower by as
    // much): its rim pixels depart by up to 0.24 (roughness 0), 0.20 (0.25), 0.07, 0.02, 0.03.
    const bound = sphere.metalness ? 1e-5 : 0.3;
    assert.ok(sphere.worst < bound, `${describe(sphere)}: off 1 by ${sphere.worst}`);
  }
});

// Bounds and what they measured: orientationFailures (checks.mjs).
test('orientation: a mirror sphere shows each face where the kit has it, its hot texel in place', async () => {
  assert.deepEqual(orientationFailures(await session.orientation('orientation', ['--profile', 'babylon'])), []);
});

test("mutation: the same maps in the kit's own cube frame fail the orientation check", async () => {
  // Measured: 22 % of the pixels wrong, the hot texels 41-54° off.
  const failures = orientationFailures(await session.orientation('orientation-kit-frame', ['--recipe', 'babylon-lights', '--dds']));
  assert.ok(failures.length > 0, "Babylon.js showed a cube in the kit's frame as if it were in its own");
});

// Measured: 1.8 % at most (metals at roughness 0.4; plastic 0.3 %, 0.7 % from roughness 0.8 up,
// the kit's render reading the full chain Babylon.js reads). Maps of the linear mapping depart by
// up to 8.4 %, 6-8.4 % at roughness 0.15-0.4.
const departureBound = 0.03;

test("the engine against the kit: Babylon.js and the kit's split sum of Babylon.js's mapping read the same mips", async () => {
  assertDeparturesWithin(await session.departuresFromKit('patches', 'babylon-lights', ['--profile', 'babylon']), departureBound);
});

// Mirrors a DDS cube of RGBA16F texels (DX10 header, faces each with their mips) in z, the kit's
// frame into Babylon.js's, independently of the kit's own code: ±Z trade places with their columns
// reversed, ±X reverse their columns, ±Y their rows.
function mirrorDdsInZ(file) {
  const bytes = readFileSync(file);
  const header = 148, mips = bytes.readUInt32LE(28), size = bytes.readUInt32LE(16);
  const texels = new BigUint64Array(bytes.buffer.slice(bytes.byteOffset + header, bytes.byteOffset + bytes.length));
  const faceTexels = [...Array(mips).keys()].reduce((sum, mip) => sum + Math.max(size >> mip, 1) ** 2, 0);
  const mirrored = new BigUint64Array(texels.length);
  for (let face = 0; face < 6; face++) {
    const source = [0, 1, 2, 3, 5, 4][face];
    let offset = 0;
    for (let mip = 0; mip < mips; mip++) {
      const n = Math.max(size >> mip, 1);
      for (let row = 0; row < n; row++)
        for (let column = 0; column < n; column++) {
          const [fromRow, fromColumn] = face === 2 || face === 3 ? [n - 1 - row, column] : [row, n - 1 - column];
          mirrored[face * faceTexels + offset + row * n + column] = texels[source * faceTexels + offset + fromRow * n + fromColumn];
        }
      offset += n * n;
    }
  }
  writeFileSync(file, Buffer.concat([bytes.subarray(0, header), Buffer.from(mirrored.buffer)]));
}

test('mutation: maps of the linear mapping fail the comparison', async () => {
  // The documents' linear spacing over Babylon.js's full chain, mirrored into its frame here: only
  // the mips' roughness differs.
  const spheres = await session.departuresFromKit('patches-linear', 'babylon-lights',
                                                  ['--recipe', 'linear-lights-pair', '--dds', '--mips', '9'], {},
                                                  (folder) => mirrorDdsInZ(path.join(folder, 'specular.dds')));
  assertSomeDepartureBeyond(spheres, departureBound);
});

// Babylon.js's own reader: the SH it projects from our DDS as it loads it (its preScaledHarmonics)
// against the kit's in the same form. Its cube is the kit's mirrored in z, so the terms odd in z
// change sign.
test("Babylon.js's SH of our DDS are the kit's", async () => {
  const folder = session.bake(null, 'sky-sh', '--profile', 'babylon');
  const theirs = await session.evaluate('iblkitSphericalHarmonics', folder);
  const manifest = JSON.parse(readFileSync(path.join(folder, 'manifest.json'), 'utf8'));
  const zSign = [1, 1, -1, 1, 1, -1, 1, -1, 1];
  const departure = (signs) => {
    const ours = shaderSh(manifest, signs);
    const scale = Math.max(...ours[0]);
    let worst = 0;
    ours.forEach((c, i) => c.forEach((v, channel) => { worst = Math.max(worst, Math.abs(v - theirs[i][channel]) / scale); }));
    return worst;
  };
  // Measured: 4.5e-5 of l00 at most (Babylon.js sums the half-float mip 0 with its own texel
  // weights; the kit sums its float source mip of 32²); in the kit's frame, unmirrored, they
  // would depart by the z-odd terms themselves.
  assert.ok(departure(zSign) < 3e-4, `Babylon.js's SH depart from the kit's by ${departure(zSign)} of l00`);
  assert.ok(departure(zSign.map(() => 1)) > 3e-4, 'the comparison cannot tell the frames apart');
});

// Measured on the dielectric spheres: 1.1 % at most (at roughness 0.4). With the light's direction
// mirrored in x, or with no light, they depart by 97-99 %.
testSunAsTheEnginesLight(session, 'Babylon.js', 'babylon-lights', 0.02);
