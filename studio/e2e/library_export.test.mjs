// End to end (issue 11 §2–§3): the library of examples, "Duplicate to workspace", a preset
// under a user heading, and the code export panel, on the real `feel studio` in Debian's
// Chromium driven by playwright-core. Screenshots to out/studio/.
//
// The expectations come from outside the Studio: the example files themselves (read here
// with JSON.parse), the primer's classes of the effect types (§6.4: the ten Conditions, the
// Dynamics named dynamic_*, the rest Waves), `feel check` on the duplicated file and
// `feel export` on the saved file (the CLI, the same generators the panel asks the server for).
//
//   FEEL=build/apps/feel/feel node --test studio/e2e/   (make test-studio)
import { test, before, after, afterEach } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, mkdirSync, readFileSync, readdirSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { feel, launchBrowser, repo, startStudio } from './harness.mjs';

const shots = resolve(repo, 'out/studio');
mkdirSync(shots, { recursive: true });
const kTimeout = 90000; // ms: a loaded 2-core machine can stall a step for seconds

// §6.4's Spatial Conditions; the Dynamic Sensations are dynamic_*; everything else is a Wave.
const kConditions = ['spring', 'damper', 'inertia', 'friction', 'angle_spring', 'axis_barrier', 'angle_barrier',
  'axis_wall', 'angle_wall', 'texture'];
const classOf = (type) => (kConditions.includes(type) ? 'condition' : type.startsWith('dynamic_') ? 'dynamic' : 'wave');

let browser, workspace, studio;
before(async () => {
  workspace = mkdtempSync(join(tmpdir(), 'feel-library-'));
  studio = await startStudio(workspace);
  browser = await launchBrowser({ width: 1400, height: 1100 });
});
after(async () => {
  await browser?.close();
  studio?.proc.kill('SIGTERM');
  rmSync(workspace, { recursive: true, force: true });
});
const pages = [];
afterEach(async () => {
  for (const p of pages.splice(0)) if (!p.isClosed()) await p.close();
});
async function open() {
  const page = await browser.newPage();
  pages.push(page);
  page.setDefaultTimeout(kTimeout);
  page.on('dialog', (d) => d.accept(page.nextAnswer ?? ''));
  await page.goto(studio.url);
  await page.waitForFunction(() => Boolean(window.__studio?.store.state.hello) && window.__studio.frames() > 2);
  return page;
}
const synced = (page) => page.waitForFunction(() => window.__studio.synced());

// Every sensation of the shipped examples, with the class its effects say.
function exampleSensations() {
  const dir = join(repo, 'examples');
  const out = [];
  for (const f of readdirSync(dir).filter((n) => n.endsWith('.feel.json'))) {
    const file = JSON.parse(readFileSync(join(dir, f), 'utf8'));
    for (const [name, s] of Object.entries(file.sensations)) {
      const classes = new Set((s.effects ?? [s]).map((e) => classOf(e.type)));
      out.push({ file: f, name, sensation: s, group: classes.size === 1 ? [...classes][0] : 'compound' });
    }
  }
  return out;
}

test('library: every example under its class, read-only; duplicate copies one into the workspace', async () => {
  const page = await open();
  await page.waitForSelector('#library li.example', { state: 'attached' });
  const expected = exampleSensations();
  const shown = await page.$$eval('#library details', (ds) =>
    ds.map((d) => ({ group: d.dataset.group, names: [...d.querySelectorAll('li.example')].map((li) => li.dataset.name) })));
  for (const g of shown) {
    const want = expected.filter((e) => e.group === g.group).map((e) => e.name).sort();
    assert.deepEqual([...g.names].sort(), want, `the ${g.group} group`);
  }
  assert.equal(shown.reduce((n, g) => n + g.names.length, 0), expected.length, 'every example sensation once');
  assert.deepEqual(shown.map((g) => g.group).sort(), [...new Set(expected.map((e) => e.group))].sort());

  // clicking one opens its file at it, read-only
  const vortex = expected.find((e) => e.name === 'vortex');
  await page.click('#library details[data-group="wave"] summary');
  await page.click('#library li.example[data-name="vortex"] .open');
  await synced(page);
  const opened = await page.evaluate(() => {
    const d = window.__studio.store.state.doc;
    return { readOnly: d.readOnly, name: d.sensations[d.current].name, effects: d.sensations[d.current].effects };
  });
  assert.equal(opened.readOnly, true);
  assert.equal(opened.name, 'vortex');
  const { description, ...vortexEffect } = vortex.sensation;
  void description;
  assert.deepEqual(opened.effects, [vortexEffect]);

  // Duplicate to workspace: a new feel/1 file holding exactly that sensation, opened for editing
  page.nextAnswer = 'vortex_copy.feel.json';
  await page.click('#library li.example[data-name="vortex"] .duplicate');
  await page.waitForFunction(() => window.__studio.store.state.doc.file === 'vortex_copy.feel.json');
  const copy = JSON.parse(readFileSync(join(workspace, 'vortex_copy.feel.json'), 'utf8'));
  assert.equal(copy.format, 'feel/1');
  assert.deepEqual(Object.keys(copy.sensations), ['vortex']);
  assert.deepEqual(copy.sensations.vortex, vortex.sensation);
  execFileSync(feel, ['check', join(workspace, 'vortex_copy.feel.json')]); // throws if feel refuses it
  assert.equal(await page.evaluate(() => window.__studio.store.state.doc.readOnly), false);
  // a second duplicate onto the same path is refused, and the first copy is kept
  page.nextAnswer = 'vortex_copy.feel.json';
  await page.click('#library li.example[data-name="vortex"] .duplicate');
  await page.waitForFunction(() => /exists/.test(document.getElementById('status').textContent));
  assert.deepEqual(JSON.parse(readFileSync(join(workspace, 'vortex_copy.feel.json'), 'utf8')), copy);
  await page.locator('#library').screenshot({ path: join(shots, 'library.png'), timeout: kTimeout });
});

test('a preset under a user heading: any effect, kept in favorites.feel.json', async () => {
  const page = await open();
  await page.click('#palette li[data-type="sweep_triangle"]');
  await synced(page);
  page.nextAnswer = 'Racing.kerb rumble';
  await page.click('#save-favorite');
  await page.waitForSelector('#palette details.presets li.preset:text("kerb_rumble")');
  const file = JSON.parse(readFileSync(join(workspace, 'favorites.feel.json'), 'utf8'));
  assert.equal(file.format, 'feel/1');
  assert.equal(file.sensations['Racing.kerb_rumble'].type, 'sweep_triangle');
  const headings = await page.$$eval('#palette details.presets summary', (s) => s.map((e) => e.textContent));
  assert.ok(headings.includes('Racing'), `headings: ${headings}`);
  execFileSync(feel, ['check', join(workspace, 'favorites.feel.json')]);
});

test('code export: C++, C and the SensationLibrary snippet of the current sensation, as feel export writes them', async () => {
  const page = await open();
  await page.click('#palette li[data-type="spring"]');
  await synced(page);
  const input = page.locator('#editor .field[data-path="conditions[0].pos_coefficient"] input[type=number]');
  await input.fill('4321');
  await input.press('Enter');
  // the edit is in the document before its answer is awaited: synced() alone is already
  // true for the previous edit if the page has not sent this one yet (seen in a loaded run)
  await page.waitForFunction(() => JSON.stringify(window.__studio.store.state.doc).includes('4321'));
  await synced(page);
  // saved, so that the library snippet has a file to load and the CLI the same input
  page.nextAnswer = 'exported.feel.json';
  await page.click('#save-as');
  await page.waitForFunction(() => window.__studio.store.state.doc.file === 'exported.feel.json');
  const name = await page.evaluate(() => window.__studio.store.state.doc.sensations[0].name);
  const cli = (lang) => execFileSync(feel, ['export', 'exported.feel.json', '--lang', lang, '--sensation', name],
    { cwd: workspace, encoding: 'utf8' });

  await page.click('#export-panel summary');
  const shownCode = async (lang) => {
    await page.click(`#export .tab[data-lang="${lang}"]`);
    await page.waitForFunction(() => document.getElementById('export').exportDone());
    return page.textContent('#export-code');
  };
  const cpp = await shownCode('cpp');
  assert.equal(cpp, cli('cpp'));
  assert.match(cpp, /fi::(x_)?spring\(4321, /);
  // the picture shows the sensation's function, not the program's opening lines
  await page.evaluate(() => {
    const pre = document.getElementById('export-code');
    const lines = pre.textContent.split('\n');
    const at = lines.findIndex((l) => l.startsWith('std::vector<feel::host::Effect> create_'));
    pre.scrollTop = (pre.scrollHeight * Math.max(0, at - 2)) / lines.length;
  });
  await page.locator('#export').screenshot({ path: join(shots, 'export.png'), timeout: kTimeout });
  const c = await shownCode('c');
  assert.equal(c, cli('c'));
  assert.match(c, /p\.conditions\[0\]\.pos_coefficient = 4321;/);
  const lib = await shownCode('library');
  assert.equal(lib, cli('library'));
  assert.match(lib, /SensationLibrary::load\("exported\.feel\.json", address\)/);

  // Download gives the code on show, under the file name the server chose
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#export-download')]);
  assert.equal(download.suggestedFilename(), `${name.replace(/\./g, '_')}.cpp`);
  assert.equal(readFileSync(await download.path(), 'utf8'), lib);

  // an edit shows in the open panel
  await page.click('#export .tab[data-lang="cpp"]');
  await input.fill('1234');
  await input.press('Enter');
  await synced(page);
  await page.waitForFunction(() => /spring\(1234, /.test(document.getElementById('export-code').textContent));
});
