// The library (issue 11 §3): the example sensations shipped with feel, read-only, grouped by
// class (Conditions, Waves, Dynamics; a compound of several classes under Compounds). Click
// a sensation to open its file at it and feel it; "Duplicate to workspace" copies it into a
// new workspace file (a feel/1 file of that one sensation) and opens the copy for editing.
import './library.css';
import { h } from '../dom';
import { type Doc, fileText, parseFile } from '../document';
import { api } from '../files';
import type { State, Store } from '../store';

interface Entry {
  example: string; // the example file, e.g. primer.feel.json
  index: number; // the sensation's index in it
  name: string;
  description?: string;
  group: string;
}

const kGroups: [string, string][] = [
  ['condition', 'Conditions'],
  ['wave', 'Waves'],
  ['dynamic', 'Dynamics'],
  ['compound', 'Compounds'],
];

export function libraryView(root: HTMLElement, store: Store, status: (t: string) => void) {
  const files = new Map<string, Doc>();
  let entries: Entry[] = [];
  let loadedFor: unknown = null;

  // The class of a type, from the device's enumeration (§6.2); a type the device lacks (no
  // Dynamics on a 1.x stick) is still shown, by its name.
  const classOf = (s: State, type: string): string => {
    const types = (s.hello?.device.types ?? {}) as Record<string, string[]>;
    for (const [cls, list] of Object.entries(types)) if (list.includes(type)) return cls;
    return type.startsWith('dynamic_') ? 'dynamic' : 'wave';
  };

  const load = async (s: State) => {
    const list = await api<{ examples: string[] }>('list', {});
    for (const example of list.examples) {
      const r = await api<{ text: string }>('read', { example });
      files.set(example, parseFile(r.text, null, true));
    }
    entries = [];
    for (const [example, doc] of files) {
      doc.sensations.forEach((sens, index) => {
        const classes = new Set(sens.effects.map((e) => classOf(s, e.type)));
        const group = classes.size === 1 ? [...classes][0] : 'compound';
        entries.push({ example, index, name: sens.name, description: sens.description, group });
      });
    }
    draw();
  };

  const openAt = (e: Entry) => {
    const doc = files.get(e.example);
    if (!doc) return;
    store.load({ ...structuredClone(doc), current: e.index });
    status(`opened ${e.name} from the example ${e.example} (read-only: duplicate it to edit)`);
  };

  const duplicate = async (e: Entry) => {
    const doc = files.get(e.example);
    if (!doc) return;
    const answer = window.prompt('Duplicate to the workspace as (a path, *.feel.json):', `${e.name}.feel.json`);
    if (answer === null || answer.trim() === '') return;
    const path = answer.trim();
    const copy: Doc = { file: path, readOnly: false, sensations: [structuredClone(doc.sensations[e.index])], current: 0 };
    const r = await api<{ text: string }>('save', { path, text: fileText(copy), overwrite: false });
    store.load(parseFile(r.text, path, false));
    status(`duplicated ${e.name} to ${path}`);
  };

  const draw = () => {
    root.replaceChildren(h('h2', {}, 'Library'));
    for (const [group, title] of kGroups) {
      const items = entries.filter((e) => e.group === group);
      if (items.length === 0) continue;
      root.append(
        h(
          'details',
          { 'data-group': group },
          h('summary', {}, `${title} (${items.length})`),
          h(
            'ul',
            {},
            ...items.map((e) =>
              h(
                'li',
                { class: 'example', 'data-name': e.name, title: e.description ?? e.example },
                h('span', { class: 'open', onclick: () => openAt(e) }, e.name),
                h(
                  'button',
                  {
                    class: 'duplicate',
                    title: 'copy it into a new file of the workspace, to edit',
                    onclick: () => duplicate(e).catch((err: Error) => status(err.message)),
                  },
                  'Duplicate to workspace',
                ),
              ),
            ),
          ),
        ),
      );
    }
  };

  return (s: State) => {
    if (!s.hello || loadedFor === s.hello) return;
    loadedFor = s.hello;
    load(s).catch((err: Error) => status(`library: ${err.message}`));
  };
}
