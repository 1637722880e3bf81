// Force profiles (§4.3.a custom force, §6.6.d): the samples as steps (each held for one
// sample period, as the engine plays them: src/engine/waves/force_profile_wave.cpp), one
// lane per channel (interleaved by channel in the file). Draw on a lane with the pointer:
// every sample under the stroke takes the level under it, in between by straight lines.
// Scale, shift (add a level) and smooth (a 3-sample moving average) act on the chosen
// lane; the number of frames can be set. Import, in the browser: a CSV column (parsed here;
// values as force, ±10000, or normalized so the peak is full scale), or a WAV file's
// amplitude envelope (decoded by the browser's own audio decoder, the Web Audio API's
// decodeAudioData, then the peak |amplitude| of its first channel over each sample period,
// full scale = 10000). An import sets the duration to one pass of the profile. Values out
// of range are not clamped: the validator names them at the field.
import { h } from '../dom';
import { block, blockOf, forceAlong, type Graphic, type GraphicContext, num, polarOf } from './graphic';
import { liveFeed } from './live_feed';
import { kW } from './time_plot';
import { clamp, draggable, Scale, svg } from './widgets/svg_kit';

const kLeft = 44;
const kRight = 14;
const kLaneGap = 8;

// CSV: one column (1-based) of numbers; a first row that is not a number is a header.
export function csvColumn(text: string, column: number): number[] {
  const rows = text.split(/\r?\n/).filter((r) => r.trim() !== '');
  const out: number[] = [];
  rows.forEach((row, i) => {
    const cells = row.split(/[,;\t]/);
    if (column < 1 || column > cells.length) {
      throw new Error(`CSV row ${i + 1}: has ${cells.length} columns, column ${column} asked (1..${cells.length})`);
    }
    const cell = cells[column - 1].trim().replace(/^"|"$/g, '');
    const v = Number(cell);
    if (cell === '' || Number.isNaN(v)) {
      if (i === 0) return; // a header
      throw new Error(`CSV row ${i + 1}, column ${column}: "${cell.slice(0, 40)}" is not a number`);
    }
    out.push(v);
  });
  if (out.length === 0) throw new Error('CSV: no numbers in that column');
  return out;
}

// The peak |amplitude| of each window of `periodUs`, 0..1 → 0..10000.
export function amplitudeEnvelope(channel: Float32Array, rateHz: number, periodUs: number): number[] {
  const window = Math.max(1, Math.round((rateHz * periodUs) / 1e6));
  const out: number[] = [];
  for (let i = 0; i < channel.length; i += window) {
    let peak = 0;
    for (let j = i; j < Math.min(channel.length, i + window); ++j) peak = Math.max(peak, Math.abs(channel[j]));
    out.push(Math.round(peak * 10000));
  }
  return out;
}

export async function decodeWavEnvelope(bytes: ArrayBuffer, periodUs: number): Promise<number[]> {
  const ctx = new OfflineAudioContext(1, 1, 44100);
  let audio: AudioBuffer;
  try {
    audio = await ctx.decodeAudioData(bytes);
  } catch (e) {
    throw new Error(`the browser could not decode this audio file (${(e as Error).message || 'unknown format'})`);
  }
  return amplitudeEnvelope(audio.getChannelData(0), audio.sampleRate, periodUs);
}

export class ProfileEditor implements Graphic {
  readonly el: HTMLElement;
  private readonly plot: SVGSVGElement;
  private readonly still: SVGGElement;
  private readonly live: SVGGElement;
  private readonly message: HTMLElement;
  private readonly laneChoice: HTMLSelectElement;
  private readonly factor: HTMLInputElement;
  private readonly shift: HTMLInputElement;
  private readonly frames: HTMLInputElement;
  private readonly column: HTMLInputElement;
  private readonly normalize: HTMLInputElement;
  private c: GraphicContext | null = null;
  private lanes: { v: Scale; top: number; bottom: number }[] = [];
  private t = new Scale(0, 1, kLeft, kW - kRight);
  private height = 200;

  constructor() {
    this.plot = svg('svg', { viewBox: `0 0 ${kW} 200`, class: 'graphic-plot profile-plot', 'data-graphic': 'profile' });
    this.still = svg('g');
    this.live = svg('g', { class: 'live' });
    this.plot.append(this.still, this.live);
    draggable(this.plot, (name) => this.draw(name));
    this.message = h('div', { class: 'graphic-message' });
    this.laneChoice = h('select', { class: 'lane-choice' });
    this.factor = h('input', { type: 'number', value: '1.5', step: '0.1', class: 'small', 'data-control': 'scale-factor' });
    this.shift = h('input', { type: 'number', value: '1000', step: '100', class: 'small', 'data-control': 'shift-level' });
    this.frames = h('input', { type: 'number', min: '1', class: 'small', 'data-control': 'frames', onchange: () => this.resize(Number(this.frames.value)) });
    this.column = h('input', { type: 'number', value: '1', min: '1', class: 'small', 'data-control': 'csv-column' });
    this.normalize = h('input', { type: 'checkbox', 'data-control': 'csv-normalize' });
    const csv = h('input', { type: 'file', accept: '.csv,text/csv,text/plain', 'data-control': 'import-csv', onchange: (e: Event) => this.importCsv(e) });
    const wav = h('input', { type: 'file', accept: '.wav,audio/*', 'data-control': 'import-wav', onchange: (e: Event) => this.importWav(e) });
    this.el = h('div', { class: 'graphic profile-editor' }, this.plot,
      h('div', { class: 'profile-tools' },
        h('label', {}, 'lane ', this.laneChoice),
        h('button', { 'data-control': 'scale', onclick: () => this.map((v) => Math.round(v * Number(this.factor.value))) }, 'scale ×'), this.factor,
        h('button', { 'data-control': 'shift', onclick: () => this.map((v) => v + Math.round(Number(this.shift.value))) }, 'shift +'), this.shift,
        h('button', { 'data-control': 'smooth', onclick: () => this.smooth() }, 'smooth'),
        h('label', {}, 'frames ', this.frames)),
      h('div', { class: 'profile-tools' },
        h('label', {}, 'import CSV column ', this.column, ' ', h('label', {}, this.normalize, 'normalize'), ' ', csv),
        h('label', {}, 'WAV envelope ', wav)),
      this.message);
    liveFeed.subscribe(() => this.drawLive());
  }

  private data(c: GraphicContext) {
    const b = block(c.fx, 'custom');
    const channels = Math.max(1, num(b, 'channels', 1));
    const samples = (b.samples as number[]) ?? [];
    return { channels, samples, period: Math.max(1, num(b, 'sample_period_us', 10000)), frames: Math.floor(samples.length / channels) };
  }

  render(c: GraphicContext): void {
    this.c = c;
    const { channels, samples, period, frames } = this.data(c);
    const laneH = channels === 1 ? 170 : Math.max(70, 300 / channels);
    this.height = 10 + channels * (laneH + kLaneGap) + 16;
    this.plot.setAttribute('viewBox', `0 0 ${kW} ${this.height}`);
    this.t = new Scale(0, Math.max(1, frames), kLeft, kW - kRight);
    const axes = (c.fx.axes as string[]) ?? [];
    const parts: SVGElement[] = [];
    this.lanes = [];
    for (let ch = 0; ch < channels; ++ch) {
      const top = 8 + ch * (laneH + kLaneGap), bottom = top + laneH;
      const v = new Scale(-10000, 10000, bottom, top);
      this.lanes.push({ v, top, bottom });
      parts.push(svg('rect', { 'data-handle': `lane:${ch}`, x: this.t.p0, y: top, width: this.t.p1 - this.t.p0, height: laneH, fill: '#f7f8fa', stroke: '#d5d9e0', class: 'lane' }));
      for (const level of [-10000, 0, 10000]) {
        parts.push(svg('line', { x1: this.t.p0, x2: this.t.p1, y1: v.px(level), y2: v.px(level), stroke: level ? '#e3e6eb' : '#aab1bd', 'pointer-events': 'none' }));
        parts.push(svg('text', { x: this.t.p0 - 4, y: v.px(level) + 3, 'text-anchor': 'end', 'font-size': 9, fill: '#7a8394' }, String(level)));
      }
      const label = channels === 1 ? (polarOf(c.fx) !== null ? 'along the direction' : axes[0] ?? '') : axes[ch] ?? `channel ${ch + 1}`;
      parts.push(svg('text', { x: this.t.p0 + 4, y: top + 11, 'font-size': 10, fill: '#48526a', 'pointer-events': 'none' }, `lane ${ch + 1}: ${label}`));
      let d = '';
      for (let k = 0; k < frames; ++k) {
        const y = v.px(clamp(samples[k * channels + ch] ?? 0, -10000, 10000));
        d += `${k === 0 ? 'M' : 'L'} ${this.t.px(k).toFixed(1)} ${y.toFixed(1)} H ${this.t.px(k + 1).toFixed(1)} `;
      }
      parts.push(svg('path', { d, fill: 'none', stroke: '#2458d6', 'stroke-width': 2, 'pointer-events': 'none' }));
    }
    parts.push(svg('text', { x: kW - kRight, y: this.height - 4, 'text-anchor': 'end', 'font-size': 9, fill: '#7a8394' },
      `${frames} frames × ${(period / 1000).toFixed(1)} ms = ${((frames * period) / 1000).toFixed(0)} ms; draw on a lane with the pointer`));
    this.still.replaceChildren(...parts);
    const chosen = this.laneChoice.value;
    this.laneChoice.replaceChildren(...Array.from({ length: channels }, (_, ch) => h('option', { value: String(ch), selected: String(ch) === chosen }, String(ch + 1))));
    if (document.activeElement !== this.frames) this.frames.value = String(frames);
    this.drawLive();
  }

  private drawLive(): void {
    const c = this.c;
    if (!c || !this.el.isConnected) return;
    const tau = liveFeed.elapsedUs(c.index);
    if (tau === null) return void this.live.replaceChildren();
    const { channels, period, frames } = this.data(c);
    if (frames === 0) return;
    const k = Math.floor(tau / period) % frames;
    const parts: SVGElement[] = [svg('rect', { x: this.t.px(k), y: 4, width: Math.max(2, this.t.px(k + 1) - this.t.px(k)), height: this.height - 20, fill: '#1b9e5a', 'fill-opacity': 0.15, class: 'playhead' })];
    const axes = (c.fx.axes as string[]) ?? [];
    this.lanes.forEach((lane, ch) => {
      const f = channels === 1 ? forceAlong(c.fx, liveFeed.frame, c.deviceAxes, polarOf(c.fx)) : (liveFeed.frame.force[c.deviceAxes.indexOf(axes[ch])] ?? null);
      if (f !== null) parts.push(svg('circle', { cx: (this.t.px(k) + this.t.px(k + 1)) / 2, cy: lane.v.px(clamp(f, -10000, 10000)), r: 5, fill: '#d63a24', class: 'live-dot' }));
    });
    this.live.replaceChildren(...parts);
  }

  // Drawing with the pointer on lane `ch`.
  private draw(name: string): ((p: { x: number; y: number }) => void) | null {
    const c = this.c;
    if (!c || !name.startsWith('lane:')) return null;
    const ch = Number(name.slice(5));
    const lane = this.lanes[ch];
    let last: { k: number; v: number } | null = null;
    return (p) => {
      const { channels, frames } = this.data(c);
      if (frames === 0) return;
      const k = clamp(Math.floor(this.t.value(p.x)), 0, frames - 1);
      const v = clamp(Math.round(lane.v.value(p.y)), -10000, 10000);
      const from = last ?? { k, v };
      last = { k, v };
      c.edit((e) => {
        const b = blockOf(e, 'custom');
        const s = [...((b.samples as number[]) ?? [])];
        const steps = Math.abs(k - from.k);
        for (let i = 0; i <= steps; ++i) {
          const kk = from.k + Math.sign(k - from.k) * i;
          s[kk * channels + ch] = steps === 0 ? v : Math.round(from.v + ((v - from.v) * i) / steps);
        }
        b.samples = s;
      });
    };
  }

  private lane(): number {
    return Number(this.laneChoice.value || 0);
  }

  private map(fn: (v: number, k: number, lane: number[]) => number): void {
    const c = this.c;
    if (!c) return;
    const { channels } = this.data(c);
    const ch = this.lane();
    c.edit((e) => {
      const b = blockOf(e, 'custom');
      const s = [...((b.samples as number[]) ?? [])];
      const lane = s.filter((_, i) => i % channels === ch);
      lane.forEach((v, k) => (s[k * channels + ch] = fn(v, k, lane)));
      b.samples = s;
    });
  }

  private smooth(): void {
    this.map((v, k, lane) => Math.round(((lane[k - 1] ?? v) + v + (lane[k + 1] ?? v)) / 3));
  }

  private resize(frames: number): void {
    const c = this.c;
    if (!c || !Number.isInteger(frames) || frames < 1) {
      this.message.textContent = 'frames: a whole number, 1 or more';
      return;
    }
    const { channels } = this.data(c);
    c.edit((e) => {
      const b = blockOf(e, 'custom');
      const s = [...((b.samples as number[]) ?? [])].slice(0, frames * channels);
      while (s.length < frames * channels) s.push(0);
      b.samples = s;
    });
  }

  // An imported lane: the selected lane takes the values (the others keep theirs, padded
  // with 0 or cut to the new length), and the duration becomes one pass.
  private setLane(values: number[], what: string): void {
    const c = this.c;
    if (!c) return;
    const { channels, samples, period } = this.data(c);
    const ch = this.lane();
    const s: number[] = [];
    for (let k = 0; k < values.length; ++k) {
      for (let i = 0; i < channels; ++i) s.push(i === ch ? values[k] : (samples[k * channels + i] ?? 0));
    }
    c.edit((e) => {
      blockOf(e, 'custom').samples = s;
      e.duration_us = values.length * period;
    });
    this.message.textContent = `${what}: ${values.length} samples into lane ${ch + 1}`;
  }

  private async importCsv(e: Event): Promise<void> {
    const file = (e.target as HTMLInputElement).files?.[0];
    if (!file) return;
    try {
      let values = csvColumn(await file.text(), Number(this.column.value));
      if (this.normalize.checked) {
        const peak = Math.max(...values.map(Math.abs));
        values = values.map((v) => (peak > 0 ? Math.round((v * 10000) / peak) : 0));
      } else {
        values = values.map(Math.round);
      }
      this.setLane(values, `CSV ${file.name}`);
    } catch (err) {
      this.message.textContent = (err as Error).message;
    }
    (e.target as HTMLInputElement).value = '';
  }

  private async importWav(e: Event): Promise<void> {
    const file = (e.target as HTMLInputElement).files?.[0];
    if (!file || !this.c) return;
    try {
      this.setLane(await decodeWavEnvelope(await file.arrayBuffer(), this.data(this.c).period), `WAV ${file.name} (envelope)`);
    } catch (err) {
      this.message.textContent = `WAV ${file.name}: ${(err as Error).message}`;
    }
    (e.target as HTMLInputElement).value = '';
  }
}
