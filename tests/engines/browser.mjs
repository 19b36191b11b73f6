// Debian's chromium, headless on SwiftShader, driven by puppeteer-core. Pages and files are served
// from folders through request interception: no port, no server, nothing from the network.
import { readFile } from 'node:fs/promises';
import { existsSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import puppeteer from 'puppeteer-core';

const here = path.dirname(fileURLToPath(import.meta.url));
const origin = 'http://iblkit.test';
const chromium = process.env.IBLKIT_CHROMIUM ?? '/usr/bin/chromium';

const contentTypes = { '.html': 'text/html', '.mjs': 'text/javascript', '.js': 'text/javascript',
                       '.json': 'application/json', '.gltf': 'model/gltf+json' };

// Launch flags: Debian's chromium as root, no network of its own, WebGL2 on SwiftShader.
const flags = ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-background-networking',
               '--disable-component-update', '--disable-sync', '--disable-quic', '--use-angle=swiftshader',
               '--enable-unsafe-swiftshader'];

export class Browser {
  static async open() {
    if (!existsSync(chromium)) throw new Error(`no chromium at ${chromium} (tools/setup.sh installs Debian's)`);
    const profile = mkdtempSync(path.join(tmpdir(), 'iblkit-chromium-'));
    const browser = await puppeteer.launch({ executablePath: chromium, headless: true, userDataDir: profile,
                                             args: flags, protocolTimeout: 600000 });
    return new Browser(browser, profile);
  }

  constructor(browser, profile) {
    this.browser = browser;
    this.profile = profile;
  }

  // Opens pages/<name>.html with /bake/ serving `bakeFolder`; resolves once the page is ready.
  async openPage(name, folders) {
    const page = await this.browser.newPage();
    const roots = { '/node_modules/': path.join(here, 'node_modules'), '/pages/': path.join(here, 'pages'), ...folders };
    const errors = [];
    page.on('pageerror', (error) => errors.push(error.message));
    page.on('console', (message) => { if (message.type() === 'error') errors.push(message.text()); });
    await page.setRequestInterception(true);
    page.on('request', (request) => serve(request, roots));
    // Loading an engine's modules through interception took over puppeteer's default 30 s on a
    // loaded 2-core machine (three engine tests beside the kit's renders).
    await page.goto(`${origin}/pages/${name}.html`, { timeout: 120000 });
    await page.waitForFunction('window.iblkitReady === true || window.iblkitFailed', { timeout: 120000 });
    page.errors = errors;
    return page;
  }

  async close() {
    await this.browser.close();
    rmSync(this.profile, { recursive: true, force: true });
  }
}

async function serve(request, roots) {
  const url = new URL(request.url());
  if (url.origin !== origin) return request.respond({ status: 404, body: '' });
  if (url.pathname === '/favicon.ico') return request.respond({ status: 204, body: '' });
  for (const [prefix, folder] of Object.entries(roots)) {
    if (!url.pathname.startsWith(prefix)) continue;
    const file = path.join(folder, decodeURIComponent(url.pathname.slice(prefix.length)));
    if (!file.startsWith(folder) || !existsSync(file)) return request.respond({ status: 404, body: '' });
    const body = await readFile(file);
    return request.respond({ status: 200, body, contentType: contentTypes[path.extname(file)] ?? 'application/octet-stream' });
  }
  return request.respond({ status: 404, body: '' });
}
