// The document being edited: a feel/1 file's sensations, each a list of effects kept as
// the format's own JSON objects (so what is saved is what the format reads).
export type EffectJson = Record<string, unknown> & { type: string };

export interface Sensation {
  name: string;
  description?: string;
  effects: EffectJson[];
}

export interface Doc {
  file: string | null; // workspace path, null until saved
  readOnly: boolean; // an example: save it under a new name
  sensations: Sensation[];
  current: number; // index into sensations
}

export function emptyDoc(): Doc {
  return { file: null, readOnly: false, sensations: [{ name: 'untitled', effects: [] }], current: 0 };
}

export function parseFile(text: string, file: string | null, readOnly: boolean): Doc {
  const data = JSON.parse(text) as { sensations: Record<string, Record<string, unknown>> };
  const sensations: Sensation[] = [];
  for (const [name, value] of Object.entries(data.sensations)) {
    const { description, effects, ...single } = value as {
      description?: string;
      effects?: EffectJson[];
    } & Record<string, unknown>;
    sensations.push({
      name,
      description,
      effects: effects ? structuredClone(effects) : [single as EffectJson],
    });
  }
  return { file, readOnly, sensations, current: 0 };
}

// The sensation as the format writes it: one effect inline, several as a compound.
export function sensationJson(s: Sensation): Record<string, unknown> {
  const head = s.description !== undefined ? { description: s.description } : {};
  if (s.effects.length === 1) return { ...head, ...s.effects[0] };
  return { ...head, effects: s.effects };
}

export function fileText(doc: Doc): string {
  const sensations: Record<string, unknown> = {};
  for (const s of doc.sensations) sensations[s.name] = sensationJson(s);
  return JSON.stringify({ format: 'feel/1', sensations }, null, 2) + '\n';
}
