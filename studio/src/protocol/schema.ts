// The browser <-> server messages of the Studio's live session, described ONCE.
//
// This object is the single source: the TypeScript types below are inferred from it, the
// front end checks every message it receives against it (check.ts), and the build writes
// it as protocol.json into the assets embedded in the feel binary, where the C++ server
// checks every message a browser sends against the same description
// (src/studio/protocol_check.cpp). docs/studio.md lists the messages.
//
// A field is {type, optional?} with type integer (min/max), number, boolean,
// string (maxLength, enum?), array (maxItems) or object. Every message also has "type".
export const schema = {
  // browser -> server
  client: {
    // the current sensation: checked by the format's reader, then sent to the device as
    // partial updates of the effects that already play
    set_sensation: {
      seq: { type: 'integer', min: 0, max: 2147483647 },
      name: { type: 'string', maxLength: 64 },
      // the file it belongs to, named in error messages as `feel check FILE` names it
      file: { type: 'string', maxLength: 200, optional: true },
      effects: { type: 'array', maxItems: 32 },
    },
    play: { effect: { type: 'integer', min: 0, max: 31 } },
    stop: { effect: { type: 'integer', min: 0, max: 31 } },
    stop_all: {},
    // "play on trigger": arm (or disarm) the effect's trigger button as a reflex
    arm: { effect: { type: 'integer', min: 0, max: 31 }, on: { type: 'boolean' } },
    // the hand's target, device axes and signs, ±10000 of the travel
    pointer: {
      seq: { type: 'integer', min: 0, max: 2147483647 },
      x: { type: 'integer', min: -10000, max: 10000 },
      y: { type: 'integer', min: -10000, max: 10000 },
    },
    button: { button: { type: 'integer', min: 1, max: 32 }, down: { type: 'boolean' } },
    hat: { hat: { type: 'integer', min: 1, max: 4 }, down: { type: 'boolean' } },
    grip: { grip: { type: 'string', maxLength: 16, enum: ['loose', 'firm', 'stiff'] } },
    gain: { gain: { type: 'integer', min: 0, max: 10000 } },
    // a .ffe, .ahap or .wav file to import into the workspace (docs/import.md): its name and
    // its bytes in base64, at most 1 MiB (1048576 bytes, 1398104 characters); the axis
    // AHAP and WAV drive
    import_file: {
      name: { type: 'string', maxLength: 200 },
      data: { type: 'string', maxLength: 1398104 },
      axis: { type: 'string', maxLength: 2, enum: ['x', 'y', 'z', 'rx', 'ry', 'rz'], optional: true },
    },
    // code export (views/export.ts): the current sensation as set_sensation sends it, as code
    export_code: {
      seq: { type: 'integer', min: 0, max: 2147483647 },
      lang: { type: 'string', maxLength: 16, enum: ['cpp', 'c', 'library'] },
      name: { type: 'string', maxLength: 64 },
      file: { type: 'string', maxLength: 200, optional: true },
      effects: { type: 'array', maxItems: 32 },
    },
  },
  // server -> browser
  server: {
    hello: {
      device: { type: 'object' },
      fields: { type: 'object' },
      starters: { type: 'object' },
      simulated: { type: 'boolean' },
      grip: { type: 'string', maxLength: 16 },
      gain: { type: 'integer', min: 0, max: 10000 },
    },
    // ~60 Hz: the device's reports since the last frame (t ms, force[axes], position[axes])
    state: {
      t_us: { type: 'number' },
      samples: { type: 'array', maxItems: 2000 },
      position: { type: 'array', maxItems: 6 },
      force: { type: 'array', maxItems: 6 },
      buttons: { type: 'integer', min: 0, max: 4294967295 },
      pointer_seq: { type: 'integer', min: 0, max: 2147483647 },
      // how long ago (server clock) the pointer message pointer_seq arrived: the server's
      // share of the pointer -> force shown latency
      pointer_age_us: { type: 'number' },
      // on the frame that first shows the newest pointer message's force change: its hops
      // through the server (seq, read_wall_us and built_wall_us on the wall clock, apply_us
      // read -> hand target set, device_us -> the first report with the new force (transit_us of it: from
      // that report's device tick to the sampler, less the fastest such transit; loop_us of it: the
      // loop's tick that took the target -> the tick of that report, on the device's clock, -1 unknown:
      // the hand's physics; software_us: hand target set -> the report of the tick that took it in the
      // sampler, -1 unknown: the device's software path), frame_us -> this frame built); docs/studio.md, "Latency"
      pointer_hops: { type: 'object', optional: true },
      // that frame's write: seq, ahead (messages queued before it), write_us (queued -> written)
      pointer_written: { type: 'object', optional: true },
      // reports the server's sampler lost because its queue was full (0 on a healthy server)
      dropped_reports: { type: 'integer', min: 0, max: 9007199254740991 },
      effects: { type: 'array', maxItems: 32 },
      // the dynamics' interim and final reports since the last frame (§5.2): effect, kind,
      // t_ms, position/velocity (mass minus handle) and handle_velocity per axis
      dynamics: { type: 'array', maxItems: 256 },
    },
    // the answer to set_sensation: errors at their fields, or how long the device took
    validated: {
      seq: { type: 'integer', min: 0, max: 2147483647 },
      ok: { type: 'boolean' },
      errors: { type: 'array', maxItems: 64 },
      apply_us: { type: 'number' },
      restarted: { type: 'array', maxItems: 32 },
    },
    // the answer to import_file: the new workspace file, its text, what was not mapped
    imported: {
      file: { type: 'string', maxLength: 200 },
      sensation: { type: 'string', maxLength: 64 },
      text: { type: 'string', maxLength: 1048576 },
      notes: { type: 'array', maxItems: 64 },
    },
    // the answer to export_code (src/studio/export_request.cpp, src/codegen)
    exported: {
      seq: { type: 'integer', min: 0, max: 2147483647 },
      lang: { type: 'string', maxLength: 16, enum: ['cpp', 'c', 'library'] },
      filename: { type: 'string', maxLength: 100 },
      code: { type: 'string', maxLength: 8000000 },
    },
    error: {
      message: { type: 'string', maxLength: 2000 },
      request: { type: 'string', maxLength: 64, optional: true },
    },
  },
} as const;

type Schema = typeof schema;
type FieldValue<F> = F extends { type: 'integer' | 'number' }
  ? number
  : F extends { type: 'boolean' }
    ? boolean
    : F extends { type: 'string'; enum: readonly (infer E)[] }
      ? E
      : F extends { type: 'string' }
        ? string
        : F extends { type: 'array' }
          ? unknown[]
          : Record<string, unknown>;
type Required<M> = { [K in keyof M as M[K] extends { optional: true } ? never : K]: FieldValue<M[K]> };
type Optional<M> = { [K in keyof M as M[K] extends { optional: true } ? K : never]?: FieldValue<M[K]> };
type Message<Side, K extends keyof Side> = { type: K } & Required<Side[K]> & Optional<Side[K]>;

export type ClientType = keyof Schema['client'];
export type ServerType = keyof Schema['server'];
export type ClientMessage<K extends ClientType = ClientType> = K extends ClientType
  ? Message<Schema['client'], K>
  : never;
export type ServerMessage<K extends ServerType = ServerType> = K extends ServerType
  ? Message<Schema['server'], K>
  : never;
