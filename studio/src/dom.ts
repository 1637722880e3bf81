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
