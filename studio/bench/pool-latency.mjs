// Pools the moves of several browser-latency.mjs runs (SAMPLES_OUT=FILE, one JSON line a
// move) and prints p50, p99 and the largest value of each hop over all of them: a run's p99
// of 200 moves is its second-largest, so the goal's p99 is read over the pooled moves.
//
//   node studio/bench/pool-latency.mjs FILE
import { readFileSync } from 'node:fs';

const file = process.argv[2];
if (!file) {
  console.error('usage: node studio/bench/pool-latency.mjs FILE (written by browser-latency.mjs with SAMPLES_OUT=FILE)');
  process.exit(2);
}
const moves = readFileSync(file, 'utf8').split('\n').filter((l) => l.trim()).map((l) => JSON.parse(l));
const quantile = (sorted, p) => sorted[Math.min(sorted.length - 1, Math.floor(p * sorted.length))];
console.log(`${moves.length} moves`);
for (const hop of ['total', 'software', 'transit', 'device', 'transport', 'paint', 'input', 'server']) {
  const v = moves.map((m) => m[hop]).filter((x) => typeof x === 'number').sort((a, b) => a - b);
  if (!v.length) continue;
  console.log(`${hop.padEnd(9)} p50=${quantile(v, 0.5).toFixed(1)} p99=${quantile(v, 0.99).toFixed(1)} max=${v[v.length - 1].toFixed(1)} ms (n=${v.length})`);
}
