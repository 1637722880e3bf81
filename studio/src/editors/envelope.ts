// The impulse envelope (§4.2.a) on a force-over-time plot: its outline and its four
// handles (impulse level at the start, settle time, fade time before the end, fade
// level at the end), each dragged along the one dimension it sets. The level law is the
// engine's (src/engine/envelope.hpp): linear from the impulse level to the steady level S
// over the settle time, then linear from there to the fade level over the last fade time;
// an endless effect has no fade.
import type { TimeFrame } from './time_plot';
import { levelAt, timeAt } from './time_plot';
import { clamp, handle, svg } from './widgets/svg_kit';

export interface EnvelopeJson {
  impulse_level?: number;
  settle_time_us?: number;
  fade_level?: number;
  fade_time_us?: number;
}

export function envelopeLevel(env: EnvelopeJson | undefined, steady: number, tauUs: number, durationUs: number | null): number {
  if (!env) return steady;
  const settle = env.settle_time_us ?? 0;
  const fade = env.fade_time_us ?? 0;
  const attack = (t: number) => (settle > 0 && t < settle ? (env.impulse_level ?? 0) + ((steady - (env.impulse_level ?? 0)) * t) / settle : steady);
  if (durationUs === null || fade <= 0 || tauUs < durationUs - fade) return attack(tauUs);
  const from = attack(durationUs - fade);
  return from + (((env.fade_level ?? 0) - from) * (tauUs - (durationUs - fade))) / fade;
}

// Outline and handles. `steadyAt(τ)` is S at τ (≥ 0: a ramp's |level| varies), drawn on
// the `sign` side of the baseline: as an outline mirrored below it for a wave that swings
// both ways, or only as handles where the curve itself is the shaped force.
export function envelopeParts(
  f: TimeFrame,
  env: EnvelopeJson | undefined,
  steadyAt: (tauUs: number) => number,
  baseline: number,
  outline: 'mirror' | 'none' = 'mirror',
  sign = 1,
): SVGElement[] {
  const duration = f.infinite ? null : f.spanUs;
  const pts = (side: number) => {
    const list: string[] = [];
    for (let i = 0; i <= 200; ++i) {
      const tau = (f.spanUs * i) / 200;
      list.push(`${f.t.px(tau).toFixed(1)},${f.v.px(baseline + side * envelopeLevel(env, steadyAt(tau), tau, duration)).toFixed(1)}`);
    }
    return list.join(' ');
  };
  const parts: SVGElement[] = [];
  if (outline === 'mirror') {
    parts.push(svg('polyline', { points: pts(sign), fill: 'none', stroke: '#e3a21a', 'stroke-width': 1.5, 'stroke-dasharray': '5 3' }));
    parts.push(svg('polyline', { points: pts(-sign), fill: 'none', stroke: '#e3a21a', 'stroke-width': 1, 'stroke-dasharray': '2 3' }));
  }
  const e = env ?? {};
  const at = (tau: number) => f.v.px(baseline + sign * steadyAt(tau));
  const settle = Math.min(e.settle_time_us ?? 0, f.spanUs);
  parts.push(handle('impulse_level', f.t.px(0), env ? f.v.px(baseline + sign * (e.impulse_level ?? 0)) : at(0), '#e3a21a', 'impulse level: drag up or down'));
  parts.push(handle('settle_time_us', f.t.px(settle), at(settle), '#c47a00', 'settle time: drag sideways'));
  if (!f.infinite) {
    const fadeStart = Math.max(0, f.spanUs - (e.fade_time_us ?? 0));
    parts.push(handle('fade_time_us', f.t.px(fadeStart), at(fadeStart), '#c47a00', 'fade time: drag sideways'));
    parts.push(handle('fade_level', f.t.px(f.spanUs), env ? f.v.px(baseline + sign * (e.fade_level ?? 0)) : at(f.spanUs), '#e3a21a', 'fade level: drag up or down'));
  }
  return parts;
}

// What dragging an envelope handle does: the new envelope (made whole the first time, so
// that it starts out as "no envelope": every level at S, no settle, no fade).
export function envelopeDrag(
  name: string,
  f: TimeFrame,
  steadyAt: (tauUs: number) => number,
  baseline: number,
  set: (env: EnvelopeJson) => void,
  current: () => EnvelopeJson | undefined,
): ((p: { x: number; y: number }) => void) | null {
  if (!['impulse_level', 'settle_time_us', 'fade_time_us', 'fade_level'].includes(name)) return null;
  return (p) => {
    const env: EnvelopeJson = { impulse_level: steadyAt(0), settle_time_us: 0, fade_level: steadyAt(f.spanUs), fade_time_us: 0, ...current() };
    if (name === 'impulse_level' || name === 'fade_level') env[name] = clamp(Math.abs(levelAt(f, p.y) - baseline), 0, 10000);
    else if (name === 'settle_time_us') env.settle_time_us = clamp(timeAt(f, p.x), 0, f.spanUs);
    else env.fade_time_us = clamp(f.spanUs - timeAt(f, p.x), 0, f.spanUs);
    set(env);
  };
}
