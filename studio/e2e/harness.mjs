// What every end-to-end file needs: `feel studio` on a free port, and Debian's Chromium with
// a fresh profile (--user-data-dir, which playwright passes for a persistent context).
import { spawn } from 'node:child_process';
import { mkdtempSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { chromium } from 'playwright-core';

export const repo = resolve(import.meta.dirname, '../..');
export const feel = resolve(repo, process.env.FEEL ?? 'build/apps/feel/feel');

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

export function launchBrowser(viewport = { width: 1400, height: 1000 }) {
  return chromium.launchPersistentContext(mkdtempSync(join(tmpdir(), 'feel-chromium-')), {
    executablePath: '/usr/bin/chromium',
    headless: true,
    acceptDownloads: true,
    viewport,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync',
      ...(process.env.FEEL_CHROMIUM_ARGS?.split(' ').filter(Boolean) ?? [])],
  });
}
