// The Studio's front end: wires the store (one-way state), the live session and the views.
// Every editor family gets its module under editors/ (editors/registry.ts); today every
// family uses the generated form, the graphical editors come next.
import './style.css';
import { type EffectJson, parseFile, fileText } from './document';
import { editorFor } from './editors/registry';
import { api } from './files';
import { Live } from './live';
import { type FieldError, Store } from './store';
import { designView, type EffectLive } from './views/design';
import { filebarView } from './views/filebar';
import { Pad } from './views/pad';
import { paletteView, type Preset } from './views/palette';
import { Plot } from './views/plot';
import { triggersView } from './views/triggers';

const store = new Store();
const live = new Live();
const el = (id: string) => document.getElementById(id)!;
const status = (t: string) => (el('status').textContent = t);
live.onStatus = status;

let liveStates: EffectLive[] = [];
let presets: Preset[] = [];
const kFavorites = 'favorites.feel.json';

const addEffects = (effects: EffectJson[]) =>
  store.update((d) => d.sensations[d.current].effects.push(...effects), store.effects().length + effects.length - 1);
const addType = (t: string) => {
  const starters = store.state.hello?.starters as Record<string, EffectJson> | undefined;
  if (starters?.[t]) addEffects([structuredClone(starters[t])]);
};

const pad = new Pad(el('pad'), store, live, () => ((store.state.hello?.device.axes as unknown[]) ?? []).length);
const plot = new Plot(el('plot'));
store.subscribe(filebarView(el('filebar'), store, live, status));
store.subscribe(paletteView(el('palette'), store, () => presets, addEffects));
store.subscribe(designView(el('design'), store, live, () => liveStates, addType));
store.subscribe(triggersView(el('triggers'), store, live));
store.subscribe((s) => editorFor(s, el('editor'), store)(s));
store.subscribe(() => pad.draw());

// Every change of the document sends the current sensation; the server answers with the
// errors at their fields (the device keeps the last valid parameters) or applies it.
let seq = 0;
const sent = new Map<number, number>();
export const editTimes: number[] = [];
const applyTimes: number[] = [];
store.onDocChange = (s) => {
  const sens = s.doc.sensations[s.doc.current];
  if (!sens) return;
  sent.set(++seq, performance.now());
  live.send({ type: 'set_sensation', seq, name: sens.name, file: s.doc.file ?? undefined, effects: sens.effects });
};

let frames = 0;
live.on((m) => {
  switch (m.type) {
    case 'hello': {
      store.state = { ...store.state, hello: m };
      const axes = (m.device.axes as { name: string }[]).map((a) => a.name);
      plot.setAxes(axes);
      pad.setGrip(m.grip);
      store.render();
      store.onDocChange(store.state);
      loadPresets();
      status(`connected to ${String(m.device.name)} (${String(m.device.class)})`);
      break;
    }
    case 'state': {
      ++frames;
      plot.push(m.samples as number[][]);
      pad.update(m.position as number[], m.force as number[], m.pointer_seq, m.pointer_age_us);
      if ((m.effects as EffectLive[]).length || liveStates.length) {
        // redraw the views only when a state, a start count or an arming changed
        const key = (l: EffectLive[]) => JSON.stringify(l.map((e) => [e.state, e.starts, e.armed]));
        const changed = key(m.effects as EffectLive[]) !== key(liveStates);
        liveStates = m.effects as EffectLive[];
        if (changed) store.render();
      }
      break;
    }
    case 'validated': {
      const t0 = sent.get(m.seq);
      if (t0 !== undefined) editTimes.push(performance.now() - t0);
      if (m.ok) applyTimes.push(m.apply_us / 1000);
      sent.delete(m.seq);
      if (m.seq === seq) store.setErrors(m.errors as FieldError[]);
      break;
    }
    case 'error':
      status(`error: ${m.message}`);
      break;
  }
});
// The plot is redrawn at most 30 times a second, when new samples came.
window.setInterval(() => plot.draw(), 33);

async function loadPresets() {
  try {
    const r = await api<{ text: string }>('read', { path: kFavorites });
    presets = parseFile(r.text, kFavorites, false).sensations.map((s) => {
      const dot = s.name.indexOf('.');
      return {
        heading: dot > 0 ? s.name.slice(0, dot).replace(/_/g, ' ') : 'My Favorites',
        name: dot > 0 ? s.name.slice(dot + 1) : s.name,
        effects: s.effects,
      };
    });
  } catch {
    presets = [];
  }
  store.render();
}

// "Save as favorite": the selected effect becomes a preset in favorites.feel.json.
el('palette').addEventListener('click', (e) => {
  if (!(e.target as HTMLElement).matches('#save-favorite')) return;
});
document.addEventListener('keydown', (e) => {
  if ((e.ctrlKey || e.metaKey) && e.key.toLowerCase() === 'z') {
    if (e.target instanceof HTMLInputElement && e.target.type !== 'checkbox') return;
    e.preventDefault();
    if (e.shiftKey) store.redo();
    else store.undo();
  }
});

export async function saveFavorite(name: string) {
  const fx = store.effects()[store.state.selected];
  if (!fx) throw new Error('select an effect first');
  let text: string | null = null;
  try {
    text = (await api<{ text: string }>('read', { path: kFavorites })).text;
  } catch {
    text = null;
  }
  const doc = text ? parseFile(text, kFavorites, false) : { file: kFavorites, readOnly: false, sensations: [], current: 0 };
  doc.sensations = doc.sensations.filter((s) => s.name !== name);
  doc.sensations.push({ name, effects: [structuredClone(fx)] });
  await api('save', { path: kFavorites, text: fileText(doc), overwrite: true });
  await loadPresets();
}

// For the end-to-end tests and the latency figures (docs/studio.md).
(window as unknown as Record<string, unknown>).__studio = {
  store,
  pad,
  plot,
  editTimes,
  applyTimes,
  frames: () => frames,
  liveStates: () => liveStates,
  saveFavorite,
};

live.connect();
