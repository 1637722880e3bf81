// One editor module per family (conditions, walls and barriers, waves, profiles, dynamics).
// A family with a graphical editor shows it above the generated form; the form stays for
// every typed value and the effect's timing (start delay, duration, iterations, gain,
// trigger). Families without one yet use the form alone.
import type { State, Store } from '../store';
import { formEditor, type FieldsDescription } from './form';
import type { Graphic } from './graphic';
import { liveFeed } from './live_feed';
import './wave_family.css';

// h11-wave: waves and sweeps, forces over time, force profiles, dynamics
import { DynamicsSchematic, kDynamicTypes, schematicTrace } from './dynamics_schematic';
import { ForceOverTimeEditor, kForceTypes } from './force_over_time';
import { ProfileEditor } from './profile';
import { kSweepTypes, kWaveTypes, WaveEditor } from './wave';

type Editor = (s: State) => void;
const editors = new Map<HTMLElement, Editor>();

// The family of each type that has a graphical editor, and how to make one.
const families: { types: string[]; make: () => Graphic }[] = [
  { types: [...kWaveTypes, ...kSweepTypes], make: () => new WaveEditor() },
  { types: kForceTypes, make: () => new ForceOverTimeEditor() },
  { types: ['force_profile'], make: () => new ProfileEditor() },
  { types: kDynamicTypes, make: () => new DynamicsSchematic() },
];

function graphicalEditor(root: HTMLElement, store: Store): Editor {
  const graphics = new Map<number, Graphic>(); // by family index, made once
  return (s: State) => {
    const fx = store.effects()[s.selected];
    const family = fx ? families.findIndex((f) => f.types.includes(fx.type)) : -1;
    if (!fx || family < 0 || !s.hello) return void root.replaceChildren();
    let g = graphics.get(family);
    if (!g) graphics.set(family, (g = families[family].make()));
    if (root.firstChild !== g.el) root.replaceChildren(g.el);
    const desc = s.hello.fields as unknown as FieldsDescription;
    const i = s.selected;
    g.render({
      state: s,
      fx,
      index: i,
      info: desc.types.find((t) => t.type === fx.type),
      deviceAxes: ((s.hello.device.axes as { name: string }[]) ?? []).map((a) => a.name),
      edit: (change) => store.update((d) => change(d.sensations[d.current].effects[i]), i),
    });
  };
}

export function editorFor(_s: State, root: HTMLElement, store: Store): Editor {
  let e = editors.get(root);
  if (!e) {
    const graphic = document.createElement('div');
    graphic.className = 'graphic-host';
    const form = document.createElement('div');
    form.className = 'form-host';
    root.replaceChildren(graphic, form);
    const g = graphicalEditor(graphic, store);
    const f = formEditor(form, store);
    e = (s: State) => {
      g(s);
      f(s);
    };
    editors.set(root, e);
  }
  return e;
}

// For the end-to-end tests: the live feed the editors animate from, and what the
// dynamics schematic drew.
(window as unknown as Record<string, unknown>).__editors = { liveFeed, schematicTrace };
