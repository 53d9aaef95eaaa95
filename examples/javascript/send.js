#!/usr/bin/env node
'use strict';
// send: one frame of each command an onboard computer sends, as NAME HEX
// (the arguments are tests/library_examples.py's SENT).

const osdk = require('osdk-kaitai');

const frames = [
  ['version_query', 2, 1, osdk.encodeVersionQuery(0)],
  ['activation', 2, 2, osdk.encodeActivation(1000001, 2, 0x03016400, Buffer.from('0123456789abcdef0123456789abcdef'))],
  ['set_frequency', 2, 3, osdk.encodeSetFrequency([1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 0, 0])],
  ['control_authority', 2, 4, osdk.encodeControlAuthority(1)],
  // a float setpoint is a number, or osdk.f32Bits(0x7fc00001) for exact bits
  ['movement_control', 0, 0x1234, osdk.encodeMovementControl(0x4b, 1.0, -2.0, 0.5, 30.0)],
];

for (const [name, session, seq, value] of frames) {
  const [cmdSet, cmdId] = osdk.COMMANDS[name];
  const frame = osdk.encodeFrame(cmdSet, cmdId, false, session, seq, value); // isAck false
  console.log(`${name} ${Buffer.from(frame).toString('hex')}`);
}
