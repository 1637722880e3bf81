// One editor module per family: a graphical editor above the shared timing panel and the
// generated form (editors/form.ts, which edits every field of every type, typed). A type
// without a graphical editor yet gets the timing panel and the form.
//
//   conditions (spring, damper, inertia, friction, angle_spring)   condition_curve.ts
//   texture                                                          texture.ts
//   walls and barriers                                               wall.ts
//   waves and sweeps                                                 wave.ts, envelope.ts
//   constant, ramp, vector force, smart pop                          force_over_time.ts
//   force profile                                                    profile.ts
//   dynamics                                                         dynamics_schematic.ts
// The last four are drawn by a Graphic (graphic.ts), which animates from its own live feed
// (live_feed.ts, fed by main.ts) and is wrapped here as an editor of the same shape.
import type { State, Store } from '../store';
import { conditionEditor } from './condition_curve';
import { DynamicsSchematic, kDynamicTypes, schematicTrace } from './dynamics_schematic';
import { commit, deviceAxes, type EditorFactory, type GraphicEditor, type LiveFeed } from './editor';
import { ForceOverTimeEditor, kForceTypes } from './force_over_time';
import { type FieldsDescription, formEditor } from './form';
import type { Graphic } from './graphic';
import { liveFeed as waveLiveFeed } from './live_feed';
import { ProfileEditor } from './profile';
import { textureEditor } from './texture';
import { type TimingPanel, timingPanel } from './timing';
import { wallEditor } from './wall';
import { kSweepTypes, kWaveTypes, WaveEditor } from './wave';
import './wave_family.css';

// A Graphic as an editor: drawn from the store's state, moved by its own live feed.
function graphicEditor(make: () => Graphic): EditorFactory {
  return (store: Store): GraphicEditor => {
    const g = make();
    return {
      el: g.el,
      render: (s, fx, i) => {
        if (!s.hello) return;
        const desc = s.hello?.fields as unknown as FieldsDescription | undefined;
        g.render({
          state: s,
          fx,
          index: i,
          info: desc?.types.find((t) => t.type === fx.type),
          deviceAxes: deviceAxes(s),
          edit: (change) => commit(store, i, change),
        });
      },
      frame: () => {},
    };
  };
}

const families: [readonly string[], EditorFactory][] = [
  [['spring', 'damper', 'inertia', 'friction', 'angle_spring'], conditionEditor],
  [['texture'], textureEditor],
  [['axis_wall', 'angle_wall', 'axis_barrier', 'angle_barrier'], wallEditor],
  [[...kWaveTypes, ...kSweepTypes], graphicEditor(() => new WaveEditor())],
  [kForceTypes, graphicEditor(() => new ForceOverTimeEditor())],
  [['force_profile'], graphicEditor(() => new ProfileEditor())],
  [kDynamicTypes, graphicEditor(() => new DynamicsSchematic())],
];

type Editor = (s: State) => void;
interface Host {
  view: Editor;
  frame: () => void;
}
const hosts = new Map<HTMLElement, Host>();

function makeHost(root: HTMLElement, store: Store, live: LiveFeed): Host {
  const graphic = document.createElement('div');
  graphic.className = 'graphic-host';
  const timingHost = document.createElement('div');
  const formRoot = document.createElement('div');
  formRoot.className = 'form';
  root.replaceChildren(graphic, timingHost, formRoot);
  const form = formEditor(formRoot, store);
  const timing: TimingPanel = timingPanel(store, live);
  const made = new Map<EditorFactory, GraphicEditor>(); // one per family, kept for its drag state
  let shown: GraphicEditor | null = null;
  let timed = false;
  return {
    view: (s) => {
      const fx = store.effects()[s.selected];
      const factory = fx ? families.find(([types]) => types.includes(fx.type))?.[1] : undefined;
      let editor: GraphicEditor | null = null;
      if (factory) {
        editor = made.get(factory) ?? factory(store, live);
        made.set(factory, editor);
      }
      if (editor !== shown) graphic.replaceChildren(...(editor ? [editor.el] : []));
      shown = editor;
      if (fx && editor) editor.render(s, fx, s.selected);
      timed = fx !== undefined && s.hello !== null;
      if (timed) {
        if (!timing.el.isConnected) timingHost.replaceChildren(timing.el);
        timing.render(s, fx, s.selected);
      } else timingHost.replaceChildren();
      form(s);
    },
    frame: () => {
      shown?.frame();
      if (timed) timing.frame();
    },
  };
}

export function editorFor(_s: State, root: HTMLElement, store: Store, live: LiveFeed): Editor {
  let host = hosts.get(root);
  if (!host) {
    host = makeHost(root, store, live);
    hosts.set(root, host);
  }
  return host.view;
}

// A state frame arrived: the editors shown move with the device, when what they draw from
// it changed (the handle, the force, the effects' states and elapsed times). A still
// device redraws nothing: every redraw costs the page's thread and the compositor's, and
// a state frame that arrives meanwhile waits (docs/studio.md, "Latency").
let lastFrameKey = '';
export function editorsFrame(): void {
  const f = waveLiveFeed.frame;
  const key = JSON.stringify([f.position.map(Math.round), f.force.map(Math.round), f.effects.map((e) => [e.state, e.starts, e.armed, e.elapsed_us])]);
  if (key === lastFrameKey) return;
  lastFrameKey = key;
  for (const host of hosts.values()) host.frame();
}

// For the end-to-end tests: the live feed the wave family animates from, and what the
// dynamics schematic drew.
(window as unknown as Record<string, unknown>).__editors = { liveFeed: waveLiveFeed, schematicTrace };
