// The texture editor (§3.6, §6.6.j): the grating along its line (its axis, or the
// direction's compass angle on two axes), drawn as docs/conditions.md defines it: a
// raised-cosine bump of width w = spacing·density/10000 centred on every multiple of the
// spacing. Drag the second bump's top to set the spacing, the first bump's right foot to
// set the width (the density), and the two arrows under the grating for the roughness
// felt moving toward + (pos_roughness) and toward − (neg_roughness). The dial sets the
// line's angle (on one axis it picks the axis). The handle is a dot on the grating at
// its coordinate along the line, with the force along the line as an arrow.
import { h, liveText } from '../dom';
import type { EffectJson } from '../document';
import type { State, Store } from '../store';
import { angleOfAxis, axisOfAngle, canvasOf, commit, commitDraft, compass, deviceAxes, type GraphicEditor, limit, type LiveFeed, perAnimationFrame } from './editor';
import { dial } from './widgets/dial';
import { attachHandles, clamp, type Handle, linear } from './widgets/drag';

const kW = 420;
const kH = 200;
const kGrating = { t: 24, b: 110 }; // the bumps' lane, px
const kRough = { y: 168, half: 150 }; // the roughness arrows: their row, the longest arrow's length

export function textureEditor(store: Store, live: LiveFeed): GraphicEditor {
  const canvas = canvasOf(kW, kH, 'texture');
  const readout = h('div', { class: 'graphic-readout' });
  const line = dial('direction', 'line', (angle) => {
    const e = fx;
    if (!e) return;
    if (((e.axes as string[]) ?? []).length === 1) commit(store, index, (x) => (x.axes = [axisOfAngle(angle)]));
    else commit(store, index, (x) => (x.direction = { polar: angle }));
  });
  const el = h('div', { class: 'graphic texture-editor' }, h('div', { class: 'graphic-row' }, canvas, h('div', { class: 'graphic-side' }, line.el)), readout);

  let index = -1;
  let s: State | null = null;
  let fx: EffectJson | null = null;
  let draft: EffectJson | null = null;
  let view = 10000; // the grating's shown length along the line; frozen while dragging
  const current = () => draft ?? fx;
  const block = (e: EffectJson | null) => (e?.texture as Record<string, number> | undefined) ?? {};
  const S = () => linear(-view / 2, view / 2, 10, kW - 10);
  const R = linear(-10000, 10000, kW / 2 - kRough.half, kW / 2 + kRough.half);
  const bumpY = linear(0, 1, kGrating.b, kGrating.t + 8);
  const edit = (change: (t: Record<string, number>) => void) => {
    if (!draft && fx) draft = structuredClone(fx);
    if (draft) change(draft.texture as Record<string, number>);
    paint();
  };
  const viewFor = (e: EffectJson) => clamp(6 * (block(e).spacing ?? 2000), 1500, 20000);

  // The unit vector of the line over the device's axes, and the handle's coordinate.
  const along = (): { s: number; f: number } | null => {
    const e = current();
    if (!e || !s) return null;
    const names = deviceAxes(s);
    const axes = (e.axes as string[]) ?? [];
    const dir = e.direction as Record<string, unknown> | undefined;
    let u = names.map(() => 0);
    if (axes.length === 1) u[names.indexOf(axes[0])] = 1;
    else if (typeof dir?.polar === 'number') {
      const [ux, uy] = compass(dir.polar);
      u = names.map((n) => (n === 'x' ? ux : n === 'y' ? uy : 0));
    } else return null;
    const dot = (v: number[]) => v.reduce((acc, x, k) => acc + x * (u[k] ?? 0), 0);
    return { s: dot(live.position()), f: dot(live.force()) };
  };

  const handles = (): Handle[] => {
    const t = block(current());
    const x = S();
    const spacing = t.spacing ?? 1;
    const w = (spacing * (t.density ?? 0)) / 10000;
    const lim = (name: string, v: number) => limit(s, 'texture', name, v);
    return [
      {
        id: 'texture.spacing', x: x.px(spacing), y: bumpY.px(1), cursor: 'ew-resize',
        drag: (px) => edit((b) => (b.spacing = lim('spacing', x.value(px)))),
      },
      {
        id: 'texture.density', x: x.px(w / 2), y: bumpY.px(0), cursor: 'ew-resize',
        drag: (px) => edit((b) => (b.density = lim('density', (2 * x.value(px) * 10000) / (b.spacing || 1)))),
      },
      {
        id: 'texture.pos_roughness', x: R.px(t.pos_roughness ?? 0), y: kRough.y - 8, cursor: 'ew-resize',
        drag: (px) => edit((b) => (b.pos_roughness = lim('pos_roughness', R.value(px)))),
      },
      {
        id: 'texture.neg_roughness', x: R.px(-(t.neg_roughness ?? 0)), y: kRough.y + 8, cursor: 'ew-resize',
        drag: (px) => edit((b) => (b.neg_roughness = lim('neg_roughness', -R.value(px)))),
      },
    ];
  };

  attachHandles(canvas, handles, () => {
    const d = draft;
    draft = null;
    if (!commitDraft(store, index, fx, d)) paint();
    if (fx) view = viewFor(fx);
  });

  function paint(): void {
    const g = canvas.getContext('2d')!;
    g.clearRect(0, 0, kW, kH);
    g.fillStyle = '#fbfcfd';
    g.fillRect(0, 0, kW, kH);
    const e = current();
    if (!e) return;
    const t = block(e);
    const x = S();
    const spacing = Math.max(1, t.spacing ?? 1);
    const w = (spacing * (t.density ?? 0)) / 10000;
    // the grating: bump(r) = (1 + cos(2πr/w))/2 within w/2 of every multiple of the spacing
    const bump = (v: number) => {
      const r = Math.abs(v - Math.round(v / spacing) * spacing);
      return w > 0 && r <= w / 2 ? (1 + Math.cos((2 * Math.PI * r) / w)) / 2 : 0;
    };
    g.fillStyle = 'rgba(120, 120, 120, 0.35)';
    g.strokeStyle = '#6b7487';
    g.beginPath();
    g.moveTo(x.px(-view / 2), bumpY.px(0));
    for (let px = 10; px <= kW - 10; px += 0.5) g.lineTo(px, bumpY.px(bump(x.value(px))));
    g.lineTo(kW - 10, bumpY.px(0));
    g.closePath();
    g.fill();
    g.stroke();
    // the spacing and the width, measured
    g.strokeStyle = '#2458d6';
    g.fillStyle = '#2458d6';
    g.font = '11px system-ui';
    g.beginPath(); g.moveTo(x.px(0), kGrating.t); g.lineTo(x.px(spacing), kGrating.t); g.stroke();
    g.fillText(`spacing ${spacing}`, x.px(spacing) + 6, kGrating.t + 4);
    g.fillText(`width ${Math.round(w)} (density ${t.density ?? 0})`, x.px(w / 2) + 6, bumpY.px(0) + 14);
    // the roughness for each direction of travel
    g.strokeStyle = '#c5cad3';
    g.beginPath(); g.moveTo(R.px(0), kRough.y - 18); g.lineTo(R.px(0), kRough.y + 18); g.stroke();
    const arrowTo = (toX: number, y: number, color: string) => {
      g.strokeStyle = color;
      g.fillStyle = color;
      g.lineWidth = 4;
      g.beginPath(); g.moveTo(R.px(0), y); g.lineTo(toX, y); g.stroke();
      g.lineWidth = 1;
      const sgn = Math.sign(toX - R.px(0)) || 1;
      g.beginPath(); g.moveTo(toX + 6 * sgn, y); g.lineTo(toX - 4 * sgn, y - 6); g.lineTo(toX - 4 * sgn, y + 6); g.fill();
    };
    arrowTo(R.px(t.pos_roughness ?? 0), kRough.y - 8, '#d63a24');
    arrowTo(R.px(-(t.neg_roughness ?? 0)), kRough.y + 8, '#e08a1e');
    g.fillStyle = '#48526a';
    g.fillText(`moving toward +: roughness ${t.pos_roughness ?? 0}`, R.px(0) + 6, kRough.y - 18);
    g.textAlign = 'right';
    g.fillText(`moving toward −: ${t.neg_roughness ?? 0}`, R.px(0) - 6, kRough.y + 30);
    g.textAlign = 'left';
    for (const hd of handles()) {
      g.fillStyle = '#fff';
      g.strokeStyle = '#2458d6';
      g.lineWidth = 2;
      g.beginPath(); g.arc(hd.x, hd.y, 5, 0, 2 * Math.PI); g.fill(); g.stroke();
      g.lineWidth = 1;
    }
    // the device: the handle's place along the line and the force along it
    const st = along();
    if (st) {
      const px = x.px(clamp(st.s, -view / 2, view / 2));
      g.fillStyle = '#2458d6';
      g.beginPath(); g.arc(px, bumpY.px(bump(st.s)) - 6, 6, 0, 2 * Math.PI); g.fill();
      const f = (st.f / 10000) * 120;
      if (Math.abs(f) > 2) {
        g.strokeStyle = '#d63a24';
        g.lineWidth = 3;
        g.beginPath(); g.moveTo(px, kGrating.t + 2); g.lineTo(px + f, kGrating.t + 2); g.stroke();
        g.lineWidth = 1;
      }
      liveText(readout, `device: ${Math.round(st.s)} along the line · force along it ${Math.round(st.f)}` +
        (Math.abs(st.s) > view / 2 ? ' (beyond the part drawn)' : ''));
    } else liveText(readout, 'a texture on two axes needs a direction: turn the dial');
  }

  return {
    el,
    render(state, effect, i) {
      s = state;
      index = i;
      fx = effect;
      const axes = (effect.axes as string[]) ?? [];
      const dir = effect.direction as Record<string, unknown> | undefined;
      if (axes.length === 1) line.set(angleOfAxis(axes[0]), deviceAxes(state).length > 1);
      else line.set(typeof dir?.polar === 'number' ? dir.polar : null, axes.includes('x') && axes.includes('y'));
      if (!draft) {
        view = viewFor(effect);
        paint();
      }
    },
    frame: perAnimationFrame(() => {
      if (!draft) paint();
    }),
  };
}
