'use strict';
// The operations of conformance/PROTOCOL.md over the generated library
// (generated/javascript, the npm package osdk-kaitai): its deframer, frame
// and payload decoding, errors and encoders. ACK matching, the control mode
// classification and ranges, and the value model are the testee's.

const osdk = require('osdk-kaitai');
const { tables } = require('./tables');
const { modelOf } = require('./model');

const NAME = 'osdk-kaitai-javascript';
const PROFILES = osdk.PROFILES;
const AXIS_RANGE = { x: 'horizontal', y: 'horizontal', z: 'vertical', yaw: 'yaw' };
// Sessions with an ACK slot (PROTOCOL.md "ACK matching", ERRATA E32).
const FIRST_ACK_SESSION = 2;
const LAST_ACK_SESSION = 31;

const commandName = (cmdSet, cmdId) => osdk.commandName(cmdSet, cmdId) || 'unknown';

class BadRequest extends Error {}
BadRequest.prototype.name = 'BadRequest';

// A rejection of the testee's own checks (check_movement_control).
class Rejection extends Error {
  constructor(cls, detail) {
    super(detail);
    this.cls = cls;
    this.detail = detail;
  }
}

const oneLine = (err) => String(err && err.message !== undefined ? err.message : err).replace(/\s+/g, ' ').trim();

// ---- arguments ------------------------------------------------------------------------

function arg(req, key, kind) {
  if (!Object.prototype.hasOwnProperty.call(req, key)) throw new BadRequest(`missing argument '${key}'`);
  const v = req[key];
  const ok = {
    integer: Number.isInteger(v),
    boolean: typeof v === 'boolean',
    string: typeof v === 'string',
    list: Array.isArray(v),
    object: v !== null && typeof v === 'object' && !Array.isArray(v),
  }[kind];
  if (!ok) throw new BadRequest(`argument '${key}' must be a ${kind}`);
  return v;
}

function hexOfArg(req, key) {
  const text = arg(req, key, 'string');
  if (!/^(?:[0-9a-fA-F]{2})*$/.test(text)) throw new BadRequest(`argument '${key}' is not a hex string of whole bytes`);
  return text;
}

const hexArg = (req) => Buffer.from(hexOfArg(req, 'hex'), 'hex');

const hexOf = (bytes) => Buffer.from(bytes.buffer, bytes.byteOffset, bytes.length).toString('hex');

// The control mode byte alone, through the generated class (no library call decodes it).
function parseControlMode(byte) {
  return new osdk.OsdkControlMode(new osdk.KaitaiStream(new Uint8Array([byte])), null, null);
}

function intArg(req, key, max) {
  const v = arg(req, key, 'integer');
  if (v < 0 || v > max) throw new BadRequest(`argument '${key}' must be 0..${max}`);
  return v;
}

const byteArg = (req, key) => intArg(req, key, 0xff);

// A float request argument {"f32": "0x…"}: its bits, for the encoder bit for bit.
function f32Arg(req, key) {
  const v = arg(req, key, 'object');
  const text = v.f32;
  if (typeof text !== 'string' || !/^0x[0-9a-fA-F]{1,8}$/.test(text)) {
    throw new BadRequest(`argument '${key}' must be {"f32": "0x…"} with at most 8 hex digits`);
  }
  return osdk.f32Bits(Number.parseInt(text.slice(2), 16));
}

// ---- operations -------------------------------------------------------------------------

function decodePayload(req, profile) {
  const data = hexArg(req);
  const cmdSet = byteArg(req, 'cmd_set');
  const cmdId = byteArg(req, 'cmd_id');
  const isAck = arg(req, 'is_ack', 'boolean');
  return { value: modelOf(osdk.decodePayload(data, cmdSet, cmdId, isAck, profile), data) };
}

function classify(req, profile) {
  const byte = byteArg(req, 'byte');
  const mode = tables.control_modes[profile].modes[byte];
  const fields = modelOf(parseControlMode(byte), Buffer.from([byte]));
  return { fields, classification: mode.classification, combination: mode.combination };
}

function checkMovementControl(req, profile) {
  const data = hexArg(req);
  // As a command value: OsdkPayload(0x01, 0x03) is osdk_movement_control plus the trailing-bytes check.
  const [cmdSet, cmdId] = osdk.COMMANDS.movement_control;
  const body = osdk.decodePayload(data, cmdSet, cmdId, false, profile);
  const value = modelOf(body, data);
  const byte = data[0];
  const modes = tables.control_modes[profile];
  const mode = modes.modes[byte];
  if (mode.classification !== 'documented') {
    throw new Rejection('undefined_mode', `mode byte 0x${byte.toString(16).padStart(2, '0')} is ${mode.classification} on ${profile}`);
  }
  const ranges = modes.ranges[String(mode.combination)];
  for (const [axis, which] of Object.entries(AXIS_RANGE)) {
    const v = body[axis]; // a double; a quieted NaN is still a NaN
    const { min, max } = ranges[which];
    if (!Number.isFinite(v) || (min !== null && v < min) || (max !== null && v > max)) {
      throw new Rejection('out_of_range', `${axis} = ${v} outside the ${which} range ${min}..${max}`);
    }
  }
  return { value, combination: mode.combination };
}

function decodeFrame(req, profile) {
  const data = hexArg(req);
  return { frame: modelOf(osdk.decodeFrame(data, profile), data) };
}

function encodeMovementControl(req) {
  const mode = byteArg(req, 'mode');
  const [x, y, z, yaw] = ['x', 'y', 'z', 'yaw'].map((k) => f32Arg(req, k));
  return { hex: hexOf(osdk.encodeMovementControl(mode, x, y, z, yaw)) };
}

function encodeFrame(req) {
  const isAck = arg(req, 'is_ack', 'boolean');
  const has = (k) => Object.prototype.hasOwnProperty.call(req, k);
  const cmdSet = has('cmd_set') ? byteArg(req, 'cmd_set') : null;
  const cmdId = has('cmd_id') ? byteArg(req, 'cmd_id') : null;
  if ((cmdSet === null) !== (cmdId === null) || (isAck && cmdSet !== null)) {
    throw new BadRequest('cmd_set and cmd_id come together, and only for a command (is_ack false)');
  }
  const session = intArg(req, 'session', 31);
  const seq = intArg(req, 'seq', 0xffff);
  const value = Buffer.from(hexOfArg(req, 'value'), 'hex');
  return { hex: hexOf(osdk.encodeFrame(cmdSet, cmdId, isAck, session, seq, value)) };
}

// Events of a stream: Deframer boundaries, Kaitai values, ACK matching.
// models = false leaves each value as Kaitai parsed it (the bench mode times
// decoding, not the value model).
class StreamDecoder {
  constructor(profile, models = true) {
    this.profile = profile;
    this.models = models;
    this.slots = new Map(); // session 2..31 -> [seq, cmd_set, cmd_id] of the command waiting for its ACK
  }

  event(ev) {
    if (ev.kind === 'garbage') return { offset: ev.offset, kind: 'garbage', length: ev.length };
    if (ev.kind === 'error') {
      return { offset: ev.offset, kind: 'error', error: ev.errorClass, detail: ev.detail, length: ev.length };
    }
    try {
      return this.frame(ev);
    } catch (err) {
      if (err instanceof osdk.OsdkError) {
        return { offset: ev.offset, kind: 'error', error: err.errorClass, detail: err.message, length: ev.raw.length };
      }
      // Our bug must not cost the rest of the stream.
      return {
        offset: ev.offset, kind: 'error', error: 'undecodable',
        detail: `internal error (${err && err.name}: ${oneLine(err)})`, length: ev.raw.length,
      };
    }
  }

  frame(ev) {
    const f = osdk.decodeFrame(ev.raw, this.profile);
    const out = { offset: ev.offset, kind: 'frame' };
    const plain = f.data instanceof osdk.OsdkFrame.FrameData;
    const headerOnly = f.len === 12;
    const hasSlot = f.session >= FIRST_ACK_SESSION && f.session <= LAST_ACK_SESSION;
    if (f.isAck && (plain || headerOnly) && hasSlot) {
      const cmd = this.slots.get(f.session);
      if (cmd !== undefined && cmd[0] === f.seq) {
        this.slots.delete(f.session);
        out.ack_of = commandName(cmd[1], cmd[2]);
        const value = plain ? f.data.ackValue : new Uint8Array(0); // a header-only ACK's value is empty
        let ack;
        try {
          ack = osdk.decodePayload(value, cmd[1], cmd[2], true, this.profile);
        } catch (err) {
          if (!(err instanceof osdk.OsdkError)) throw err;
          return {
            offset: ev.offset, kind: 'error', error: err.errorClass, detail: err.message,
            length: ev.raw.length, ack_of: out.ack_of,
          };
        }
        out.ack = this.models ? modelOf(ack, value) : ack;
      }
    } else if (!f.isAck && plain && hasSlot) {
      this.slots.set(f.session, [f.seq, f.data.cmdSet, f.data.cmdId]);
    }
    out.frame = this.models ? modelOf(f, ev.raw) : f;
    return out;
  }
}

// `data` cut into reads of the given sizes; what they leave over is one last read.
function splitChunks(data, sizes) {
  const out = [];
  let pos = 0;
  for (const size of sizes) {
    out.push(data.subarray(Math.min(pos, data.length), Math.min(pos + size, data.length)));
    pos += size;
  }
  if (pos < data.length) out.push(data.subarray(pos));
  return out;
}

function decodeStream(req, profile) {
  const data = hexArg(req);
  const sizes = arg(req, 'chunks', 'list');
  if (!sizes.every((s) => Number.isInteger(s) && s >= 0)) {
    throw new BadRequest("argument 'chunks' must be a list of non-negative integers");
  }
  const events = [];
  const stream = eventStream(profile, true, (ev) => events.push(ev));
  for (const chunk of splitChunks(data, sizes)) stream.feed(chunk);
  stream.finish();
  return { events };
}

// decode_stream's events, one read after another, each handed to onEvent
// (also the bench mode's loop).
function eventStream(profile, models, onEvent) {
  const deframer = new osdk.Deframer();
  const decoder = new StreamDecoder(profile, models);
  return {
    feed: (chunk) => { for (const ev of deframer.feed(chunk)) onEvent(decoder.event(ev)); },
    finish: () => { for (const ev of deframer.finish()) onEvent(decoder.event(ev)); },
  };
}

const OPS = {
  decode_stream: decodeStream,
  decode_frame: decodeFrame,
  decode_payload: decodePayload,
  classify_control_mode: classify,
  check_movement_control: checkMovementControl,
};

// operations that take no profile
const PLAIN_OPS = {
  encode_movement_control: encodeMovementControl,
  encode_frame: encodeFrame,
};

// The response to a request object with an "op" string. Throws BadRequest
// for arguments it cannot use; anything else thrown is a bug of ours.
function answer(req) {
  const { op } = req;
  if (op === 'capabilities') {
    return {
      ok: true, result: { name: NAME, operations: [...Object.keys(OPS), ...Object.keys(PLAIN_OPS)], profiles: PROFILES },
    };
  }
  const own = (table) => (Object.prototype.hasOwnProperty.call(table, op) ? table[op] : null);
  const plain = own(PLAIN_OPS);
  const fn = own(OPS);
  if (plain === null && (fn === null || !PROFILES.includes(req.profile))) return { ok: false, unsupported: true };
  try {
    return { ok: true, result: plain !== null ? plain(req) : fn(req, req.profile) };
  } catch (err) {
    if (err instanceof Rejection) return { ok: false, error: err.cls, detail: err.detail };
    if (err instanceof osdk.OsdkError) return { ok: false, error: err.errorClass, detail: err.message };
    throw err;
  }
}

module.exports = { BadRequest, PROFILES, answer, eventStream };
