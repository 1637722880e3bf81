// Code export (issue 11 §2; §1.4, §9.1: the Studio "automatically generates the code"): the
// current sensation as a C++ program on the §8 wrappers and the host API, a C program on
// feel.h, or the two SensationLibrary calls for the saved file. The server generates it
// (src/codegen, the same generators as `feel export`); this panel shows it and downloads it.
import { h } from '../dom';
import type { Live } from '../live';
import type { ServerMessage } from '../protocol/schema';
import type { State, Store } from '../store';

type Lang = 'cpp' | 'c' | 'library';
const kLangs: [Lang, string][] = [
  ['cpp', 'C++ (§8 wrappers)'],
  ['c', 'C (feel.h)'],
  ['library', 'SensationLibrary'],
];

export function exportView(root: HTMLElement, store: Store, live: Live, status: (t: string) => void) {
  let lang: Lang = 'cpp';
  let seq = 0;
  let answered = 0;
  let code = '';
  let filename = '';
  let sentFor = ''; // the request the code on show answers
  const pre = h('pre', { id: 'export-code', class: 'code' });
  const note = h('span', { id: 'export-note', class: 'note' });
  const details = h('details', { id: 'export-panel' });

  const request = () => {
    const s = store.state;
    const sens = s.doc.sensations[s.doc.current];
    if (!details.open || !sens) return;
    const key = JSON.stringify([lang, sens.name, s.doc.file, sens.effects]);
    if (key === sentFor) return;
    sentFor = key;
    if (sens.effects.length === 0) {
      code = '';
      note.textContent = 'the sensation has no effects yet';
      pre.textContent = '';
      return;
    }
    note.textContent = lang === 'library' && !s.doc.file ? 'save the file first: the snippet loads the saved file' : 'generating…';
    live.send({ type: 'export_code', seq: ++seq, lang, name: sens.name, file: s.doc.file ?? undefined, effects: sens.effects });
  };
  const download = () => {
    if (!code) return;
    const a = h('a', { href: URL.createObjectURL(new Blob([code], { type: 'text/plain' })), download: filename });
    a.click();
    window.setTimeout(() => URL.revokeObjectURL(a.href), 10000); // after the browser has read it
    status(`downloaded ${filename}`);
  };
  const tabs = kLangs.map(([l, title]) =>
    h('button', { class: 'tab', 'data-lang': l, onclick: () => ((lang = l), (sentFor = ''), draw(), request()) }, title),
  );
  const draw = () => {
    for (const t of tabs) t.classList.toggle('on', t.dataset.lang === lang);
  };
  details.append(
    h('summary', {}, 'Code export'),
    h(
      'div',
      { class: 'bar' },
      ...tabs,
      h('button', { id: 'export-download', onclick: download, title: 'save the code as a file' }, 'Download'),
      note,
    ),
    pre,
  );
  details.addEventListener('toggle', request);
  root.replaceChildren(details);
  draw();

  live.on((m: ServerMessage) => {
    if (m.type === 'exported' && m.seq === seq) {
      answered = m.seq;
      code = m.code;
      filename = m.filename;
      pre.textContent = code;
      note.textContent = `${filename}, ${code.split('\n').length} lines`;
    } else if (m.type === 'error' && m.request === 'export_code') {
      code = '';
      pre.textContent = '';
      note.textContent = m.message;
    }
  });
  // For the tests: the code on show answers the newest request.
  (root as HTMLElement & { exportDone?: () => boolean }).exportDone = () => answered === seq && seq > 0;

  // After an edit, the open panel shows the new code (a quarter second after the last change).
  let timer = 0;
  return (_s: State) => {
    window.clearTimeout(timer);
    timer = window.setTimeout(request, 250);
  };
}
