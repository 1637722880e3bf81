// Standard file handling (§9.3, §9.5): new, open (workspace files and the read-only
// examples), save, save as, rename, copy, combine; the file's sensations; undo/redo; the
// device's gain and stop all.
import { h } from '../dom';
import { type Doc, emptyDoc, fileText, parseFile } from '../document';
import { api } from '../files';
import type { Live } from '../live';
import type { State, Store } from '../store';
import { importView } from './import';

export function filebarView(root: HTMLElement, store: Store, live: Live, status: (t: string) => void) {
  const run = (f: () => Promise<void>) => () => f().catch((e: Error) => status(e.message));
  const ask = (q: string, d = '') => {
    const a = window.prompt(q, d);
    return a === null || a.trim() === '' ? null : a.trim();
  };
  const saveAs = async (path: string, overwrite: boolean) => {
    const r = await api<{ text: string }>('save', { path, text: fileText(store.state.doc), overwrite });
    const doc: Doc = { ...parseFile(r.text, path, false), current: store.state.doc.current };
    store.saved(doc);
    status(`saved ${path}`);
  };
  const open = async () => {
    const list = await api<{ workspace: string[]; examples: string[] }>('list', {});
    const choices = [...list.workspace, ...list.examples.map((e) => `examples/${e} (read-only)`)];
    const pick = ask(`Open which file?\n${choices.join('\n')}`, list.workspace[0] ?? '');
    if (!pick) return;
    if (pick.startsWith('examples/')) {
      const name = pick.replace(/^examples\//, '').replace(/ \(read-only\)$/, '');
      const r = await api<{ text: string }>('read', { example: name });
      store.load(parseFile(r.text, null, true));
      status(`opened example ${name} (read-only: save it under a new name)`);
    } else {
      const r = await api<{ text: string }>('read', { path: pick });
      store.load(parseFile(r.text, pick, false));
      status(`opened ${pick}`);
    }
  };
  let gainTimer = 0;
  const importer = importView(store, live, status);
  return (s: State) => {
    const doc = s.doc;
    const title = `${doc.file ?? (doc.readOnly ? 'example (read-only)' : 'unsaved')}${s.dirty ? ' •' : ''}`;
    root.replaceChildren(
      h('strong', { class: 'brand' }, 'feel Studio'),
      h('span', { id: 'file-name', class: 'file' }, title),
      h('button', { id: 'new', onclick: () => store.load(emptyDoc()) }, 'New'),
      h('button', { id: 'open', onclick: run(open) }, 'Open…'),
      h('button', { id: 'save', onclick: run(async () => {
        if (doc.file && !doc.readOnly) return saveAs(doc.file, true);
        const p = ask('Save as (a path in the workspace, *.feel.json):', 'my.feel.json');
        if (p) await saveAs(p, false);
      }) }, 'Save'),
      h('button', { id: 'save-as', onclick: run(async () => {
        const p = ask('Save as (a path in the workspace, *.feel.json):', doc.file ?? 'my.feel.json');
        if (p) await saveAs(p, false);
      }) }, 'Save as…'),
      h('button', { id: 'rename-file', disabled: !doc.file, onclick: run(async () => {
        const p = ask('Rename the file to:', doc.file ?? '');
        if (!p || !doc.file) return;
        await api('rename', { from: doc.file, to: p });
        store.saved({ ...store.state.doc, file: p });
        status(`renamed to ${p}`);
      }) }, 'Rename…'),
      h('button', { id: 'copy-file', disabled: !doc.file, onclick: run(async () => {
        const p = ask('Copy the file to:', '');
        if (!p || !doc.file) return;
        await api('copy', { from: doc.file, to: p });
        status(`copied to ${p}`);
      }) }, 'Copy…'),
      h('button', { id: 'combine', onclick: run(async () => {
        const list = await api<{ workspace: string[] }>('list', {});
        const src = ask(`Combine which files (comma-separated)?\n${list.workspace.join('\n')}`);
        const to = src && ask('Into the new file:', 'combined.feel.json');
        if (!src || !to) return;
        const r = await api<{ text: string }>('combine', { sources: src.split(',').map((x) => x.trim()), to });
        store.load(parseFile(r.text, to, false));
        status(`combined into ${to}`);
      }) }, 'Combine…'),
      importer,
      h('span', { class: 'sep' }),
      h('select', { id: 'sensation', onchange: (e: Event) => {
        const i = Number((e.target as HTMLSelectElement).value);
        store.update((d) => (d.current = i), 0);
      } }, ...doc.sensations.map((x, i) => h('option', { value: i, selected: i === doc.current }, x.name))),
      h('button', { id: 'new-sensation', onclick: () => {
        const n = ask('Name of the new sensation (letters, digits, _ - .):');
        if (n) store.update((d) => { d.sensations.push({ name: n, effects: [] }); d.current = d.sensations.length - 1; }, -1);
      } }, '+ sensation'),
      h('button', { id: 'rename-sensation', onclick: () => {
        const n = ask('Rename the sensation to:', doc.sensations[doc.current]?.name);
        if (n) store.update((d) => (d.sensations[d.current].name = n));
      } }, 'rename'),
      h('button', { id: 'copy-sensation', onclick: () => {
        const n = ask('Name of the copy:', `${doc.sensations[doc.current]?.name}_copy`);
        if (n) store.update((d) => { d.sensations.push({ ...structuredClone(d.sensations[d.current]), name: n }); d.current = d.sensations.length - 1; });
      } }, 'copy'),
      h('span', { class: 'sep' }),
      h('button', { id: 'undo', title: 'Ctrl+Z', onclick: () => store.undo() }, '↶'),
      h('button', { id: 'redo', title: 'Ctrl+Shift+Z', onclick: () => store.redo() }, '↷'),
      h('span', { class: 'sep' }),
      h('button', { id: 'stop-all', onclick: () => live.send({ type: 'stop_all' }) }, 'Stop all'),
      h('label', { class: 'gain' }, 'gain ', h('input', { id: 'gain', type: 'range', min: 0, max: 10000, step: 100, value: String(s.hello?.gain ?? 10000), oninput: (e: Event) => {
        const v = Number((e.target as HTMLInputElement).value);
        window.clearTimeout(gainTimer);
        gainTimer = window.setTimeout(() => live.send({ type: 'gain', gain: v }), 30);
      } })),
    );
  };
}
