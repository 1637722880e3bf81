// Periodic waves and their sweeps (§4.1–4.2, §9.4): the waveform over one play, drawn by
// the engine's law (offset + envelope(|magnitude|)·sign·waveform(cycle fraction), cycle
// fraction = τ/period + phase, src/engine/waves/periodic_wave.cpp), with handles for the
// magnitude, the offset, the phase (where a cycle starts) and the period (where the next
// one starts), and the envelope's four (envelope.ts). A sweep adds two direction dials,
// start and end, showing the arc swept in its sense, and the sense as a toggle; a wave
// with a polar direction gets a dial for it. Live: the playhead at the effect's own time,
// the device's force along the effect there, the dials' red needle where it comes from.
import { h } from '../dom';
import { envelopeDrag, envelopeLevel, envelopeParts, type EnvelopeJson } from './envelope';
import { block, blockOf, forceAlong, type Graphic, type GraphicContext, num, polarOf } from './graphic';
import { liveFeed } from './live_feed';
import { curve, frameParts, kH, kW, levelAt, playheadParts, timeAt, timeFrame, type TimeFrame } from './time_plot';
import { DirectionDial, forceFromAngle } from './widgets/direction_dial';
import { clamp, draggable, handle, svg } from './widgets/svg_kit';

export const kWaveTypes = ['sine', 'square', 'triangle', 'saw_up', 'saw_down'];
export const kSweepTypes = kWaveTypes.map((t) => `sweep_${t}`);

export function waveformValue(type: string, p: number): number {
  switch (type.replace(/^sweep_/, '')) {
    case 'sine': return Math.sin(2 * Math.PI * p);
    case 'square': return p < 0.5 ? 1 : -1;
    case 'triangle': return p < 0.25 ? 4 * p : p < 0.75 ? 2 - 4 * p : 4 * p - 4;
    case 'saw_up': return 2 * p - 1;
    case 'saw_down': return 1 - 2 * p;
  }
  return 0;
}

// The sweep's angle at τ (0.01°), as the engine moves it: linearly over the duration, the
// sense's way round; clockwise increases the compass angle.
export function sweepAngle(b: Record<string, unknown>, tauUs: number, durationUs: number): number {
  const start = num(b, 'sweep_start_angle'), end = num(b, 'sweep_end_angle');
  const progress = Math.min(1, tauUs / durationUs);
  const mod = (v: number) => ((v % 36000) + 36000) % 36000;
  return b.sweep_sense === 'counterclockwise' ? mod(start - mod(start - end) * progress) : mod(start + mod(end - start) * progress);
}

export class WaveEditor implements Graphic {
  readonly el: HTMLElement;
  private readonly plot: SVGSVGElement;
  private readonly still: SVGGElement;
  private readonly live: SVGGElement;
  private readonly dials: HTMLElement;
  private readonly startDial: DirectionDial;
  private readonly endDial: DirectionDial;
  private readonly polarDial: DirectionDial;
  private readonly sense: HTMLButtonElement;
  private c: GraphicContext | null = null;
  private frame: TimeFrame | null = null;
  private liveShown = false; // the end dial shows a live needle

  constructor() {
    this.plot = svg('svg', { viewBox: `0 0 ${kW} ${kH}`, class: 'graphic-plot', 'data-graphic': 'wave' });
    this.still = svg('g');
    this.live = svg('g', { class: 'live' });
    this.plot.append(this.still, this.live);
    draggable(this.plot, (name) => this.drag(name));
    const periodic = (set: (b: Record<string, unknown>) => void) => this.c?.edit((e) => set(blockOf(e, 'periodic')));
    this.startDial = new DirectionDial('sweep_start_angle', 'sweep start', (a) => periodic((b) => (b.sweep_start_angle = a)));
    this.endDial = new DirectionDial('sweep_end_angle', 'sweep end', (a) => periodic((b) => (b.sweep_end_angle = a)));
    this.polarDial = new DirectionDial('direction.polar', 'direction (polar)', (a) => this.c?.edit((e) => (e.direction = { polar: a })));
    this.sense = h('button', {
      class: 'sense', 'data-control': 'sweep_sense',
      onclick: () => periodic((b) => (b.sweep_sense = b.sweep_sense === 'counterclockwise' ? 'clockwise' : 'counterclockwise')),
    });
    this.dials = h('div', { class: 'dials' });
    this.el = h('div', { class: 'graphic wave-editor' }, this.plot, this.dials);
    liveFeed.subscribe(() => this.drawLive());
  }

  render(c: GraphicContext): void {
    this.c = c;
    const fx = c.fx;
    const b = block(fx, 'periodic');
    const period = Math.max(1, num(b, 'period_us', 100000));
    const f = timeFrame(fx.duration_us, Math.max(1000000, 4 * period));
    this.frame = f;
    const mag = num(b, 'magnitude'), offset = num(b, 'offset'), phase = num(b, 'phase');
    const env = fx.envelope as EnvelopeJson | undefined;
    const duration = f.infinite ? null : f.spanUs;
    const value = (tau: number) => {
      const frac = ((tau % period) / period + phase / 36000) % 1;
      return offset + Math.sign(mag) * envelopeLevel(env, Math.abs(mag), tau, duration) * waveformValue(fx.type, frac);
    };
    const cycleStart = ((1 - phase / 36000) % 1) * period;
    const parts: SVGElement[] = [...frameParts(f)];
    // at most 3 points a pixel: more cycles than that are a band of colour either way
    parts.push(curve(f, value, Math.min(1500, Math.max(800, Math.round((f.spanUs / period) * 40)))));
    parts.push(svg('line', { x1: f.t.p0, x2: f.t.p1, y1: f.v.px(offset), y2: f.v.px(offset), stroke: '#7a3fc4', 'stroke-dasharray': '3 3' }));
    parts.push(...envelopeParts(f, env, () => Math.abs(mag), offset));
    // one period, bracketed above the wave
    const yb = f.v.px(clamp(offset + Math.abs(mag), -10000, 10000)) - 14;
    const x0 = f.t.px(cycleStart), x1 = f.t.px(Math.min(f.spanUs, cycleStart + period));
    parts.push(svg('path', { d: `M ${x0} ${yb + 5} V ${yb} H ${x1} V ${yb + 5}`, fill: 'none', stroke: '#1b9e5a' }));
    parts.push(svg('text', { x: x1 + 4, y: yb + 3, 'font-size': 9, fill: '#1b9e5a' }, `period ${(period / 1000).toFixed(1)} ms`));
    parts.push(handle('phase', x0, f.v.px(offset), '#1b9e5a', 'phase: drag where a cycle starts'));
    parts.push(handle('period_us', f.t.px(cycleStart + period), f.v.px(offset), '#0f7a43', 'period: drag where the next cycle starts'));
    parts.push(handle('magnitude', f.t.px(f.spanUs / 2), f.v.px(clamp(offset + mag, -10000, 10000)), '#2458d6', 'magnitude: drag up or down'));
    parts.push(svg('rect', { 'data-handle': 'offset', x: f.t.px(f.spanUs * 0.75) - 5, y: f.v.px(offset) - 5, width: 10, height: 10, fill: '#7a3fc4', class: 'handle' }, svg('title', {}, 'offset: drag up or down')));
    this.still.replaceChildren(...parts);
    // the dials
    const sweep = fx.type.startsWith('sweep_');
    const kids: HTMLElement[] = [];
    if (sweep) {
      const arc = { from: num(b, 'sweep_start_angle'), to: num(b, 'sweep_end_angle'), clockwise: b.sweep_sense !== 'counterclockwise' };
      this.startDial.draw({ angle: arc.from, arc });
      this.endDial.draw({ angle: arc.to, arc });
      this.sense.textContent = arc.clockwise ? '↻ clockwise' : '↺ counterclockwise';
      kids.push(this.startDial.el, this.endDial.el, h('div', { class: 'dial-box' }, h('div', { class: 'dial-label' }, 'sense'), this.sense));
    } else if (polarOf(fx) !== null) {
      this.polarDial.draw({ angle: polarOf(fx) ?? 0 });
      kids.push(this.polarDial.el);
    }
    kids.push(h('div', { class: 'graphic-legend' },
      'Drag: ', h('b', { style: 'color:#2458d6' }, 'magnitude'), ', ', h('b', { style: 'color:#7a3fc4' }, 'offset'), ', ',
      h('b', { style: 'color:#1b9e5a' }, 'phase, period'), ', ', h('b', { style: 'color:#c47a00' }, 'envelope'), ' (impulse, settle, fade time, fade level). Live: ',
      h('b', { style: 'color:#1b9e5a' }, 'playhead'), ', ', h('b', { style: 'color:#d63a24' }, 'device force'), '.'));
    this.dials.replaceChildren(...kids);
    this.drawLive();
  }

  private drawLive(): void {
    const c = this.c, f = this.frame;
    if (!c || !f || !this.el.isConnected) return;
    const tau = liveFeed.elapsedUs(c.index);
    const b = block(c.fx, 'periodic');
    const sweep = c.fx.type.startsWith('sweep_');
    const angle = sweep && tau !== null && !f.infinite ? sweepAngle(b, tau, f.spanUs) : polarOf(c.fx);
    const force = tau === null ? null : forceAlong(c.fx, liveFeed.frame, c.deviceAxes, angle);
    this.live.replaceChildren(...playheadParts(f, tau, force));
    if (sweep && (tau !== null || this.liveShown)) {
      this.liveShown = tau !== null;
      const from = tau === null ? null : forceFromAngle(liveFeed.frame.force[c.deviceAxes.indexOf('x')] ?? 0, liveFeed.frame.force[c.deviceAxes.indexOf('y')] ?? 0);
      const arc = { from: num(b, 'sweep_start_angle'), to: num(b, 'sweep_end_angle'), clockwise: b.sweep_sense !== 'counterclockwise' };
      this.endDial.draw({ angle: arc.to, arc, live: from });
    }
  }

  private drag(name: string): ((p: { x: number; y: number }) => void) | null {
    const c = this.c, f = this.frame;
    if (!c || !f) return null;
    const b = () => block(c.fx, 'periodic');
    const set = (k: string, v: number) => c.edit((e) => (blockOf(e, 'periodic')[k] = v));
    const offset = () => num(b(), 'offset');
    const env = envelopeDrag(name, f, () => Math.abs(num(b(), 'magnitude')), offset(), (x) => c.edit((e) => (e.envelope = x)), () => c.fx.envelope as EnvelopeJson | undefined);
    if (env) return env;
    switch (name) {
      case 'magnitude': return (p) => set('magnitude', clamp(levelAt(f, p.y) - offset(), -10000, 10000));
      case 'offset': return (p) => set('offset', clamp(levelAt(f, p.y), -10000, 10000));
      case 'phase': return (p) => {
        const period = Math.max(1, num(b(), 'period_us', 100000));
        const frac = ((1 - ((f.t.value(p.x) / period) % 1)) % 1 + 1) % 1;
        set('phase', Math.round(frac * 36000) % 36000);
      };
      case 'period_us': return (p) => {
        const period = Math.max(1, num(b(), 'period_us', 100000));
        const start = ((1 - num(b(), 'phase') / 36000) % 1) * period;
        set('period_us', Math.max(1000, timeAt(f, p.x) - Math.round(start / 1000) * 1000));
      };
    }
    return null;
  }
}
