// Dynamics (§5): a schematic of the simulated mass and what holds it, animated from the
// device's interim reports (§5.2: the mass's position relative to the handle, per axis),
// with the handle drawn where the device reports it. The named dynamics that are the
// control law (recoil, impact, liquid, inertia, center drift, the law itself) show a mass
// on a tether: a spring, a dashpot beside it, the free play as a gap, gravity as an arrow.
// The sling shows a ball on a string, the paddle a ball above a paddle. Beside it, the
// §8.4 mapping: what each parameter of the named dynamic sets on the control law (the
// engine's table, src/engine/dynamics/control_law_mapping.cpp; docs/dynamics.md), with
// the values now. A direction dial sets a directional dynamic's angle. The reports come
// only when the effect asks for them (interim_reporting): the checkbox here sets it.
import { h } from '../dom';
import { block, blockOf, type Graphic, type GraphicContext, num } from './graphic';
import { type DynamicReportJson, liveFeed } from './live_feed';
import { DirectionDial } from './widgets/direction_dial';
import { svg } from './widgets/svg_kit';

export const kDynamicTypes = ['dynamic_recoil', 'dynamic_impact', 'dynamic_liquid', 'dynamic_inertia', 'dynamic_center_drift',
  'dynamic_control_law', 'dynamic_sling', 'dynamic_paddle'];

// §8.4: parameter -> control-law term, per named dynamic.
const kMapping: Record<string, [string, string][]> = {
  dynamic_recoil: [['blast_intensity', 'VelInit (split over x, y by blast_direction)'], ['dynamic_mass', 'Mass'], ['blast_resonance', 'KPos = KNeg'], ['blast_decay', 'B']],
  dynamic_impact: [['impact_intensity', 'VelInit (split by impact_direction)'], ['dynamic_mass', 'Mass'], ['elasticity', 'KPos = KNeg'], ['collision_absorption', 'B']],
  dynamic_liquid: [['density', 'Mass'], ['settle', 'KPos = KNeg'], ['viscosity', 'B, and Drag']],
  dynamic_inertia: [['inertia', 'Mass'], ['play', 'Length (free play)'], ['—', 'KPos = KNeg = 10000, B for damping ratio 0.7']],
  dynamic_center_drift: [['stiffness', 'KPos = KNeg'], ['drift_resistance', 'Drag (time constant 10 s × resistance / stiffness)'], ['—', 'Mass = 1, B critical']],
  dynamic_control_law: [['mass', 'Mass'], ['k_pos / k_neg', 'KPos / KNeg'], ['b', 'B'], ['drag', 'Drag'], ['gravity', 'Gravity'], ['length', 'Length (free play)'], ['pos_init / vel_init', 'PosInit / VelInit']],
  dynamic_sling: [['—', 'not the control law: a ball on a string (its own law)'], ['ball_mass', 'the ball'], ['string_length', 'the slack'], ['string_compliance', 'the string’s stretch'], ['ball_damping', 'the string’s damping']],
  dynamic_paddle: [['—', 'not the control law: a ball bouncing on a paddle'], ['ball_mass', 'the ball'], ['initial_velocity', 'its launch speed, along initial_velocity_direction'], ['paddle_compliance', 'the paddle’s give'], ['paddle_damping', 'its damping'], ['gravity', 'the pull on the ball']],
};
const kDirectionField: Record<string, string> = {
  dynamic_recoil: 'blast_direction', dynamic_impact: 'impact_direction', dynamic_paddle: 'initial_velocity_direction',
};

const kSize = 260;
const kC = kSize / 2;

// What the tests read: every interim report the schematic drew, with where the mass went.
export const schematicTrace: { t_ms: number; drawnAt: number; x: number; y: number }[] = [];

function zigzag(x0: number, y0: number, x1: number, y1: number, turns = 8, width = 7): string {
  const dx = x1 - x0, dy = y1 - y0, len = Math.hypot(dx, dy) || 1;
  const nx = -dy / len, ny = dx / len;
  let d = `M ${x0} ${y0}`;
  for (let i = 1; i < turns * 2; ++i) {
    const f = i / (turns * 2), s = i % 2 ? width : -width;
    d += ` L ${x0 + dx * f + nx * s} ${y0 + dy * f + ny * s}`;
  }
  return `${d} L ${x1} ${y1}`;
}

export class DynamicsSchematic implements Graphic {
  readonly el: HTMLElement;
  private readonly pic: SVGSVGElement;
  private readonly side: HTMLElement;
  private readonly dial: DirectionDial;
  private c: GraphicContext | null = null;
  private newest: DynamicReportJson | null = null;
  private peak = 0; // the largest offset of the mass seen in this play, position units
  private trail: DynamicReportJson[] = []; // this play's reports (bounded): the mass's path
  private trailStarts = -1; // the play they belong to (the effect's start count)

  constructor() {
    this.pic = svg('svg', { viewBox: `0 0 ${kSize} ${kSize}`, width: kSize, height: kSize, class: 'schematic', 'data-graphic': 'dynamics' });
    this.side = h('div', { class: 'mapping' });
    this.dial = new DirectionDial('dynamic_direction', 'direction', (a) => {
      const c = this.c;
      const field = c && kDirectionField[c.fx.type];
      if (c && field) c.edit((e) => (blockOf(e, 'dynamic')[field] = a));
    });
    this.el = h('div', { class: 'graphic dynamics-editor' }, this.pic, this.side);
    liveFeed.subscribe((_f, reports) => {
      const c = this.c;
      if (!c) return;
      const mine = reports.filter((r) => r.effect === c.index);
      if (mine.length) {
        this.newest = mine[mine.length - 1];
        const starts = liveFeed.frame.effects[c.index]?.starts ?? 0;
        if (starts !== this.trailStarts) this.trail = [];
        this.trailStarts = starts;
        this.trail.push(...mine);
        if (this.trail.length > 240) this.trail.splice(0, this.trail.length - 240);
        for (const r of mine) schematicTrace.push({ t_ms: r.t_ms, drawnAt: performance.now(), x: r.position[0] ?? 0, y: r.position[1] ?? 0 });
        if (schematicTrace.length > 4000) schematicTrace.splice(0, schematicTrace.length - 4000);
      }
      if (this.el.isConnected) this.drawPicture();
    });
  }

  render(c: GraphicContext): void {
    if (this.c?.fx.type !== c.fx.type || this.c.index !== c.index) {
      this.newest = null;
      this.peak = 0;
      this.trail = [];
    }
    this.c = c;
    const d = block(c.fx, 'dynamic');
    const rows = (kMapping[c.fx.type] ?? []).map(([p, term]) => {
      const laws = (d.control_law as Record<string, unknown>[]) ?? [];
      const value = p === '—' ? '' : c.fx.type === 'dynamic_control_law'
        ? laws.map((l) => p.split(' / ').map((k) => String(l[k] ?? 0)).join(' / ')).join(' · ')
        : String(d[p] ?? 0);
      return h('tr', {}, h('td', { class: 'param' }, p), h('td', {}, value), h('td', {}, '→ ' + term));
    });
    const on = d.interim_reporting === true;
    const kids: HTMLElement[] = [
      h('h5', {}, '§8.4: what it sets on the control law'),
      h('table', { class: 'mapping-table' }, ...rows),
      h('label', { class: 'interim' }, h('input', {
        type: 'checkbox', 'data-control': 'interim_reporting', checked: on,
        onchange: (e: Event) => c.edit((x) => (blockOf(x, 'dynamic').interim_reporting = (e.target as HTMLInputElement).checked)),
      }), ' animate from the device’s interim reports (interim_reporting)'),
    ];
    if (!on) kids.push(h('div', { class: 'hint' }, 'Interim reports are off: the schematic shows the mass at rest.'));
    const field = kDirectionField[c.fx.type];
    if (field && ((c.fx.axes as string[]) ?? []).length >= 2) {
      this.dial.draw({ angle: num(d, field) });
      kids.push(this.dial.el);
    }
    this.side.replaceChildren(...kids);
    this.drawPicture();
  }

  private drawPicture(): void {
    const c = this.c;
    if (!c) return;
    const d = block(c.fx, 'dynamic');
    const axes = (c.fx.axes as string[]) ?? [];
    const two = axes.length >= 2;
    const handlePos = liveFeed.frame.position;
    const hxRaw = handlePos[c.deviceAxes.indexOf(axes[0])] ?? 0;
    const hyRaw = two ? (handlePos[c.deviceAxes.indexOf(axes[1])] ?? 0) : 0;
    // the handle, in the travel (±10000 → ±kC·0.8)
    const travel = (kC * 0.8) / 10000;
    const hx = kC + hxRaw * travel, hy = kC - hyRaw * travel;
    const r = this.newest;
    const rel = [r?.position[0] ?? 0, two ? (r?.position[1] ?? 0) : 0];
    const parts: SVGElement[] = [
      svg('rect', { x: 2, y: 2, width: kSize - 4, height: kSize - 4, rx: 6, fill: '#f7f8fa', stroke: '#d5d9e0' }),
      svg('rect', { x: kC - kC * 0.8, y: kC - kC * 0.8, width: kC * 1.6, height: kC * 1.6, fill: 'none', stroke: '#e3e6eb', 'stroke-dasharray': '4 4' }),
    ];
    const type = c.fx.type;
    if (type === 'dynamic_sling') {
      const len = Math.max(20, (num(d, 'string_length') * travel));
      // the ball hangs where the report puts it; at rest, straight down the string's length
      const bx = hx + (r ? rel[0] * travel : 0), by = hy - (r ? rel[1] * travel : -len);
      parts.push(svg('line', { x1: hx, y1: hy, x2: bx, y2: by, stroke: '#48526a', 'stroke-width': 1.5 }));
      parts.push(svg('circle', { cx: bx, cy: by, r: 6 + Math.sqrt(num(d, 'ball_mass', 1)) / 10, fill: '#c4783f', class: 'mass' }));
      parts.push(svg('text', { x: 8, y: kSize - 8, 'font-size': 10, fill: '#48526a' }, 'ball on a string (to scale with the travel)'));
    } else if (type === 'dynamic_paddle') {
      parts.push(svg('line', { x1: hx - 30, y1: hy, x2: hx + 30, y2: hy, stroke: '#2458d6', 'stroke-width': 5, 'stroke-linecap': 'round' }));
      const bx = hx + rel[0] * travel, by = hy - Math.max(0, rel[1]) * travel - 10;
      parts.push(svg('circle', { cx: bx, cy: by, r: 6 + Math.sqrt(num(d, 'ball_mass', 1)) / 10, fill: '#c4783f', class: 'mass' }));
      this.gravity(parts, bx + 20, by, num(d, 'gravity'));
      parts.push(svg('text', { x: 8, y: kSize - 8, 'font-size': 10, fill: '#48526a' }, 'ball against a paddle (to scale with the travel)'));
    } else {
      // the mass on its tether: the offset magnified so that the largest seen spans 60 px
      this.peak = Math.max(this.peak, Math.abs(rel[0]), Math.abs(rel[1]));
      const scale = 60 / Math.max(50, this.peak);
      const rest = 60; // the tether drawn with a rest length, along +x, so it shows
      const mx = hx + rest + rel[0] * scale, my = hy - rel[1] * scale;
      // the mass's path in this play
      const path = this.trail.map((t) => `${(hx + rest + (t.position[0] ?? 0) * scale).toFixed(1)},${(hy - (two ? (t.position[1] ?? 0) : 0) * scale).toFixed(1)}`);
      if (path.length > 1) parts.push(svg('polyline', { points: path.join(' '), fill: 'none', stroke: '#c4783f', 'stroke-width': 1, 'stroke-opacity': 0.6, class: 'trail' }, svg('title', {}, 'the mass’s path in this play')));
      const law = ((d.control_law as Record<string, unknown>[]) ?? [])[0] ?? {};
      const play = type === 'dynamic_inertia' ? num(d, 'play') : type === 'dynamic_control_law' ? num(law, 'length') : 0;
      parts.push(svg('path', { d: zigzag(hx, hy, mx, my, 7, 6), fill: 'none', stroke: '#1b9e5a', 'stroke-width': 1.6, class: 'spring' }));
      {  // the dashpot beside the spring (every tether here has a B)
        const ay = hy + 14, by = my + 14, ax = hx, bx = mx;
        const midx = (ax + bx) / 2, midy = (ay + by) / 2;
        parts.push(svg('line', { x1: ax, y1: ay, x2: midx, y2: midy, stroke: '#7a3fc4', 'stroke-width': 1.5 }));
        parts.push(svg('rect', { x: midx - 8, y: midy - 6, width: 16, height: 12, fill: 'none', stroke: '#7a3fc4', 'stroke-width': 1.5, class: 'dashpot' }));
        parts.push(svg('line', { x1: midx + 2, y1: midy, x2: bx, y2: by, stroke: '#7a3fc4', 'stroke-width': 1.5 }));
      }
      if (play > 0) {
        parts.push(svg('circle', { cx: mx, cy: my, r: 13 + Math.min(30, play * scale), fill: 'none', stroke: '#9aa3b2', 'stroke-dasharray': '3 3' }, svg('title', {}, 'free play')));
      }
      const mass = type === 'dynamic_liquid' ? num(d, 'density', 1) : type === 'dynamic_inertia' ? num(d, 'inertia', 1)
        : type === 'dynamic_control_law' ? num(law, 'mass', 1) : type === 'dynamic_center_drift' ? 1 : num(d, 'dynamic_mass', 1);
      parts.push(svg('rect', { x: mx - 8 - Math.sqrt(mass) / 12, y: my - 8 - Math.sqrt(mass) / 12, width: 16 + Math.sqrt(mass) / 6, height: 16 + Math.sqrt(mass) / 6, rx: 3, fill: '#c4783f', class: 'mass' }, svg('title', {}, 'the mass')));
      if (type === 'dynamic_control_law') this.gravity(parts, mx + 26, my, num(law, 'gravity'));
      parts.push(svg('text', { x: 8, y: kSize - 8, 'font-size': 10, fill: '#48526a' }, `mass on its tether: offset ×${(scale / travel).toFixed(1)} the travel`));
    }
    parts.push(svg('circle', { cx: hx, cy: hy, r: 7, fill: '#2458d6', class: 'handle-dot' }, svg('title', {}, 'the handle (as the device reports it)')));
    parts.push(svg('text', { x: 8, y: 14, 'font-size': 10, fill: r ? '#1b9e5a' : '#7a8394' }, r ? `interim report t = ${r.t_ms.toFixed(0)} ms` : 'no reports (at rest)'));
    this.pic.replaceChildren(...parts);
  }

  private gravity(parts: SVGElement[], x: number, y: number, g: number): void {
    if (g === 0) return;
    const len = 10 + Math.min(30, Math.abs(g) / 300);
    const dir = g < 0 ? 1 : -1; // negative gravity pulls toward -y: down on the screen
    parts.push(svg('line', { x1: x, y1: y, x2: x, y2: y + dir * len, stroke: '#d63a24', 'stroke-width': 2 }));
    parts.push(svg('path', { d: `M ${x - 4} ${y + dir * (len - 6)} L ${x} ${y + dir * len} L ${x + 4} ${y + dir * (len - 6)}`, fill: 'none', stroke: '#d63a24', 'stroke-width': 2 }));
    parts.push(svg('text', { x: x + 5, y: y + dir * len, 'font-size': 9, fill: '#d63a24' }, 'g'));
  }
}
