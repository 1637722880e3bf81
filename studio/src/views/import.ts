// Import (docs/import.md): a DirectInput effect file, an Apple AHAP pattern or a WAV sound
// from the user's disk goes to the server in one import_file message; the server converts
// it with feel's importers, saves it as a new file in the workspace and answers
// `imported`, and the Studio opens that file.
import { parseFile } from '../document';
import { h } from '../dom';
import type { Live } from '../live';
import type { Store } from '../store';

// The schema's bound on import_file.data, as bytes (base64 is 4 characters per 3 bytes).
export const kMaxImportBytes = 1 << 20;

function base64Of(file: File): Promise<string> {
  return new Promise((resolve, reject) => {
    const reader = new FileReader();
    reader.onload = () => resolve(String(reader.result).replace(/^data:[^,]*,/, ''));
    reader.onerror = () => reject(new Error(`${file.name}: cannot be read`));
    reader.readAsDataURL(file);
  });
}

// The import control of the file bar: a button, the axis for AHAP and WAV, a hidden file
// input. Made once, so that a re-render of the bar keeps a pending file choice.
export function importView(store: Store, live: Live, status: (t: string) => void): HTMLElement {
  const axis = h('select', { id: 'import-axis', title: 'The axis an AHAP pattern or a WAV sound drives' },
    ...['x', 'y', 'z', 'rx', 'ry', 'rz'].map((a) => h('option', { value: a }, a)));
  const input = h('input', { id: 'import-file', type: 'file', accept: '.ffe,.ahap,.wav', style: 'display:none' });
  input.onchange = () => {
    const file = input.files?.[0];
    input.value = '';
    if (!file) return;
    if (file.size > kMaxImportBytes) {
      status(`import: ${file.name} has ${file.size} bytes; the Studio imports files up to ${kMaxImportBytes} bytes (1 MiB): use \`feel import\` for larger ones`);
      return;
    }
    base64Of(file)
      .then((data) => {
        live.send({ type: 'import_file', name: file.name, data, axis: axis.value as 'x' | 'y' | 'z' | 'rx' | 'ry' | 'rz' });
        status(`importing ${file.name}…`);
      })
      .catch((e: Error) => status(`import: ${e.message}`));
  };
  live.on((m) => {
    if (m.type !== 'imported') return;
    store.load(parseFile(m.text, m.file, false));
    const notes = m.notes.length ? ` (${m.notes.length} note${m.notes.length > 1 ? 's' : ''}: ${m.notes.join(' | ')})` : '';
    status(`imported "${m.sensation}" into ${m.file}${notes}`);
  });
  return h('span', { class: 'import' },
    h('button', { id: 'import', title: 'Import a DirectInput .ffe, an Apple .ahap or a .wav file', onclick: () => input.click() }, 'Import…'),
    axis, input);
}
