// The end-to-end harness for the editor suites: `feel studio` on a free port, Debian's
// headless Chromium through playwright-core, pages that wait on the Studio's own signals
// (the server answered the newest edit, the device's clock passed), never on fixed sleeps.
import { spawn } from 'node:child_process';
import { mkdtempSync, mkdirSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { chromium } from 'playwright-core';

export const repo = resolve(import.meta.dirname, '../../..');
export const feel = resolve(repo, process.env.FEEL ?? 'build/apps/feel/feel');
export const shots = resolve(repo, 'out/studio');
mkdirSync(shots, { recursive: true });
export const kTimeout = 90000; // ms: a loaded 2-core machine can stall a step for seconds

// Starts `feel studio` on a free port; resolves with its URL and process.
export function startStudio(workspace, device = 'sim:iforce2') {
  return new Promise((ok, fail) => {
    const p = spawn(feel, ['studio', '--workspace', workspace, '--device', device, '--port', '0'], {
      stdio: ['ignore', 'pipe', 'inherit'],
    });
    let out = '';
    p.stdout.on('data', (d) => {
      out += d;
      const m = out.match(/open (http:\/\/\S+)/);
      if (m) ok({ url: m[1], proc: p });
    });
    p.on('exit', (code) => fail(new Error(`feel studio exited ${code}: ${out}`)));
  });
}

export function launchBrowser() {
  return chromium.launchPersistentContext(mkdtempSync(join(tmpdir(), 'feel-chromium-')), {
    executablePath: '/usr/bin/chromium',
    headless: true,
    viewport: { width: 1400, height: 1100 },
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
}

export async function openPage(browser, url) {
  const page = await browser.newPage();
  page.setDefaultTimeout(kTimeout);
  await page.goto(url);
  await page.waitForFunction(() => Boolean(window.__studio?.store.state.hello) && window.__studio.frames() > 2);
  return page;
}

// Until the server has answered the newest edit (validated or refused at its field).
export const synced = (page) => page.waitForFunction(() => window.__studio.synced());
export const errors = (page) => page.evaluate(() => window.__studio.store.state.errors);
export const effects = (page) => page.evaluate(() => window.__studio.store.effects());

// A new sensation holding one effect of `type` from the palette, selected.
export async function freshEffect(page, type) {
  await page.evaluate(() => window.__studio.store.update((d) => (d.sensations[d.current].effects = []), -1));
  await page.click(`#palette li[data-type="${type}"]`);
  await synced(page);
}

// Replaces effect 0 by `change(effect)` (a function source run in the page).
export async function editEffect(page, change) {
  await page.evaluate((src) => {
    const f = new Function('e', src);
    window.__studio.store.update((d) => f(d.sensations[d.current].effects[0]), 0);
  }, change);
  await synced(page);
}

export async function setField(page, path, value) {
  const input = page.locator(`#editor .field[data-path="${path}"] input[type=number]`);
  await input.fill(String(value));
  await input.press('Enter');
  await input.blur();
  await synced(page);
}
export const fieldValue = (page, path) => page.locator(`#editor .field[data-path="${path}"] input[type=number]`).inputValue();

// The device's samples (plot window rows [t_ms, force…, position…]) newer than `fromMs`.
export const samplesSince = (page, fromMs) => page.evaluate((t) => window.__studio.plot.window().filter((r) => r[0] > t), fromMs);
export const deviceNow = (page) => page.evaluate(() => { const w = window.__studio.plot.window(); return w.length ? w[w.length - 1][0] : 0; });
export const deviceAfter = (page, from, ms) => page.waitForFunction(([t, d]) => {
  const w = window.__studio.plot.window();
  return w.length > 0 && w[w.length - 1][0] >= t + d;
}, [from, ms]);

// Plays effect 0 and waits until it has played and stopped by itself (a finite duration),
// and the device's clock has gone 100 ms beyond; returns the device time just before the
// play. On a loaded machine the start can come long after the click: this waits on the
// device's own account of the effect, not on a time.
export async function playThrough(page) {
  const from = await deviceNow(page);
  const before = await page.evaluate(() => window.__studio.liveStates()[0]?.starts ?? 0);
  await page.locator('#design .icon button.play').first().click();
  await page.waitForFunction((n) => {
    const st = window.__studio.liveStates()[0];
    return st !== undefined && st.starts > n && st.state === 'playing';
  }, before);
  await page.waitForFunction(() => window.__studio.liveStates()[0]?.state !== 'playing');
  await deviceAfter(page, await deviceNow(page), 100);
  return from;
}

// The centre of an SVG element, in page pixels.
export async function centreOf(locator) {
  const b = await locator.boundingBox();
  return [b.x + b.width / 2, b.y + b.height / 2];
}
// An SVG point (viewBox units) of `svgLocator`, in page pixels.
export const pagePoint = (svgLocator, x, y) => svgLocator.evaluate((s, [x, y]) => {
  const p = new DOMPoint(x, y).matrixTransform(s.getScreenCTM());
  return [p.x, p.y];
}, [x, y]);
