// The editor of spring, damper, inertia, friction and angle spring (§3.1–3.5): the
// Condition Struct's response curve, force against the input (position for a spring,
// velocity for a damper and friction, acceleration for an inertia), drawn from the
// block's parameters exactly as docs/conditions.md writes the curve:
//
//   F(d) = 0                                               |d| <= deadband
//   F(d) = -clamp(pos_coefficient·(d - deadband)/10000, ±pos_saturation)    d > deadband
//   F(d) = -clamp(neg_coefficient·(d + deadband)/10000, ±neg_saturation)    d < -deadband
//
// with d the input measured from the offset (friction: plateaus of ∓coefficient on each
// side, reached smoothly through the bristle's presliding). Each parameter is a handle:
// the offset is the centre (drag sideways), the deadband the flat band's edges (the
// triangles under the axis), a coefficient the slope (drag the dot at the end of the
// slope's line up or down), a saturation its plateau (drag the bar). The device's state
// is a dot at (its input, the force it sends along the block's axis), moving with the
// reports; next to the curve a spring, dashpot, flywheel or rough surface moves with it.
//
// The block shown is one axis's (per-axis conditions) or the one block along the
// direction (angle_spring, or a condition given a direction, §3.1). The dial sets that
// direction; on one axis it picks the axis. For a spring, CenterSpring and
// SpringAtCurrentLocation (§8.2) set the centre to the travel's centre or to where the
// handle is when the spring starts (offset_mode relative).
import { h, liveText } from '../dom';
import type { EffectJson } from '../document';
import type { State, Store } from '../store';
import { type ConditionFamily, drawConditionIcon } from './condition_icon';
import { angleOfAxis, axisOfAngle, canvasOf, commit, commitDraft, compass, deviceAxes, type GraphicEditor, limit, type LiveFeed, motion, perAnimationFrame } from './editor';
import { dial } from './widgets/dial';
import { attachHandles, clamp, type Handle, linear } from './widgets/drag';

type Block = Record<string, unknown>;
const kW = 380;
const kH = 230;
const kIconW = 96;
const kPad = { l: 34, r: 10, t: 12, b: 22 };
const kRange = 12000; // the input axis: ±12000 (the travel is ±10000)

const num = (b: Block | undefined, k: string, dflt = 0) => (typeof b?.[k] === 'number' ? (b[k] as number) : dflt);

function familyOf(type: string): ConditionFamily {
  return type === 'angle_spring' ? 'spring' : (type as ConditionFamily);
}

// The curve's force at input d from the offset, as docs/conditions.md defines it.
export function conditionForce(family: ConditionFamily, b: Block, input: number): number {
  const d = input - num(b, 'offset');
  const db = num(b, 'deadband');
  const ps = num(b, 'pos_saturation', 10000);
  const ns = num(b, 'neg_saturation', 10000);
  const pc = num(b, 'pos_coefficient');
  const nc = num(b, 'neg_coefficient');
  if (family === 'friction') {
    // a plateau each side, reached smoothly (drawn over 4% of the scale)
    if (Math.abs(d) <= db) return 0;
    const s = Math.tanh((d - Math.sign(d) * db) / 400);
    return s > 0 ? -clamp(pc, -ps, ps) * s : -clamp(nc, -ns, ns) * s;
  }
  if (Math.abs(d) <= db) return 0;
  if (d > 0) return -clamp((pc * (d - db)) / 10000, -ps, ps);
  return -clamp((nc * (d + db)) / 10000, -ns, ns);
}

export function conditionEditor(store: Store, live: LiveFeed): GraphicEditor {
  const curve = canvasOf(kW, kH, 'curve');
  const icon = canvasOf(kIconW, kH, 'condition-icon');
  const blockPick = h('span', { class: 'block-pick' });
  const presets = h('span', { class: 'presets' });
  const readout = h('div', { class: 'graphic-readout' });
  const direction = dial('direction', 'direction', (angle) => setDirection(angle));
  const el = h('div', { class: 'graphic condition-editor' },
    h('div', { class: 'graphic-row' }, curve, icon, h('div', { class: 'graphic-side' }, direction.el, blockPick, presets)),
    readout);

  let s: State | null = null;
  let index = -1;
  let fx: EffectJson | null = null;
  let draft: EffectJson | null = null; // while a handle is dragged
  let block = 0; // which block is shown

  const X = linear(-kRange, kRange, kPad.l, kW - kPad.r);
  const Y = linear(10000, -10000, kPad.t, kH - kPad.b);
  const current = () => draft ?? fx;
  const blocks = (e: EffectJson | null) => ((e?.conditions as Block[]) ?? []);
  const directed = (e: EffectJson) => e.type === 'angle_spring' || (e.direction !== undefined && blocks(e).length === 1);
  const family = () => familyOf(current()?.type ?? 'spring');

  // The draft's block being dragged: a copy of the effect, changed in place.
  const edit = (change: (b: Block) => void) => {
    if (!draft && fx) draft = structuredClone(fx);
    const b = blocks(draft)[block];
    if (b) change(b);
    paint();
  };
  const setDirection = (angle: number) => {
    const e = fx;
    if (!e || !s) return;
    const axes = (e.axes as string[]) ?? [];
    if (axes.length === 1) {
      // one axis: the dial picks it (north: y, east: x)
      const pick = axisOfAngle(angle);
      if (deviceAxes(s).includes(pick)) commit(store, index, (x) => (x.axes = [pick]));
      return;
    }
    commit(store, index, (x) => {
      x.direction = { polar: angle };
      const list = blocks(x);
      if (list.length > 1) x.conditions = [list[Math.min(block, list.length - 1)]];
    });
    block = 0;
  };

  // The input and force the device shows along the shown block's axis: its position,
  // velocity or acceleration (scaled as the engine scales them) and the force along it.
  const deviceState = (): { input: number | null; travel: number; force: number; note: string } => {
    const e = current();
    if (!e || !s) return { input: null, travel: 0, force: 0, note: '' };
    const names = deviceAxes(s);
    const axes = (e.axes as string[]) ?? [];
    const pos = live.position();
    const frc = live.force();
    let u: number[] = names.map(() => 0);
    const dir = e.direction as Record<string, unknown> | undefined;
    if (directed(e) && typeof dir?.polar === 'number') {
      const [ux, uy] = compass(dir.polar);
      u = names.map((n) => (n === 'x' ? ux : n === 'y' ? uy : 0));
    } else if (directed(e) && Array.isArray(dir?.cartesian)) {
      const v = dir.cartesian as number[];
      const len = Math.hypot(...v) || 1;
      u = names.map((n) => (axes.includes(n) ? (v[axes.indexOf(n)] ?? 0) / len : 0));
    } else if (!directed(e)) {
      const a = names.indexOf(axes[block] ?? '');
      if (a >= 0) u[a] = 1;
    } else {
      return { input: null, travel: 0, force: 0, note: 'the live dot follows polar and cartesian directions' };
    }
    const dot = (v: number[]) => v.reduce((acc, x, k) => acc + x * (u[k] ?? 0), 0);
    const travel = dot(pos);
    const force = dot(frc);
    const fam = family();
    if (fam === 'spring') return { input: travel, travel, force, note: '' };
    const device = s.hello?.device as Record<string, unknown> | undefined;
    const ref = Number(fam === 'inertia' ? device?.acceleration_ref : device?.velocity_ref);
    if (!(ref > 0)) return { input: null, travel, force, note: 'the device does not say its velocity scale: no live dot' };
    const rows = live.rows();
    const m = names.map((_, a) => motion(rows, names.length, a));
    const v = dot(m.map((x) => (fam === 'inertia' ? x.acceleration : x.velocity)));
    return { input: (v * 10000) / ref, travel, force, note: '' };
  };

  const handles = (): Handle[] => {
    const e = current();
    const b = blocks(e)[block];
    if (!e || !b) return [];
    const fam = family();
    const off = num(b, 'offset');
    const db = num(b, 'deadband');
    const y0 = Y.px(0);
    const list: Handle[] = [];
    const lim = (name: string, v: number) => limit(s, e.type, name, v);
    const inputAt = (px: number) => lim('offset', X.value(px));
    const forceAt = (py: number) => clamp(Y.value(py), -10000, 10000);
    list.push({ id: 'condition.offset', x: X.px(off), y: y0, cursor: 'ew-resize', drag: (px) => edit((bb) => (bb.offset = inputAt(px))) });
    for (const side of [1, -1]) {
      list.push({
        id: `condition.deadband${side > 0 ? '+' : '-'}`, x: X.px(off + side * db), y: y0 + 12, cursor: 'ew-resize',
        drag: (px) => edit((bb) => (bb.deadband = lim('deadband', Math.abs(X.value(px) - num(bb, 'offset'))))),
      });
      const coef = side > 0 ? 'pos_coefficient' : 'neg_coefficient';
      const sat = side > 0 ? 'pos_saturation' : 'neg_saturation';
      const c = num(b, coef);
      // the coefficient's handle: the end of the slope's line at a lever of up to 4000
      // beyond the deadband (the line goes on dashed past a saturation), or, for friction,
      // the plateau's height
      const edge = off + side * db;
      const far = clamp(edge + side * 4000, -kRange + 500, kRange - 500);
      const lever = Math.max(500, Math.abs(far - edge));
      const at = edge + side * lever;
      const fy = fam === 'friction' ? -side * c : -(c * lever) / 10000;
      list.push({
        id: `condition.${coef}`, x: X.px(at), y: Y.px(fy), cursor: 'ns-resize',
        drag: (_px, py) => edit((bb) => {
          const f = forceAt(py);
          bb[coef] = lim(coef, fam === 'friction' ? -side * f : (-f * 10000) / lever);
        }),
      });
      const sv = num(b, sat, 10000);
      const sx = side * 9000 + (side > 0 ? Math.max(0, off) : Math.min(0, off)) * 0.1;
      const sign = c >= 0 ? -side : side;
      list.push({
        id: `condition.${sat}`, x: X.px(sx), y: Y.px(sign * sv), cursor: 'ns-resize',
        hit: (px, py) => (Math.abs(px - X.px(sx)) < 24 ? Math.abs(py - Y.px(sign * sv)) : Infinity),
        drag: (_px, py) => edit((bb) => (bb[sat] = lim(sat, Math.abs(forceAt(py))))),
      });
    }
    return list;
  };

  attachHandles(curve, handles, () => {
    const d = draft;
    draft = null;
    if (!commitDraft(store, index, fx, d)) paint();
  });

  const inputName = () => ({ spring: 'position', damper: 'velocity', inertia: 'acceleration', friction: 'velocity' })[family()];

  function paint(): void {
    const e = current();
    const g = curve.getContext('2d')!;
    g.clearRect(0, 0, kW, kH);
    g.fillStyle = '#fbfcfd';
    g.fillRect(0, 0, kW, kH);
    const b = blocks(e)[block];
    if (!e || !b) return;
    const fam = family();
    // axes and the travel's ends
    g.strokeStyle = '#d5d9e0';
    g.lineWidth = 1;
    g.beginPath();
    g.moveTo(X.px(-kRange), Y.px(0)); g.lineTo(X.px(kRange), Y.px(0));
    g.moveTo(X.px(0), Y.px(10000)); g.lineTo(X.px(0), Y.px(-10000));
    g.stroke();
    g.setLineDash([2, 3]);
    g.beginPath();
    g.moveTo(X.px(-10000), Y.px(10000)); g.lineTo(X.px(-10000), Y.px(-10000));
    g.moveTo(X.px(10000), Y.px(10000)); g.lineTo(X.px(10000), Y.px(-10000));
    g.stroke();
    g.setLineDash([]);
    g.fillStyle = '#7a8394';
    g.font = '10px system-ui';
    g.fillText('+10000', 2, Y.px(10000) + 8);
    g.fillText('force', 2, Y.px(0) - 4);
    g.fillText('−10000', 2, Y.px(-10000));
    g.textAlign = 'right';
    g.fillText(`${inputName()} →`, kW - kPad.r, Y.px(0) + 32);
    g.textAlign = 'left';
    const off = num(b, 'offset');
    const db = num(b, 'deadband');
    // the deadband: a flat band
    g.fillStyle = 'rgba(36, 88, 214, 0.08)';
    g.fillRect(X.px(off - db), Y.px(10000), X.px(off + db) - X.px(off - db), Y.px(-10000) - Y.px(10000));
    // the saturations' plateaus (dashed guides across their side)
    g.strokeStyle = 'rgba(214, 58, 36, 0.35)';
    g.setLineDash([5, 4]);
    for (const side of [1, -1]) {
      const c = num(b, side > 0 ? 'pos_coefficient' : 'neg_coefficient');
      const sv = num(b, side > 0 ? 'pos_saturation' : 'neg_saturation', 10000);
      const yv = Y.px((c >= 0 ? -side : side) * sv);
      g.beginPath(); g.moveTo(X.px(off), yv); g.lineTo(X.px(side * kRange), yv); g.stroke();
      if (fam !== 'friction') {
        // the slope's line, beyond the saturation too
        const edge = off + side * db;
        g.strokeStyle = 'rgba(72, 82, 106, 0.35)';
        g.beginPath(); g.moveTo(X.px(edge), Y.px(0));
        const endX = side * kRange;
        g.lineTo(X.px(endX), Y.px(clamp((-c * (endX - edge)) / 10000, -10000, 10000)));
        g.stroke();
        g.strokeStyle = 'rgba(214, 58, 36, 0.35)';
      }
    }
    g.setLineDash([]);
    // the curve
    g.strokeStyle = '#d63a24';
    g.lineWidth = 2.5;
    g.beginPath();
    for (let px = kPad.l; px <= kW - kPad.r; ++px) {
      const f = conditionForce(fam, b, X.value(px));
      if (px === kPad.l) g.moveTo(px, Y.px(f));
      else g.lineTo(px, Y.px(f));
    }
    g.stroke();
    g.lineWidth = 1;
    // the offset: the centre
    g.strokeStyle = '#1b9e5a';
    g.setLineDash([3, 3]);
    g.beginPath(); g.moveTo(X.px(off), Y.px(10000)); g.lineTo(X.px(off), Y.px(-10000)); g.stroke();
    g.setLineDash([]);
    for (const hd of handles()) {
      const id = hd.id.slice('condition.'.length);
      if (id === 'offset') {
        g.fillStyle = '#1b9e5a';
        g.beginPath(); g.arc(hd.x, hd.y, 6, 0, 2 * Math.PI); g.fill();
      } else if (id.startsWith('deadband')) {
        g.fillStyle = '#2458d6';
        g.beginPath(); g.moveTo(hd.x, hd.y - 6); g.lineTo(hd.x - 6, hd.y + 5); g.lineTo(hd.x + 6, hd.y + 5); g.fill();
      } else if (id.endsWith('saturation')) {
        g.fillStyle = '#d63a24';
        g.fillRect(hd.x - 14, hd.y - 3, 28, 6);
      } else {
        g.fillStyle = '#fff';
        g.strokeStyle = '#d63a24';
        g.lineWidth = 2;
        g.beginPath(); g.arc(hd.x, hd.y, 6, 0, 2 * Math.PI); g.fill(); g.stroke();
        g.lineWidth = 1;
      }
    }
    paintLive();
  }

  // The device's state: the dot on the curve and the icon.
  function paintLive(): void {
    const e = current();
    const b = blocks(e)[block];
    if (!e || !b) return;
    const st = deviceState();
    const g = curve.getContext('2d')!;
    if (st.input !== null) {
      const x = X.px(clamp(st.input, -kRange, kRange));
      const y = Y.px(clamp(st.force, -10000, 10000));
      g.fillStyle = '#2458d6';
      g.strokeStyle = '#fff';
      g.lineWidth = 2;
      g.beginPath(); g.arc(x, y, 5, 0, 2 * Math.PI); g.fill(); g.stroke();
      g.lineWidth = 1;
    }
    drawConditionIcon(icon.getContext('2d')!, kIconW, kH, family(), (st.input ?? 0) - num(b, 'offset'), st.travel, st.force);
    const f = (v: number) => Math.round(v).toString();
    liveText(readout, st.input === null
      ? st.note
      : `device: ${inputName()} ${f(st.input)} · force ${f(st.force)} · the curve says ${f(conditionForce(family(), b, st.input))}` +
        (b.offset_mode === 'relative' ? ' (the centre is relative: where the handle was at the start)' : '') +
        (family() === 'friction' ? ' (at rest the bristle holds up to the coefficient: stiction)' : ''));
  }

  // The live dot moves with the curve redrawn under it (it is cheap), once per animation frame.
  const frame = perAnimationFrame(() => {
    if (!draft) paint();
  });

  return {
    el,
    render(state, effect, i) {
      s = state;
      if (i !== index) block = 0;
      index = i;
      fx = effect;
      const e = effect;
      const list = blocks(e);
      block = Math.min(block, Math.max(0, list.length - 1));
      const axes = (e.axes as string[]) ?? [];
      // which block: one per axis, or the one along the direction
      blockPick.replaceChildren(
        ...(directed(e)
          ? [h('span', { class: 'hint' }, 'one block, along the direction')]
          : list.map((_, k) => h('button', { class: `block ${k === block ? 'on' : ''}`, 'data-block': k, onclick: () => { block = k; this.render(state, effect, i); } }, `${e.conditions && axes[k] ? axes[k] : k}`))),
      );
      const dir = e.direction as Record<string, unknown> | undefined;
      if (axes.length === 1) direction.set(angleOfAxis(axes[0]), deviceAxes(state).length > 1);
      else direction.set(typeof dir?.polar === 'number' ? dir.polar : null, axes.includes('x') && axes.includes('y'));
      const spring = e.type === 'spring' || e.type === 'angle_spring';
      const everyBlock = (change: (b: Block) => void) => commit(store, i, (x) => blocks(x).forEach(change));
      const buttons = [
        directed(e) && e.type !== 'angle_spring'
          ? h('button', { class: 'per-axis', title: 'one block per axis, no direction', onclick: () => commit(store, i, (x) => {
              const b0 = blocks(x)[0];
              x.conditions = axes.map(() => structuredClone(b0));
              delete x.direction;
            }) }, 'per axis')
          : null,
        spring ? h('button', { class: 'center-spring', title: 'CenterSpring (§8.2): the centre at the travel\'s centre', onclick: () => everyBlock((b) => { b.offset = 0; delete b.offset_mode; }) }, 'CenterSpring') : null,
        spring ? h('button', { class: 'spring-here', title: 'SpringAtCurrentLocation (§8.2): the centre where the handle is when it starts', onclick: () => everyBlock((b) => { b.offset = 0; b.offset_mode = 'relative'; }) }, 'SpringAtCurrentLocation') : null,
      ];
      presets.replaceChildren(...buttons.filter((b): b is HTMLButtonElement => b !== null));
      if (!draft) paint();
    },
    frame,
  };
}
