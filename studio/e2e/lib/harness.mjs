// The end-to-end harness for the editor suites: `feel studio` on a free port, Debian's
// headless Chromium through playwright-core, pages that wait on the Studio's own signals
// (the server answered the newest edit, the device's clock passed), never on fixed sleeps.
import { mkdirSync } from 'node:fs';
import { resolve } from 'node:path';
import { launchBrowser as launchWith, repo } from '../harness.mjs';

export { feel, repo, startStudio } from '../harness.mjs';
export const shots = resolve(repo, 'out/studio');
mkdirSync(shots, { recursive: true });
export const kTimeout = 90000; // ms: a loaded 2-core machine can stall a step for seconds

// The editors need the taller page: the graphic, the timing panel and the form.
export const launchBrowser = () => launchWith({ width: 1400, height: 1100 });

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
  // the new effect is in the document before its answer is awaited: synced() is still true
  // for the previous change until the page has sent this one
  await page.waitForFunction((t) => {
    const list = window.__studio.store.effects();
    return list.length === 1 && list[0].type === t;
  }, type);
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

// Every state report the page receives from now on (the plot's rows [t_ms, force…,
// position…]), kept in the page: the plot keeps only 5 s, and on a loaded machine a play
// can be older than that by the time the test reads it. Bounded to 60 s of reports.
export const record = (page) => page.evaluate(() => {
  const plot = window.__studio.plot;
  window.__recorded = [];
  if (!plot.__recording) {
    const push = plot.push.bind(plot);
    plot.push = (rows) => {
      window.__recorded.push(...rows);
      if (window.__recorded.length > 30000) window.__recorded.splice(0, window.__recorded.length - 30000);
      push(rows);
    };
    plot.__recording = true;
  }
});
// The recorded samples newer than `fromMs` (device time).
export const samplesSince = (page, fromMs) => page.evaluate((t) => window.__recorded.filter((r) => r[0] > t), fromMs);
export const deviceNow = (page) => page.evaluate(() => { const w = window.__studio.plot.window(); return w.length ? w[w.length - 1][0] : 0; });
export const deviceAfter = (page, from, ms) => page.waitForFunction(([t, d]) => {
  const w = window.__studio.plot.window();
  return w.length > 0 && w[w.length - 1][0] >= t + d;
}, [from, ms]);

// Plays effect 0 (of `durationMs`) and waits until the device's force has started and
// the device's clock has gone the duration and 150 ms beyond; returns the device time just
// before the play. On a loaded machine the start can come long after the click: this
// waits on the device's own reports, not on a time.
export async function playThrough(page, durationMs) {
  await record(page);
  const from = await deviceNow(page);
  await page.locator('#design .icon button.play').first().click();
  await page.waitForFunction(([t, d]) => {
    const rows = window.__recorded;
    const start = rows.find((r) => r[0] > t && r.slice(1, 1 + (r.length - 1) / 2).some((f) => f !== 0));
    return start !== undefined && rows[rows.length - 1][0] >= start[0] + d + 150;
  }, [from, durationMs]);
  return from;
}

// The centre of an SVG element, in page pixels. The editors redraw their SVG whenever the
// state arrives, so the element seen visible may be replaced before its box is read (the box
// is then null): read it again, for up to 5 s, from the element drawn since.
export async function centreOf(locator) {
  const deadline = Date.now() + 5000;
  for (;;) {
    await locator.waitFor({ state: 'visible' }); // drawn once the editor has the new state
    const b = await locator.boundingBox();
    if (b) return [b.x + b.width / 2, b.y + b.height / 2];
    if (Date.now() > deadline) throw new Error(`centreOf: ${locator} has no box after 5 s (redrawn away each time)`);
    await new Promise((resolve) => setTimeout(resolve, 20));
  }
}
// An SVG point (viewBox units) of `svgLocator`, in page pixels.
export const pagePoint = (svgLocator, x, y) => svgLocator.evaluate((s, [x, y]) => {
  const p = new DOMPoint(x, y).matrixTransform(s.getScreenCTM());
  return [p.x, p.y];
}, [x, y]);
