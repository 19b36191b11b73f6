// Runs `iblkit bake` for the engine tests: IBLKIT_EXECUTABLE names the program (ctest sets it).
import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';

export function iblkit() {
  const program = process.env.IBLKIT_EXECUTABLE;
  if (!program) throw new Error('IBLKIT_EXECUTABLE is not set (ctest sets it to build/tools/iblkit/iblkit)');
  return program;
}

// `cache`: the session's own cache folder, so that a bake a session repeats (a mutation's, before
// the test rewrites its files) is served from it; none: --no-cache.
export function bake(environment, folder, { cache } = {}, ...flags) {
  const caching = cache ? ['--cache', cache] : ['--no-cache'];
  const args = ['bake', ...(environment ? [environment] : []), '-o', folder, ...caching, '-q', ...flags];
  execFileSync(iblkit(), args, { stdio: ['ignore', 'ignore', 'inherit'], env: { XDG_RUNTIME_DIR: '/tmp', ...process.env } });
  return folder;
}

// The kit's own split-sum render of its sphere grid with `recipe`'s maps (docs/render.md), without
// the Monte Carlo reference: only the split sum is compared.
export function kitRender(environment, folder, recipe, cell) {
  const args = ['render', ...(environment ? [environment] : []), '-o', folder, '--recipe', recipe, '--cell-size',
                String(cell), '--split-sum-only', '-q'];
  execFileSync(iblkit(), args, { stdio: ['ignore', 'ignore', 'inherit'], env: { XDG_RUNTIME_DIR: '/tmp', ...process.env } });
  return folder;
}

export function scratchFolder(name) {
  const folder = mkdtempSync(path.join(tmpdir(), `iblkit-${name}-`));
  return { folder, remove: () => rmSync(folder, { recursive: true, force: true }) };
}
