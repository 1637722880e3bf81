// A compass dial: an angle in hundredths of a degree, 0 = north (+y, up on the screen),
// growing clockwise (9000 = east, +x), as the format's polar angles and wall angles are
// (docs/conventions.md). Drag anywhere on the dial to turn the needle; the angle snaps to
// whole degrees (hold Shift for hundredths). Releasing commits.
import { h } from '../../dom';
import { attachHandles } from './drag';

export interface Dial {
  el: HTMLElement;
  set(angle: number | null, enabled?: boolean): void; // null: no angle yet (drawn hollow)
}

const kSize = 84;

export function dial(id: string, label: string, commit: (angle: number) => void): Dial {
  const canvas = h('canvas', { width: kSize, height: kSize, class: 'dial', 'data-dial': id, title: `${label}: drag to turn` });
  const text = h('span', { class: 'dial-value' });
  let value: number | null = null;
  let draft: number | null = null;
  let enabled = true;
  let fine = false;
  const c = kSize / 2;
  const r = kSize / 2 - 8;
  const paint = () => {
    const g = canvas.getContext('2d')!;
    const v = draft ?? value;
    g.clearRect(0, 0, kSize, kSize);
    g.strokeStyle = enabled ? '#8a93a3' : '#d5d9e0';
    g.lineWidth = 1.5;
    g.beginPath(); g.arc(c, c, r, 0, 2 * Math.PI); g.stroke();
    g.fillStyle = '#8a93a3';
    g.font = '9px system-ui';
    g.textAlign = 'center';
    g.fillText('N', c, 8);
    for (let k = 0; k < 8; ++k) {
      const t = (k * Math.PI) / 4;
      g.beginPath();
      g.moveTo(c + Math.sin(t) * (r - 4), c - Math.cos(t) * (r - 4));
      g.lineTo(c + Math.sin(t) * r, c - Math.cos(t) * r);
      g.stroke();
    }
    if (v !== null) {
      const t = ((v / 100) * Math.PI) / 180;
      const tip = [c + Math.sin(t) * (r - 2), c - Math.cos(t) * (r - 2)];
      g.strokeStyle = enabled ? '#2458d6' : '#a9b4c8';
      g.lineWidth = 3;
      g.beginPath(); g.moveTo(c, c); g.lineTo(tip[0], tip[1]); g.stroke();
      g.fillStyle = g.strokeStyle;
      g.beginPath(); g.arc(tip[0], tip[1], 4, 0, 2 * Math.PI); g.fill();
    }
    text.textContent = v === null ? `${label}: —` : `${label}: ${(v / 100).toFixed(2)}°`;
  };
  canvas.addEventListener('pointerdown', (e) => (fine = e.shiftKey));
  attachHandles(
    canvas,
    () => {
      const v = value ?? 0;
      const t = ((v / 100) * Math.PI) / 180;
      return enabled
        ? [{
            id: `dial.${id}`,
            x: c + Math.sin(t) * (r - 2),
            y: c - Math.cos(t) * (r - 2),
            hit: (px: number, py: number) => (Math.hypot(px - c, py - c) <= r + 4 ? 0 : Infinity),
            cursor: 'grab',
            drag: (px: number, py: number) => {
              const deg = ((Math.atan2(px - c, c - py) * 180) / Math.PI + 360) % 360;
              const hundredths = fine ? Math.round(deg * 100) : Math.round(deg) * 100;
              draft = hundredths % 36000;
              paint();
            },
          }]
        : [];
    },
    () => {
      if (draft !== null && draft !== value) commit(draft);
      draft = null;
    },
  );
  const el = h('div', { class: 'dial-box' }, canvas, text);
  return {
    el,
    set(angle, on = true) {
      value = angle;
      enabled = on;
      paint();
    },
  };
}
