// The scrolling plot: force and position on each axis over the last 5 s (uPlot).
import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';

const kWindowMs = 5000;
const kColors = ['#d63a24', '#2458d6', '#e08a1e', '#1b9e5a', '#7a3fc4', '#555'];

export class Plot {
  private plot: uPlot | null = null;
  private rows: number[][] = []; // [t_ms, f..., p...]
  private axisNames: string[] = [];

  constructor(private root: HTMLElement) {}

  setAxes(names: string[]): void {
    this.axisNames = names;
    const series: uPlot.Series[] = [{ label: 't (s)' }];
    names.forEach((n, i) => series.push({ label: `force ${n}`, stroke: kColors[i % 6], width: 1.5, scale: 'f' }));
    // Position: the axis's colour, thin and faded. Not dashed: a dashed 2500-point path is
    // the costliest thing the page's one thread drew (Chromium strokes dashes in software
    // without a GPU), and a state frame waits while it draws (docs/studio.md, "Latency").
    names.forEach((n, i) => series.push({ label: `position ${n}`, stroke: `${kColors[i % 6]}80`, width: 1, scale: 'f' }));
    this.plot?.destroy();
    this.plot = new uPlot(
      {
        width: Math.max(400, this.root.clientWidth - 8),
        height: 210,
        series,
        scales: { x: { time: false }, f: { range: [-10000, 10000] } },
        axes: [{ label: 's' }, { scale: 'f', label: '±10000', size: 60 }],
        legend: { live: false },
        cursor: { show: false },
      },
      [[], ...series.slice(1).map(() => [])] as uPlot.AlignedData,
      this.root,
    );
  }

  push(samples: number[][]): void {
    if (!this.plot || samples.length === 0) return;
    for (const s of samples) this.rows.push(s);
    const newest = this.rows[this.rows.length - 1][0];
    let drop = 0;
    while (drop < this.rows.length && this.rows[drop][0] < newest - kWindowMs) ++drop;
    if (drop) this.rows.splice(0, drop);
  }

  private drawn = -1;

  // How long each redraw took (ms), for the latency figures: the redraw holds the page's
  // one thread, and a state frame that arrives meanwhile waits.
  drawTimes: number[] = [];

  draw(): void {
    if (!this.plot || this.rows.length === 0) return;
    const newest = this.rows[this.rows.length - 1][0];
    if (newest === this.drawn) return;
    const t0 = performance.now();
    this.drawn = newest;
    const n = this.axisNames.length;
    const cols: number[][] = [this.rows.map((r) => r[0] / 1000)];
    for (let c = 1; c <= 2 * n; ++c) cols.push(this.rows.map((r) => r[c] ?? 0));
    this.plot.setData(cols as uPlot.AlignedData);
    this.drawTimes.push(performance.now() - t0);
    if (this.drawTimes.length > 5000) this.drawTimes.shift();
  }

  // For tests and the latency probe: the samples in the window.
  window(): number[][] {
    return this.rows;
  }
}
