// Checks a message against the schema (schema.ts): the same rules the server applies
// (src/studio/protocol_check.cpp) to what the browser sends.
import { schema } from './schema';

type FieldRule = {
  type: string;
  min?: number;
  max?: number;
  maxLength?: number;
  maxItems?: number;
  enum?: readonly string[];
  optional?: boolean;
};

export function checkMessage(side: 'client' | 'server', msg: unknown): string | null {
  if (typeof msg !== 'object' || msg === null || Array.isArray(msg)) return 'a message is a JSON object';
  const m = msg as Record<string, unknown>;
  const table = schema[side] as Record<string, Record<string, FieldRule>>;
  if (typeof m.type !== 'string' || !(m.type in table)) {
    return `unknown message type ${JSON.stringify(m.type)} (allowed: ${Object.keys(table).join(', ')})`;
  }
  const rules = table[m.type];
  for (const key of Object.keys(m)) {
    if (key !== 'type' && !(key in rules)) return `${m.type}: unknown field "${key}"`;
  }
  for (const [key, rule] of Object.entries(rules)) {
    const v = m[key];
    if (v === undefined) {
      if (rule.optional) continue;
      return `${m.type}: missing field "${key}"`;
    }
    const at = `${m.type}.${key}`;
    switch (rule.type) {
      case 'integer':
      case 'number':
        if (typeof v !== 'number' || !Number.isFinite(v)) return `${at}: expected a number`;
        if (rule.type === 'integer' && !Number.isInteger(v)) return `${at}: expected an integer`;
        if (rule.min !== undefined && rule.max !== undefined && (v < rule.min || v > rule.max)) {
          return `${at} = ${v} is out of range (allowed ${rule.min}..${rule.max})`;
        }
        break;
      case 'boolean':
        if (typeof v !== 'boolean') return `${at}: expected true or false`;
        break;
      case 'string':
        if (typeof v !== 'string') return `${at}: expected a string`;
        if (rule.maxLength !== undefined && v.length > rule.maxLength) return `${at}: longer than ${rule.maxLength}`;
        if (rule.enum && !rule.enum.includes(v)) return `${at}: expected one of ${rule.enum.join(', ')}`;
        break;
      case 'array':
        if (!Array.isArray(v)) return `${at}: expected an array`;
        if (rule.maxItems !== undefined && v.length > rule.maxItems) return `${at}: more than ${rule.maxItems} items`;
        break;
      case 'object':
        if (typeof v !== 'object' || v === null || Array.isArray(v)) return `${at}: expected an object`;
        break;
    }
  }
  return null;
}
