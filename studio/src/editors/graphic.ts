// What a graphical editor is: an element made once (so that a drag survives the redraws
// that each edit causes) and redrawn from the store's state; edits go back through the
// store (state flows one way). The generated form stays below it for the typed values
// and the effect's timing (registry.ts).
import type { EffectJson } from '../document';
import type { State } from '../store';
import type { TypeInfo } from './form';
import type { LiveFrame } from './live_feed';

export interface GraphicContext {
  state: State;
  fx: EffectJson;
  index: number;
  info: TypeInfo | undefined;
  deviceAxes: string[];
  edit: (change: (e: EffectJson) => void) => void;
}

export interface Graphic {
  readonly el: HTMLElement;
  render(c: GraphicContext): void;
}

export const block = (fx: EffectJson, key: string) => (fx[key] ?? {}) as Record<string, unknown>;
export const num = (o: Record<string, unknown>, k: string, dflt = 0) => (typeof o[k] === 'number' ? (o[k] as number) : dflt);
export const blockOf = (e: EffectJson, key: string) => {
  if (typeof e[key] !== 'object' || e[key] === null) e[key] = {};
  return e[key] as Record<string, unknown>;
};

// The device's force along an effect: its single axis, or the line of a polar angle
// (0.01°; the force of a positive value pushes away from where it comes from, §6.5).
export function forceAlong(fx: EffectJson, frame: LiveFrame, deviceAxes: string[], polar: number | null): number | null {
  const axes = (fx.axes as string[]) ?? [];
  const at = (a: string) => frame.force[deviceAxes.indexOf(a)] ?? 0;
  if (frame.force.length === 0) return null;
  if (polar !== null && axes.includes('x') && axes.includes('y')) {
    const t = (polar / 100) * (Math.PI / 180);
    return -(at('x') * Math.sin(t) + at('y') * Math.cos(t));
  }
  return axes.length ? at(axes[0]) : null;
}

export function polarOf(fx: EffectJson): number | null {
  const d = fx.direction as Record<string, unknown> | undefined;
  return d && typeof d.polar === 'number' ? d.polar : null;
}
