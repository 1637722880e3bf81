// The Sensation Palette (§9.3, left): the types the device enumerates, by class, and the
// user's own presets (favorites.feel.json in the workspace), grouped by heading.
import { h } from '../dom';
import type { EffectJson } from '../document';
import type { State, Store } from '../store';

const kClasses: [string, string][] = [
  ['condition', 'Conditions'],
  ['wave', 'Waves'],
  ['dynamic', 'Dynamics'],
];

export interface Preset {
  heading: string;
  name: string;
  effects: EffectJson[];
}

export function paletteView(root: HTMLElement, store: Store, presets: () => Preset[], add: (e: EffectJson[]) => void) {
  let drawnFor: unknown = null;
  let drawnPresets = '';
  return (s: State) => {
    const p = presets();
    const key = JSON.stringify(p);
    if (drawnFor === s.hello && drawnPresets === key) return;
    drawnFor = s.hello;
    drawnPresets = key;
    root.replaceChildren(h('h2', {}, 'Sensation Palette'));
    if (!s.hello) return;
    const types = s.hello.device.types as Record<string, string[]>;
    const starters = s.hello.starters as Record<string, EffectJson>;
    for (const [cls, title] of kClasses) {
      const list = types[cls] ?? [];
      if (list.length === 0) continue;
      root.append(
        h(
          'details',
          { open: true, 'data-class': cls },
          h('summary', {}, `${title} (${list.length})`),
          h(
            'ul',
            {},
            ...list.map((t) =>
              h(
                'li',
                {
                  class: 'type',
                  'data-type': t,
                  draggable: 'true',
                  title: `add a ${t} (click or drag to the design space)`,
                  ondragstart: (e: DragEvent) => e.dataTransfer?.setData('text/x-feel-type', t),
                  onclick: () => add([structuredClone(starters[t])]),
                },
                t,
              ),
            ),
          ),
        ),
      );
    }
    const headings = new Map<string, Preset[]>();
    for (const preset of p) headings.set(preset.heading, [...(headings.get(preset.heading) ?? []), preset]);
    root.append(
      h('button', { id: 'save-favorite', title: 'keep the current sensation as a preset (favorites.feel.json)' }, '★ Save as favorite…'),
    );
    for (const [heading, items] of headings) {
      root.append(
        h(
          'details',
          { open: true, class: 'presets' },
          h('summary', {}, heading),
          h(
            'ul',
            {},
            ...items.map((preset) =>
              h('li', { class: 'preset', onclick: () => add(structuredClone(preset.effects)) }, preset.name),
            ),
          ),
        ),
      );
    }
    void store;
  };
}
