// The handle pad: the device's travel as a square in its own axes and signs
// (docs/conventions.md: +x right, +y forward = up on the screen). Dragging moves the
// simulated hand's target; the handle is drawn where the device reports it, the force as
// an arrow from it, and the spatial effects of the sensation where they are: spring
// centres, walls, barriers, texture bumps. A 1-axis device gets a slider.
import { h, liveText } from '../dom';
import type { EffectJson } from '../document';
import type { Live } from '../live';
import type { Store } from '../store';

export interface PadState {
  position: number[];
  force: number[];
  target: [number, number] | null;
}

// One pointer move's way to the screen, in ms (docs/studio.md, "Latency"): the pointer
// event's timestamp -> its message sent (input), -> the server's share (pointer message
// received -> the state frame that shows the new force built: the device's loop, its
// report, the frame's pacing), -> that frame received (transport: the sockets, both
// ends' queues), -> the canvas drawn with it in the next animation frame (paint).
//
// The server's hops (pointer_hops, on the frame that first shows the change) split these
// further, all in ms: sendToRead (the message sent -> the server's socket read, both on
// the wall clock), apply (read -> the hand's target set), device (-> the first report
// with the new force in the server's sampler: the device's tick, its report, the
// in-process link, the sampler's wake-up), frame (-> the state frame built: the frame
// timer), builtToArrive (-> the browser's onmessage, wall clock), and, a frame later,
// write (the frame queued -> written to the socket) and ahead (messages before it).
export interface LatencySample {
  seq: number;
  at: number; // the pointer event's time (performance.now()'s clock), to find the move in a trace
  total: number;
  input: number;
  server: number;
  transport: number;
  paint: number;
  sendToRead?: number;
  apply?: number;
  device?: number;
  transit?: number;
  loop?: number;
  software?: number; // the device's software path: target set -> the taking tick's report at the server
  minFade?: number; // the device's lowest safety fade meanwhile (below 1: it faded the force)
  frame?: number;
  builtToArrive?: number;
  write?: number;
  ahead?: number;
}
export interface PointerHops {
  seq: number;
  read_wall_us: number;
  built_wall_us: number;
  apply_us: number;
  device_us: number;
  transit_us: number;
  loop_us: number;
  software_us: number;
  taken_t_us: number;
  min_fade: number;
  frame_us: number;
}
export interface PointerWritten {
  seq: number;
  ahead: number;
  write_us: number;
}
interface Probe {
  seq: number;
  event: number; // PointerEvent.timeStamp (performance.now()'s clock)
  sent: number;
  arrived?: number;
  server?: number;
  hops?: PointerHops;
}

const kSize = 320;
const kSliderHeight = 72; // a 1-axis device's pad: a slider, as wide as the square
const kMargin = 14;

export class Pad {
  readonly canvas: HTMLCanvasElement;
  private seq = 0;
  private dragging = false;
  state: PadState = { position: [0, 0], force: [0, 0], target: null };
  // pointer -> force shown, for the latency figures (docs/studio.md)
  private probe: Probe | null = null;
  latencies: LatencySample[] = [];
  lastHops: PointerHops | null = null; // the newest hops, for the latency bench's diagnosis
  private drawPending = false;
  private rect: DOMRect | null = null; // the canvas's place during a drag

  constructor(
    root: HTMLElement,
    private store: Store,
    private live: Live,
    private axes: () => number,
  ) {
    this.canvas = h('canvas', { width: kSize, height: kSize, id: 'pad-canvas', title: 'drag to move the hand' });
    const grip = h(
      'select',
      { id: 'grip', onchange: (e: Event) => live.send({ type: 'grip', grip: (e.target as HTMLSelectElement).value as 'firm' }) },
      ...['loose', 'firm', 'stiff'].map((g) => h('option', { value: g, selected: g === 'firm' }, `${g} hand`)),
    );
    root.replaceChildren(h('h2', {}, 'Handle'), this.canvas, h('div', { class: 'pad-tools' }, grip, h('span', { id: 'readout' })));
    this.canvas.addEventListener('pointerdown', (e) => {
      this.dragging = true;
      this.rect = this.canvas.getBoundingClientRect();
      this.canvas.setPointerCapture(e.pointerId);
      this.move(e);
    });
    // pointerrawupdate (where the browser has it) comes as the pointer moves; pointermove
    // is held back to the next animation frame, up to 16 ms later.
    const moveEvent = 'onpointerrawupdate' in window ? 'pointerrawupdate' : 'pointermove';
    this.canvas.addEventListener(moveEvent, (e) => this.dragging && this.move(e as PointerEvent));
    this.canvas.addEventListener('pointerup', () => (this.dragging = false));
    // the page moved under a drag: read the canvas's place again at the next move
    window.addEventListener('scroll', () => (this.rect = null), { capture: true, passive: true });
    window.addEventListener('resize', () => (this.rect = null));
  }


  setGrip(g: string): void {
    (document.getElementById('grip') as HTMLSelectElement).value = g;
  }

  private toScreen(x: number, y: number): [number, number] {
    const s = (kSize - 2 * kMargin) / 20000;
    const oneAxis = this.axes() === 1;
    return [kMargin + (x + 10000) * s, oneAxis ? this.canvas.height / 2 : kMargin + (10000 - y) * s];
  }

  private move(e: PointerEvent): void {
    // Read once per drag, not at each move: reading it after the page changed forces a
    // style and layout pass before the pointer's message can leave.
    const r = (this.rect ??= this.canvas.getBoundingClientRect());
    const s = (kSize - 2 * kMargin) / 20000;
    const px = ((e.clientX - r.left) * kSize) / r.width;
    const py = ((e.clientY - r.top) * this.canvas.height) / r.height;
    const clamp = (v: number) => Math.max(-10000, Math.min(10000, Math.round(v)));
    const x = clamp((px - kMargin) / s - 10000);
    const y = this.axes() === 1 ? 0 : clamp(10000 - (py - kMargin) / s);
    this.state.target = [x, y];
    this.live.send({ type: 'pointer', seq: ++this.seq, x, y });
    this.probe = { seq: this.seq, event: e.timeStamp, sent: performance.now() };
    this.draw();
  }

  // A state frame: the device's newest position and force. The first frame that answers
  // the newest pointer message with a changed force ends its probe once it is drawn.
  update(
    position: number[],
    force: number[],
    pointerSeq: number,
    pointerAgeUs: number,
    hops?: PointerHops,
    written?: PointerWritten,
  ): void {
    // A frame that changes nothing drawn (the handle and the force, in whole units) draws
    // nothing: a redraw costs the page's thread and the compositor's (docs/studio.md).
    const same = (a: number[], b: number[]) => a.length === b.length && a.every((v, i) => Math.round(v) === Math.round(b[i]));
    const changed = !same(position, this.state.position) || !same(force, this.state.force);
    this.state.position = position;
    this.state.force = force;
    const p = this.probe;
    if (p && hops?.seq === p.seq) p.hops = hops;
    if (hops) this.lastHops = hops;
    // The probe ends at the server's answer (the frame with this message's hops: the first
    // report of a tick after the device took the target whose force moved by more than 20
    // from the newest when the target was set),
    // not at a frame whose force still moves from the last target (a hand still settling).
    if (p && p.arrived === undefined && pointerSeq >= p.seq && hops?.seq === p.seq) {
      p.arrived = performance.now();
      p.server = pointerAgeUs / 1000;
    }
    if (written) {
      const l = this.latencies.find((s) => s.seq === written.seq);
      if (l) {
        l.write = written.write_us / 1000;
        l.ahead = written.ahead;
      }
    }
    if (changed || p?.arrived !== undefined) this.draw();
  }

  // Draws in the next animation frame, once however many frames arrived before it.
  draw(): void {
    if (this.drawPending) return;
    this.drawPending = true;
    requestAnimationFrame(() => {
      this.drawPending = false;
      this.paint();
      const p = this.probe;
      if (p?.arrived !== undefined) {
        const painted = performance.now();
        const server = Math.min(p.server ?? 0, p.arrived - p.sent);
        const sample: LatencySample = {
          seq: p.seq,
          at: p.event,
          total: painted - p.event,
          input: p.sent - p.event,
          server,
          transport: p.arrived - p.sent - server,
          paint: painted - p.arrived,
        };
        if (p.hops) {
          const wall = (t: number) => (performance.timeOrigin + t) * 1000; // µs
          sample.sendToRead = (p.hops.read_wall_us - wall(p.sent)) / 1000;
          sample.apply = p.hops.apply_us / 1000;
          sample.device = p.hops.device_us / 1000;
          sample.transit = p.hops.transit_us / 1000;
          if (p.hops.loop_us >= 0) sample.loop = p.hops.loop_us / 1000;
          if (p.hops.software_us >= 0) sample.software = p.hops.software_us / 1000;
          sample.minFade = p.hops.min_fade;
          sample.frame = p.hops.frame_us / 1000;
          sample.builtToArrive = (wall(p.arrived) - p.hops.built_wall_us) / 1000;
        }
        this.latencies.push(sample);
        if (this.latencies.length > 5000) this.latencies.shift();
        this.probe = null;
      }
    });
  }

  private paint(): void {
    const fmt = (v: number[]) => v.map((n) => Math.round(n)).join(', ');
    const readout = document.getElementById('readout');
    if (readout) liveText(readout, `position ${fmt(this.state.position)} · force ${fmt(this.state.force)}`);
    const c = this.canvas.getContext('2d')!;
    const oneAxis = this.axes() === 1;
    const height = oneAxis ? kSliderHeight : kSize;
    if (this.canvas.height !== height) {
      this.canvas.height = height;
      this.canvas.style.height = `${height}px`;
    }
    c.clearRect(0, 0, kSize, kSize);
    c.fillStyle = '#f7f8fa';
    c.fillRect(0, 0, kSize, kSize);
    c.strokeStyle = '#c5cad3';
    c.lineWidth = 1;
    if (oneAxis) {
      const [x0, y0] = this.toScreen(-10000, 0);
      const [x1] = this.toScreen(10000, 0);
      c.strokeRect(x0, y0 - 10, x1 - x0, 20);
    } else {
      const [x0, y0] = this.toScreen(-10000, 10000);
      const [x1, y1] = this.toScreen(10000, -10000);
      c.strokeRect(x0, y0, x1 - x0, y1 - y0);
      c.beginPath();
      const [cx, cy] = this.toScreen(0, 0);
      c.moveTo(cx, y0); c.lineTo(cx, y1); c.moveTo(x0, cy); c.lineTo(x1, cy);
      c.stroke();
    }
    for (const fx of this.store.effects()) this.drawEffect(c, fx);
    if (this.state.target) {
      const [tx, ty] = this.toScreen(this.state.target[0], this.state.target[1]);
      c.strokeStyle = '#8a93a3';
      c.setLineDash([3, 3]);
      c.beginPath(); c.arc(tx, ty, 9, 0, 2 * Math.PI); c.stroke();
      c.setLineDash([]);
    }
    const [hx, hy] = this.toScreen(this.state.position[0] ?? 0, oneAxis ? 0 : (this.state.position[1] ?? 0));
    c.fillStyle = '#2458d6';
    c.beginPath(); c.arc(hx, hy, 7, 0, 2 * Math.PI); c.fill();
    // the force: 10000 (full scale) is a third of the pad
    const k = (kSize / 3) / 10000;
    const fx = (this.state.force[0] ?? 0) * k;
    const fy = oneAxis ? 0 : -(this.state.force[1] ?? 0) * k;
    if (Math.hypot(fx, fy) > 2) {
      c.strokeStyle = '#d63a24';
      c.fillStyle = '#d63a24';
      c.lineWidth = 3;
      c.beginPath(); c.moveTo(hx, hy); c.lineTo(hx + fx, hy + fy); c.stroke();
      const a = Math.atan2(fy, fx);
      c.beginPath();
      c.moveTo(hx + fx, hy + fy);
      c.lineTo(hx + fx - 9 * Math.cos(a - 0.45), hy + fy - 9 * Math.sin(a - 0.45));
      c.lineTo(hx + fx - 9 * Math.cos(a + 0.45), hy + fy - 9 * Math.sin(a + 0.45));
      c.fill();
      c.lineWidth = 1;
    }
  }

  // Spatial effects where they act, from their parameters (the format's JSON).
  private drawEffect(c: CanvasRenderingContext2D, fx: EffectJson): void {
    const axes = (fx.axes as string[]) ?? [];
    const num = (o: unknown, k: string) => Number((o as Record<string, unknown> | undefined)?.[k] ?? 0);
    const line = (x0: number, y0: number, x1: number, y1: number) => {
      const [a, b] = this.toScreen(x0, y0);
      const [d, e] = this.toScreen(x1, y1);
      c.beginPath(); c.moveTo(a, b); c.lineTo(d, e); c.stroke();
    };
    // a line across the pad at distance `offset` along the compass angle (0 = +y, 9000 = +x)
    const across = (angle: number, offset: number) => {
      const t = (angle / 100) * (Math.PI / 180);
      const ux = Math.sin(t), uy = Math.cos(t);
      const px = ux * offset, py = uy * offset;
      line(px - uy * 15000, py + ux * 15000, px + uy * 15000, py - ux * 15000);
    };
    const alongAxis = (axis: string, offset: number) => (axis === 'x' ? across(9000, offset) : axis === 'y' ? across(0, offset) : undefined);
    c.save();
    c.beginPath();
    c.rect(kMargin, kMargin, kSize - 2 * kMargin, this.canvas.height - 2 * kMargin);
    c.clip();
    switch (fx.type) {
      case 'spring': case 'damper': case 'inertia': case 'friction': case 'angle_spring': {
        const conds = (fx.conditions as Record<string, unknown>[]) ?? [];
        if (fx.type !== 'spring' && fx.type !== 'angle_spring') break;
        const polar = (fx.direction as Record<string, unknown> | undefined)?.polar;
        if (typeof polar === 'number' && conds.length === 1) {
          // along a direction (an angle spring, a spring given one): the line it pulls
          // along, through its centre at `offset` along u (docs/conditions.md)
          const t = (polar / 100) * (Math.PI / 180);
          const ux = Math.sin(t), uy = Math.cos(t), off = num(conds[0], 'offset');
          c.strokeStyle = '#1b9e5a';
          c.lineWidth = 2;
          c.setLineDash([6, 4]);
          line(ux * (off - 15000), uy * (off - 15000), ux * (off + 15000), uy * (off + 15000));
          c.setLineDash([]);
          const [sx, sy] = this.toScreen(ux * off, uy * off);
          c.beginPath(); c.moveTo(sx - 8, sy); c.lineTo(sx + 8, sy); c.moveTo(sx, sy - 8); c.lineTo(sx, sy + 8); c.stroke();
          break;
        }
        const ox = axes.indexOf('x') >= 0 ? num(conds[fx.type === 'angle_spring' ? 0 : axes.indexOf('x')], 'offset') : 0;
        const oy = axes.indexOf('y') >= 0 && fx.type === 'spring' ? num(conds[axes.indexOf('y')], 'offset') : 0;
        const [sx, sy] = this.toScreen(ox, oy);
        c.strokeStyle = '#1b9e5a';
        c.lineWidth = 2;
        c.beginPath(); c.moveTo(sx - 8, sy); c.lineTo(sx + 8, sy); c.moveTo(sx, sy - 8); c.lineTo(sx, sy + 8); c.stroke();
        break;
      }
      case 'axis_wall': case 'angle_wall': {
        const w = fx.wall as Record<string, unknown>;
        c.strokeStyle = '#7a3fc4';
        c.lineWidth = 4;
        if (fx.type === 'axis_wall') alongAxis(axes[0], num(w, 'offset'));
        else across(num(w, 'angle'), num(w, 'offset'));
        break;
      }
      case 'axis_barrier': case 'angle_barrier': {
        const b = fx.barrier as Record<string, unknown>;
        c.strokeStyle = 'rgba(196, 120, 63, 0.55)';
        const px = (kSize - 2 * kMargin) / 20000;
        c.lineWidth = Math.max(2, num(b, 'thickness') * px);
        if (fx.type === 'axis_barrier') alongAxis(axes[0], num(b, 'offset'));
        else across(num(b, 'angle'), num(b, 'offset'));
        break;
      }
      case 'texture': {
        const t = fx.texture as Record<string, unknown>;
        const spacing = Math.max(200, num(t, 'spacing'));
        c.strokeStyle = 'rgba(120, 120, 120, 0.5)';
        c.lineWidth = 1;
        for (let p = 0; p <= 10000; p += spacing) {
          for (const s of p === 0 ? [0] : [p, -p]) alongAxis(axes[0], s);
        }
        break;
      }
    }
    c.restore();
  }
}
