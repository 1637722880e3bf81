// The Studio's front end: wires the store (one-way state), the live session and the views.
// Every editor family gets its module under editors/ (editors/registry.ts): a graphical
// editor, the shared timing panel and the generated form.
import './style.css';
import { type Doc, type EffectJson, parseFile, fileText } from './document';
import type { FieldsDescription } from './editors/form';
import type { LiveFeed } from './editors/editor';
import { editorFor, editorsFrame } from './editors/registry';
import { handlePositions } from './editors/widgets/drag';
import { liveFeed as waveLiveFeed } from './editors/live_feed';
import { ApiError, api } from './files';
import { Live } from './live';
import { type FieldError, Store } from './store';
import { designView, type EffectLive } from './views/design';
import { exportView } from './views/export';
import { filebarView } from './views/filebar';
import { libraryView } from './views/library';
import { Pad, type PointerHops, type PointerWritten } from './views/pad';
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
  store.update(
    (d) => d.sensations[d.current].effects.push(...effects.map((e) => fitToDevice(e))),
    store.effects().length + effects.length - 1,
  );
const addType = (t: string) => {
  const starters = store.state.hello?.starters as Record<string, EffectJson> | undefined;
  if (starters?.[t]) addEffects([structuredClone(starters[t])]);
};

// A starter (or a preset) on the device's axes: the axes it lacks are left out, with their
// per-axis blocks, and a direction that no longer fits them (a one-axis wave needs none).
// On the wheel, the spring of x and y becomes a spring of x. What cannot be fitted stays
// as it is, and the validator says why.
function fitToDevice(fx: EffectJson): EffectJson {
  const hello = store.state.hello;
  const desc = hello?.fields as unknown as FieldsDescription | undefined;
  const deviceAxes = ((hello?.device.axes as { name: string }[]) ?? []).map((a) => a.name);
  const axes = (fx.axes as string[] | undefined) ?? [];
  const kept = axes.map((a, i) => [a, i] as const).filter(([a]) => deviceAxes.includes(a));
  if (!desc || kept.length === axes.length || kept.length === 0) return fx;
  const info = desc.types.find((t) => t.type === fx.type);
  fx.axes = kept.map(([a]) => a);
  const pick = (list: unknown) => (Array.isArray(list) ? kept.map(([, i]) => list[i]).filter((b) => b !== undefined) : list);
  if (info?.shape === 'per_axis') fx[info.block] = pick(fx[info.block]);
  if (info?.control_law) {
    const block = fx[info.block] as Record<string, unknown> | undefined;
    if (block) block.control_law = pick(block.control_law);
  }
  const kind = Object.keys((fx.direction as object | undefined) ?? {})[0];
  const form = desc.direction?.forms.find((f) => f.form === kind);
  const now = fx.axes as string[];
  if (form && !(now.every((a) => form.axes.includes(a)) && (!form.exact_axes || now.length === form.axes.length))) {
    delete fx.direction;
  }
  return fx;
}

const pad = new Pad(el('pad'), store, live, () => ((store.state.hello?.device.axes as unknown[]) ?? []).length);
const plot = new Plot(el('plot'));
store.subscribe(filebarView(el('filebar'), store, live, status));
store.subscribe(paletteView(el('palette'), store, () => presets, addEffects));
store.subscribe(designView(el('design'), store, live, () => liveStates, addType));
store.subscribe(triggersView(el('triggers'), store, live));
// what the editors see of the device: its newest report, the plot's window, the effects
const liveFeed: LiveFeed = {
  position: () => pad.state.position,
  force: () => pad.state.force,
  rows: () => plot.window(),
  effects: () => liveStates,
  target: () => pad.state.target,
};
store.subscribe((s) => editorFor(s, el('editor'), store, liveFeed)(s));
store.subscribe(() => pad.draw());
store.subscribe(libraryView(el('library'), store, status));
store.subscribe(exportView(el('export'), store, live, status));

// Every change of the document sends the current sensation; the server answers with the
// errors at their fields (the device keeps the last valid parameters) or applies it.
let seq = 0;
let validatedSeq = 0; // the newest set_sensation the server answered
const sent = new Map<number, number>();
export const editTimes: number[] = [];
const applyTimes: number[] = [];
store.onDocChange = (s) => {
  const sens = s.doc.sensations[s.doc.current];
  if (!sens) return;
  sent.set(++seq, performance.now());
  live.send({ type: 'set_sensation', seq, name: sens.name, file: s.doc.file ?? undefined, effects: sens.effects });
  const w = plot.window();
  editSentAtDeviceMs = w.length ? w[w.length - 1][0] : 0;
};
// The device time of the newest sample shown when the last edit left: the tests measure
// edit -> plot change from it, in the device's own time.
let editSentAtDeviceMs = 0;

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
      waveLiveFeed.push(m);
      plot.push(m.samples as number[][]);
      pad.update(
        m.position as number[],
        m.force as number[],
        m.pointer_seq,
        m.pointer_age_us,
        m.pointer_hops as PointerHops | undefined,
        m.pointer_written as PointerWritten | undefined,
      );
      editorsFrame();
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
      validatedSeq = Math.max(validatedSeq, m.seq);
      if (m.seq === seq) store.setErrors(m.errors as FieldError[]);
      break;
    }
    case 'error':
      status(`error: ${m.message}`);
      break;
  }
});
// The plot is redrawn at most 20 times a second, when new samples came: its redraw holds the
// page's one thread (a state frame waits meanwhile), and 20 Hz scrolls a 5 s window smoothly
// enough (docs/studio.md, "Latency").
window.setInterval(() => plot.draw(), 50);

// The user's presets (§9.3): the sensations of favorites.feel.json, under the heading
// before the first '.' of their name. No file yet (404) is no presets; any other problem
// (a file that is not valid feel/1) is shown, and the file is left as it is.
async function readFavorites(): Promise<Doc | null> {
  try {
    const r = await api<{ text: string }>('read', { path: kFavorites });
    return parseFile(r.text, kFavorites, false);
  } catch (e) {
    if (e instanceof ApiError && e.status === 404) return null;
    throw e;
  }
}

async function loadPresets() {
  try {
    const doc = await readFavorites();
    presets = (doc?.sensations ?? []).map((s) => {
      const dot = s.name.indexOf('.');
      return {
        heading: dot > 0 ? s.name.slice(0, dot).replace(/_/g, ' ') : 'My Favorites',
        name: dot > 0 ? s.name.slice(dot + 1) : s.name,
        effects: s.effects,
      };
    });
  } catch (e) {
    presets = [];
    status(`favorites: ${(e as Error).message}`);
  }
  store.render();
}

// "Save as favorite": the current sensation (all its effects, as they are now) becomes a
// preset in favorites.feel.json. `name` is "Heading.name", or a name for "My Favorites".
export async function saveFavorite(name: string) {
  const effects = store.effects();
  if (effects.length === 0) throw new Error('save as favorite: the sensation has no effects yet');
  const full = name.includes('.') ? name.replace(/ /g, '_') : `My_Favorites.${name.replace(/ /g, '_')}`;
  const doc = (await readFavorites()) ?? { file: kFavorites, readOnly: false, sensations: [], current: 0 };
  doc.sensations = doc.sensations.filter((s) => s.name !== full);
  doc.sensations.push({ name: full, effects: structuredClone(effects) });
  await api('save', { path: kFavorites, text: fileText(doc), overwrite: true });
  await loadPresets();
  status(`saved "${full}" in ${kFavorites}`);
}

el('palette').addEventListener('click', (e) => {
  if (!(e.target as HTMLElement).matches('#save-favorite')) return;
  const sens = store.state.doc.sensations[store.state.doc.current];
  const name = window.prompt('Save the sensation as a favorite. Name (Heading.name, or a name under My Favorites):', sens?.name ?? '');
  if (name === null || name.trim() === '') return;
  saveFavorite(name.trim()).catch((err: Error) => status(err.message));
});
document.addEventListener('keydown', (e) => {
  if ((e.ctrlKey || e.metaKey) && e.key.toLowerCase() === 'z') {
    if (e.target instanceof HTMLInputElement && e.target.type !== 'checkbox') return;
    e.preventDefault();
    if (e.shiftKey) store.redo();
    else store.undo();
  }
});

// For the end-to-end tests and the latency figures (docs/studio.md).
(window as unknown as Record<string, unknown>).__studio = {
  store,
  pad,
  plot,
  editTimes,
  applyTimes,
  frames: () => frames,
  // the server has answered the newest edit (the tests wait on this, not on a time)
  synced: () => validatedSeq === seq,
  editSentAt: () => editSentAtDeviceMs,
  liveStates: () => liveStates,
  saveFavorite,
  // where each graphical editor's handle is on the page (the tests drag them)
  handles: handlePositions,
};

live.connect();
