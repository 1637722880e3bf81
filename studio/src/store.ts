// The Studio's state and the one way it changes: an action produces a new document, the
// store keeps it (and the undo history) and tells every view to draw itself again. Views
// never change the document themselves; they call store.update() or the helpers below.
import { type Doc, type EffectJson, emptyDoc } from './document';
import type { ServerMessage } from './protocol/schema';

export type Hello = ServerMessage<'hello'>;
export type FieldError = { effect: number; field: string; message: string };

export interface State {
  doc: Doc;
  selected: number; // effect index in the current sensation, -1 for none
  errors: FieldError[];
  hello: Hello | null;
  dirty: boolean;
}

type View = (s: State) => void;
const kMaxHistory = 200;

export class Store {
  state: State = { doc: emptyDoc(), selected: -1, errors: [], hello: null, dirty: false };
  private undoStack: string[] = [];
  private redoStack: string[] = [];
  private views: View[] = [];
  onDocChange: (s: State) => void = () => {};

  subscribe(v: View): void {
    this.views.push(v);
  }

  render(): void {
    for (const v of this.views) v(this.state);
  }

  // Every edit goes through here: it is recorded for undo, then sent to the device.
  update(change: (doc: Doc) => void, selected?: number): void {
    this.undoStack.push(JSON.stringify(this.state.doc));
    if (this.undoStack.length > kMaxHistory) this.undoStack.shift();
    this.redoStack = [];
    const doc = structuredClone(this.state.doc);
    change(doc);
    this.replace(doc, selected ?? this.state.selected, true);
  }

  // A document from a file: no undo across files.
  load(doc: Doc): void {
    this.undoStack = [];
    this.redoStack = [];
    this.replace(doc, doc.sensations[doc.current]?.effects.length ? 0 : -1, false);
  }

  undo(): void {
    const prev = this.undoStack.pop();
    if (prev === undefined) return;
    this.redoStack.push(JSON.stringify(this.state.doc));
    this.replace(JSON.parse(prev) as Doc, this.state.selected, true);
  }

  redo(): void {
    const next = this.redoStack.pop();
    if (next === undefined) return;
    this.undoStack.push(JSON.stringify(this.state.doc));
    this.replace(JSON.parse(next) as Doc, this.state.selected, true);
  }

  private replace(doc: Doc, selected: number, dirty: boolean): void {
    const count = doc.sensations[doc.current]?.effects.length ?? 0;
    this.state = {
      ...this.state,
      doc,
      selected: Math.min(selected, count - 1),
      dirty: dirty || this.state.dirty,
    };
    this.onDocChange(this.state);
    this.render();
  }

  setErrors(errors: FieldError[]): void {
    this.state = { ...this.state, errors };
    this.render();
  }

  select(i: number): void {
    this.state = { ...this.state, selected: i };
    this.render();
  }

  saved(doc: Doc): void {
    this.state = { ...this.state, doc, dirty: false };
    this.render();
  }

  effects(): EffectJson[] {
    const d = this.state.doc;
    return d.sensations[d.current]?.effects ?? [];
  }
}
