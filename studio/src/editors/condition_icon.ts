// The little machine next to a condition's curve (§3.2–3.5), drawn from the live state:
// a spring that stretches with the handle's distance from the centre, a dashpot whose
// piston slides out with the velocity, a flywheel that turns with the travel and shows
// the acceleration as an arrow, a block on a rough surface that slides with the travel
// and shows the friction's pull. `input` is the curve's input (±10000), `force` the
// force along the block's axis (±10000, + pushes toward +).
export type ConditionFamily = 'spring' | 'damper' | 'inertia' | 'friction';

export function drawConditionIcon(c: CanvasRenderingContext2D, w: number, hgt: number, family: ConditionFamily, input: number, travel: number, force: number): void {
  c.clearRect(0, 0, w, hgt);
  c.fillStyle = '#f7f8fa';
  c.fillRect(0, 0, w, hgt);
  const cx = w / 2;
  const k = 70 / 10000; // px per unit: full scale stretches 70 px
  c.strokeStyle = '#48526a';
  c.fillStyle = '#48526a';
  c.lineWidth = 2;
  const arrow = (x: number, y: number, len: number, color: string) => {
    if (Math.abs(len) < 3) return;
    c.strokeStyle = color;
    c.fillStyle = color;
    c.beginPath(); c.moveTo(x, y); c.lineTo(x, y - len); c.stroke();
    const s = Math.sign(len);
    c.beginPath(); c.moveTo(x, y - len); c.lineTo(x - 5, y - len + 8 * s); c.lineTo(x + 5, y - len + 8 * s); c.fill();
  };
  // the base (the ground the machine is fixed to)
  const ground = (y: number) => {
    c.strokeStyle = '#48526a';
    c.beginPath(); c.moveTo(cx - 30, y); c.lineTo(cx + 30, y); c.stroke();
    for (let x = cx - 30; x < cx + 30; x += 8) { c.beginPath(); c.moveTo(x, y); c.lineTo(x - 6, y + 6); c.stroke(); }
  };
  // up on the screen is + along the block's axis
  const d = Math.max(-10000, Math.min(10000, input));
  switch (family) {
    case 'spring': {
      const top = 24;
      const rest = hgt * 0.55;
      const end = rest - d * k; // the handle's end moves up with +d
      ground(top); // fixed above: the spring hangs from it
      c.strokeStyle = '#1b9e5a';
      c.beginPath();
      c.moveTo(cx, top);
      const coils = 9;
      const span = end - top - 20;
      c.lineTo(cx, top + 10);
      for (let n = 0; n < coils; ++n) c.lineTo(cx + (n % 2 ? -12 : 12), top + 10 + (span * (n + 0.5)) / coils);
      c.lineTo(cx, end - 10);
      c.lineTo(cx, end);
      c.stroke();
      c.fillStyle = '#2458d6';
      c.fillRect(cx - 14, end, 28, 16);
      arrow(cx + 30, end + 8, force * k, '#d63a24');
      break;
    }
    case 'damper': {
      const top = 24;
      ground(top);
      c.strokeStyle = '#7a3fc4';
      c.strokeRect(cx - 14, top + 6, 28, 90); // the cylinder
      c.beginPath(); c.moveTo(cx, top); c.lineTo(cx, top + 6); c.stroke();
      const piston = top + 56 - d * k * 0.5; // slides out with the velocity
      c.fillStyle = '#c9b3ea';
      c.fillRect(cx - 12, top + 6, 24, Math.max(0, piston - top - 6));
      c.strokeStyle = '#48526a';
      c.beginPath(); c.moveTo(cx - 12, piston); c.lineTo(cx + 12, piston); c.moveTo(cx, piston); c.lineTo(cx, hgt - 40); c.stroke();
      c.fillStyle = '#2458d6';
      c.fillRect(cx - 14, hgt - 40, 28, 16);
      arrow(cx + 30, hgt - 32, force * k, '#d63a24');
      break;
    }
    case 'inertia': {
      const cy = hgt * 0.45;
      const r = 34;
      const turn = (travel / 10000) * 2 * Math.PI; // the wheel rolls with the travel
      c.strokeStyle = '#e08a1e';
      c.lineWidth = 4;
      c.beginPath(); c.arc(cx, cy, r, 0, 2 * Math.PI); c.stroke();
      c.lineWidth = 2;
      for (let n = 0; n < 4; ++n) {
        const t = turn + (n * Math.PI) / 2;
        c.beginPath(); c.moveTo(cx, cy); c.lineTo(cx + Math.cos(t) * r, cy + Math.sin(t) * r); c.stroke();
      }
      c.fillStyle = '#48526a';
      c.beginPath(); c.arc(cx, cy, 4, 0, 2 * Math.PI); c.fill();
      arrow(cx - 46, cy, d * k * 0.6, '#2458d6'); // the acceleration
      arrow(cx + 46, cy, force * k * 0.6, '#d63a24'); // the force resisting it
      break;
    }
    case 'friction': {
      const surface = hgt * 0.7;
      c.strokeStyle = '#48526a';
      c.beginPath();
      for (let x = 6; x < w - 6; x += 6) c.lineTo(x, surface + ((x / 6) % 2 ? 3 : 0)); // rough
      c.stroke();
      const slide = ((((travel / 10000) * 30) % 60) + 60) % 60 - 30; // the block slides with the travel
      c.fillStyle = '#2458d6';
      c.fillRect(cx - 16 + slide, surface - 24, 32, 22);
      // the friction's pull along the surface (sideways: + is right)
      const f = force * k * 0.6;
      if (Math.abs(f) > 3) {
        c.strokeStyle = '#d63a24';
        c.fillStyle = '#d63a24';
        const y = surface - 36;
        c.beginPath(); c.moveTo(cx + slide, y); c.lineTo(cx + slide + f, y); c.stroke();
        const s = Math.sign(f);
        c.beginPath(); c.moveTo(cx + slide + f, y); c.lineTo(cx + slide + f - 8 * s, y - 5); c.lineTo(cx + slide + f - 8 * s, y + 5); c.fill();
      }
      break;
    }
  }
  c.lineWidth = 1;
}
