'use strict';
// Where the generated artefacts are, and the derived tables
// (generated/tables/osdk_tables.json, written by tools/tables.py).

const fs = require('fs');
const path = require('path');

const ROOT = path.resolve(__dirname, '..', '..', '..');
const GENERATED_JS = path.join(ROOT, 'generated', 'javascript');
const tables = JSON.parse(fs.readFileSync(path.join(ROOT, 'generated', 'tables', 'osdk_tables.json'), 'utf8'));

module.exports = { GENERATED_JS, tables };
