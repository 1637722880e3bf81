// The Button Trigger Palette (§9.3, right): the device's buttons and hats. Drop an effect
// on a button to make it that button's reflex; set the repeat interval there. Press a
// button by clicking it (held while the pointer is down) or with the keys 1-9.
import { h } from '../dom';
import type { Live } from '../live';
import type { State, Store } from '../store';

export function triggersView(root: HTMLElement, store: Store, live: Live) {
  const held = new Set<number>();
  const press = (button: number, down: boolean) => {
    if (down === held.has(button)) return;
    if (down) held.add(button);
    else held.delete(button);
    live.send({ type: 'button', button, down });
    root.querySelector(`[data-button="${button}"]`)?.classList.toggle('pressed', down);
  };
  const typing = (e: KeyboardEvent) => e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement;
  window.addEventListener('keydown', (e) => {
    if (typing(e) || e.ctrlKey || e.metaKey || e.altKey) return;
    const n = Number(e.key);
    const buttons = Number(store.state.hello?.device.buttons ?? 0);
    if (n >= 1 && n <= 9 && n <= buttons) {
      e.preventDefault();
      press(n, true);
    }
  });
  window.addEventListener('keyup', (e) => {
    const n = Number(e.key);
    if (n >= 1 && n <= 9) press(n, false);
  });
  window.addEventListener('blur', () => [...held].forEach((b) => press(b, false)));

  return (s: State) => {
    if (!s.hello) return;
    const count = Number(s.hello.device.buttons ?? 0);
    const effects = store.effects();
    const assign = (i: number, trigger: number | string) =>
      store.update((d) => {
        d.sensations[d.current].effects[i].trigger_button = trigger;
      }, i);
    const rows = [];
    for (let b = 1; b <= count; ++b) {
      const on = effects.map((e, i) => [e, i] as const).filter(([e]) => e.trigger_button === b);
      rows.push(
        h(
          'div',
          {
            class: 'button',
            'data-button': b,
            ondragover: (e: DragEvent) => e.preventDefault(),
            ondrop: (e: DragEvent) => {
              const i = Number(e.dataTransfer?.getData('text/x-feel-effect'));
              if (Number.isInteger(i) && i >= 0) assign(i, b);
            },
          },
          h(
            'button',
            {
              class: 'press',
              title: b <= 9 ? `press (or key ${b})` : 'press',
              onpointerdown: () => press(b, true),
              onpointerup: () => press(b, false),
              onpointerleave: () => press(b, false),
            },
            `${b}`,
          ),
          h(
            'div',
            { class: 'reflexes' },
            ...on.map(([e, i]) =>
              h(
                'div',
                { class: 'reflex' },
                `#${i + 1} ${e.type} every `,
                h('input', {
                  type: 'number',
                  class: 'repeat',
                  min: 0,
                  step: 1000,
                  value: String(e.trigger_repeat_interval_us ?? 0),
                  title: 'trigger_repeat_interval_us (µs, 0 = no repeat)',
                  onchange: (ev: Event) => {
                    const v = Number((ev.target as HTMLInputElement).value);
                    store.update((d) => {
                      const fx = d.sensations[d.current].effects[i];
                      if (v === 0) delete fx.trigger_repeat_interval_us;
                      else fx.trigger_repeat_interval_us = v;
                    }, i);
                  },
                }),
                ' µs ',
                h('button', { title: 'remove the assignment', onclick: () => store.update((d) => {
                  const fx = d.sensations[d.current].effects[i];
                  delete fx.trigger_button;
                  delete fx.trigger_repeat_interval_us;
                }, i) }, '✕'),
              ),
            ),
          ),
        ),
      );
    }
    const hats = Number(s.hello.device.hats ?? 0);
    for (let t = 1; t <= hats; ++t) {
      rows.push(
        h(
          'div',
          {
            class: 'button hat',
            ondragover: (e: DragEvent) => e.preventDefault(),
            ondrop: (e: DragEvent) => {
              const i = Number(e.dataTransfer?.getData('text/x-feel-effect'));
              if (Number.isInteger(i) && i >= 0) assign(i, `hat${t}`);
            },
          },
          h('button', {
            class: 'press',
            onpointerdown: () => live.send({ type: 'hat', hat: t, down: true }),
            onpointerup: () => live.send({ type: 'hat', hat: t, down: false }),
          }, `hat ${t}`),
          h('div', { class: 'reflexes' }, ...effects.filter((e) => e.trigger_button === `hat${t}`).map((e) => h('div', {}, e.type))),
        ),
      );
    }
    root.replaceChildren(h('h2', {}, 'Button Trigger Palette'), h('p', { class: 'hint' }, 'Drop an effect on a button; press with the mouse or keys 1–9.'), ...rows);
    for (const b of held) root.querySelector(`[data-button="${b}"]`)?.classList.add('pressed');
  };
}
