// Constant force, ramp, vector force and smart pop (§4, §8.x): the force over one play,
// with a start and an end handle (a ramp's start and end levels; a constant's magnitude,
// which both ends set), the envelope's handles where the type takes one, and a direction
// dial for a polar direction (a vector force). The shaped curve follows the engine: the
// envelope shapes |value| and keeps its sign (src/engine/envelope.hpp). Live: the
// playhead and the device's force along the effect; the dial's red needle is where the
// device's force comes from now.
import { h } from '../dom';
import { envelopeDrag, envelopeLevel, envelopeParts, type EnvelopeJson } from './envelope';
import { block, blockOf, forceAlong, type Graphic, type GraphicContext, num, polarOf } from './graphic';
import { liveFeed } from './live_feed';
import { curve, frameParts, kH, kW, levelAt, playheadParts, timeFrame, type TimeFrame } from './time_plot';
import { DirectionDial, forceFromAngle } from './widgets/direction_dial';
import { clamp, draggable, svg } from './widgets/svg_kit';

export const kForceTypes = ['constant', 'ramp', 'vector_force', 'smart_pop'];

const square = (name: string, x: number, y: number, title: string) =>
  svg('rect', { 'data-handle': name, x: x - 6, y: y - 6, width: 12, height: 12, fill: '#2458d6', stroke: '#fff', 'stroke-width': 2, class: 'handle' }, svg('title', {}, title));

export class ForceOverTimeEditor implements Graphic {
  readonly el: HTMLElement;
  private readonly plot: SVGSVGElement;
  private readonly still: SVGGElement;
  private readonly live: SVGGElement;
  private readonly side: HTMLElement;
  private readonly dial: DirectionDial;
  private c: GraphicContext | null = null;
  private frame: TimeFrame | null = null;

  constructor() {
    this.plot = svg('svg', { viewBox: `0 0 ${kW} ${kH}`, class: 'graphic-plot', 'data-graphic': 'force' });
    this.still = svg('g');
    this.live = svg('g', { class: 'live' });
    this.plot.append(this.still, this.live);
    draggable(this.plot, (name) => this.drag(name));
    this.dial = new DirectionDial('direction.polar', 'direction (polar)', (a) => this.c?.edit((e) => (e.direction = { polar: a })));
    this.side = h('div', { class: 'dials' });
    this.el = h('div', { class: 'graphic force-editor' }, this.plot, this.side);
    liveFeed.subscribe(() => this.drawLive());
  }

  private levels(c: GraphicContext): [number, number] {
    if (c.fx.type === 'ramp') {
      const r = block(c.fx, 'ramp');
      return [num(r, 'start'), num(r, 'end')];
    }
    const m = num(block(c.fx, 'constant'), 'magnitude');
    return [m, m];
  }

  render(c: GraphicContext): void {
    this.c = c;
    const f = timeFrame(c.fx.duration_us, 1000000);
    this.frame = f;
    const [start, end] = this.levels(c);
    const env = c.info?.envelope ? (c.fx.envelope as EnvelopeJson | undefined) : undefined;
    const duration = f.infinite ? null : f.spanUs;
    const raw = (tau: number) => (f.infinite ? start : start + ((end - start) * tau) / f.spanUs);
    const shaped = (tau: number) => Math.sign(raw(tau)) * envelopeLevel(env, Math.abs(raw(tau)), tau, duration);
    const parts: SVGElement[] = [...frameParts(f)];
    if (env) parts.push(curve(f, raw, 50, { stroke: '#9aa3b2', 'stroke-dasharray': '4 3', 'stroke-width': 1 }));
    parts.push(curve(f, shaped, 400, { 'stroke-width': 2.2 }));
    if (c.info?.envelope) parts.push(...envelopeParts(f, env, (tau) => Math.abs(raw(tau)), 0, 'none', start + end < 0 ? -1 : 1));
    parts.push(square('start', f.t.px(0) + 8, f.v.px(start), c.fx.type === 'ramp' ? 'ramp start: drag up or down' : 'magnitude: drag up or down'));
    parts.push(square('end', f.t.px(f.spanUs) - 8, f.v.px(f.infinite ? start : end), c.fx.type === 'ramp' ? 'ramp end: drag up or down' : 'magnitude: drag up or down'));
    this.still.replaceChildren(...parts);
    const kids: HTMLElement[] = [];
    if (polarOf(c.fx) !== null) {
      this.dial.draw({ angle: polarOf(c.fx) ?? 0 });
      kids.push(this.dial.el);
    }
    kids.push(h('div', { class: 'graphic-legend' },
      c.fx.type === 'ramp' ? 'Drag the ramp’s start and end (squares)' : 'Drag the magnitude (either square)',
      c.info?.envelope ? ', and the envelope (impulse, settle, fade time, fade level)' : '',
      polarOf(c.fx) !== null ? '; the dial sets where the force comes from' : '',
      '. Live: the playhead and the device’s force (red).'));
    this.side.replaceChildren(...kids);
    this.drawLive();
  }

  private drawLive(): void {
    const c = this.c, f = this.frame;
    if (!c || !f || !this.el.isConnected) return;
    const tau = liveFeed.elapsedUs(c.index);
    const force = tau === null ? null : forceAlong(c.fx, liveFeed.frame, c.deviceAxes, polarOf(c.fx));
    this.live.replaceChildren(...playheadParts(f, tau, force));
    if (polarOf(c.fx) !== null) {
      const ax = (a: string) => liveFeed.frame.force[c.deviceAxes.indexOf(a)] ?? 0;
      this.dial.draw({ angle: polarOf(c.fx) ?? 0, live: tau === null ? null : forceFromAngle(ax('x'), ax('y')) });
    }
  }

  private drag(name: string): ((p: { x: number; y: number }) => void) | null {
    const c = this.c, f = this.frame;
    if (!c || !f) return null;
    const [start, end] = this.levels(c);
    const raw = (tau: number) => Math.abs(f.infinite ? start : start + ((end - start) * tau) / f.spanUs);
    const env = envelopeDrag(name, f, raw, 0, (x) => c.edit((e) => (e.envelope = x)), () => c.fx.envelope as EnvelopeJson | undefined);
    if (env) return env;
    if (name !== 'start' && name !== 'end') return null;
    return (p) => {
      const v = clamp(levelAt(f, p.y), -10000, 10000);
      c.edit((e) => {
        if (e.type === 'ramp') blockOf(e, 'ramp')[name] = v;
        else blockOf(e, 'constant').magnitude = v;
      });
    };
  }
}
