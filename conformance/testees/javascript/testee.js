#!/usr/bin/env node
'use strict';
// The bundled "js" testee: the Kaitai-generated JavaScript parsers
// (generated/javascript, compiled from spec/*.ksy) behind the testee protocol
// of conformance/PROTOCOL.md. `osdkc run --impl js`; build with `make build`.
//
// Module resolution. The generated modules do require('kaitai-struct/KaitaiStream'),
// which Node resolves from generated/javascript upwards, where there is no
// node_modules, and generated code is never edited nor is anything put beside
// it. The runtime lives in this directory's node_modules (npm ci). NODE_PATH
// is Node's documented way to add a resolution root, but Node reads it only at
// start-up; so when it does not name our node_modules yet, this script runs
// itself once more with it set (sharing stdin/stdout/stderr) rather than
// reaching into Node's private loader functions.

const path = require('path');

const RUNTIME = path.join(__dirname, 'node_modules');
const nodePath = (process.env.NODE_PATH || '').split(path.delimiter).filter(Boolean);

if (!nodePath.includes(RUNTIME)) {
  const { spawnSync } = require('child_process');
  const env = { ...process.env, NODE_PATH: [RUNTIME, ...nodePath].join(path.delimiter) };
  const run = spawnSync(process.execPath, [...process.execArgv, __filename, ...process.argv.slice(2)],
    { stdio: 'inherit', env });
  if (run.error) {
    process.stderr.write(`cannot start ${process.execPath}: ${run.error.message}\n`);
    process.exit(1);
  }
  if (run.signal) process.kill(process.pid, run.signal);
  process.exit(run.status === null ? 1 : run.status);
} else if (process.argv.length > 2) {
  process.exitCode = require('./bench').main(process.argv.slice(2)); // --bench FILE --profile P (bench.js)
} else {
  serve();
}

// One JSON line in, one JSON line out (conformance/PROTOCOL.md). Input the
// testee cannot use is answered bad_request, a bug of its own internal_error:
// a failed case, never a dead testee (osdk_conformance/harness/serve.py).
function serve() {
  // The call-site walk that names a failed `valid` check needs the frames up
  // to the generated _read; the default of 10 is enough today, this is slack.
  Error.stackTraceLimit = 50;
  const readline = require('readline');
  const { BadRequest, answer } = require('./ops');
  const { dumps } = require('./model');

  const respond = (line) => {
    let res;
    try {
      let req;
      try {
        req = JSON.parse(line);
      } catch (err) {
        throw new BadRequest(`${err.name}: ${err.message}`);
      }
      if (req === null || typeof req !== 'object' || Array.isArray(req) || typeof req.op !== 'string') {
        throw new BadRequest('a request is a JSON object with an "op" string');
      }
      res = answer(req);
    } catch (err) {
      const cls = err instanceof BadRequest ? 'bad_request' : 'internal_error';
      res = { ok: false, error: cls, detail: `${err && err.name}: ${err && err.message}` };
    }
    let text;
    try {
      text = dumps(res);
    } catch (err) {
      text = JSON.stringify({ ok: false, error: 'internal_error', detail: `unserialisable answer: ${err.message}` });
    }
    process.stdout.write(`${text}\n`);
  };

  const lines = readline.createInterface({ input: process.stdin, crlfDelay: Infinity });
  lines.on('line', (line) => {
    if (line.trim()) respond(line);
  });
}
