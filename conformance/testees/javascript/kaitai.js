'use strict';
// The Kaitai-generated parsers (generated/javascript) and how their
// exceptions become error classes of docs/VALUE-MODEL.md.

const fs = require('fs');
const path = require('path');
// Resolved through NODE_PATH (see testee.js) so that this is the very module
// instance the generated files require: `instanceof` on its errors must hold.
const KaitaiStream = require('kaitai-struct/KaitaiStream');
const { GENERATED_JS, tables } = require('./tables');

const MODEL = tables.model;

function loadModule(name) {
  return require(path.join(GENERATED_JS, `${name}.js`))[name];
}

const OsdkFrame = loadModule('OsdkFrame');
const OsdkPayload = loadModule('OsdkPayload');
const OsdkControlMode = loadModule('OsdkControlMode');

// Generated class -> ksy type key ("file" or "file.subtype"), from class_path.
const TYPE_OF_CLASS = new Map();
for (const [key, t] of Object.entries(MODEL.types)) {
  let cls = loadModule(t.class_path[0]);
  for (const part of t.class_path.slice(1)) cls = cls && cls[part];
  if (typeof cls !== 'function') throw new Error(`no generated class ${t.class_path.join('.')} for ${key}`);
  TYPE_OF_CLASS.set(cls, key);
}

function typeKeyOf(obj) {
  return obj !== null && typeof obj === 'object' ? TYPE_OF_CLASS.get(obj.constructor) : undefined;
}

class Rejection extends Error {
  constructor(cls, detail) {
    super(detail);
    this.cls = cls;
    this.detail = detail;
  }
}

// The value the generated parsers take for a profile id.
function profileValue(name) {
  const value = tables.profile_values[name];
  if (OsdkPayload.Profile[value] === undefined) {
    throw new Error(`profile ${name} has no value of the enum osdk_payload.profile`);
  }
  return value;
}

// ---- Kaitai exceptions -> error classes ------------------------------------------

const VALIDATION_ERRORS = Object.keys(KaitaiStream)
  .filter((k) => /^Validation\w+Error$/.test(k))
  .map((k) => KaitaiStream[k]);

const sourceLines = new Map(); // generated file -> its lines

function linesOf(file) {
  if (!sourceLines.has(file)) sourceLines.set(file, fs.readFileSync(file, 'utf8').split('\n'));
  return sourceLines.get(file);
}

// V8's structured call sites of an error (https://v8.dev/docs/stack-trace-api).
// Read before anything formats `stack`: V8 builds it on first access.
function callSites(err) {
  const saved = Error.prepareStackTrace;
  Error.prepareStackTrace = (_, sites) => sites;
  try {
    const sites = err.stack;
    return Array.isArray(sites) ? sites : [];
  } finally {
    Error.prepareStackTrace = saved;
  }
}

// Generated file stem + class name -> ksy type key. V8 names a frame's
// receiver by its constructor's own name only, so a nested class is told by
// the file it lives in; a name that is not unique there maps to null.
const TYPE_AT_SITE = new Map();
for (const [key, t] of Object.entries(MODEL.types)) {
  const id = `${t.class_path[0]}/${t.class_path[t.class_path.length - 1]}`;
  TYPE_AT_SITE.set(id, TYPE_AT_SITE.has(id) ? null : key);
}

// [type key, ksy field id] whose `valid` check raised `err`, or null.
//
// The 0.11.0 runtime's Validation*Error constructors take (expected, actual)
// only, so the io and src_path ("/seq/N") the generated code passes are
// dropped. Both can be read at the throw site instead: the innermost stack
// frame in a generated file is the raising object's _read, V8 names that
// frame's receiver type, and the source line it threw from holds the literal
// src_path. This is the Python testee's traceback walk, done with V8's
// call-site API. (The receiver itself is not available: the runtime is strict
// code, and V8 hides `this` of every frame below a strict one.)
function raisingField(err) {
  const site = callSites(err).find((s) => {
    const file = s.getFileName();
    return file && path.dirname(file) === GENERATED_JS;
  });
  if (!site) return null;
  const file = site.getFileName();
  const key = TYPE_AT_SITE.get(`${path.basename(file, '.js')}/${site.getTypeName()}`);
  const m = /"\/seq\/(\d+)"/.exec(linesOf(file)[site.getLineNumber() - 1] || '');
  if (!key || !m) return null;
  const { seq } = MODEL.types[key];
  const n = Number(m[1]);
  return n < seq.length ? [key, seq[n]] : null;
}

function oneLine(err) {
  return String(err && err.message !== undefined ? err.message : err).replace(/\s+/g, ' ').trim();
}

function rejection(err) {
  if (VALIDATION_ERRORS.some((cls) => err instanceof cls)) {
    const where = raisingField(err);
    const cls = (where && tables.error_by_field[where[1]]) || 'undecodable';
    return new Rejection(cls, `${where ? where.join(': ') : 'unknown field'}: ${err.name}: ${oneLine(err)}`);
  }
  if (err instanceof KaitaiStream.EOFError) return new Rejection('truncated_payload', oneLine(err));
  return new Rejection('undecodable', `${err && err.name}: ${oneLine(err)}`);
}

// make(stream) with Kaitai errors turned into a Rejection.
function parse(make, bytes) {
  try {
    return make(new KaitaiStream(new Uint8Array(bytes.buffer, bytes.byteOffset, bytes.length)));
  } catch (err) {
    throw rejection(err);
  }
}

const parseFrame = (raw, profile) => parse((io) => new OsdkFrame(io, null, null, profileValue(profile)), raw);

const parsePayload = (bytes, cmdSet, cmdId, isAck, profile) =>
  parse((io) => new OsdkPayload(io, null, null, cmdSet, cmdId, isAck, profileValue(profile)), bytes);

const parseControlMode = (byte) => parse((io) => new OsdkControlMode(io, null, null), Buffer.from([byte]));

module.exports = {
  OsdkFrame, Rejection, oneLine, parseControlMode, parseFrame, parsePayload, typeKeyOf,
};
