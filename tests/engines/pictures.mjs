// docs/engines.md's pictures: each engine's render of the built-in sky from its profile's bake,
// above the kit's own split sum of the same recipe, and the per-sphere ratio of their light.
//   IBLKIT_EXECUTABLE=build/tools/iblkit/iblkit node tests/engines/pictures.mjs docs/engines
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { EngineSession } from './checks.mjs';
import { kitRender } from './bake.mjs';
import { kitSpan, opaqueSpheres, readKitRender } from './kit_render.mjs';
import { writePng } from './png.mjs';
import { luminance, spherePixels } from './spheres.mjs';

const engines = [{ page: 'three', profile: 'threejs', title: 'three.js r187' },
                 { page: 'babylon', profile: 'babylon', title: 'Babylon.js 9' },
                 { page: 'filament', profile: 'filament', title: 'Filament 1.53' }];
const cell = 48;
const out = process.argv[2];
if (!out) throw new Error('usage: node tests/engines/pictures.mjs OUTPUT_FOLDER');
mkdirSync(out, { recursive: true });

const sections = [];
for (const engine of engines) {
  const session = new EngineSession(engine.page, engine.profile, { cell });
  await session.open();
  try {
    const bakeFolder = session.bake(null, 'sky', '--profile', engine.profile);
    const recipe = JSON.parse(readFileSync(path.join(bakeFolder, 'manifest.json'), 'utf8')).profile.recipe;
    const kitFolder = kitRender(null, session.folder('kit'), recipe, cell);
    const kit = readKitRender(kitFolder);
    const exposure = JSON.parse(readFileSync(path.join(kitFolder, 'errors.json'), 'utf8')).exposure;
    const spheres = opaqueSpheres(kit.grid);
    const image = await session.render(bakeFolder, spheres, { span: kitSpan });
    const kitOpaque = { ...kit.image, height: image.height,
                        pixels: kit.image.pixels.slice((kit.image.height - image.height) * kit.image.width * 4) };
    writePng(path.join(out, `${engine.profile}.png`), [image, kitOpaque], exposure);
    const light = (picture, sphere) =>
      spherePixels(picture, cell, sphere.column, sphere.row, { span: kitSpan }).reduce((sum, p) => sum + luminance(p.colour), 0);
    const rows = kit.grid.rows.filter((row) => row.transmittance === 0).map((row) => {
      const ratios = spheres.filter((s) => s.material === row.name).map((s) => (light(image, s) / light(kitOpaque, s)).toFixed(2));
      return `| ${row.name} | ${ratios.join(' | ')} |`;
    });
    sections.push([`### ${engine.title}: \`--profile ${engine.profile}\` (recipe \`${recipe}\`)`, '',
                   `![${engine.title} above, the kit below](engines/${engine.profile}.png)`, '',
                   `Each sphere's light, ${engine.title} over the kit:`, '',
                   `| material | ${kit.grid.roughness.map((r) => r.toFixed(2)).join(' | ')} |`,
                   `|---|${kit.grid.roughness.map(() => '---|').join('')}`, ...rows, ''].join('\n'));
  } finally {
    await session.close();
  }
}
writeFileSync(path.join(out, 'pictures.md'),
              ['<!-- written by tests/engines/pictures.mjs; docs/engines.md includes it by hand -->', ...sections].join('\n'));
