// The checks every engine's page passes, with that engine's bounds: the white furnace, the
// orientation cube in a mirror sphere, and the comparisons with the kit's own split sum, of colour
// patches and of a sun the bake takes out as a light.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { Browser } from './browser.mjs';
import { bake, kitRender, scratchFolder } from './bake.mjs';
import { angleBetween, faceOf, marginOf } from './cube.mjs';
import { orientation, writeFurnace, writeOrientationCube, writePatches, writeSunBeside } from './environments.mjs';
import { kitSpan, opaqueSpheres, readKitRender } from './kit_render.mjs';
import { luminance, spherePixels } from './spheres.mjs';

export const white = [1, 1, 1];
const roughnesses = [0, 0.25, 0.5, 0.75, 1];

// One page a session, its scratch folder served at /scratch/: loading Babylon.js's modules takes
// 5 s, each time a page opens.
export class EngineSession {
  constructor(pageName, profile, { cell = 64 } = {}) {
    Object.assign(this, { pageName, profile, cell });
  }

  async open() {
    this.scratch = scratchFolder(this.pageName);
    this.browser = await Browser.open();
    this.page = await this.browser.openPage(this.pageName, { '/scratch/': this.scratch.folder });
  }

  async close() {
    await this.browser?.close();
    this.scratch?.remove();
  }

  folder(name) { return path.join(this.scratch.folder, name); }

  bake(environment, name, ...flags) { return bake(environment, this.folder(name), { cache: this.folder('cache') }, ...flags); }

  // Calls the page's window[name](request) with request.bake the URL of `bakeFolder`; what the
  // page logged as errors meanwhile fails the test.
  async evaluate(name, bakeFolder, request = {}) {
    this.page.errors.length = 0;
    const bakeUrl = `/scratch/${path.relative(this.scratch.folder, bakeFolder)}`;
    const result = await this.page.evaluate((name, request) => window[name](request), name, { bake: bakeUrl, ...request });
    assert.deepEqual(this.page.errors, [], 'the page logged errors');
    return result;
  }

  async render(bakeFolder, spheres, options = {}) {
    return this.evaluate('iblkitRender', bakeFolder, { spheres, cell: this.cell, ...options });
  }

  // The largest |pixel - 1| of white metal and white dielectric spheres at five roughnesses in
  // a constant environment of 1, per sphere.
  async furnaceDepartures() {
    const environment = writeFurnace(this.folder('env'));
    const folder = this.bake(environment, 'furnace', '--profile', this.profile, '--size', '32');
    const spheres = [...roughnesses.map((roughness) => ({ color: white, metalness: 1, roughness })),
                     ...roughnesses.map((roughness) => ({ color: white, metalness: 0, roughness }))];
    const image = await this.render(folder, spheres);
    return spheres.map((sphere, index) => {
      let worst = 0;
      for (const { colour } of spherePixels(image, this.cell, index))
        worst = Math.max(worst, ...colour.map((c) => Math.abs(c - 1)));
      return { ...sphere, worst };
    });
  }

  // A mirror sphere in the orientation cube baked with `flags` (`prepare` may rewrite the files): the share of pixels away from the
  // faces' edges that show another face's colour than the kit has in their mirror direction, and
  // per visible face the angle from its brightest pixel's mirror direction to its hot texel.
  async orientation(name, flags, prepare = () => {}) {
    const environment = writeOrientationCube(this.folder('env'));
    const bakeFolder = this.bake(environment, name, ...flags);
    prepare(bakeFolder);
    const image = await this.render(bakeFolder, [{ color: white, metalness: 1, roughness: 0 }],
                                    { lights: false });
    const pixels = spherePixels(image, this.cell, 0);
    const wrong = pixels.filter((p) => marginOf(p.reflected) > 1.2 && nearestFace(p.colour) !== faceOf(p.reflected));
    const hotTexels = [];
    for (let face = 0; face < 6; face++) {
      const hot = orientation.hotDirection(face);
      if (hot[2] < -0.5) continue; // at the rim of a sphere seen from +Z
      const onFace = pixels.filter((p) => faceOf(p.reflected) === face);
      const brightest = onFace.reduce((a, b) => (luminance(b.colour) > luminance(a.colour) ? b : a));
      hotTexels.push({ face, degrees: (angleBetween(brightest.reflected, hot) * 180) / Math.PI });
    }
    return { wrongShare: wrong.length / pixels.length, hotTexels };
  }

  // The kit's render grid's opaque spheres on a panorama of colour patches, rendered by the engine
  // from a bake with `flags` and by the kit's split sum with `kitRecipe`. Per pixel, each
  // renderer's value over its own in the white furnace, which takes out each one's BRDF scale (its
  // DFG table, multiple scattering, diffuse source); per sphere, the median over its pixels of
  // |engine / kit - 1|.
  // `prepare` may rewrite the bake's files before the engine reads them (the tests' mutations).
  async departuresFromKit(name, kitRecipe, flags, options = {}, prepare = () => {}) {
    const basis = await this.comparisonBasis(kitRecipe);
    const bakeFolder = this.bake(basis.patches, `engine-${name}`, ...flags);
    prepare(bakeFolder);
    const engine = await this.render(bakeFolder, basis.spheres, { span: kitSpan, ...options });
    return this.departures(basis.spheres, engine, basis.kit.image, basis);
  }

  // The kit's render grid's dielectric spheres under a small sun beside them (writeSunBeside),
  // which the bake with `flags` takes out into lights.gltf and the page adds as the engine's own
  // light, against the kit's split sum of `kitRecipe`, which shades the sun's disk; per sphere, the
  // median over its pixels of |engine / kit - 1| as departuresFromKit takes it. A dielectric's
  // light is mostly its diffuse, so the check sees the light's direction and illuminance, not how
  // each engine shades a sun's highlight on a metal. `prepare` may rewrite the bake's files.
  async sunDepartures(name, kitRecipe, flags, prepare = () => {}) {
    this.suns ??= new Map();
    if (!this.suns.has(kitRecipe)) this.suns.set(kitRecipe, this.makeSunBasis(kitRecipe));
    const { sun, kit } = await this.suns.get(kitRecipe);
    const basis = await this.comparisonBasis(kitRecipe);
    const spheres = basis.spheres.filter((sphere) => sphere.metalness === 0);
    const bakeFolder = this.bake(sun, `engine-${name}`, ...flags);
    prepare(bakeFolder);
    const engine = await this.render(bakeFolder, spheres, { span: kitSpan });
    return this.departures(spheres, engine, kit.image, basis);
  }

  async makeSunBasis(kitRecipe) {
    const sun = writeSunBeside(this.folder('env'));
    return { sun, kit: readKitRender(kitRender(sun, this.folder(`kit-sun-${kitRecipe}`), kitRecipe, this.cell)) };
  }

  // Per sphere, the median over its pixels of |engine / kit - 1|, each renderer's value over its
  // own in the white furnace.
  departures(spheres, engine, kit, { engineFurnace, kitFurnace }) {
    const values = (image, sphere) =>
      spherePixels(image, this.cell, sphere.column, sphere.row, { span: kitSpan }).map((p) => luminance(p.colour));
    return spheres.map((sphere) => {
      const [e, ef, k, kf] = [engine, engineFurnace, kit, kitFurnace.image].map((image) => values(image, sphere));
      const departures = e.map((value, i) => Math.abs(value / ef[i] / (k[i] / kf[i]) - 1)).sort((a, b) => a - b);
      return { ...sphere, departure: departures[departures.length >> 1] };
    });
  }

  // What every comparison with `kitRecipe` shares, made once a session: the patches, the kit's
  // renders of them and of the furnace, and the engine's furnace from its own profile's bake.
  comparisonBasis(kitRecipe) {
    this.bases ??= new Map();
    if (!this.bases.has(kitRecipe)) this.bases.set(kitRecipe, this.makeComparisonBasis(kitRecipe));
    return this.bases.get(kitRecipe);
  }

  async makeComparisonBasis(kitRecipe) {
    const patches = writePatches(this.folder('env'));
    const furnace = writeFurnace(this.folder('env'));
    const kit = readKitRender(kitRender(patches, this.folder(`kit-${kitRecipe}`), kitRecipe, this.cell));
    const kitFurnace = readKitRender(kitRender(furnace, this.folder(`kit-furnace-${kitRecipe}`), kitRecipe, this.cell));
    const spheres = opaqueSpheres(kit.grid);
    const engineFurnace = await this.render(this.bake(furnace, 'engine-furnace', '--profile', this.profile, '--size', '32'),
                                            spheres, { span: kitSpan });
    return { patches, kit, kitFurnace, spheres, engineFurnace };
  }
}

// The sun's check and its mutation, for an engine whose profile bakes with `recipe`: every
// dielectric sphere within `bound` of the kit, and lights.gltf's direction mirrored in x beyond it.
export function testSunAsTheEnginesLight(session, engine, recipe, bound) {
  const flags = ['--profile', session.profile];
  test(`a sun the bake takes out reaches ${engine} as its own light, where the kit has it`, async () => {
    assertDeparturesWithin(await session.sunDepartures('sun', recipe, flags), bound);
  });
  test("mutation: lights.gltf's direction mirrored in x fails the sun's comparison", async () => {
    assertSomeDepartureBeyond(await session.sunDepartures('sun-mirrored', recipe, flags, mirrorLightsInX), bound);
  });
}

// A mutation: lights.gltf's lights shining from their direction mirrored in x.
function mirrorLightsInX(folder) {
  const file = path.join(folder, 'lights.gltf');
  const gltf = JSON.parse(readFileSync(file, 'utf8'));
  for (const light of gltf.extensions.KHR_lights_punctual.lights) light.extras.direction[0] *= -1;
  writeFileSync(file, JSON.stringify(gltf));
}

// What an orientation result gets wrong. Measured for each engine: no pixel shows another face's
// colour, each hot texel within 2.1° of where the kit has it (a texel spans 5.6° at 16²); a cube in
// another frame gets a fifth of the pixels wrong and its hot texels 30-60° off.
export function orientationFailures({ wrongShare, hotTexels }) {
  const failures = hotTexels.filter((hot) => hot.degrees >= 4).map((hot) => `face ${hot.face}: hot texel ${hot.degrees.toFixed(1)}° off`);
  if (wrongShare > 0.002) failures.push(`${(100 * wrongShare).toFixed(1)} % of the pixels show another face's colour`);
  return failures;
}

function nearestFace(colour) {
  const scale = Math.max(...colour);
  let best = -1, bestDistance = Infinity;
  orientation.colours.forEach((reference, face) => {
    const distance = Math.hypot(...reference.map((c, i) => c - colour[i] / scale));
    if (distance < bestDistance) [best, bestDistance] = [face, distance];
  });
  return best;
}

// A bake manifest's SH as the engines' shaders take them (Filament's IndirectLight, Babylon.js's
// preScaledHarmonics): E(n)/π over the plain polynomials 1, y, z, x, xy, yz, 3z² - 1, xz, x² - y²,
// the irradiance coefficients times each basis function's constant; `signs` per term.
export function shaderSh(manifest, signs = Array(9).fill(1)) {
  const basis = [0.282095, 0.488603, 0.488603, 0.488603, 1.092548, 1.092548, 0.315392, 1.092548, 0.546274];
  return manifest.irradiance.sh.irradiance_over_pi.map((c, i) => c.map((v) => v * basis[i] * signs[i]));
}

export function assertDeparturesWithin(spheres, bound) {
  for (const sphere of spheres)
    assert.ok(sphere.departure < bound, `${describe(sphere)}: ${(100 * sphere.departure).toFixed(1)} % from the kit`);
}

// A mutation must fail: some sphere departs by the bound or more.
export function assertSomeDepartureBeyond(spheres, bound) {
  const worst = Math.max(...spheres.map((sphere) => sphere.departure));
  assert.ok(worst >= bound,
            `every sphere is within the bound (the worst ${(100 * worst).toFixed(1)} %): the check cannot tell`);
}

export function describe(sphere) {
  return `${sphere.material ?? (sphere.metalness ? 'metal' : 'dielectric')} at roughness ${sphere.roughness.toFixed(2)}`;
}
