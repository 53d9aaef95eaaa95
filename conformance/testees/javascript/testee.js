#!/usr/bin/env node
'use strict';
// The bundled "js" testee: the generated JavaScript library (generated/javascript:
// the Kaitai parsers of spec/*.ksy and the tools/libgen glue) behind the
// testee protocol of conformance/PROTOCOL.md. `osdkc run --impl js`; build with `make build`.
//
// The library is the npm package osdk-kaitai (a file: dependency on
// generated/javascript, installed by `make build`); it brings the Kaitai
// runtime with it, so plain Node module resolution finds everything.

if (process.argv.length > 2) {
  process.exitCode = require('./bench').main(process.argv.slice(2)); // --bench FILE --profile P (bench.js)
} else {
  serve();
}

// One JSON line in, one JSON line out (conformance/PROTOCOL.md). Input the
// testee cannot use is answered bad_request, a bug of its own internal_error:
// a failed case, never a dead testee (osdk_conformance/harness/serve.py).
function serve() {
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
