'use strict';
// The derived tables the library does not carry (generated/tables/osdk_tables.json,
// written by tools/tables.py): the value model's field kinds and enums, and
// the control mode classification with its setpoint ranges.

const fs = require('fs');
const path = require('path');

const ROOT = path.resolve(__dirname, '..', '..', '..');
const tables = JSON.parse(fs.readFileSync(path.join(ROOT, 'generated', 'tables', 'osdk_tables.json'), 'utf8'));

module.exports = { tables };
