// The effect's timing, shown by every editor (§6.4's common parameters): start delay,
// duration, iterations, gain and trigger, drawn as a timeline. The start delay is a grey
// lead-in, each iteration a block as long as the duration and as tall as the gain, a
// trigger button's repeat interval a row of ticks; while the effect plays a playhead
// moves with the device's elapsed time. The delay's end, the first block's end and its
// top are handles (drag them); every value is also a typed field of the form below.
//
// One panel per editor host; the graphical editors of every family use it
// (timingPanel(store, live) -> {el, render, frame}).
import { h, liveText } from '../dom';
import type { EffectJson } from '../document';
import type { State, Store } from '../store';
import { canvasOf, commitDraft, limit, type LiveFeed, perAnimationFrame } from './editor';
import { attachHandles, clamp, type Handle, linear } from './widgets/drag';

const kW = 480;
const kH = 74;
const kLane = { l: 8, r: 30, t: 14, b: 22 };
const kShownIterations = 4; // blocks drawn; more are written as ×N

export interface TimingPanel {
  el: HTMLElement;
  render(s: State, fx: EffectJson, i: number): void;
  frame(): void;
}

const us = (v: number) => (v >= 1e6 ? `${(v / 1e6).toFixed(v % 1e6 ? 2 : 0)} s` : `${Math.round(v / 1000)} ms`);

export function timingPanel(store: Store, live: LiveFeed): TimingPanel {
  const canvas = canvasOf(kW, kH, 'timing');
  const text = h('div', { class: 'timing-text' });
  const el = h('div', { class: 'timing-panel' }, h('div', { class: 'timing-title' }, 'timing'), canvas, text);
  let s: State | null = null;
  let index = -1;
  let fx: EffectJson | null = null;
  let draft: EffectJson | null = null;
  let span = 1e6; // µs shown across the lane; frozen while a handle is dragged

  const current = () => draft ?? fx;
  const numOr = (v: unknown, d: number) => (typeof v === 'number' ? v : d);
  const timing = (e: EffectJson) => {
    const infinite = e.duration_us === 'infinite';
    return {
      delay: numOr(e.start_delay_us, 0),
      duration: infinite ? null : numOr(e.duration_us, 0),
      iterations: e.iterations === 'infinite' ? Infinity : numOr(e.iterations, 1),
      gain: numOr(e.gain, 10000),
      trigger: e.trigger_button,
      repeat: numOr(e.trigger_repeat_interval_us, 0),
    };
  };
  const spanFor = (e: EffectJson) => {
    const t = timing(e);
    const shown = t.duration === null ? 1e6 : t.duration * Math.min(t.iterations, kShownIterations);
    return Math.max(100000, (t.delay + shown) * 1.15);
  };
  const T = () => linear(0, span, kLane.l, kW - kLane.r);
  const G = linear(0, 10000, kH - kLane.b, kLane.t);
  const edit = (change: (e: EffectJson) => void) => {
    if (!draft && fx) draft = structuredClone(fx);
    if (draft) change(draft);
    paint();
  };

  const handles = (): Handle[] => {
    const e = current();
    if (!e) return [];
    const t = timing(e);
    const x = T();
    const list: Handle[] = [
      {
        id: 'timing.start_delay_us', x: x.px(t.delay), y: kH - kLane.b + 8, cursor: 'ew-resize',
        drag: (px) => edit((d) => {
          const v = limit(s, e.type, 'start_delay_us', Math.round(x.value(px) / 1000) * 1000);
          if (v === 0) delete d.start_delay_us;
          else d.start_delay_us = v;
        }),
      },
    ];
    if (t.duration !== null) {
      list.push({
        id: 'timing.duration_us', x: x.px(t.delay + t.duration), y: G.px(t.gain / 2), cursor: 'ew-resize',
        drag: (px) => edit((d) => {
          d.duration_us = limit(s, e.type, 'duration_us', Math.max(1000, Math.round((x.value(px) - t.delay) / 1000) * 1000));
        }),
      });
    }
    const end = t.duration === null ? span : t.delay + t.duration;
    list.push({
      id: 'timing.gain', x: x.px((t.delay + Math.min(end, span)) / 2), y: G.px(t.gain), cursor: 'ns-resize',
      drag: (_px, py) => edit((d) => {
        const v = limit(s, e.type, 'gain', Math.round(G.value(py) / 100) * 100);
        if (v === 10000) delete d.gain;
        else d.gain = v;
      }),
    });
    return list;
  };

  attachHandles(canvas, handles, () => {
    const d = draft;
    draft = null;
    if (!commitDraft(store, index, fx, d)) paint();
  });

  function paint(): void {
    const g = canvas.getContext('2d')!;
    g.clearRect(0, 0, kW, kH);
    g.fillStyle = '#fbfcfd';
    g.fillRect(0, 0, kW, kH);
    const e = current();
    if (!e) return;
    const t = timing(e);
    const x = T();
    const base = G.px(0);
    g.strokeStyle = '#c5cad3';
    g.beginPath(); g.moveTo(kLane.l, base); g.lineTo(kW - kLane.r + 20, base); g.stroke();
    // the time axis: 0 and the end of what is shown
    g.fillStyle = '#7a8394';
    g.font = '10px system-ui';
    g.fillText('0', x.px(0) + 10, base + 14);
    g.textAlign = 'right';
    g.fillText(us(span), kW - kLane.r, base + 14);
    g.textAlign = 'left';
    // the start delay
    g.fillStyle = '#e6e8ee';
    g.fillRect(x.px(0), G.px(10000), x.px(t.delay) - x.px(0), base - G.px(10000));
    // the iterations
    const top = G.px(t.gain);
    const n = t.duration === null ? 1 : Math.min(t.iterations, kShownIterations);
    for (let k = 0; k < n; ++k) {
      const a = t.delay + (t.duration ?? 0) * k;
      const b = t.duration === null ? span * 1.2 : a + t.duration;
      g.fillStyle = k === 0 ? 'rgba(36, 88, 214, 0.30)' : 'rgba(36, 88, 214, 0.16)';
      g.fillRect(x.px(a), top, Math.min(x.px(b), kW) - x.px(a), base - top);
      g.strokeStyle = '#2458d6';
      g.strokeRect(x.px(a), top, Math.min(x.px(b), kW + 2) - x.px(a), base - top);
    }
    g.fillStyle = '#48526a';
    g.font = '11px system-ui';
    if (t.duration === null) g.fillText('∞', kW - kLane.r + 8, top + 12);
    else if (t.iterations > kShownIterations) g.fillText(t.iterations === Infinity ? '×∞' : `×${t.iterations}`, kW - kLane.r + 2, top + 12);
    // a trigger's repeat interval: ticks where the reflex starts it again
    if (t.trigger !== undefined && t.repeat > 0) {
      g.strokeStyle = '#e08a1e';
      for (let r = t.repeat; r < span; r += t.repeat) {
        g.beginPath(); g.moveTo(x.px(r), base + 2); g.lineTo(x.px(r), base + 9); g.stroke();
      }
    }
    // the live playhead: the device's elapsed time of this effect while it plays
    const st = live.effects()[index];
    if (st?.state === 'playing' && typeof st.elapsed_us === 'number') {
      const px = x.px(clamp(st.elapsed_us, 0, span));
      g.strokeStyle = '#d63a24';
      g.lineWidth = 2;
      g.beginPath(); g.moveTo(px, kLane.t - 4); g.lineTo(px, base + 4); g.stroke();
      g.lineWidth = 1;
    }
    for (const hd of handles()) {
      g.fillStyle = hd.id === 'timing.gain' ? '#2458d6' : '#48526a';
      if (hd.id === 'timing.gain') g.fillRect(hd.x - 10, hd.y - 3, 20, 6);
      else { g.beginPath(); g.arc(hd.x, hd.y, 5, 0, 2 * Math.PI); g.fill(); }
    }
    const trig = t.trigger === undefined ? 'no trigger' : `trigger ${String(t.trigger)}${t.repeat ? `, repeats every ${us(t.repeat)}` : ''}`;
    liveText(text, `delay ${us(t.delay)} · duration ${t.duration === null ? '∞' : us(t.duration)} · ` +
      `${t.iterations === Infinity ? '∞' : t.iterations} iteration${t.iterations === 1 ? '' : 's'} · gain ${t.gain} · ${trig}` +
      (st ? ` · ${st.state}` : '') + (st?.state === 'playing' && typeof st.elapsed_us === 'number' ? ` ${us(st.elapsed_us)}` : ''));
  }

  return {
    el,
    render(state, effect, i) {
      s = state;
      index = i;
      fx = effect;
      if (!draft) {
        span = spanFor(effect);
        paint();
      }
    },
    frame: perAnimationFrame(() => {
      if (!draft) paint();
    }),
  };
}
