// The scrolling plot: force and position on each axis over the last 5 s (uPlot).
import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';

const kWindowMs = 5000;
const kColors = ['#d63a24', '#2458d6', '#e08a1e', '#1b9e5a', '#7a3fc4', '#555'];

export class Plot {
  private plot: uPlot | null = null;
  private rows: number[][] = []; // [t_ms, f..., p...]
  // The same window as uPlot's columns, kept as the rows come and go (appended, and cut
  // at the front when they leave the 5 s window), so that a redraw hands uPlot the columns
  // it has rather than rebuilding ~2500 rows' worth of them.
  private cols: number[][] = [[]];
  // Whether a row arrived whose values differ from the row before it: at rest the server's
  // keep-alive frames only carry the device's clock on, and the plot need not redraw.
  private dirty = false;

  constructor(private root: HTMLElement) {}

  setAxes(names: string[]): void {
    const series: uPlot.Series[] = [{ label: 't (s)' }];
    names.forEach((n, i) => series.push({ label: `force ${n}`, stroke: kColors[i % 6], width: 1.5, scale: 'f' }));
    // Position: the axis's colour, thin and faded. Not dashed: a dashed 2500-point path is
    // the costliest thing the page's one thread drew (Chromium strokes dashes in software
    // without a GPU), and a state frame waits while it draws (docs/studio.md, "Latency").
    names.forEach((n, i) => series.push({ label: `position ${n}`, stroke: `${kColors[i % 6]}80`, width: 1, scale: 'f' }));
    this.plot?.destroy();
    this.rows = [];
    this.cols = series.map(() => []);
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
      this.cols as uPlot.AlignedData,
      this.root,
    );
  }

  push(samples: number[][]): void {
    if (!this.plot || samples.length === 0) return;
    const width = this.cols.length;
    for (const s of samples) {
      const last = this.rows[this.rows.length - 1];
      if (!last || s.some((v, i) => i > 0 && v !== last[i])) this.dirty = true;
      this.rows.push(s);
      this.cols[0].push(s[0] / 1000);
      for (let c = 1; c < width; ++c) this.cols[c].push(s[c] ?? 0);
    }
    const newest = this.rows[this.rows.length - 1][0];
    let drop = 0;
    while (drop < this.rows.length && this.rows[drop][0] < newest - kWindowMs) ++drop;
    if (drop) {
      this.rows.splice(0, drop);
      for (const c of this.cols) c.splice(0, drop);
    }
  }

  // How long each redraw took (ms), for the latency figures: the redraw holds the page's
  // one thread, and a state frame that arrives meanwhile waits.
  drawTimes: number[] = [];

  // Redraws when a row with new values came since the last redraw; at rest the plot stays
  // as it is (it shows the last 5 s of activity) and costs the page nothing.
  draw(): void {
    if (!this.plot || this.rows.length === 0 || !this.dirty) return;
    const t0 = performance.now();
    this.dirty = false;
    this.plot.setData(this.cols as uPlot.AlignedData);
    this.drawTimes.push(performance.now() - t0);
    if (this.drawTimes.length > 5000) this.drawTimes.shift();
  }

  // For tests and the latency probe: the samples in the window.
  window(): number[][] {
    return this.rows;
  }
}
