// The generated form: every field of every type, driven by the server's one field
// description (src/studio/field_schema.cpp: the format's field table with the validator's
// ranges). Nothing here knows a particular type. Errors appear at their field with the
// message `feel check` prints.
import { h } from '../dom';
import type { EffectJson } from '../document';
import type { FieldError, State, Store } from '../store';

export interface FieldInfo {
  name: string;
  kind: 'integer' | 'boolean' | 'choice';
  required: boolean;
  choices?: string[];
  min?: number;
  max?: number;
  infinite?: boolean;
  unit: string;
  scale?: number; // shown = value × scale (angles: 0.01° in the file, degrees in the form)
  shown_unit?: string;
}
export interface DirectionForm {
  form: string; // polar, spherical, cartesian, moments (§6.5)
  axes: string[]; // the axes it fits: exactly these (exact_axes), or any of them
  exact_axes: boolean;
  per_axis: boolean; // one component per axis of the effect
  components: FieldInfo[];
  default: number[];
}
export interface TypeInfo {
  type: string;
  class: string;
  block: string;
  shape: 'object' | 'per_axis' | 'one_block';
  one_block_with_direction?: boolean; // per_axis: given a direction, one block applied along it
  envelope: boolean;
  samples: boolean;
  fields: FieldInfo[];
  control_law?: FieldInfo[];
  envelope_fields?: FieldInfo[];
}
export interface FieldsDescription {
  types: TypeInfo[];
  common: FieldInfo[];
  direction: { forms: DirectionForm[] };
}

type Get = () => unknown;
type Set = (v: unknown) => void;

// A value as the form shows it (degrees for an angle), and back, exactly, to the file's
// integer unit.
const shown = (f: FieldInfo, v: number) => (f.scale ? Number((v * f.scale).toFixed(6)) : v);
const stored = (f: FieldInfo, v: number) => (f.scale ? Math.round(v / f.scale) : v);

function range(f: FieldInfo): string {
  const r = f.min !== undefined && f.max !== undefined ? `${shown(f, f.min)}..${shown(f, f.max)}` : '';
  const unit = f.shown_unit ? `${f.shown_unit} (${f.unit} in the file)` : f.unit;
  return [r, f.infinite ? 'or infinite' : '', unit].filter(Boolean).join(' ');
}

// The errors that belong to a field: its own path, or a part of it.
const errorsAt = (errors: FieldError[], path: string) =>
  errors.filter((e) => e.field === path || e.field.startsWith(path + '[') || e.field.startsWith(path + '.'));

function fieldRow(path: string, f: FieldInfo, get: Get, set: Set, errors: FieldError[], label = f.name): HTMLElement {
  const value = get();
  let input: HTMLElement;
  if (f.kind === 'boolean') {
    input = h('input', { type: 'checkbox', checked: value === true, onchange: (e: Event) => set((e.target as HTMLInputElement).checked) });
  } else if (f.kind === 'choice') {
    input = h(
      'select',
      { onchange: (e: Event) => set((e.target as HTMLSelectElement).value || undefined) },
      f.required ? null : h('option', { value: '' }, '(default)'),
      ...(f.choices ?? []).map((c) => h('option', { value: c, selected: value === c }, c)),
    );
  } else {
    const infinite = value === 'infinite';
    input = h(
      'span',
      { class: 'number' },
      h('input', {
        type: 'number',
        step: f.scale ?? 1,
        value: infinite || typeof value !== 'number' ? '' : String(shown(f, value)),
        placeholder: f.required ? '' : 'default',
        disabled: infinite,
        onchange: (e: Event) => {
          const t = (e.target as HTMLInputElement).value.trim();
          set(t === '' ? undefined : stored(f, Number(t)));
        },
      }),
      f.infinite
        ? h('label', {}, h('input', { type: 'checkbox', class: 'infinite', checked: infinite, onchange: (e: Event) => set((e.target as HTMLInputElement).checked ? 'infinite' : (f.max ?? 1000000)) }), '∞')
        : null,
    );
  }
  const mine = errorsAt(errors, path);
  return h(
    'div',
    { class: `field ${mine.length ? 'has-error' : ''}`, 'data-path': path },
    h('label', { class: 'name', title: path }, label, f.required ? h('span', { class: 'req' }, '*') : null),
    input,
    h('span', { class: 'range' }, range(f)),
    ...mine.map((e) => h('div', { class: 'error', 'data-error-for': path }, e.message)),
  );
}

// The direction (§6.5): a choice of the forms that fit the effect's axes (and the one it
// has, fitting or not, so that the validator's error shows where it is), then a numeric
// field per component, all from the description's forms.
function directionRows(
  forms: DirectionForm[],
  fx: EffectJson,
  axes: string[],
  edit: (change: (e: EffectJson) => void) => void,
  errors: FieldError[],
): HTMLElement[] {
  const current = (fx.direction ?? {}) as Record<string, number | number[]>;
  const kind = Object.keys(current)[0] ?? '';
  const fits = (f: DirectionForm) =>
    axes.length > 0 && axes.every((a) => f.axes.includes(a)) && (!f.exact_axes || axes.length === f.axes.length);
  const offered = forms.filter((f) => fits(f) || f.form === kind);
  const form = forms.find((f) => f.form === kind);
  const scalar = form !== undefined && !form.per_axis && form.components.length === 1;
  // the form's own errors ("needs a direction", "polar needs the axes x and y"); a scalar
  // form's path is its component's too, and shows there
  const own = errors.filter((e) => e.field === 'direction' || (!scalar && e.field === `direction.${kind}`));
  const rows: HTMLElement[] = [
    h(
      'div',
      { class: `field ${own.length ? 'has-error' : ''}`, 'data-path': 'direction' },
      h('label', { class: 'name' }, 'direction'),
      h(
        'select',
        {
          class: 'direction-form',
          onchange: (e: Event) => {
            const form = forms.find((f) => f.form === (e.target as HTMLSelectElement).value);
            edit((x) => {
              if (!form) delete x.direction;
              else if (form.per_axis) x.direction = { [form.form]: axes.map((_, i) => form.default[i] ?? 0) };
              else x.direction = { [form.form]: form.components.length === 1 ? form.default[0] : form.default.slice() };
            });
          },
        },
        h('option', { value: '', selected: kind === '' }, '(none)'),
        ...offered.map((f) => h('option', { value: f.form, selected: f.form === kind }, f.form)),
      ),
      h('span', { class: 'range' }, 'where the force comes from (§6.5); the forms that fit the axes'),
      ...own.map((e) => h('div', { class: 'error', 'data-error-for': 'direction' }, e.message)),
    ),
  ];
  if (!form) return rows;
  const value = current[kind];
  const list = Array.isArray(value) ? value : [value];
  const count = form.per_axis ? Math.max(axes.length, list.length) : form.components.length;
  for (let i = 0; i < count; ++i) {
    const c = form.per_axis ? form.components[0] : form.components[i];
    const path = scalar ? `direction.${kind}` : `direction.${kind}[${i}]`;
    const label = form.per_axis ? `${kind}[${i}] (${axes[i] ?? '?'})` : `${kind} ${c.name}`;
    const get = () => list[i];
    const set: Set = (v) =>
      edit((x) => {
        const d = x.direction as Record<string, number | number[]>;
        if (scalar) d[kind] = (v as number) ?? form.default[0];
        else {
          const next = Array.isArray(d[kind]) ? [...(d[kind] as number[])] : [];
          next[i] = (v as number) ?? 0;
          d[kind] = next;
        }
      });
    // a component's own errors only; the form's are on the choice above
    rows.push(fieldRow(path, c, get, set, errors.filter((e) => e.field === path), label));
  }
  return rows;
}

function obj(parent: Record<string, unknown>, key: string): Record<string, unknown> {
  if (typeof parent[key] !== 'object' || parent[key] === null) parent[key] = {};
  return parent[key] as Record<string, unknown>;
}

export function formEditor(root: HTMLElement, store: Store) {
  return (s: State) => {
    const i = s.selected;
    const effects = store.effects();
    const fx = effects[i];
    const desc = s.hello?.fields as unknown as FieldsDescription | undefined;
    if (!fx || !desc) {
      root.replaceChildren(h('p', { class: 'hint' }, 'Select an effect to edit it.'));
      const general = s.errors.filter((e) => e.effect === -1 || e.field === '');
      root.append(...general.map((e) => h('div', { class: 'error' }, e.message)));
      return;
    }
    const info = desc.types.find((t) => t.type === fx.type);
    const errors = s.errors.filter((e) => e.effect === i || e.effect === -1);
    const edit = (change: (e: EffectJson) => void) =>
      store.update((d) => change(d.sensations[d.current].effects[i]), i);
    const setIn = (target: (e: EffectJson) => Record<string, unknown>, key: string): Set => (v) =>
      edit((e) => {
        const t = target(e);
        if (v === undefined) delete t[key];
        else t[key] = v;
      });
    const rows: HTMLElement[] = [];
    rows.push(h('h3', {}, `#${i + 1} ${fx.type}`, h('span', { class: 'class' }, info?.class ?? '')));
    for (const f of desc.common) {
      rows.push(fieldRow(f.name, f, () => fx[f.name], setIn((e) => e, f.name), errors));
    }
    // axes: the device's, in order
    const deviceAxes = ((s.hello?.device.axes as { name: string }[]) ?? []).map((a) => a.name);
    const axes = (fx.axes as string[]) ?? [];
    rows.push(
      h(
        'div',
        { class: `field ${errors.some((e) => e.field.startsWith('axes')) ? 'has-error' : ''}`, 'data-path': 'axes' },
        h('label', { class: 'name' }, 'axes', h('span', { class: 'req' }, '*')),
        h('span', {}, ...deviceAxes.map((a) =>
          h('label', { class: 'axis' }, h('input', { type: 'checkbox', 'data-axis': a, checked: axes.includes(a), onchange: (e: Event) => edit((x) => {
            const on = (e.target as HTMLInputElement).checked;
            const next = deviceAxes.filter((n) => (n === a ? on : axes.includes(n)));
            x.axes = next;
          }) }), a))),
        h('span', { class: 'range' }, 'the device’s axes'),
        ...errors.filter((e) => e.field.startsWith('axes')).map((e) => h('div', { class: 'error' }, e.message)),
      ),
    );
    // trigger button: the device's buttons and hats
    const buttons = Number(s.hello?.device.buttons ?? 0);
    const hats = Number(s.hello?.device.hats ?? 0);
    rows.push(
      h(
        'div',
        { class: 'field', 'data-path': 'trigger_button' },
        h('label', { class: 'name' }, 'trigger_button'),
        h('select', { onchange: (e: Event) => {
          const v = (e.target as HTMLSelectElement).value;
          setIn((x) => x, 'trigger_button')(v === '' ? undefined : v.startsWith('hat') ? v : Number(v));
        } },
          h('option', { value: '' }, '(none)'),
          ...Array.from({ length: buttons }, (_, b) => h('option', { value: String(b + 1), selected: fx.trigger_button === b + 1 }, `button ${b + 1}`)),
          ...Array.from({ length: hats }, (_, t) => h('option', { value: `hat${t + 1}`, selected: fx.trigger_button === `hat${t + 1}` }, `hat ${t + 1}`)),
        ),
        h('span', { class: 'range' }, 'a reflex (§1.2.c)'),
        ...errors.filter((e) => e.field === 'trigger_button').map((e) => h('div', { class: 'error' }, e.message)),
      ),
    );
    rows.push(...directionRows(desc.direction?.forms ?? [], fx, axes, edit, errors));
    if (info?.envelope) {
      const has = typeof fx.envelope === 'object';
      rows.push(h('h4', {}, h('label', {}, h('input', { type: 'checkbox', class: 'envelope-on', checked: has, onchange: (e: Event) => edit((x) => {
        if ((e.target as HTMLInputElement).checked) x.envelope = { impulse_level: 10000, settle_time_us: 0 };
        else delete x.envelope;
      }) }), 'envelope')));
      if (has) {
        for (const f of info.envelope_fields ?? []) {
          rows.push(fieldRow(`envelope.${f.name}`, f, () => (fx.envelope as Record<string, unknown>)[f.name], setIn((e) => obj(e, 'envelope'), f.name), errors));
        }
      }
    }
    if (info) {
      rows.push(h('h4', {}, info.block));
      if (info.shape === 'object') {
        const block = (fx[info.block] as Record<string, unknown>) ?? {};
        for (const f of info.fields) {
          rows.push(fieldRow(`${info.block}.${f.name}`, f, () => block[f.name], setIn((e) => obj(e, info.block), f.name), errors));
        }
        if (info.control_law) {
          const laws = (block.control_law as Record<string, unknown>[]) ?? [];
          laws.forEach((law, a) => {
            rows.push(h('h5', {}, `control_law[${a}] (${axes[a] ?? '?'})`));
            for (const f of info.control_law ?? []) {
              rows.push(fieldRow(`dynamic.control_law[${a}].${f.name}`, f, () => law[f.name], setIn((e) => ((obj(e, 'dynamic').control_law as Record<string, unknown>[])[a]), f.name), errors));
            }
          });
          rows.push(h('button', { onclick: () => edit((e) => {
            const list = (obj(e, 'dynamic').control_law as Record<string, unknown>[]) ?? [];
            list.push(structuredClone(list[0] ?? { mass: 1000, k_pos: 1000, k_neg: 1000 }));
            obj(e, 'dynamic').control_law = list;
          }) }, '+ control law (one per axis)'));
        }
        if (info.samples) {
          const samples = (block.samples as number[]) ?? [];
          rows.push(
            h('div', { class: `field ${errors.some((e) => e.field.includes('samples')) ? 'has-error' : ''}`, 'data-path': 'custom.samples' },
              h('label', { class: 'name' }, 'samples'),
              h('input', { type: 'text', class: 'json', value: samples.join(', '), onchange: (e: Event) => {
                const list = (e.target as HTMLInputElement).value.split(',').map((x) => Number(x.trim())).filter((x) => !Number.isNaN(x));
                setIn((x) => obj(x, info.block), 'samples')(list);
              } }),
              h('span', { class: 'range' }, '±10000 each, interleaved by channel'),
              ...errors.filter((e) => e.field.includes('samples')).map((e) => h('div', { class: 'error' }, e.message)),
            ),
          );
        }
      } else {
        const blocks = (fx[info.block] as Record<string, unknown>[]) ?? [];
        const single = info.shape === 'one_block' || (info.one_block_with_direction === true && fx.direction !== undefined);
        const count = single ? 1 : Math.max(1, axes.length);
        for (let a = 0; a < count; ++a) {
          rows.push(h('h5', {}, single ? `${info.block}[0]${info.shape === 'per_axis' ? ' (along the direction)' : ''}` : `${info.block}[${a}] (${axes[a] ?? '?'})`));
          for (const f of info.fields) {
            rows.push(fieldRow(`${info.block}[${a}].${f.name}`, f, () => blocks[a]?.[f.name], setIn((e) => {
              const list = (e[info.block] as Record<string, unknown>[]) ?? [];
              while (list.length <= a) list.push({});
              e[info.block] = list;
              return list[a];
            }, f.name), errors));
          }
        }
      }
    }
    const unplaced = errors.filter((e) => !rows.some((r) => r.querySelector?.(`[data-error-for]`) && r.textContent?.includes(e.message)));
    root.replaceChildren(...rows, ...unplaced.filter((e) => !root.isConnected || true).filter((e) => e.field === '' ).map((e) => h('div', { class: 'error general' }, e.message)));
  };
}
