'use strict';
// The JSON value model of docs/VALUE-MODEL.md for generated objects, driven
// by tables.model (field ids in wire order, kinds, widths, enums), and a JSON
// writer that prints float values the way the Python tools do.
//
// Signalling NaNs. The runtime reads f4 through DataView.getFloat32, which
// widens to a double and sets the quiet bit of a signalling NaN on the way
// (f8 NaN payloads are not promised to survive V8 either). The model compares
// IEEE bits, so for every NaN the bits are re-read from the wire. While
// rendering, the walk tracks each field's byte offset in its object's stream,
// as the Python testee's restore_nan_bits does: every type here is fixed-size
// given what was read (primitives have their width, bit fields are packed and
// byte-aligned before the next byte-sized field, raw bytes the length read,
// `if`-false fields are absent, a sub-object with its own substream
// (`_raw_<field>`) starts at 0 of those bytes, any other sub-object continues
// in the parent's stream). As a guard against an offset error the wire bits
// must be the NaN Kaitai returned modulo the quiet bit, else it is an error.

const { tables } = require('./tables');
const { typeKeyOf } = require('osdk-kaitai');

const TYPES = tables.model.types;
const ENUMS = tables.model.enums;

// ksy field id -> the generated property name (Kaitai's lowerCamelCase).
const camelCache = new Map();
function camel(id) {
  let name = camelCache.get(id);
  if (name === undefined) {
    name = id.replace(/_([a-z0-9])/g, (_, c) => c.toUpperCase());
    camelCache.set(id, name);
  }
  return name;
}

// A float's "value" for people; FloatText lets dumps() print it like Python.
class FloatText {
  constructor(n) {
    this.n = n;
  }
}

function readable(n) {
  if (Number.isNaN(n)) return 'NaN';
  if (n === Infinity) return 'Infinity';
  if (n === -Infinity) return '-Infinity';
  return new FloatText(n);
}

const scratch = new DataView(new ArrayBuffer(8));

function bitsOfDouble(n, width) {
  if (width === 4) {
    scratch.setFloat32(0, n, true);
    return BigInt(scratch.getUint32(0, true));
  }
  scratch.setFloat64(0, n, true);
  return scratch.getBigUint64(0, true);
}

function floatFromBits(bits, width) {
  if (width === 4) {
    scratch.setUint32(0, Number(bits), true);
    return scratch.getFloat32(0, true);
  }
  scratch.setBigUint64(0, bits, true);
  return scratch.getFloat64(0, true);
}

function floatModel(bits, width) {
  const key = width === 4 ? 'f32' : 'f64';
  return { [key]: `0x${bits.toString(16).padStart(width * 2, '0')}`, value: readable(floatFromBits(bits, width)) };
}

function wireBits(wire, pos, width) {
  if (!wire || pos + width > wire.length) return null;
  let bits = 0n;
  for (let i = width - 1; i >= 0; i--) bits = (bits << 8n) | BigInt(wire[pos + i]);
  return bits;
}

function floatValue(v, width, id, wire, pos) {
  const seen = bitsOfDouble(v, width);
  if (!Number.isNaN(v)) return floatModel(seen, width);
  const wire_ = wireBits(wire, pos, width);
  const quiet = 1n << (width === 4 ? 22n : 51n);
  if (wire_ === null || (seen !== wire_ && seen !== (wire_ | quiet)) || !Number.isNaN(floatFromBits(wire_, width))) {
    throw new Error(`NaN bit recovery for ${id} at offset ${pos} read ${wire_ === null ? 'nothing' : `0x${wire_.toString(16)}`}, `
      + `Kaitai read 0x${seen.toString(16)}`);
  }
  return floatModel(wire_, width);
}

function hexOf(bytes) {
  return Buffer.from(bytes.buffer, bytes.byteOffset, bytes.length).toString('hex');
}

function enumModel(value, key) {
  const names = ENUMS[key] || {};
  return { value, name: Object.prototype.hasOwnProperty.call(names, String(value)) ? names[String(value)] : null };
}

// Model of one element of field `f` of `owner` starting at `pos` of `wire`:
// [model, end position].
function element(v, f, owner, raw, wire, pos) {
  if (f.kind === 'float') return [floatValue(v, f.width, f.id, wire, pos), pos + f.width];
  if (typeof v === 'boolean') return [v, pos];
  if (typeof v === 'number') {
    const m = f.enum ? enumModel(v, f.enum) : v;
    return [m, f.kind === 'int' ? pos + f.width : pos];
  }
  if (v instanceof Uint8Array) return [hexOf(v), pos + v.length];
  if (typeKeyOf(v) !== null) {
    if (raw instanceof Uint8Array) return [structModel(v, raw, 0)[0], pos + raw.length];
    return structModel(v, wire, pos);
  }
  throw new TypeError(`no model for field ${f.id} (${Object.prototype.toString.call(v)})`);
}

// [model, end position] of a generated object that starts at `pos` of `wire`.
function structModel(obj, wire, pos) {
  const key = typeKeyOf(obj);
  const out = {};
  let bits = 0;
  for (const f of TYPES[key].fields) {
    const name = camel(f.id);
    const v = obj[name];
    if (v === undefined) continue; // `if` was false
    if (f.kind === 'bits' || f.kind === 'bool') {
      bits += f.width_bits;
      out[f.id] = f.enum ? enumModel(v, f.enum) : v;
      continue;
    }
    pos += Math.ceil(bits / 8);
    bits = 0;
    const raw = obj[`_raw_${name}`];
    if (f.repeat) {
      out[f.id] = v.map((e, i) => {
        const [m, end] = element(e, f, obj, Array.isArray(raw) ? raw[i] : undefined, wire, pos);
        pos = end;
        return m;
      });
    } else {
      [out[f.id], pos] = element(v, f, obj, raw, wire, pos);
    }
  }
  return [out, pos + Math.ceil(bits / 8)];
}

// The model of a generated object parsed from all of `wire`.
function modelOf(obj, wire) {
  return structModel(obj, wire, 0)[0];
}

// ---- JSON text ----------------------------------------------------------------------

// Python's repr of a float: shortest round trip, always with a fraction or
// exponent, exponent of at least two digits, -0.0 kept.
function floatText(n) {
  if (Object.is(n, -0)) return '-0.0';
  const a = Math.abs(n);
  if (a !== 0 && (a >= 1e16 || a < 1e-4)) {
    return n.toExponential().replace(/e([+-])(\d)$/, 'e$10$2');
  }
  const s = String(n);
  return /[.e]/.test(s) ? s : `${s}.0`;
}

function dumps(v) {
  if (v instanceof FloatText) return floatText(v.n);
  if (v === null || typeof v === 'boolean' || typeof v === 'string') return JSON.stringify(v);
  if (typeof v === 'number') {
    if (!Number.isFinite(v)) throw new TypeError(`bare ${v} in a model`);
    return JSON.stringify(v);
  }
  if (Array.isArray(v)) return `[${v.map(dumps).join(',')}]`;
  if (typeof v === 'object') {
    const parts = [];
    for (const [k, x] of Object.entries(v)) {
      if (x !== undefined) parts.push(`${JSON.stringify(k)}:${dumps(x)}`);
    }
    return `{${parts.join(',')}}`;
  }
  throw new TypeError(`cannot write ${typeof v} as JSON`);
}

module.exports = { dumps, modelOf };
