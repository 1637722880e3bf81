// The scrolling plot: force and position on each axis over the last 5 s (uPlot).
import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';

const kWindowMs = 5000;
// The plot redraws at most 20 times a second: a redraw holds the page's one thread, and
// 20 Hz scrolls a 5 s window smoothly enough (docs/studio.md, "Latency").
const kRedrawMs = 50;
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

  private scheduled = false;
  private lastDraw = -Infinity;

  // `yieldFrame(t)`: whether the animation frame at time t belongs to something more
  // urgent (the pad showing a pointer's answer); the redraw then waits for the next one.
  constructor(
    private root: HTMLElement,
    private yieldFrame: (frameTime: number) => boolean = () => false,
  ) {}

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
    if (this.dirty) this.schedule();
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

  // The redraw goes in an animation frame (drawn with the frame's other canvases, one
  // frame to composite rather than two), at most every kRedrawMs, and not in a frame that
  // shows a pointer's answer on the pad (it waits one frame for the next).
  private schedule(): void {
    if (this.scheduled) return;
    this.scheduled = true;
    let yielded = false; // once: a drag has an answer in nearly every frame
    const inFrame = (t: number) => {
      if (!yielded && this.yieldFrame(t)) {
        yielded = true;
        requestAnimationFrame(inFrame);
        return;
      }
      this.scheduled = false;
      this.lastDraw = performance.now();
      this.draw();
    };
    window.setTimeout(() => requestAnimationFrame(inFrame), Math.max(0, this.lastDraw + kRedrawMs - performance.now()));
  }

  // Redraws when a row with new values came since the last redraw; at rest the plot stays
  // as it is (it shows the last 5 s of activity) and costs the page nothing.
  draw(): void {
    if (!this.plot || this.rows.length === 0 || !this.dirty) return;
    const t0 = performance.now();
    this.dirty = false;
    this.plot.setData(this.decimated(Math.max(1, Math.round(this.plot.bbox.width))) as uPlot.AlignedData);
    this.drawTimes.push(performance.now() - t0);
    if (this.drawTimes.length > 5000) this.drawTimes.shift();
  }

  // The window as uPlot draws it: a 5 s window holds some 5000 rows (the device reports
  // at 1 kHz) for a plot some 700 pixels wide, and uPlot would walk and stroke every one
  // of them at each redraw, on the page's one thread. Each pixel column keeps only what
  // a line drawn through all its rows shows there: each series' lowest and highest value,
  // in the order they came, at the column's first and last time. The lines look the
  // same; the redraw walks at most two points per pixel (docs/studio.md, "Latency").
  private decimated(pixels: number): number[][] {
    const x = this.cols[0];
    const n = x.length;
    if (n <= 2 * pixels) return this.cols;
    const x0 = x[0];
    const span = x[n - 1] - x0 || 1;
    const out = this.cols.map(() => [] as number[]);
    const series = this.cols.length;
    let i = 0;
    while (i < n) {
      const column = Math.min(pixels - 1, Math.floor(((x[i] - x0) / span) * pixels));
      let end = i + 1;
      while (end < n && Math.min(pixels - 1, Math.floor(((x[end] - x0) / span) * pixels)) === column) ++end;
      out[0].push(x[i]);
      if (end - i > 1) out[0].push(x[end - 1]);
      for (let c = 1; c < series; ++c) {
        const v = this.cols[c];
        let lo = i, hi = i;
        for (let k = i + 1; k < end; ++k) {
          if (v[k] < v[lo]) lo = k;
          if (v[k] > v[hi]) hi = k;
        }
        if (end - i > 1) {
          out[c].push(v[Math.min(lo, hi)], v[Math.max(lo, hi)]);
        } else {
          out[c].push(v[i]);
        }
      }
      i = end;
    }
    return out;
  }

  // For tests and the latency probe: the samples in the window.
  window(): number[][] {
    return this.rows;
  }
}
