// The wall and barrier editor (§3.7–3.8, §6.6.g–h), drawn in a copy of the handle pad's
// travel square (+x right, +y forward = up, docs/conventions.md), with the geometry of
// docs/conditions.md: u is the effect's axis or (sin a, cos a) for the compass angle a,
// the surface is the line s = offset, s = position·u.
//
// * The wall's surface is a purple line, its solid side shaded as deep as the hardness
//   (red-brown for a negative hardness, which pulls the handle in). Drag the line to
//   set the offset; the arrow across it points into the solid (the sense): click it to
//   flip. A barrier is an orange slab as wide as its thickness: drag its middle for the
//   offset, its edge for the thickness; its two hardnesses label the direction of the
//   crossing they apply to.
// * The dial sets the angle (an axis wall or barrier: the dial picks its axis).
// * Surface friction: the dots along the surface, as dense as μ; surface texture: the
//   ridges every 200 units, as tall as τ. While the handle presses on the surface, the
//   rubbing it would meet (pressure mode: N·(μ + τ), N the force pressing it) is drawn as
//   two arrows along the surface. Clipping: where the device reports the handle while it
//   is inside the solid (on the surface), with a dashed line to where the hand is.
import { h, liveText } from '../dom';
import type { EffectJson } from '../document';
import type { State, Store } from '../store';
import { angleOfAxis, axisOfAngle, canvasOf, commit, commitDraft, compass, deviceAxes, type GraphicEditor, limit, type LiveFeed, perAnimationFrame } from './editor';
import { dial } from './widgets/dial';
import { attachHandles, type Handle } from './widgets/drag';

const kSize = 260;
const kMargin = 12;
type Block = Record<string, unknown>;

export function wallEditor(store: Store, live: LiveFeed): GraphicEditor {
  const canvas = canvasOf(kSize, kSize, 'travel');
  const readout = h('div', { class: 'graphic-readout' });
  const angleDial = dial('angle', 'angle', (angle) => {
    const e = fx;
    if (!e) return;
    if (e.type.startsWith('axis_')) commit(store, index, (x) => (x.axes = [axisOfAngle(angle)]));
    else commit(store, index, (x) => ((x[key(x)] as Block).angle = angle));
  });
  const el = h('div', { class: 'graphic wall-editor' }, h('div', { class: 'graphic-row' }, canvas, h('div', { class: 'graphic-side' }, angleDial.el)), readout);

  let index = -1;
  let s: State | null = null;
  let fx: EffectJson | null = null;
  let draft: EffectJson | null = null;
  let flipped = false; // the sense flips once per press of its arrow
  const current = () => draft ?? fx;
  const key = (e: EffectJson) => (e.type.endsWith('barrier') ? 'barrier' : 'wall');
  const blockOf = (e: EffectJson | null): Block => (e ? ((e[key(e)] as Block) ?? {}) : {});
  const num = (b: Block, k: string, d = 0) => (typeof b[k] === 'number' ? (b[k] as number) : d);
  const scale = (kSize - 2 * kMargin) / 20000;
  const toPx = (x: number, y: number): [number, number] => [kMargin + (x + 10000) * scale, kMargin + (10000 - y) * scale];
  const fromPx = (px: number, py: number): [number, number] => [(px - kMargin) / scale - 10000, 10000 - (py - kMargin) / scale];
  // u, the direction across the surface (null: an axis the square does not show)
  const unit = (e: EffectJson): [number, number] | null => {
    if (e.type.startsWith('axis_')) {
      const a = ((e.axes as string[]) ?? [])[0];
      return a === 'x' ? [1, 0] : a === 'y' ? [0, 1] : null;
    }
    return compass(num(blockOf(e), 'angle'));
  };
  const edit = (change: (b: Block) => void) => {
    if (!draft && fx) draft = structuredClone(fx);
    if (draft) change(blockOf(draft));
    paint();
  };

  const handles = (): Handle[] => {
    const e = current();
    if (!e) return [];
    const u = unit(e);
    if (!u) return [];
    const b = blockOf(e);
    const off = num(b, 'offset');
    const sOf = (px: number, py: number) => {
      const [x, y] = fromPx(px, py);
      return x * u[0] + y * u[1];
    };
    const t: [number, number] = [u[1], -u[0]]; // along the surface
    const at = (sv: number, along: number) => toPx(u[0] * sv + t[0] * along, u[1] * sv + t[1] * along);
    const lineDistance = (sv: number) => (px: number, py: number) => Math.abs(sOf(px, py) - sv) * scale;
    const list: Handle[] = [];
    const [ox, oy] = at(off, -6000);
    list.push({
      id: `${key(e)}.offset`, x: ox, y: oy, hit: lineDistance(off), cursor: 'move',
      drag: (px, py) => edit((bb) => (bb.offset = limit(s, e.type, 'offset', sOf(px, py)))),
    });
    if (key(e) === 'wall') {
      const into = b.sense === 'negative' ? -1 : 1;
      const [ax, ay] = at(off + into * 1500, 5000);
      list.push({
        id: 'wall.sense', x: ax, y: ay, cursor: 'pointer',
        drag: () => {
          if (flipped) return;
          flipped = true;
          edit((bb) => (bb.sense = bb.sense === 'negative' ? 'positive' : 'negative'));
        },
      });
    } else {
      const half = num(b, 'thickness') / 2;
      const [tx, ty] = at(off + half, 6000);
      list.push({
        id: 'barrier.thickness', x: tx, y: ty, cursor: 'ew-resize',
        drag: (px, py) => edit((bb) => (bb.thickness = limit(s, e.type, 'thickness', 2 * Math.abs(sOf(px, py) - num(bb, 'offset'))))),
      });
    }
    return list;
  };

  attachHandles(canvas, handles, () => {
    flipped = false;
    const d = draft;
    draft = null;
    if (!commitDraft(store, index, fx, d)) paint();
  });

  function paint(): void {
    const g = canvas.getContext('2d')!;
    g.clearRect(0, 0, kSize, kSize);
    g.fillStyle = '#f7f8fa';
    g.fillRect(0, 0, kSize, kSize);
    const [x0, y0] = toPx(-10000, 10000);
    const [x1, y1] = toPx(10000, -10000);
    g.strokeStyle = '#c5cad3';
    g.strokeRect(x0, y0, x1 - x0, y1 - y0);
    const e = current();
    if (!e || !s) return;
    const u = unit(e);
    if (!u) {
      liveText(readout, 'this axis is not in the travel square (x, y): its fields are below');
      return;
    }
    const b = blockOf(e);
    const off = num(b, 'offset');
    const t: [number, number] = [u[1], -u[0]];
    const at = (sv: number, along: number) => toPx(u[0] * sv + t[0] * along, u[1] * sv + t[1] * along);
    const band = (s0: number, s1: number, color: string) => {
      g.fillStyle = color;
      g.beginPath();
      for (const [sv, al] of [[s0, -30000], [s1, -30000], [s1, 30000], [s0, 30000]] as const) g.lineTo(...at(sv, al));
      g.fill();
    };
    const lineAt = (sv: number, color: string, width: number) => {
      g.strokeStyle = color;
      g.lineWidth = width;
      g.beginPath(); g.moveTo(...at(sv, -30000)); g.lineTo(...at(sv, 30000)); g.stroke();
      g.lineWidth = 1;
    };
    g.save();
    g.beginPath(); g.rect(x0, y0, x1 - x0, y1 - y0); g.clip();
    const wall = key(e) === 'wall';
    const friction = num(b, 'surface_friction') / 10000;
    const texture = num(b, 'surface_texture') / 10000;
    let faces: number[];
    if (wall) {
      const hard = num(b, 'hardness');
      const into = b.sense === 'negative' ? -1 : 1;
      const alpha = 0.08 + 0.5 * Math.abs(hard) / 10000;
      band(off, off + into * 30000, hard >= 0 ? `rgba(122, 63, 196, ${alpha})` : `rgba(160, 82, 45, ${alpha})`);
      lineAt(off, '#7a3fc4', 4);
      faces = [off];
    } else {
      const half = num(b, 'thickness') / 2;
      band(off - half, off + half, 'rgba(196, 120, 63, 0.45)');
      lineAt(off, 'rgba(196, 120, 63, 0.9)', 1);
      faces = [off - half, off + half];
    }
    // surface friction (dots, as dense as μ) and texture (ridges every 200 units, as tall as τ)
    g.fillStyle = '#48526a';
    g.strokeStyle = '#48526a';
    for (const f of faces) {
      if (friction > 0) {
        const step = 2400 - 2000 * friction;
        for (let al = -15000; al <= 15000; al += step) { const [px, py] = at(f, al); g.fillRect(px - 1, py - 1, 2, 2); }
      }
      if (texture > 0) {
        // every fourth ridge (the ridges are 200 apart, 2 px here: too dense to read)
        for (let al = -15000; al <= 15000; al += 800) {
          const side = wall && b.sense === 'negative' ? 1 : -1; // ridges on the free side
          const [ax, ay] = at(f, al);
          const [bx, by] = at(f + side * 900 * texture, al);
          g.beginPath(); g.moveTo(ax, ay); g.lineTo(bx, by); g.stroke();
        }
      }
    }
    g.restore();
    // the handles
    for (const hd of handles()) {
      if (hd.id === 'wall.sense') {
        // the arrow into the solid
        const into = b.sense === 'negative' ? -1 : 1;
        const [ax, ay] = at(off - into * 600, 5000);
        const [bx, by] = at(off + into * 1500, 5000);
        g.strokeStyle = '#1d2330';
        g.fillStyle = '#1d2330';
        g.lineWidth = 3;
        g.beginPath(); g.moveTo(ax, ay); g.lineTo(bx, by); g.stroke();
        const a = Math.atan2(by - ay, bx - ax);
        g.beginPath(); g.moveTo(bx + 4 * Math.cos(a), by + 4 * Math.sin(a));
        g.lineTo(bx - 8 * Math.cos(a - 0.5), by - 8 * Math.sin(a - 0.5));
        g.lineTo(bx - 8 * Math.cos(a + 0.5), by - 8 * Math.sin(a + 0.5)); g.fill();
        g.lineWidth = 1;
      } else {
        g.fillStyle = '#fff';
        g.strokeStyle = wall ? '#7a3fc4' : '#c4783f';
        g.lineWidth = 2;
        g.beginPath(); g.arc(hd.x, hd.y, 6, 0, 2 * Math.PI); g.fill(); g.stroke();
        g.lineWidth = 1;
      }
    }
    // labels: hardness, clipping, offset mode
    g.fillStyle = '#1d2330';
    g.font = '11px system-ui';
    const labels = wall
      ? [`hardness ${num(b, 'hardness')}`, b.clipping === true ? 'clipping on' : 'clipping off']
      : [`crossing toward +: ${num(b, 'pos_hardness')}`, `crossing toward −: ${num(b, 'neg_hardness')}`, `thickness ${num(b, 'thickness')}`];
    if (friction || texture) labels.push(`surface friction ${num(b, 'surface_friction')} · texture ${num(b, 'surface_texture')}`);
    if (b.offset_mode === 'relative') labels.push('offset from the start position');
    labels.forEach((l, k) => g.fillText(l, x0 + 4, y0 + 13 + 13 * k));
    paintLive(g, u, b, wall, friction + texture);
  }

  // The handle where the device reports it, the force, the rubbing (pressure mode) while
  // it presses on the surface, and, with clipping, where the hand really is.
  function paintLive(g: CanvasRenderingContext2D, u: [number, number], b: Block, wall: boolean, rub: number): void {
    const names = s ? deviceAxes(s) : [];
    const pos = live.position();
    const frc = live.force();
    const xi = names.indexOf('x');
    const yi = names.indexOf('y');
    const p: [number, number] = [xi >= 0 ? pos[xi] ?? 0 : 0, yi >= 0 ? pos[yi] ?? 0 : 0];
    const f: [number, number] = [xi >= 0 ? frc[xi] ?? 0 : 0, yi >= 0 ? frc[yi] ?? 0 : 0];
    const [hx, hy] = toPx(p[0], p[1]);
    const k = (kSize / 3) / 10000;
    const normal = f[0] * u[0] + f[1] * u[1]; // the surface's push, along u
    // clipping: the reported position sits on the surface while the hand is in the solid
    const target = live.target();
    if (wall && b.clipping === true && target) {
      const into = b.sense === 'negative' ? -1 : 1;
      const depth = (target[0] * u[0] + target[1] * u[1] - num(b, 'offset')) * into;
      if (depth > 0) {
        const [tx, ty] = toPx(target[0], target[1]);
        g.strokeStyle = '#8a93a3';
        g.setLineDash([3, 3]);
        g.beginPath(); g.moveTo(hx, hy); g.lineTo(tx, ty); g.stroke();
        g.beginPath(); g.arc(tx, ty, 6, 0, 2 * Math.PI); g.stroke();
        g.setLineDash([]);
        g.fillStyle = '#48526a';
        g.fillText('clipped', hx + 8, hy - 8);
      }
    }
    g.fillStyle = '#2458d6';
    g.beginPath(); g.arc(hx, hy, 6, 0, 2 * Math.PI); g.fill();
    if (Math.hypot(f[0], f[1]) * k > 2) {
      g.strokeStyle = '#d63a24';
      g.lineWidth = 3;
      g.beginPath(); g.moveTo(hx, hy); g.lineTo(hx + f[0] * k, hy - f[1] * k); g.stroke();
      g.lineWidth = 1;
    }
    // pressure mode: the rubbing grows with how hard the handle presses on the surface
    const pressing = Math.abs(normal) > 200 && rub > 0;
    if (pressing) {
      const len = Math.min(60, Math.abs(normal) * rub * k);
      const t: [number, number] = [u[1], -u[0]];
      g.strokeStyle = '#e08a1e';
      g.lineWidth = 2;
      for (const sgn of [1, -1]) {
        g.beginPath(); g.moveTo(hx, hy); g.lineTo(hx + sgn * t[0] * len, hy - sgn * t[1] * len); g.stroke();
      }
      g.lineWidth = 1;
    }
    liveText(readout, `device: handle ${Math.round(p[0])}, ${Math.round(p[1])} · ${Math.round(p[0] * u[0] + p[1] * u[1])} across the surface · ` +
      `surface push ${Math.round(normal)}` + (pressing ? ` · rubbing up to ${Math.round(Math.abs(normal) * rub)} (pressure mode)` : ''));
  }

  return {
    el,
    render(state, effect, i) {
      s = state;
      index = i;
      fx = effect;
      const axial = effect.type.startsWith('axis_');
      angleDial.set(axial ? angleOfAxis(((effect.axes as string[]) ?? [])[0]) : num(blockOf(effect), 'angle'), !axial || deviceAxes(state).length > 1);
      if (!draft) paint();
    },
    frame: perAnimationFrame(() => {
      if (!draft) paint();
    }),
  };
}
