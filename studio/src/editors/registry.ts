// One editor module per family (conditions, walls and barriers, waves, profiles, dynamics).
// The next issue adds the graphical editors; until then every family uses the generated
// form, which already edits every field of every type.
import type { State, Store } from '../store';
import { formEditor } from './form';

type Editor = (s: State) => void;
const editors = new Map<HTMLElement, Editor>();

export function editorFor(_s: State, root: HTMLElement, store: Store): Editor {
  let e = editors.get(root);
  if (!e) {
    e = formEditor(root, store);
    editors.set(root, e);
  }
  return e;
}
