// End to end: importing a file through the Studio (docs/import.md). A real DirectX 7 SDK
// effect file (tests/import/data/magneta.ffe, origin in ORIGIN.md) chosen in the file bar's
// Import goes to the server, which saves it as a new workspace file; the Studio opens it.
// The expected values are the file's bytes read by hand (a constant force of -10000 from
// 90°, 6.874 s after 455 ms, with an envelope), not the importer's output. A file over the
// 1 MiB limit is refused in the browser, naming the limit; a broken file gets the
// importer's sentence.
//
//   FEEL=build/apps/feel/feel node --test studio/e2e/   (make test-studio)
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { mkdtempSync, readFileSync, existsSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { chromium } from 'playwright-core';

const repo = resolve(import.meta.dirname, '../..');
const feel = resolve(repo, process.env.FEEL ?? 'build/apps/feel/feel');
const kTimeout = Number(process.env.KT ?? 90000); // ms: a loaded 2-core machine can stall a step for seconds

function startStudio(workspace) {
  return new Promise((ok, fail) => {
    const p = spawn(feel, ['studio', '--workspace', workspace, '--device', 'sim:iforce2', '--port', '0'], {
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

let browser, workspace, studio;
before(async () => {
  workspace = mkdtempSync(join(tmpdir(), 'feel-import-'));
  studio = await startStudio(workspace);
  browser = await chromium.launchPersistentContext(mkdtempSync(join(tmpdir(), 'feel-chromium-')), {
    executablePath: '/usr/bin/chromium',
    headless: true,
    viewport: { width: 1400, height: 1000 },
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
});
after(async () => {
  await browser?.close();
  studio?.proc.kill('SIGTERM');
  rmSync(workspace, { recursive: true, force: true });
});

const statusText = (page) => page.locator('#status').textContent();

test('a DirectInput effect file imports through the file bar into the workspace', async () => {
  const page = await browser.newPage();
  page.setDefaultTimeout(kTimeout);
  await page.goto(studio.url);
  await page.waitForFunction(() => Boolean(window.__studio?.store.state.hello));

  await page.setInputFiles('#import-file', resolve(repo, 'tests/import/data/magneta.ffe'));
  // Until the answer (or a refusal) shows; then it must be the import.
  await page.waitForFunction(() => /^(imported|error|import:)/.test(document.querySelector('#status')?.textContent ?? ''));
  assert.match(await statusText(page), /imported "magneta" into magneta\.feel\.json/);

  // The server saved it in the workspace, in canonical feel/1.
  const path = join(workspace, 'magneta.feel.json');
  assert.ok(existsSync(path));
  const saved = JSON.parse(readFileSync(path, 'utf8')).sensations.magneta;
  assert.equal(saved.type, 'constant');
  assert.equal(saved.constant.magnitude, -10000);
  assert.equal(saved.duration_us, 6874000);
  assert.equal(saved.start_delay_us, 455000);
  assert.deepEqual(saved.direction, { polar: 9000 });
  assert.equal(saved.envelope.settle_time_us, 962360);
  assert.equal(saved.envelope.fade_time_us, 1099840);

  // The Studio opened it: the file bar names it and the design space holds its effect.
  await page.waitForFunction(() => document.querySelector('#file-name')?.textContent?.startsWith('magneta.feel.json'));
  const doc = await page.evaluate(() => window.__studio.store.state.doc);
  assert.equal(doc.file, 'magneta.feel.json');
  assert.equal(doc.sensations[doc.current].name, 'magneta');
  assert.equal(doc.sensations[doc.current].effects[0].type, 'constant');

  // A second import of the same file gets a free name rather than overwriting.
  await page.setInputFiles('#import-file', resolve(repo, 'tests/import/data/magneta.ffe'));
  await page.waitForFunction(() => document.querySelector('#status')?.textContent?.includes('magneta_2.feel.json'));
  assert.ok(existsSync(join(workspace, 'magneta_2.feel.json')));

  // Over the limit: refused in the browser, naming it; nothing is sent or saved.
  await page.setInputFiles('#import-file', { name: 'big.wav', mimeType: 'audio/wav', buffer: Buffer.alloc((1 << 20) + 1) });
  await page.waitForFunction(() => document.querySelector('#status')?.textContent?.startsWith('import: big.wav'));
  assert.match(await statusText(page), /up to 1048576 bytes \(1 MiB\)/);
  assert.ok(!existsSync(join(workspace, 'big.feel.json')));

  // A broken file: the importer's sentence, with the field and the allowed range.
  const broken = readFileSync(resolve(repo, 'tests/import/data/magneta.ffe'));
  broken.writeUInt32LE(20000, 0xe0); // DIENVELOPE.dwAttackLevel: after its chunk's id, size and dwSize (0xd4..0xdf)
  await page.setInputFiles('#import-file', { name: 'broken.ffe', mimeType: 'application/octet-stream', buffer: broken });
  await page.waitForFunction(() => document.querySelector('#status')?.textContent?.startsWith('error:'));
  assert.match(await statusText(page), /DIENVELOPE\.dwAttackLevel = 20000 is out of range \(allowed 0\.\.10000\)/);
  assert.ok(!existsSync(join(workspace, 'broken.feel.json')));
  await page.close();
});
