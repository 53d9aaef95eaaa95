#!/usr/bin/env node
// Compile .ksy files with the pinned kaitai-struct-compiler npm package.
//
// usage: node compile.js --target LANG --out DIR [--python-package PKG]
//        [--go-package PKG] [--java-package PKG] FILE.ksy...
//
// The npm build of the compiler offers only a JS API, and that API silently
// drops style warnings (it throws on errors only). We need "compiles with no
// warnings" to be checkable, so this driver loads the compiler source with a
// one-line hook at the place where precompile problems are collected, prints
// every problem, and exits non-zero if there was any warning or error.
'use strict';
const fs = require('fs');
const path = require('path');
const Module = require('module');
const yaml = require('js-yaml');

function fail(msg) {
  process.stderr.write(`ksc: ${msg}\n`);
  process.exit(2);
}

function parseArgs(argv) {
  const opts = { files: [], target: null, out: null, pythonPackage: '', goPackage: '', javaPackage: '' };
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    if (a === '--target') opts.target = argv[++i];
    else if (a === '--out') opts.out = argv[++i];
    else if (a === '--python-package') opts.pythonPackage = argv[++i];
    else if (a === '--go-package') opts.goPackage = argv[++i];
    else if (a === '--java-package') opts.javaPackage = argv[++i];
    else if (a.startsWith('--')) fail(`unknown option ${a}`);
    else opts.files.push(a);
  }
  if (!opts.target || !opts.out || opts.files.length === 0) {
    fail('usage: compile.js --target LANG --out DIR [--python-package PKG] [--go-package PKG] [--java-package PKG] FILE.ksy...');
  }
  return opts;
}

// Anchor in kaitai-struct-compiler 0.11.0: the list of precompile problems
// just before the JS API discards the warnings among them.
const ANCHOR = 'var problems = $as_sc_Iterable(problems$2);';

// Anchor in kaitai-struct-compiler 0.11.0: the runtime configuration the JS
// API builds for every compile, with the Go package and the Java package
// hard-wired to "" (no `package` clause, which is not valid Go). The hook lets
// the command line choose them, as the compiler's own CLI does with
// --go-package and --java-package.
const CONFIG_ANCHOR = 'var config = new $c_Lio_kaitai_struct_RuntimeConfig((!debug), debug, false, true, false, new $c_Lio_kaitai_struct_CppRuntimeConfig($m_sci_Nil$(), false, false, false, $m_Lio_kaitai_struct_CppRuntimeConfig$RawPointers$()), "", new $c_Lio_kaitai_struct_JavaRuntimeConfig("", ';
const CONFIG_HOOKED = 'var config = new $c_Lio_kaitai_struct_RuntimeConfig((!debug), debug, false, true, false, new $c_Lio_kaitai_struct_CppRuntimeConfig($m_sci_Nil$(), false, false, false, $m_Lio_kaitai_struct_CppRuntimeConfig$RawPointers$()), globalThis.__kscGoPackage, new $c_Lio_kaitai_struct_JavaRuntimeConfig(globalThis.__kscJavaPackage, ';

function loadCompiler() {
  const file = require.resolve('kaitai-struct-compiler');
  const src = fs.readFileSync(file, 'utf8');
  if (src.split(ANCHOR).length !== 2) {
    fail('cannot find the problem-reporting hook in kaitai-struct-compiler; is it version 0.11.0?');
  }
  if (src.split(CONFIG_ANCHOR).length !== 2) {
    fail('cannot find the runtime-configuration hook in kaitai-struct-compiler; is it version 0.11.0?');
  }
  // split/join, not replace: the compiled source is full of `$`.
  const hooked = src.split(CONFIG_ANCHOR).join(CONFIG_HOOKED).replace(ANCHOR,
    ANCHOR + ' if (globalThis.__kscProblems) { $n(problems).foreach__F1__V(new $c_sjsr_AnonFunction1((p) => { globalThis.__kscProblems(p); })); }');
  const m = new Module(file, module);
  m.filename = file;
  m.paths = Module._nodeModulePaths(path.dirname(file));
  m._compile(hooked, file);
  const exported = m.exports;
  return typeof exported === 'function' ? new exported() : exported;
}

function loadKsy(file) {
  try {
    return yaml.load(fs.readFileSync(file, 'utf8'));
  } catch (e) {
    fail(`${file}: ${e.message}`);
  }
}

async function main() {
  const opts = parseArgs(process.argv.slice(2));
  globalThis.__kscGoPackage = opts.goPackage;
  globalThis.__kscJavaPackage = opts.javaPackage;
  const compiler = loadCompiler();
  let problems = 0;
  globalThis.__kscProblems = (p) => {
    problems += 1;
    const sev = String(p.severity__Lio_kaitai_struct_problems_ProblemSeverity()).replace(/\$$/, '');
    process.stderr.write(`ksc: ${sev}: ${p.message__T()}\n`);
  };
  fs.mkdirSync(opts.out, { recursive: true });
  const written = [];
  for (const file of opts.files) {
    const dir = path.dirname(path.resolve(file));
    // Imports are resolved relative to the importing file, like ksc does.
    const importer = {
      importYaml: (name) => Promise.resolve(loadKsy(path.join(dir, `${name}.ksy`))),
    };
    let files;
    try {
      files = await compiler.compile(opts.target, loadKsy(file), importer, false);
    } catch (e) {
      fail(`${file}: ${String(e).replace(/^io\.kaitai\.struct\.problems\.CompilationProblemException: /, '')}`);
    }
    for (const [name, contents] of Object.entries(files).sort()) {
      let text = contents;
      if (opts.pythonPackage && opts.target === 'python') {
        // Generated modules import their siblings by bare name; inside a
        // package they must import them through it (`--python-package .`:
        // relative to it, so the package works under any name).
        text = text.replace(/^import ([a-z_][a-z0-9_]*)$/gm, (line, mod) =>
          (fs.existsSync(path.join(dir, `${mod}.ksy`)) ? `from ${opts.pythonPackage} import ${mod}` : line));
      }
      const dest = path.join(opts.out, name);
      fs.mkdirSync(path.dirname(dest), { recursive: true });
      fs.writeFileSync(dest, text);
      written.push(dest);
    }
  }
  if (problems > 0) fail(`${problems} problem(s) reported; the spec must compile cleanly`);
  process.stdout.write(`ksc ${compiler.version}: ${written.length} file(s) for ${opts.target}\n`);
}

main().catch((e) => fail(String(e && e.stack || e)));
