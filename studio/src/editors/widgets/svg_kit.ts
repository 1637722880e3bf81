// Small SVG helpers for the graphical editors: an element builder, a linear scale and the
// one way a handle is dragged (pointer captured by the persistent <svg>, so the drawing
// can be rebuilt under the pointer while a drag goes on).
const NS = 'http://www.w3.org/2000/svg';

export function svg<K extends keyof SVGElementTagNameMap>(
  tag: K,
  attrs: Record<string, string | number | undefined> = {},
  ...children: (Node | string | null | undefined)[]
): SVGElementTagNameMap[K] {
  const e = document.createElementNS(NS, tag);
  for (const [k, v] of Object.entries(attrs)) if (v !== undefined) e.setAttribute(k, String(v));
  for (const c of children) if (c !== null && c !== undefined) e.append(c);
  return e;
}

// data <-> pixels, linear
export class Scale {
  constructor(
    readonly d0: number,
    readonly d1: number,
    readonly p0: number,
    readonly p1: number,
  ) {}
  px(v: number): number {
    return this.p0 + ((v - this.d0) * (this.p1 - this.p0)) / (this.d1 - this.d0);
  }
  value(p: number): number {
    return this.d0 + ((p - this.p0) * (this.d1 - this.d0)) / (this.p1 - this.p0);
  }
}

export type Point = { x: number; y: number };
// Called at pointerdown on an element with data-handle: returns what each move does.
export type DragStart = (handle: string, at: Point, e: PointerEvent) => ((at: Point) => void) | null;

// The pointer in the svg's own coordinates (its viewBox).
export function svgPoint(root: SVGSVGElement, e: { clientX: number; clientY: number }): Point {
  const m = root.getScreenCTM();
  if (!m) return { x: 0, y: 0 };
  const p = new DOMPoint(e.clientX, e.clientY).matrixTransform(m.inverse());
  return { x: p.x, y: p.y };
}

export function draggable(root: SVGSVGElement, start: DragStart): void {
  let move: ((at: Point) => void) | null = null;
  root.addEventListener('pointerdown', (e) => {
    const target = (e.target as Element).closest('[data-handle]');
    const handle = target?.getAttribute('data-handle') ?? (root.dataset.background ?? '');
    if (!handle) return;
    move = start(handle, svgPoint(root, e), e);
    if (!move) return;
    e.preventDefault();
    root.setPointerCapture(e.pointerId);
    move(svgPoint(root, e));
  });
  root.addEventListener('pointermove', (e) => move?.(svgPoint(root, e)));
  const end = () => (move = null);
  root.addEventListener('pointerup', end);
  root.addEventListener('pointercancel', end);
}

// A round handle with its name (for the drag and for the tests).
export function handle(name: string, x: number, y: number, color: string, title: string): SVGElement {
  return svg('circle', { 'data-handle': name, cx: x, cy: y, r: 6, fill: color, stroke: '#fff', 'stroke-width': 2, class: 'handle' },
    svg('title', {}, title));
}

export const clamp = (v: number, lo: number, hi: number) => Math.max(lo, Math.min(hi, v));
