// What a graphical editor is, and what it is given (editors/registry.ts builds them).
//
// State flows one way: the store's document is drawn; a drag changes the editor's own
// draft (drawn at once) and, when the pointer is released, becomes one store.update()
// (one undo step, one set_sensation that the server validates and sends to the device).
// The typed fields stay below the picture (the generated form): every parameter can be
// dragged or typed, and a value the validator refuses shows its message at its field.
//
// The device's live state comes through LiveFeed, read on every state frame (frame()).
import type { EffectJson } from '../document';
import type { State, Store } from '../store';
import type { FieldInfo, FieldsDescription } from './form';

export interface EffectLiveState {
  state: string;
  starts: number;
  armed: boolean;
  elapsed_us?: number;
}

// The device as the editors see it: its newest report and the recent ones.
export interface LiveFeed {
  position(): number[]; // ±10000 per device axis
  force(): number[]; // ±10000 per device axis
  rows(): number[][]; // the plot's window: [t_ms, force per axis..., position per axis...]
  effects(): EffectLiveState[]; // per effect of the sensation, 10 times a second
  target(): [number, number] | null; // where the pad's pointer holds the simulated hand (x, y)
}

export interface GraphicEditor {
  el: HTMLElement;
  // the document changed (or another effect was selected): draw effect i from it
  render(s: State, fx: EffectJson, i: number): void;
  // a state frame arrived: move what shows the device's state
  frame(): void;
}

export type EditorFactory = (store: Store, live: LiveFeed) => GraphicEditor;

// Changes effect i of the current sensation as one edit.
export function commit(store: Store, i: number, change: (fx: EffectJson) => void): void {
  store.update((d) => change(d.sensations[d.current].effects[i]), i);
}

// The description of a field of a type's block (its range, its unit), or of a common one.
export function fieldOf(s: State, type: string, name: string): FieldInfo | undefined {
  const desc = s.hello?.fields as unknown as FieldsDescription | undefined;
  const info = desc?.types.find((t) => t.type === type);
  return info?.fields.find((f) => f.name === name) ?? desc?.common.find((f) => f.name === name);
}

// The device's axis names, in its order.
export const deviceAxes = (s: State): string[] => ((s.hello?.device.axes as { name: string }[]) ?? []).map((a) => a.name);

// Velocity and acceleration of device axis `a`, in position units per second (and per
// second²), from the newest reports: least-squares slopes over the last `windowMs` of
// the device's own time (the reports are quantized; a slope over ~20 reports is smooth).
export function motion(rows: number[][], axisCount: number, a: number, windowMs = 30): { velocity: number; acceleration: number } {
  const col = 1 + axisCount + a;
  const recent = rows.slice(-400); // 400 ms of reports at 1 kHz (800 at 500 Hz): more than the windows need
  const slope = (from: number, to: number) => {
    const pts = recent.filter((r) => r[0] > from && r[0] <= to);
    if (pts.length < 3) return 0;
    const mt = pts.reduce((s, r) => s + r[0], 0) / pts.length;
    const mx = pts.reduce((s, r) => s + r[col], 0) / pts.length;
    let num = 0;
    let den = 0;
    for (const r of pts) {
      num += (r[0] - mt) * (r[col] - mx);
      den += (r[0] - mt) ** 2;
    }
    return den > 0 ? (num / den) * 1000 : 0; // per ms -> per s
  };
  const t = rows.length ? rows[rows.length - 1][0] : 0;
  const v1 = slope(t - windowMs, t);
  const v0 = slope(t - 2 * windowMs, t - windowMs);
  return { velocity: v1, acceleration: ((v1 - v0) / windowMs) * 1000 };
}

// A unit vector for a compass angle in hundredths of a degree (0 = +y, 9000 = +x).
export function compass(angle: number): [number, number] {
  const t = ((angle / 100) * Math.PI) / 180;
  return [Math.sin(t), Math.cos(t)];
}

// A 2-D canvas, its pixel size fixed, for an editor's picture.
export function canvasOf(w: number, hgt: number, cls: string): HTMLCanvasElement {
  const c = document.createElement('canvas');
  c.width = w;
  c.height = hgt;
  c.className = cls;
  return c;
}

// A dragged draft of effect i becomes the effect, as one edit (nothing if unchanged).
export function commitDraft(store: Store, i: number, before: EffectJson | null, draft: EffectJson | null): boolean {
  if (!draft || !before || JSON.stringify(draft) === JSON.stringify(before)) return false;
  store.update((d) => (d.sensations[d.current].effects[i] = structuredClone(draft)), i);
  return true;
}

// A dial on a one-axis effect picks its axis: east (9000) is x, north (0) is y.
export const axisOfAngle = (angle: number): 'x' | 'y' => (Math.abs(((angle + 18000) % 18000) - 9000) < 4500 ? 'x' : 'y');
export const angleOfAxis = (axis: string | undefined): number | null => (axis === 'x' ? 9000 : axis === 'y' ? 0 : null);

// A dragged value kept within its field's range, as the field description gives it (the
// validator's own range: no range is written twice), rounded to the file's integer unit.
export function limit(s: State | null, type: string, name: string, v: number): number {
  const f = s ? fieldOf(s, type, name) : undefined;
  return Math.round(Math.max(f?.min ?? -Infinity, Math.min(f?.max ?? Infinity, v)));
}

// Coalesces repaints to one per animation frame, however many state frames arrive (up to
// 250 a second while the browser interacts): the page's one thread stays free for them.
export function perAnimationFrame(paint: () => void): () => void {
  let pending = false;
  return () => {
    if (pending) return;
    pending = true;
    requestAnimationFrame(() => {
      pending = false;
      paint();
    });
  };
}
