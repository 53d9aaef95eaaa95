'use strict';
// The bench mode (conformance/PROTOCOL.md): `testee.js --bench FILE --profile P`
// runs FILE (standard input for `-`) in reads of at most 64 KiB through
// decode_stream's own loop (ops.eventStream) without value models, keeps
// only counters, and prints one JSON line with the counts and the seconds of
// the loop. Bad arguments or unreadable input: one stderr line, exit 2.

const fs = require('fs');
const { PROFILES, eventStream } = require('./ops');

const IMPL = 'js';
const READ_SIZE = 64 * 1024;
const USAGE = 'usage: --bench FILE|- --profile P';

class BenchError extends Error {}

// [file, profile] from `--bench FILE --profile P` in either order.
function parseArgs(argv) {
  const opts = new Map();
  for (let i = 0; i < argv.length; i += 2) {
    const key = argv[i];
    if (key !== '--bench' && key !== '--profile') throw new BenchError(`unknown argument '${key}'; ${USAGE}`);
    if (i + 1 >= argv.length) throw new BenchError(`${key} needs a value; ${USAGE}`);
    if (opts.has(key)) throw new BenchError(`${key} given twice; ${USAGE}`);
    opts.set(key, argv[i + 1]);
  }
  if (!opts.has('--bench') || !opts.has('--profile')) throw new BenchError(USAGE);
  const profile = opts.get('--profile');
  if (!PROFILES.includes(profile)) {
    throw new BenchError(`unknown profile '${profile}' (known: ${PROFILES.join(', ')})`);
  }
  return [opts.get('--bench'), profile];
}

const waitCell = new Int32Array(new SharedArrayBuffer(4));

function readSome(fd, buf) {
  for (;;) {
    try {
      return fs.readSync(fd, buf, 0, buf.length, null);
    } catch (err) {
      // An inherited non-blocking stdin has no data yet: wait a moment rather than spin.
      if (err.code !== 'EAGAIN') throw err;
      Atomics.wait(waitCell, 0, 0, 1);
    }
  }
}

function bench(path, profile) {
  const cannot = (err) => new BenchError(`cannot read ${path}: ${err.message}`);
  let fd;
  try {
    fd = path === '-' ? 0 : fs.openSync(path, 'r');
  } catch (err) {
    throw cannot(err);
  }
  const counts = { frames: 0, errors: 0, garbage_bytes: 0 };
  const stream = eventStream(profile, false, (ev) => {
    if (ev.kind === 'frame') counts.frames += 1;
    else if (ev.kind === 'error') counts.errors += 1;
    else counts.garbage_bytes += ev.length;
  });
  // The deframer copies what it keeps, so one read buffer serves every read.
  const buf = Buffer.allocUnsafe(READ_SIZE);
  let bytes = 0;
  const start = process.hrtime.bigint(); // monotonic
  try {
    for (let n; (n = readSome(fd, buf)) > 0;) {
      bytes += n;
      stream.feed(buf.subarray(0, n));
    }
  } catch (err) {
    if (err instanceof BenchError || !err.code) throw err;
    throw cannot(err);
  } finally {
    if (fd !== 0) fs.closeSync(fd);
  }
  stream.finish();
  const seconds = Number(process.hrtime.bigint() - start) / 1e9;
  return { profile, bytes, ...counts, seconds: Math.round(seconds * 1e6) / 1e6 };
}

// The exit status of the bench mode.
function main(argv) {
  let result;
  try {
    const [path, profile] = parseArgs(argv);
    result = bench(path, profile);
  } catch (err) {
    if (!(err instanceof BenchError)) throw err;
    process.stderr.write(`${IMPL} --bench: ${err.message}\n`);
    return 2;
  }
  process.stdout.write(`${JSON.stringify({ impl: IMPL, ...result })}\n`);
  return 0;
}

module.exports = { main };
