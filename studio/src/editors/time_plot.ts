// The frame every "force over time" editor draws in (waves, forces, profiles): time of one
// play across (the duration, or a window of an endless effect), force ±10000 up, a grid,
// and the live playhead (the effect's own time) with the device's force at it.
import { Scale, svg } from './widgets/svg_kit';

export const kW = 560;
export const kH = 230;
const kLeft = 44;
const kRight = 14;
const kTop = 12;
const kBottom = 26;

export interface TimeFrame {
  t: Scale; // µs -> x
  v: Scale; // force -> y
  spanUs: number; // the time shown
  infinite: boolean;
}

export function timeFrame(durationUs: unknown, endlessWindowUs: number): TimeFrame {
  const infinite = typeof durationUs !== 'number';
  const spanUs = infinite ? endlessWindowUs : Math.max(1, durationUs as number);
  return {
    t: new Scale(0, spanUs, kLeft, kW - kRight),
    v: new Scale(-10000, 10000, kH - kBottom, kTop),
    spanUs,
    infinite,
  };
}

const fmtTime = (us: number) => (us >= 1e6 ? `${+(us / 1e6).toFixed(2)} s` : `${+(us / 1000).toFixed(1)} ms`);

export function frameParts(f: TimeFrame): SVGElement[] {
  const parts: SVGElement[] = [svg('rect', { x: f.t.p0, y: f.v.p1, width: f.t.p1 - f.t.p0, height: f.v.p0 - f.v.p1, fill: '#f7f8fa', stroke: '#d5d9e0' })];
  for (const v of [-10000, -5000, 0, 5000, 10000]) {
    parts.push(svg('line', { x1: f.t.p0, x2: f.t.p1, y1: f.v.px(v), y2: f.v.px(v), stroke: v === 0 ? '#aab1bd' : '#e3e6eb' }));
    parts.push(svg('text', { x: f.t.p0 - 4, y: f.v.px(v) + 3, 'text-anchor': 'end', 'font-size': 9, fill: '#7a8394' }, String(v)));
  }
  for (let i = 0; i <= 4; ++i) {
    const us = (f.spanUs * i) / 4;
    parts.push(svg('text', { x: f.t.px(us), y: kH - 12, 'text-anchor': i === 0 ? 'start' : i === 4 ? 'end' : 'middle', 'font-size': 9, fill: '#7a8394' }, fmtTime(us)));
  }
  parts.push(svg('text', { x: kW - kRight, y: kH - 2, 'text-anchor': 'end', 'font-size': 9, fill: '#7a8394' },
    f.infinite ? `endless: the first ${fmtTime(f.spanUs)} shown` : 'time of one play (duration)'));
  return parts;
}

// A polyline of value(τ) over the frame, n points.
export function curve(f: TimeFrame, value: (tauUs: number) => number, n = 800, attrs: Record<string, string | number> = {}): SVGElement {
  const pts: string[] = [];
  for (let i = 0; i <= n; ++i) {
    const tau = (f.spanUs * i) / n;
    pts.push(`${f.t.px(tau).toFixed(1)},${f.v.px(value(tau)).toFixed(1)}`);
  }
  return svg('polyline', { points: pts.join(' '), fill: 'none', stroke: '#2458d6', 'stroke-width': 1.6, ...attrs });
}

// The live part: where the effect is in its play, and the device's force there.
export function playheadParts(f: TimeFrame, tauUs: number | null, force: number | null): SVGElement[] {
  if (tauUs === null) return [];
  const tau = f.infinite ? tauUs % f.spanUs : Math.min(tauUs, f.spanUs);
  const x = f.t.px(tau);
  const parts: SVGElement[] = [svg('line', { x1: x, x2: x, y1: f.v.p1, y2: f.v.p0, stroke: '#1b9e5a', 'stroke-width': 1.5, class: 'playhead' })];
  if (force !== null) parts.push(svg('circle', { cx: x, cy: f.v.px(Math.max(-10000, Math.min(10000, force))), r: 5, fill: '#d63a24', class: 'live-dot' }, svg('title', {}, 'the device’s force now')));
  return parts;
}

// One µs of time from a pointer x, to whole milliseconds (what a hand can place).
export const timeAt = (f: TimeFrame, x: number) => Math.max(0, Math.round(f.t.value(x) / 1000) * 1000);
export const levelAt = (f: TimeFrame, y: number) => Math.round(f.v.value(y));
