// The Design Space (§9.3, centre): the current sensation's effects as icons. Add from the
// palette (click or drop), select to edit, duplicate, remove, play, stop, play on trigger.
import { h } from '../dom';
import type { EffectJson } from '../document';
import type { Live } from '../live';
import type { State, Store } from '../store';

export interface EffectLive {
  state: string;
  starts: number;
  armed: boolean;
}

export function designView(
  root: HTMLElement,
  store: Store,
  live: Live,
  liveStates: () => EffectLive[],
  addType: (t: string) => void,
) {
  root.addEventListener('dragover', (e) => e.preventDefault());
  root.addEventListener('drop', (e) => {
    const t = e.dataTransfer?.getData('text/x-feel-type');
    if (t) addType(t);
  });
  return (s: State) => {
    const effects = store.effects();
    const states = liveStates();
    const icons = effects.map((e: EffectJson, i: number) => {
      const st = states[i];
      const trig = e.trigger_button !== undefined ? ` ⇢ ${String(e.trigger_button)}` : '';
      const bad = s.errors.some((x) => x.effect === i || x.effect === -1);
      return h(
        'div',
        {
          class: `icon ${i === s.selected ? 'selected' : ''} ${st?.state === 'playing' ? 'playing' : ''} ${bad ? 'invalid' : ''}`,
          'data-effect': i,
          draggable: 'true',
          ondragstart: (ev: DragEvent) => ev.dataTransfer?.setData('text/x-feel-effect', String(i)),
          onclick: () => store.select(i),
        },
        h('div', { class: 'icon-type' }, e.type),
        h('div', { class: 'icon-meta' }, `#${i + 1}${trig} · ${st?.state ?? '—'}`),
        h(
          'div',
          { class: 'icon-buttons' },
          h('button', { class: 'play', title: 'play', onclick: (ev: Event) => (ev.stopPropagation(), live.send({ type: 'play', effect: i })) }, '▶'),
          h('button', { class: 'stop', title: 'stop', onclick: (ev: Event) => (ev.stopPropagation(), live.send({ type: 'stop', effect: i })) }, '■'),
          h(
            'label',
            { class: 'arm', title: 'play on trigger: armed as a reflex on its button' },
            h('input', {
              type: 'checkbox',
              checked: st ? st.armed : true,
              onchange: (ev: Event) =>
                live.send({ type: 'arm', effect: i, on: (ev.target as HTMLInputElement).checked }),
            }),
            '⇢',
          ),
          h('button', { class: 'dup', title: 'duplicate', onclick: (ev: Event) => {
            ev.stopPropagation();
            store.update((d) => d.sensations[d.current].effects.splice(i + 1, 0, structuredClone(e)), i + 1);
          } }, 'dup'),
          h('button', { class: 'remove', title: 'remove', onclick: (ev: Event) => {
            ev.stopPropagation();
            store.update((d) => d.sensations[d.current].effects.splice(i, 1), Math.max(-1, i - 1));
          } }, '✕'),
        ),
      );
    });
    root.replaceChildren(
      h('h2', {}, `Design Space — ${s.doc.sensations[s.doc.current]?.name ?? ''}`),
      h('div', { class: 'icons' }, ...icons, effects.length ? null : h('p', { class: 'hint' }, 'Click or drag a type from the palette to add an effect.')),
    );
  };
}
