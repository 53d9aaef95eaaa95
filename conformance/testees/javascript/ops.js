'use strict';
// The operations of conformance/PROTOCOL.md, as the Kaitai-Python testee
// (conformance/testees/kaitai_python_testee.py) does them: layouts, fields,
// enums and `valid` checks come from the generated parsers; CRCs, deframing,
// ACK matching, mode classification and ranges are glue over the tables.

const { tables } = require('./tables');
const { HEADER_LEN, Deframer, crc32Matches, frameLength, headerProblem, splitChunks } = require('./deframe');
const { OsdkFrame, Rejection, oneLine, parseControlMode, parseFrame, parsePayload } = require('./kaitai');
const { modelOf } = require('./model');

const NAME = 'osdk-kaitai-javascript';
const PROFILES = tables.profiles;
const AXIS_RANGE = { x: 'horizontal', y: 'horizontal', z: 'vertical', yaw: 'yaw' };
const PENDING_LIMIT = 1024; // unanswered commands remembered for ACK matching

const COMMAND_NAMES = new Map(tables.commands.map((c) => [`${c.cmd_set}.${c.cmd_id}`, c.name]));
const commandName = (cmdSet, cmdId) => COMMAND_NAMES.get(`${cmdSet}.${cmdId}`) || 'unknown';

class BadRequest extends Error {}
BadRequest.prototype.name = 'BadRequest';

// ---- arguments ------------------------------------------------------------------------

function arg(req, key, kind) {
  if (!Object.prototype.hasOwnProperty.call(req, key)) throw new BadRequest(`missing argument '${key}'`);
  const v = req[key];
  const ok = {
    integer: Number.isInteger(v),
    boolean: typeof v === 'boolean',
    string: typeof v === 'string',
    list: Array.isArray(v),
  }[kind];
  if (!ok) throw new BadRequest(`argument '${key}' must be a ${kind}`);
  return v;
}

function hexArg(req) {
  const text = arg(req, 'hex', 'string');
  if (!/^(?:[0-9a-fA-F]{2})*$/.test(text)) throw new BadRequest("argument 'hex' is not a hex string of whole bytes");
  return Buffer.from(text, 'hex');
}

function byteArg(req, key) {
  const v = arg(req, key, 'integer');
  if (v < 0 || v > 0xff) throw new BadRequest(`argument '${key}' must be 0..255`);
  return v;
}

// ---- operations -------------------------------------------------------------------------

function decodePayload(req, profile) {
  const data = hexArg(req);
  const cmdSet = byteArg(req, 'cmd_set');
  const cmdId = byteArg(req, 'cmd_id');
  const isAck = arg(req, 'is_ack', 'boolean');
  return { value: modelOf(parsePayload(data, cmdSet, cmdId, isAck, profile), data).body };
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
  const payload = parsePayload(data, 0x01, 0x03, false, profile);
  const value = modelOf(payload, data).body;
  const byte = data[0];
  const modes = tables.control_modes[profile];
  const mode = modes.modes[byte];
  if (mode.classification !== 'documented') {
    throw new Rejection('undefined_mode', `mode byte 0x${byte.toString(16).padStart(2, '0')} is ${mode.classification} on ${profile}`);
  }
  const ranges = modes.ranges[String(mode.combination)];
  for (const [axis, which] of Object.entries(AXIS_RANGE)) {
    const v = payload.body[axis]; // a double; a quieted NaN is still a NaN
    const { min, max } = ranges[which];
    if (!Number.isFinite(v) || (min !== null && v < min) || (max !== null && v > max)) {
      throw new Rejection('out_of_range', `${axis} = ${v} outside the ${which} range ${min}..${max}`);
    }
  }
  return { value, combination: mode.combination };
}

function decodeFrame(req, profile) {
  const data = hexArg(req);
  // The receiver's checks, in the order a receiver meets them.
  if (!data.length) throw new Rejection('truncated_frame', 'no bytes');
  if (data[0] !== 0xaa) throw new Rejection('bad_sof', `first byte 0x${data[0].toString(16)} is not the start byte`);
  if (data.length < HEADER_LEN) throw new Rejection('truncated_frame', `${data.length} bytes, less than a header`);
  const problem = headerProblem(data.subarray(0, HEADER_LEN));
  if (problem) throw new Rejection(problem[0], problem[1]);
  const length = frameLength(data);
  if (data.length < length) throw new Rejection('truncated_frame', `${data.length} bytes of a frame of LEN ${length}`);
  if (data.length > length) throw new Rejection('length_mismatch', `${data.length} bytes for LEN ${length}`);
  if (length > HEADER_LEN && !crc32Matches(data)) throw new Rejection('bad_crc32', 'CRC-32 does not match');
  return { frame: modelOf(parseFrame(data, profile), data) };
}

// Events of a stream: Deframer boundaries, Kaitai values, ACK matching.
// models = false leaves each value as Kaitai parsed it (the bench mode times
// decoding, not the value model).
class StreamDecoder {
  constructor(profile, models = true) {
    this.profile = profile;
    this.models = models;
    this.pending = new Map(); // "session.seq" -> [cmd_set, cmd_id], oldest first
  }

  event(ev) {
    if (ev.type === 'garbage') return { offset: ev.offset, kind: 'garbage', length: ev.length };
    if (ev.type === 'rejected') {
      return { offset: ev.offset, kind: 'error', error: ev.error, detail: ev.detail, length: ev.length };
    }
    try {
      return this.frame(ev);
    } catch (err) {
      if (err instanceof Rejection) {
        return { offset: ev.offset, kind: 'error', error: err.cls, detail: err.detail, length: ev.raw.length };
      }
      // Our bug must not cost the rest of the stream.
      return {
        offset: ev.offset, kind: 'error', error: 'undecodable',
        detail: `internal error (${err && err.name}: ${oneLine(err)})`, length: ev.raw.length,
      };
    }
  }

  frame(ev) {
    const f = parseFrame(ev.raw, this.profile);
    const out = { offset: ev.offset, kind: 'frame' };
    if (f.len > HEADER_LEN && f.data instanceof OsdkFrame.FrameData) {
      const key = `${f.session}.${f.seq}`;
      if (f.isAck) {
        const cmd = this.pending.get(key);
        if (cmd !== undefined) {
          this.pending.delete(key);
          out.ack_of = commandName(cmd[0], cmd[1]);
          let ack;
          try {
            ack = parsePayload(f.data.ackValue, cmd[0], cmd[1], true, this.profile);
          } catch (err) {
            if (!(err instanceof Rejection)) throw err;
            return {
              offset: ev.offset, kind: 'error', error: err.cls, detail: err.detail,
              length: ev.raw.length, ack_of: out.ack_of,
            };
          }
          out.ack = this.models ? modelOf(ack, f.data.ackValue).body : ack.body;
        }
      } else if (f.session > 0) {
        this.pending.set(key, [f.data.cmdSet, f.data.cmdId]);
        if (this.pending.size > PENDING_LIMIT) this.pending.delete(this.pending.keys().next().value);
      }
    }
    out.frame = this.models ? modelOf(f, ev.raw) : f;
    return out;
  }
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
  const deframer = new Deframer();
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

// The response to a request object with an "op" string. Throws BadRequest
// for arguments it cannot use; anything else thrown is a bug of ours.
function answer(req) {
  const { op } = req;
  if (op === 'capabilities') {
    return { ok: true, result: { name: NAME, operations: Object.keys(OPS), profiles: PROFILES } };
  }
  const fn = Object.prototype.hasOwnProperty.call(OPS, op) ? OPS[op] : null;
  if (fn === null || !PROFILES.includes(req.profile)) return { ok: false, unsupported: true };
  try {
    return { ok: true, result: fn(req, req.profile) };
  } catch (err) {
    if (err instanceof Rejection) return { ok: false, error: err.cls, detail: err.detail };
    throw err;
  }
}

module.exports = { BadRequest, PROFILES, answer, eventStream };
