// A tiny element builder: h('button', {class: 'x', onclick}, 'text').
type Attrs = Record<string, unknown>;
export function h<K extends keyof HTMLElementTagNameMap>(
  tag: K,
  attrs: Attrs = {},
  ...children: (Node | string | null | undefined)[]
): HTMLElementTagNameMap[K] {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (v === undefined || v === null || v === false) continue;
    if (k.startsWith('on') && typeof v === 'function') {
      e.addEventListener(k.slice(2), v as EventListener);
    } else if (k === 'value' && 'value' in e) {
      (e as HTMLInputElement).value = String(v);
    } else if (k === 'checked' && 'checked' in e) {
      (e as HTMLInputElement).checked = Boolean(v);
    } else {
      e.setAttribute(k, v === true ? '' : String(v));
    }
  }
  for (const c of children) if (c !== null && c !== undefined) e.append(c);
  return e;
}

// A readout that changes with the live frames (the pad's position and force, the editors'
// device lines): written at most ten times a second, all of them in one task, and only when
// the text differs, through the box's one text node. A text changed in the page costs its
// thread a layout and a paint of the whole document in that animation frame, however
// contained the box: written at every frame, the readouts were half of what the page's
// thread did while the pointer moved, and a state frame waited behind it (docs/studio.md,
// "Ninth pass"). The canvases still move at every frame; a number read by a person needs
// no more than ten changes a second.
const kLiveTextPeriodMs = 100;
const liveTexts = new Map<Element, string>();
let liveTextTimer = 0;
let liveTextWritten = -Infinity;

function writeText(e: Element, text: string): void {
  const node = e.firstChild;
  if (node instanceof Text && node === e.lastChild) {
    if (node.data !== text) node.data = text;
  } else e.replaceChildren(document.createTextNode(text));
}

function flushLiveTexts(): void {
  liveTextTimer = 0;
  liveTextWritten = performance.now();
  for (const [e, text] of liveTexts) writeText(e, text);
  liveTexts.clear();
}

export function liveText(e: Element, text: string): void {
  liveTexts.set(e, text);
  if (liveTextTimer) return;
  const wait = liveTextWritten + kLiveTextPeriodMs - performance.now();
  if (wait <= 0) flushLiveTexts();
  else liveTextTimer = window.setTimeout(flushLiveTexts, wait);
}
