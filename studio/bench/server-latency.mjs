// The server's share of pointer -> force, without a browser: `feel studio` on the in-process
// simulated stick, a WebSocket client (Node's) that plays a spring of coefficient 5000,
// moves the stiff hand's target between -6000 and +6000 every 30 ms, and times each move
// to the state frame that answers it (the first report of a tick after the take whose force
// moved; total: the client's clock; server: the
// frame's pointer_age_us, the server's clock), with the server's hops (pointer_hops: the
// target handed to the hand, the first report with the new force, the frame built).
// Prints p50/p99/max and the load average (docs/studio.md, "Latency").
//
//   node --experimental-websocket studio/bench/server-latency.mjs build/apps/feel/feel [moves]
import { spawn } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { loadavg, tmpdir } from 'node:os';
import { join } from 'node:path';

const feel = process.argv[2] ?? 'build/apps/feel/feel';
const moves = Number(process.argv[3] ?? 300);
// the pause between a move answered and the next (the browser moves again at once)
const pauseMs = Number(process.argv[4] ?? 30);
const workspace = mkdtempSync(join(tmpdir(), 'feel-studio-bench-'));
const proc = spawn(feel, ['studio', '--workspace', workspace, '--port', '0', '--hand', 'stiff'], {
  stdio: ['ignore', 'pipe', 'inherit'],
});
// The server and its workspace go with this process however it ends (a thrown timeout, an
// unhandled rejection, or `timeout`/Ctrl-C sending a signal): a bench must not leave a
// `feel studio` running that holds its output pipe.
process.on('exit', () => {
  try { proc.kill('SIGTERM'); } catch { /* gone */ }
  rmSync(workspace, { recursive: true, force: true });
});
for (const [signal, code] of [['SIGINT', 130], ['SIGTERM', 143], ['SIGHUP', 129]]) process.on(signal, () => process.exit(code));
const host = await new Promise((ok, fail) => {
  let out = '';
  proc.stdout.on('data', (d) => {
    out += d;
    const m = out.match(/open http:\/\/(\S+)\//);
    if (m) ok(m[1]);
  });
  proc.on('exit', (code) => fail(new Error(`feel studio exited ${code}: ${out}`)));
});
const ws = new WebSocket(`ws://${host}/live`);
let last = null;
let waiter = null;
// Every report's device time, from the frames' samples: the plot's completeness (the device
// reports at every tick of its loop, up to 1 kHz; a longer gap is reports the plot never got).
const sampleTimes = [];
let reportMs = 1;
ws.onmessage = (e) => {
  const m = JSON.parse(e.data);
  if (m.type === 'hello') reportMs = 1000 / Math.min(1000, m.device.loop_rate_hz);
  if (m.type !== 'state') return;
  for (const row of m.samples) sampleTimes.push(row[0]);
  last = m;
  waiter?.(m);
};
await new Promise((ok) => (ws.onopen = ok));
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
const condition = { pos_coefficient: 5000, neg_coefficient: 5000 };
const spring = { type: 'spring', duration_us: 'infinite', axes: ['x', 'y'], conditions: [condition, condition] };
ws.send(JSON.stringify({ type: 'set_sensation', seq: 1, name: 'spring', effects: [spring] }));
await sleep(300);
ws.send(JSON.stringify({ type: 'play', effect: 0 }));
await sleep(300);

const total = [];
const server = [];
const hops = { apply: [], device: [], software: [], loop: [], transit: [], frame: [] };
for (let i = 1; i <= moves; ++i) {
  const t0 = performance.now();
  ws.send(JSON.stringify({ type: 'pointer', seq: i, x: i % 2 ? 6000 : -6000, y: 0 }));
  for (;;) {
    const m = await new Promise((ok) => (waiter = ok));
    if (m.pointer_hops?.seq === i) {
      hops.apply.push(m.pointer_hops.apply_us / 1000);
      hops.device.push(m.pointer_hops.device_us / 1000);
      hops.transit.push(m.pointer_hops.transit_us / 1000);
      hops.loop.push(m.pointer_hops.loop_us / 1000);
      hops.software.push(m.pointer_hops.software_us / 1000);
      hops.frame.push(m.pointer_hops.frame_us / 1000);
    }
    if (m.pointer_hops?.seq === i) { // the answer: a tick after the take, its force moved
      total.push(performance.now() - t0);
      server.push(m.pointer_age_us / 1000);
      break;
    }
  }
  await sleep(pauseMs);
}
const q = (list, p) => {
  const s = [...list].sort((a, b) => a - b);
  return s[Math.min(s.length - 1, Math.floor(p * s.length))].toFixed(1);
};
console.log(`pointer message -> frame with the new force (n=${moves}): client p50=${q(total, 0.5)} ms ` +
  `p99=${q(total, 0.99)} ms max=${q(total, 1)} ms; server p50=${q(server, 0.5)} ms p99=${q(server, 0.99)} ms ` +
  `max=${q(server, 1)} ms; hops p50/p99: apply ${q(hops.apply, 0.5)}/${q(hops.apply, 0.99)}, ` +
  `device ${q(hops.device, 0.5)}/${q(hops.device, 0.99)} (software ${q(hops.software, 0.5)}/${q(hops.software, 0.99)}; of it the hand ${q(hops.loop, 0.5)}/${q(hops.loop, 0.99)}, transit ${q(hops.transit, 0.5)}/${q(hops.transit, 0.99)}), frame ${q(hops.frame, 0.5)}/${q(hops.frame, 0.99)} ms ` +
  `(n=${hops.device.length}); load average ${loadavg().map((l) => l.toFixed(1)).join(' ')}`);
// The slowest device hops, split: a stall in the loop's taking of the target, the handle's
// motion (loop), or the way back (transit)?
const slow = hops.device.map((d, i) => ({ device: d, loop: hops.loop[i], transit: hops.transit[i] }))
  .sort((a, b) => b.device - a.device).slice(0, 3);
console.log(`slowest device hops (ms): ${slow.map((h) => `${h.device.toFixed(1)} = take ${(h.device - h.loop - h.transit).toFixed(1)} + loop ${h.loop.toFixed(1)} + transit ${h.transit.toFixed(1)}`).join('; ')}`);
let missing = 0;
const gaps = new Map(); // gap (ms) -> how often: a skipped tick of the device's 1 kHz loop makes 2 ms
for (let i = 1; i < sampleTimes.length; ++i) {
  const gap = Math.round(sampleTimes[i] - sampleTimes[i - 1]);
  missing += Math.max(0, Math.round(gap / reportMs) - 1);
  if (gap > reportMs) gaps.set(gap, (gaps.get(gap) ?? 0) + 1);
}
console.log(`plot samples: ${sampleTimes.length} received, ${missing} missing by the device's clock ` +
  `(${((100 * missing) / (sampleTimes.length + missing)).toFixed(2)}%; gaps in ms×count: ` +
  `${[...gaps].sort((a, b) => a[0] - b[0]).map(([g, n]) => `${g}×${n}`).join(' ') || 'none'}), ` +
  `the sampler's queue dropped ${last.dropped_reports}`);
ws.close();
proc.kill('SIGTERM');
rmSync(workspace, { recursive: true, force: true });
process.exit(0);
