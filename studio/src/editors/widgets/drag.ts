// Draggable handles on a canvas, the one pointer mechanism of the graphical editors.
//
// An editor draws its picture and lists its handles (where they are, in canvas pixels, and
// what dragging them does). Pressing near a handle captures the pointer; every move calls
// the handle's drag() with the pointer in canvas pixels, so the editor can change its
// draft and redraw (what you see follows the pointer at once); releasing calls drop(),
// where the editor commits the draft to the store as one edit (one undo step, one
// set_sensation to the device). A press away from every handle does nothing.
//
// Every canvas with handles is registered, so that handlePositions() can tell where each
// handle is on the page: the end-to-end tests drag them with the real mouse from there.

export interface Handle {
  id: string; // unique on the page while shown, e.g. "spring.pos_coefficient"
  x: number; // canvas pixels
  y: number;
  // distance from the pointer to the handle in canvas pixels (default: to the point x, y)
  hit?: (px: number, py: number) => number;
  cursor?: string;
  drag: (px: number, py: number) => void;
}

interface Registered {
  canvas: HTMLCanvasElement;
  handles: () => Handle[];
}
const registry = new Set<Registered>();
const kGrab = 9; // px: how near the pointer must be to take a handle

export function attachHandles(canvas: HTMLCanvasElement, handles: () => Handle[], drop: () => void): void {
  const entry: Registered = { canvas, handles };
  registry.add(entry);
  let active: Handle | null = null;
  const at = (e: PointerEvent): [number, number] => {
    const r = canvas.getBoundingClientRect();
    return [((e.clientX - r.left) * canvas.width) / r.width, ((e.clientY - r.top) * canvas.height) / r.height];
  };
  const nearest = (px: number, py: number): Handle | null => {
    let best: Handle | null = null;
    let bestDistance = kGrab;
    for (const hd of handles()) {
      const d = hd.hit ? hd.hit(px, py) : Math.hypot(px - hd.x, py - hd.y);
      if (d <= bestDistance) {
        best = hd;
        bestDistance = d;
      }
    }
    return best;
  };
  canvas.addEventListener('pointerdown', (e) => {
    const [px, py] = at(e);
    active = nearest(px, py);
    if (!active) return;
    canvas.setPointerCapture(e.pointerId);
    e.preventDefault();
    active.drag(px, py);
  });
  canvas.addEventListener('pointermove', (e) => {
    const [px, py] = at(e);
    if (active) active.drag(px, py);
    else canvas.style.cursor = nearest(px, py)?.cursor ?? 'default';
  });
  const end = () => {
    if (!active) return;
    active = null;
    drop();
  };
  canvas.addEventListener('pointerup', end);
  canvas.addEventListener('pointercancel', end);
}

// Where every shown handle is, in the page's CSS pixels (for the tests).
export function handlePositions(): Record<string, [number, number]> {
  const out: Record<string, [number, number]> = {};
  for (const entry of [...registry]) {
    if (!entry.canvas.isConnected) {
      registry.delete(entry);
      continue;
    }
    const r = entry.canvas.getBoundingClientRect();
    for (const hd of entry.handles()) {
      out[hd.id] = [r.left + (hd.x * r.width) / entry.canvas.width, r.top + (hd.y * r.height) / entry.canvas.height];
    }
  }
  return out;
}

// A value kept within a drag's range (the field's own range, from the field description).
export const clamp = (v: number, lo: number, hi: number) => Math.max(lo, Math.min(hi, v));

// A linear map between a value range and a pixel range (either may be reversed).
export function linear(v0: number, v1: number, p0: number, p1: number) {
  const k = (p1 - p0) / (v1 - v0);
  return { px: (v: number) => p0 + (v - v0) * k, value: (p: number) => v0 + (p - p0) / k };
}
