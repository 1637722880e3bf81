// The device's live state as the graphical editors see it: the newest state frame (force,
// position, the effects' states) and the dynamics' interim reports (§5.2). main.ts pushes
// every checked `state` message here; an editor subscribes to animate its drawing between
// the store's renders (the document is never changed from here: state flows one way).
export interface EffectLive {
  state: string;
  starts: number;
  armed: boolean;
  elapsed_us: number;
}
export interface DynamicReportJson {
  effect: number;
  kind: 'interim' | 'final';
  t_ms: number;
  position: number[]; // mass minus handle, per effect axis, position units (±10000 travel)
  velocity: number[];
  handle_velocity: number[];
}
export interface LiveFrame {
  position: number[];
  force: number[];
  effects: EffectLive[];
  effectsAt: number; // performance.now() when the effects' states last changed
  deviceMs: number; // the device time of the newest sample
}

type Listener = (f: LiveFrame, reports: DynamicReportJson[]) => void;

export class LiveFeed {
  frame: LiveFrame = { position: [], force: [], effects: [], effectsAt: 0, deviceMs: 0 };
  // the newest dynamics reports (bounded)
  reports: DynamicReportJson[] = [];
  private listeners = new Set<Listener>();
  private pending: DynamicReportJson[] = [];
  private drawPending = false;

  push(m: { position: unknown[]; force: unknown[]; effects: unknown[]; samples: unknown[]; dynamics: unknown[] }): void {
    const effects = m.effects as EffectLive[];
    const key = (l: EffectLive[]) => JSON.stringify(l.map((e) => [e.state, e.elapsed_us]));
    const changed = key(effects) !== key(this.frame.effects);
    const samples = m.samples as number[][];
    this.frame = {
      position: m.position as number[],
      force: m.force as number[],
      effects,
      effectsAt: changed ? performance.now() : this.frame.effectsAt,
      deviceMs: samples.length ? samples[samples.length - 1][0] : this.frame.deviceMs,
    };
    const reports = m.dynamics as DynamicReportJson[];
    if (reports.length) {
      this.reports.push(...reports);
      if (this.reports.length > 2000) this.reports.splice(0, this.reports.length - 2000);
      this.pending.push(...reports);
    }
    // the editors draw once per animation frame, however many state frames came before it,
    // and only when one listens (no animation frame is asked for nothing)
    if (this.drawPending || this.listeners.size === 0) return;
    this.drawPending = true;
    requestAnimationFrame(() => {
      this.drawPending = false;
      const fresh = this.pending.splice(0);
      for (const l of this.listeners) l(this.frame, fresh);
    });
  }

  subscribe(l: Listener): () => void {
    this.listeners.add(l);
    return () => this.listeners.delete(l);
  }

  // The effect's own time now (µs): its reported elapsed time (10 Hz), carried on by the
  // page's clock since that report arrived; null when it does not play.
  elapsedUs(effect: number): number | null {
    const e = this.frame.effects[effect];
    if (!e || e.state !== 'playing') return null;
    return e.elapsed_us + (performance.now() - this.frame.effectsAt) * 1000;
  }
}

export const liveFeed = new LiveFeed();
