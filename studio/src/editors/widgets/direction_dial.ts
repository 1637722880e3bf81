// A compass dial for an angle in hundredths of a degree (docs/conventions.md: 0 = +y,
// forward, up on the screen; 9000 = +x, right; clockwise increases). Drag the needle (or
// anywhere on the dial) to set it. A sweep's dial also shows the arc it sweeps (§9.4's
// figure: start and end, the sense), and any dial can show a live needle (where the
// device's force comes from now). Named direction_dial to stay apart from the condition
// editors' dial until the two are unified.
import { draggable, svg } from './svg_kit';

export interface DialDraw {
  angle: number; // 0.01°
  arc?: { from: number; to: number; clockwise: boolean }; // a sweep, 0.01°
  live?: number | null; // 0.01°, drawn thin in red
}

const kR = 40;
const kC = 50;

const toXY = (angle: number, r: number) => {
  const t = (angle / 100) * (Math.PI / 180);
  return [kC + r * Math.sin(t), kC - r * Math.cos(t)];
};

export class DirectionDial {
  readonly el: HTMLElement;
  private readonly root: SVGSVGElement;
  private readonly readout: HTMLElement;

  constructor(
    readonly name: string,
    label: string,
    set: (angle: number) => void,
  ) {
    this.root = svg('svg', { viewBox: '0 0 100 100', width: 100, height: 100, class: 'dial', 'data-dial': name });
    this.root.dataset.background = 'needle';
    draggable(this.root, () => (p) => {
      const a = Math.atan2(p.x - kC, kC - p.y) * (180 / Math.PI);
      set(((Math.round(a * 100) % 36000) + 36000) % 36000);
    });
    this.readout = document.createElement('div');
    this.readout.className = 'dial-readout';
    this.el = document.createElement('div');
    this.el.className = 'dial-box';
    const caption = document.createElement('div');
    caption.className = 'dial-label';
    caption.textContent = label;
    this.el.append(caption, this.root, this.readout);
  }

  draw(d: DialDraw): void {
    const parts: SVGElement[] = [
      svg('circle', { cx: kC, cy: kC, r: kR, fill: '#f7f8fa', stroke: '#c5cad3' }),
    ];
    for (let a = 0; a < 36000; a += 4500) {
      const [x0, y0] = toXY(a, kR - (a % 9000 ? 3 : 6));
      const [x1, y1] = toXY(a, kR);
      parts.push(svg('line', { x1: x0, y1: y0, x2: x1, y2: y1, stroke: '#9aa3b2' }));
    }
    parts.push(svg('text', { x: kC, y: 8, 'text-anchor': 'middle', 'font-size': 8, fill: '#7a8394' }, '+y'));
    parts.push(svg('text', { x: 97, y: kC + 3, 'text-anchor': 'end', 'font-size': 8, fill: '#7a8394' }, '+x'));
    if (d.arc) {
      const span = d.arc.clockwise ? (((d.arc.to - d.arc.from) % 36000) + 36000) % 36000 : (((d.arc.from - d.arc.to) % 36000) + 36000) % 36000;
      const [x0, y0] = toXY(d.arc.from, kR - 10);
      const [x1, y1] = toXY(d.arc.to, kR - 10);
      const large = span > 18000 ? 1 : 0;
      parts.push(svg('path', {
        d: `M ${x0} ${y0} A ${kR - 10} ${kR - 10} 0 ${large} ${d.arc.clockwise ? 1 : 0} ${x1} ${y1}`,
        fill: 'none', stroke: '#e3a21a', 'stroke-width': 4, 'stroke-opacity': 0.7,
      }));
    }
    const [nx, ny] = toXY(d.angle, kR - 4);
    parts.push(svg('line', { x1: kC, y1: kC, x2: nx, y2: ny, stroke: '#2458d6', 'stroke-width': 3, 'stroke-linecap': 'round' }));
    parts.push(svg('circle', { 'data-handle': 'needle', cx: nx, cy: ny, r: 5, fill: '#2458d6', stroke: '#fff', 'stroke-width': 1.5, class: 'handle' }));
    if (d.live !== undefined && d.live !== null) {
      const [lx, ly] = toXY(d.live, kR);
      parts.push(svg('line', { x1: kC, y1: kC, x2: lx, y2: ly, stroke: '#d63a24', 'stroke-width': 1.5 }));
    }
    parts.push(svg('circle', { cx: kC, cy: kC, r: 3, fill: '#1d2330' }));
    this.root.replaceChildren(...parts);
    this.readout.textContent = `${(d.angle / 100).toFixed(2)}°`;
  }
}

// The compass angle (0.01°) a force comes from, given the force vector on x and y (a
// force pushes away from where it comes from); null when it is too small to say.
export function forceFromAngle(fx: number, fy: number): number | null {
  if (Math.hypot(fx, fy) < 200) return null;
  const a = Math.atan2(-fx, -fy) * (180 / Math.PI);
  return ((Math.round(a * 100) % 36000) + 36000) % 36000;
}
