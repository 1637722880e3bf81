// Pointer -> force shown in the browser, and where the machine's CPU goes meanwhile: the
// e2e's latency scenario (a spring of coefficient 5000, the stiff hand, the pointer moved
// between -6000 and +6000 on the handle pad, each move timed to the pad drawn with the new
// force) on its own, with the CPU time of every process taking part (the feel server, and
// Chromium's browser, renderer, GPU and utility processes, from /proc) over the moves.
// Optionally the page's own JavaScript profile (PROFILE=1: the functions that held the
// page's one thread, by self time). Prints the load average (docs/studio.md, "Latency").
//
//   node studio/bench/browser-latency.mjs build/apps/feel/feel [moves]
//   SAMPLES_OUT=FILE ... appends every move's hops to FILE (pool-latency.mjs pools runs)
//   FEEL_CHROMIUM_ARGS="--flag --flag" ... tries Chromium flags on top of the harness's
import { appendFileSync, readFileSync, readdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { loadavg, tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
process.env.FEEL ??= resolve(process.argv[2] ?? 'build/apps/feel/feel');
// a page whose document the harness served (FEEL_DIST below) is not on the loopback for
// Chromium's local network access checks, and its WebSocket to the server would be refused
if (process.env.FEEL_DIST) process.env.FEEL_CHROMIUM_ARGS = `${process.env.FEEL_CHROMIUM_ARGS ?? ''} --disable-features=LocalNetworkAccessChecks`;
const { launchBrowser, startStudio } = await import('../e2e/harness.mjs'); // after FEEL is set
const moves = Number(process.argv[3] ?? 200);
const tick = 100; // USER_HZ: /proc's CPU times are in 1/100 s
const quantile = (list, p) => {
  const l = [...list].sort((a, b) => a - b);
  return l.length ? l[Math.min(l.length - 1, Math.floor(p * l.length))] : NaN;
};
const stat = (pid) => {
  try {
    const f = readFileSync(`/proc/${pid}/stat`, 'utf8').split(') ')[1].split(' ');
    return (Number(f[11]) + Number(f[12])) / tick; // utime + stime, s
  } catch {
    return 0;
  }
};
// Every process below `root`, with what it is (Chromium's --type, or its name).
function processes(root) {
  const kids = new Map();
  for (const d of readdirSync('/proc')) {
    if (!/^\d+$/.test(d)) continue;
    try {
      const ppid = Number(readFileSync(`/proc/${d}/stat`, 'utf8').split(') ')[1].split(' ')[1]);
      if (!kids.has(ppid)) kids.set(ppid, []);
      kids.get(ppid).push(Number(d));
    } catch { /* gone */ }
  }
  const out = [];
  const walk = (pid) => {
    for (const k of kids.get(pid) ?? []) {
      // Chromium rewrites its argv into one string: read the flags from the whole line
      const cmd = readFileSync(`/proc/${k}/cmdline`, 'utf8').replace(/\0/g, ' ');
      const type = cmd.match(/--type=(\S+)/)?.[1];
      const sub = cmd.match(/--utility-sub-type=(\S+)/)?.[1];
      const name = type ? `chromium ${type}${sub ? ` ${sub.split('.').pop()}` : ''}` : cmd.split(' ')[0].split('/').pop();
      out.push({ pid: k, name });
      walk(k);
    }
  };
  walk(root);
  return out;
}

const workspace = mkdtempSync(join(tmpdir(), 'feel-studio-bench-'));
const studio = await startStudio(workspace);

// The server and its workspace go with this process however it ends (a thrown timeout, an
// unhandled rejection, or `timeout`/Ctrl-C sending a signal): a bench must not leave a
// `feel studio` running that holds its output pipe (docs/studio.md, "Latency").
process.on('exit', () => {
  try { studio.proc.kill('SIGTERM'); } catch { /* gone */ }
  rmSync(workspace, { recursive: true, force: true });
});
for (const [signal, code] of [['SIGINT', 130], ['SIGTERM', 143], ['SIGHUP', 129]]) process.on(signal, () => process.exit(code));
const browser = await launchBrowser();
const page = await browser.newPage();
// FEEL_DIST=DIR: the front end from a Vite build in DIR instead of the one embedded in the
// binary (`npm run build -- --outDir DIR`: tries a page change without relinking `feel`)
if (process.env.FEEL_DIST) {
  await page.route(/\/(index\.html|assets\/.*)?$/, (route) => {
    const path = new URL(route.request().url()).pathname;
    const file = join(process.env.FEEL_DIST, path === '/' ? 'index.html' : path);
    route.fulfill({ path: file, contentType: file.endsWith('.js') ? 'text/javascript' : file.endsWith('.css') ? 'text/css' : 'text/html' });
  });
}
await page.goto(studio.url);
await page.waitForFunction(() => Boolean(window.__studio?.store.state.hello) && window.__studio.frames() > 2);
await page.click('#palette li[data-type="spring"]');
for (const a of [0, 1]) {
  for (const side of ['pos', 'neg']) { // as the e2e sets them: through the form
    const input = page.locator(`#editor .field[data-path="conditions[${a}].${side}_coefficient"] input[type=number]`);
    await input.fill('5000');
    await input.press('Enter');
    await input.blur();
    await page.waitForFunction(() => window.__studio.synced());
  }
}
await page.click('#design .icon[data-effect="0"] button.play');
await page.waitForFunction(() => window.__studio.liveStates()[0]?.state === 'playing');
await page.selectOption('#grip', 'stiff');
const box = await page.locator('#pad-canvas').boundingBox();
const at = (x) => box.x + box.width / 2 + (x / 20000) * (box.width - 28);
await page.mouse.move(at(0), box.y + box.height / 2);
await page.mouse.down();
await page.waitForTimeout(500);

// what a part of the page costs: PAGE_EVAL="window.__studio.plot.draw = () => {}" switches it off
if (process.env.PAGE_EVAL) await page.evaluate(process.env.PAGE_EVAL);
if (process.env.IDLE) {
  // the page at rest (the spring playing, the pointer still): what the Studio costs the
  // machine when nothing happens
  const procs = processes(process.pid);
  const before = new Map(procs.map((p) => [p.pid, stat(p.pid)]));
  const seconds = Number(process.env.IDLE);
  await page.waitForTimeout(seconds * 1000);
  const cpu = new Map();
  for (const p of procs) cpu.set(p.name, (cpu.get(p.name) ?? 0) + stat(p.pid) - before.get(p.pid));
  console.log(`CPU at rest over ${seconds} s (% of one core): ` +
    [...cpu].filter(([, s]) => s > 0).sort((a, b) => b[1] - a[1]).map(([n, s]) => `${n} ${((100 * s) / seconds).toFixed(0)}%`).join(', ') +
    `; load average ${loadavg().map((l) => l.toFixed(1)).join(' ')}${process.env.FEEL_CHROMIUM_ARGS ? `; extra flags: ${process.env.FEEL_CHROMIUM_ARGS}` : ''}`);
}
const cdp = process.env.PROFILE ? await browser.newCDPSession(page) : null;
if (cdp) {
  await cdp.send('Profiler.enable');
  await cdp.send('Profiler.setSamplingInterval', { interval: 200 });
  await cdp.send('Profiler.start');
}
// TRACE=1: Chromium's own trace of the moves, summed per thread and event (where the
// renderer's main thread, its compositor and the GPU process spend their time).
const tracer = process.env.TRACE ? await browser.newCDPSession(page) : null;
const traceEvents = [];
if (tracer) {
  tracer.on('Tracing.dataCollected', (d) => traceEvents.push(...d.value));
  await tracer.send('Tracing.start', {
    transferMode: 'ReportEvents',
    traceConfig: { includedCategories: [...(process.env.TRACE_INVALIDATIONS ? ['disabled-by-default-devtools.timeline.invalidationTracking'] : []), 'blink.user_timing', 'devtools.timeline', 'disabled-by-default-devtools.timeline', 'toplevel', 'viz', 'cc', 'gpu', 'blink', 'v8'] },
  });
}
const procs = [...processes(process.pid)];
const before = new Map(procs.map((p) => [p.pid, stat(p.pid)]));
const t0 = performance.now();
await page.evaluate(() => (window.__studio.pad.latencies.length = 0));
// where the moves begin on the page's clock, and (TRACE=1) on the trace's
const markAt = await page.evaluate(() => performance.mark('feel-bench-moves').startTime);
for (let i = 0; i < moves; ++i) {
  await page.mouse.move(at(i % 2 ? 6000 : -6000), box.y + box.height / 2);
  await page.waitForFunction((n) => window.__studio.pad.latencies.length > n, i, { timeout: 30000 });
  if (process.env.SLOWEST) {
    // a slow device hop: the device's reports around it (device ms, force x, position x)
    const around = await page.evaluate(() => {
      const s = window.__studio.pad;
      const h = s.lastHops;
      if (!h || h.device_us < 30000) return null;
      const t0 = h.taken_t_us / 1000;
      return { hops: h, rows: window.__studio.plot.window().filter((r) => r[0] >= t0 - 6 && r[0] <= t0 + h.loop_us / 1000 + 3)
        .map((r) => `${(r[0] - t0).toFixed(0)}:${r[1]}/${r[3]}`).join(' ') };
    });
    if (around) console.log(`  slow device hop: ${JSON.stringify(around.hops)}\n    reports (ms after the take: force x/position x): ${around.rows}`);
  }
}
const seconds = (performance.now() - t0) / 1000;
const cpu = new Map();
for (const p of procs) cpu.set(p.name, (cpu.get(p.name) ?? 0) + stat(p.pid) - before.get(p.pid));
const lat = await page.evaluate(() => window.__studio.pad.latencies.slice());
const stage = (k) => {
  const v = lat.map((l) => l[k]).filter((x) => x !== undefined);
  return `p50=${quantile(v, 0.5).toFixed(1)} p99=${quantile(v, 0.99).toFixed(1)}`;
};
// SAMPLES_OUT=FILE: every move's hops appended to FILE, one JSON line a move, so that runs
// can be pooled (studio/bench/pool-latency.mjs: p50 and p99 over all of them).
if (process.env.SAMPLES_OUT) appendFileSync(process.env.SAMPLES_OUT, lat.map((l) => JSON.stringify(l)).join('\n') + '\n');
const faded = lat.filter((l) => l.minFade < 1);
console.log(`moves during which the device's safety faded the force: ${faded.length}` +
  (faded.length ? ` (their device hops: ${faded.map((l) => l.device?.toFixed(0)).join(' ')} ms)` : ''));
console.log(`pointer->force shown (n=${lat.length}): ${stage('total')} ms; input ${stage('input')}, server ${stage('server')}, ` +
  `transport ${stage('transport')}, paint ${stage('paint')}; device ${stage('device')} (software ${stage('software')}, hand ${stage('loop')}, transit ${stage('transit')}), frame ${stage('frame')}, built->onmessage ${stage('builtToArrive')}`);
if (process.env.SLOWEST) {
  for (const l of [...lat].sort((a, b) => b.total - a.total).slice(0, Number(process.env.SLOWEST))) {
    console.log(`  slow: ${Object.entries(l).map(([k, v]) => `${k}=${typeof v === 'number' ? v.toFixed(1) : v}`).join(' ')}`);
  }
}
console.log(`CPU over the ${seconds.toFixed(1)} s of moves (% of one core): ` +
  [...cpu].sort((a, b) => b[1] - a[1]).map(([n, s]) => `${n} ${((100 * s) / seconds).toFixed(0)}%`).join(', ') +
  `; load average ${loadavg().map((l) => l.toFixed(1)).join(' ')}${process.env.FEEL_CHROMIUM_ARGS ? `; extra flags: ${process.env.FEEL_CHROMIUM_ARGS}` : ''}`);
if (tracer) {
  const done = new Promise((ok) => tracer.once('Tracing.tracingComplete', ok));
  await tracer.send('Tracing.end');
  await done;
  // TRACE_OUT=FILE: the raw events too, for a closer look (e.g. chrome://tracing)
  if (process.env.TRACE_OUT) writeFileSync(process.env.TRACE_OUT, JSON.stringify({ traceEvents }));
  const threads = new Map(); // pid:tid -> name
  for (const e of traceEvents) if (e.ph === 'M' && e.name === 'thread_name') threads.set(`${e.pid}:${e.tid}`, e.args.name);
  const sums = new Map();
  for (const e of traceEvents) {
    if (e.ph !== 'X' || !e.dur) continue;
    const key = `${threads.get(`${e.pid}:${e.tid}`) ?? e.tid} ${e.name}`;
    const v = sums.get(key) ?? [0, 0];
    v[0] += e.dur / 1000;
    v[1] += 1;
    sums.set(key, v);
  }
  console.log('trace (inclusive ms over the run, count), top 40:');
  for (const [k, [ms, n]] of [...sums].sort((a, b) => b[1][0] - a[1][0]).slice(0, 40)) console.log(`  ${ms.toFixed(0)} ms  ${n}  ${k}`);
  waits(traceEvents, threads, lat);
}
// What the page's main thread did while a move's answering frame waited for it: for the
// TRACE_SLOW (default 5) slowest moves, the main thread's tasks between the frame built at
// the server and the page's paint, each with its costliest parts; and over all the moves,
// the main thread's busy time within those waits by the kind of task.
function waits(events, threads, latencies) {
  const mark = events.find((e) => e.name === 'feel-bench-moves');
  if (!mark) return console.log('no mark in the trace: the waits cannot be placed');
  const shift = mark.ts - markAt * 1000; // trace µs = page ms * 1000 + shift
  const tid = [...threads].find(([k, n]) => n === 'CrRendererMain' && k.startsWith(`${mark.pid}:`))?.[0];
  const main = events.filter((e) => e.ph === 'X' && `${e.pid}:${e.tid}` === tid && e.dur !== undefined).sort((a, b) => a.ts - b.ts || b.dur - a.dur);
  // nest them: a task's children are the events inside it
  const tops = [];
  const stack = [];
  for (const e of main) {
    e.kids = [];
    while (stack.length && stack[stack.length - 1].ts + stack[stack.length - 1].dur <= e.ts) stack.pop();
    if (stack.length) stack[stack.length - 1].kids.push(e);
    else tops.push(e);
    stack.push(e);
  }
  const label = (e) => e.args?.data?.type ?? e.args?.data?.functionName ?? e.args?.data?.url?.split('/').pop() ?? '';
  const describe = (e, depth = 0) => {
    const parts = e.kids.filter((k) => k.dur >= 300).sort((a, b) => b.dur - a.dur).slice(0, 4);
    return parts.map((k) => `${' '.repeat(depth * 2)}      ${(k.dur / 1000).toFixed(1)} ${k.name}${label(k) ? ` (${label(k)})` : ''}\n${depth < 3 ? describe(k, depth + 1) : ''}`).join('');
  };
  // the kind of a task: its costliest leaf-ward chain's names, two deep
  const kind = (e) => {
    let k = e;
    const names = [];
    while (k.kids.length && names.length < 3) {
      k = k.kids.reduce((a, b) => (b.dur > a.dur ? b : a));
      names.push(k.name + (label(k) ? `(${label(k)})` : ''));
    }
    return names.join(' > ') || e.name;
  };
  const lat = latencies.filter((l) => l.builtToArrive !== undefined);
  const byKind = new Map();
  let waited = 0;
  for (const l of lat) {
    const built = (l.at + l.total - l.paint - l.builtToArrive) * 1000 + shift;
    const arrived = (l.at + l.total - l.paint) * 1000 + shift;
    waited += arrived - built;
    for (const t of tops) {
      const a = Math.max(t.ts, built), b = Math.min(t.ts + t.dur, arrived);
      if (b <= a) continue;
      const k = kind(t);
      byKind.set(k, (byKind.get(k) ?? 0) + (b - a));
    }
  }
  // the main thread's JavaScript by function (inclusive), and its frames
  const fns = new Map();
  for (const e of main) {
    if (e.name !== 'FunctionCall' && e.name !== 'TimerFire' && e.name !== 'FireAnimationFrame') continue;
    const d = e.args?.data ?? {};
    const k = `${e.name} ${d.functionName ?? ''} ${d.url ? `${d.url.split('/').pop()}:${d.lineNumber}:${d.columnNumber}` : ''}`;
    const v = fns.get(k) ?? [0, 0];
    v[0] += e.dur / 1000;
    v[1] += 1;
    fns.set(k, v);
  }
  console.log('main thread by callback (inclusive ms, count), top 12:');
  for (const [k, [ms, n]] of [...fns].sort((a, b) => b[1][0] - a[1][0]).slice(0, 12)) console.log(`  ${ms.toFixed(0)} ms  ${n}  ${k}`);
  const bmf = main.filter((e) => e.name === 'ProxyMain::BeginMainFrame');
  const busy = tops.reduce((a, t) => a + t.dur, 0) / 1000;
  console.log(`main thread busy ${busy.toFixed(0)} ms; ${bmf.length} main frames, ${(bmf.reduce((a, e) => a + e.dur, 0) / 1000).toFixed(0)} ms`);
  console.log(`main thread busy during the frames' waits (built -> onmessage, ${(waited / 1000).toFixed(0)} ms over ${lat.length} moves), by task kind:`);
  for (const [k, us] of [...byKind].sort((a, b) => b[1] - a[1]).slice(0, 15)) console.log(`  ${(us / 1000).toFixed(1)} ms  ${k}`);
  for (const l of [...lat].sort((a, b) => b.total - a.total).slice(0, Number(process.env.TRACE_SLOW ?? 5))) {
    const built = (l.at + l.total - l.paint - l.builtToArrive) * 1000 + shift;
    const painted = (l.at + l.total) * 1000 + shift;
    console.log(`  move ${l.seq}: total ${l.total.toFixed(1)}, built->onmessage ${l.builtToArrive.toFixed(1)}, paint ${l.paint.toFixed(1)} ms; main thread's tasks from built (ms after it: start, length):`);
    for (const t of tops) {
      if (t.ts + t.dur <= built || t.ts >= painted || t.dur < 200) continue;
      console.log(`    ${((t.ts - built) / 1000).toFixed(1)} +${(t.dur / 1000).toFixed(1)} ${t.name}\n${describe(t)}`.trimEnd());
    }
  }
}
if (cdp) {
  const { profile } = await cdp.send('Profiler.stop');
  const self = new Map();
  const dt = new Map();
  profile.samples.forEach((id, i) => dt.set(id, (dt.get(id) ?? 0) + (profile.timeDeltas[i] ?? 0)));
  for (const n of profile.nodes) {
    const f = n.callFrame;
    const key = `${f.functionName || '(anon)'} ${f.url.split('/').pop()}:${f.lineNumber}`;
    self.set(key, (self.get(key) ?? 0) + (dt.get(n.id) ?? 0));
  }
  const total = [...self.values()].reduce((a, b) => a + b, 0);
  console.log('page JS self time (top 15, % of the run):');
  for (const [k, us] of [...self].sort((a, b) => b[1] - a[1]).slice(0, 15)) {
    console.log(`  ${((100 * us) / total).toFixed(1)}%  ${(us / 1000).toFixed(0)} ms  ${k}`);
  }
}
await page.mouse.up();
await browser.close();
studio.proc.kill('SIGTERM');
rmSync(workspace, { recursive: true, force: true });
