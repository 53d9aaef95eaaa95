'use strict';
// Frame-layer receiver logic that a .ksy cannot express: the two CRCs and
// the SDK-like hunt for frames in a byte stream. A port of
// osdk_conformance/core/deframe.py (same check order, same rescans, same events),
// so that every bundled testee meets the same receiver.

const { tables } = require('./tables');

const SOF = 0xaa;
const HEADER_LEN = 12;
const CRC32_LEN = 4;
const MAX_LEN = 0x3ff;

// ---- CRC ------------------------------------------------------------------------------

function reflectBits(value, width) {
  let out = 0;
  for (let i = 0; i < width; i++) {
    if (value & (2 ** i)) out += 2 ** (width - 1 - i);
  }
  return out;
}

// A table-driven CRC from the tables' parameters. `init` is the register's
// start value as the SDK code holds it, i.e. already in the register's own
// bit order, so it is used as is for either direction.
function makeCrc(p) {
  const { width } = p;
  const mask = width === 32 ? 0xffffffff : (1 << width) - 1;
  const table = new Uint32Array(256);
  if (p.reflect_in) {
    const poly = reflectBits(p.poly, width);
    for (let n = 0; n < 256; n++) {
      let c = n;
      for (let k = 0; k < 8; k++) c = c & 1 ? (c >>> 1) ^ poly : c >>> 1;
      table[n] = c >>> 0;
    }
  } else {
    const top = 2 ** (width - 1);
    for (let n = 0; n < 256; n++) {
      let c = (n * 2 ** (width - 8)) >>> 0;
      for (let k = 0; k < 8; k++) c = (c & top ? ((c << 1) ^ p.poly) : c << 1) & mask;
      table[n] = c >>> 0;
    }
  }
  const crc = (data) => {
    let c = p.init >>> 0;
    if (p.reflect_in) {
      for (const b of data) c = (table[(c ^ b) & 0xff] ^ (c >>> 8)) >>> 0;
    } else {
      for (const b of data) c = (table[((c >>> (width - 8)) ^ b) & 0xff] ^ (c << 8)) & mask;
    }
    if (p.reflect_in !== p.reflect_out) c = reflectBits(c, width);
    return ((c ^ p.xorout) & mask) >>> 0;
  };
  // Wrong parameters would reject every frame; fail at start-up instead.
  const got = crc(Buffer.from('123456789', 'ascii'));
  if (got !== p.check) {
    throw new Error(`CRC-${width} check value is 0x${got.toString(16)}, the tables say 0x${p.check.toString(16)}`);
  }
  return crc;
}

const crc16 = makeCrc(tables.crc.crc16);
const crc32 = makeCrc(tables.crc.crc32);

function crc32Matches(raw) {
  const n = raw.length - CRC32_LEN;
  return crc32(raw.subarray(0, n)) === raw.readUInt32LE(n);
}

// ---- header ---------------------------------------------------------------------------

const hex = (n, digits) => n.toString(16).padStart(digits, '0');

function frameLength(header) {
  return (header[1] | (header[2] << 8)) & 0x3ff;
}

// [error class, detail] of the first thing wrong with a 12-byte header, or
// null. CRC-16 comes first: when it fails, the other fields mean nothing.
function headerProblem(header) {
  const stored = header[10] | (header[11] << 8);
  const computed = crc16(header.subarray(0, 10));
  if (computed !== stored) return ['bad_crc16', `CRC-16 is 0x${hex(stored, 4)}, expected 0x${hex(computed, 4)}`];
  const word = header[1] | (header[2] << 8);
  const length = word & 0x3ff;
  const ver = word >> 10;
  if (ver !== 0) return ['bad_version', `header version ${ver}, must be 0`];
  if (header[3] >> 6) return ['reserved_bits', `RES0 is ${header[3] >> 6}, must be 0`];
  if (header[5] || header[6] || header[7]) {
    return ['reserved_bits', `RES1 is 0x${hex(header[7], 2)}${hex(header[6], 2)}${hex(header[5], 2)}, must be 0`];
  }
  if (length < HEADER_LEN || (length > HEADER_LEN && length <= HEADER_LEN + CRC32_LEN)) {
    return ['impossible_length', `LEN ${length} is impossible (12, or 17 to ${MAX_LEN})`];
  }
  return null;
}

// ---- the streaming receiver -------------------------------------------------------------

// Events: {type: 'frame', offset, raw} | {type: 'rejected', offset, error, detail, length}
//       | {type: 'garbage', offset, length}. Offsets are absolute.
class Deframer {
  constructor() {
    this.buf = Buffer.alloc(0);
    this.base = 0; // absolute offset of buf[0]
    this.garbageStart = null;
  }

  feed(chunk) {
    this.buf = this.buf.length ? Buffer.concat([this.buf, chunk]) : Buffer.from(chunk);
    return this.scan(false);
  }

  finish() {
    return this.scan(true);
  }

  drop(n) {
    this.buf = this.buf.subarray(n);
    this.base += n;
  }

  flushGarbage(events) {
    if (this.garbageStart !== null) {
      events.push({ type: 'garbage', offset: this.garbageStart, length: this.base - this.garbageStart });
      this.garbageStart = null;
    }
  }

  scan(final) {
    const events = [];
    while (this.buf.length) {
      const buf = this.buf;
      if (buf[0] !== SOF) {
        const next = buf.indexOf(SOF);
        if (this.garbageStart === null) this.garbageStart = this.base;
        this.drop(next < 0 ? buf.length : next);
        continue;
      }
      this.flushGarbage(events);
      if (buf.length < HEADER_LEN) {
        if (!final) break;
        events.push(this.truncated(null));
        continue;
      }
      const problem = headerProblem(buf.subarray(0, HEADER_LEN));
      if (problem) {
        events.push({ type: 'rejected', offset: this.base, error: problem[0], detail: problem[1], length: 1 });
        this.drop(1);
        continue;
      }
      const length = frameLength(buf);
      if (buf.length < length) {
        if (!final) break;
        events.push(this.truncated(length));
        continue;
      }
      const raw = Buffer.from(buf.subarray(0, length));
      if (length > HEADER_LEN && !crc32Matches(raw)) {
        const stored = raw.readUInt32LE(length - CRC32_LEN);
        const computed = crc32(raw.subarray(0, length - CRC32_LEN));
        events.push({
          type: 'rejected', offset: this.base, error: 'bad_crc32',
          detail: `CRC-32 is 0x${hex(stored, 8)}, expected 0x${hex(computed, 8)}`, length,
        });
        this.drop(1);
        continue;
      }
      events.push({ type: 'frame', offset: this.base, raw });
      this.drop(length);
    }
    if (final) this.flushGarbage(events);
    return events;
  }

  // At the end of the input a started frame can no longer complete. Report
  // it, then rescan after its start byte like any rejection, so a shorter
  // frame inside it is still found.
  truncated(length) {
    const have = this.buf.length;
    const want = length ? `LEN ${length}` : 'a 12-byte header';
    const event = {
      type: 'rejected', offset: this.base, error: 'truncated_frame',
      detail: `input ended after ${have} byte(s) of ${want}`, length: have,
    };
    this.drop(1);
    return event;
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

module.exports = { HEADER_LEN, Deframer, crc32Matches, frameLength, headerProblem, splitChunks };
