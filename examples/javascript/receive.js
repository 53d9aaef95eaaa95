#!/usr/bin/env node
'use strict';
// receive PROFILE: the bytes on standard input through the library's
// receiver, one line per event (the format is tests/library_examples.py's).

const osdk = require('osdk-kaitai');

const profile = process.argv[2];
if (process.argv.length !== 3 || !osdk.PROFILES.includes(profile)) {
  process.stderr.write(`usage: receive.js PROFILE (one of ${osdk.PROFILES.join(', ')})\n`);
  process.exit(2);
}

function show(ev) {
  if (ev.kind === 'garbage') return console.log(`garbage ${ev.offset} ${ev.length}`);
  if (ev.kind === 'error') return console.log(`error ${ev.offset} ${ev.length} ${ev.errorClass}`);
  let frame;
  try {
    frame = osdk.decodeFrame(ev.raw, profile);
  } catch (err) {
    if (!(err instanceof osdk.OsdkError)) throw err;
    // err.field names the ksy field that failed, e.g. reserved_flags
    return console.log(`error ${ev.offset} ${ev.raw.length} ${err.errorClass}`);
  }
  if (frame.data === undefined) return console.log(`empty ${ev.offset} ${frame.seq}`);
  if (frame.isAck) return console.log(`ack ${ev.offset} ${frame.seq}`);
  if (!(frame.data instanceof osdk.OsdkFrame.FrameData)) return console.log(`encrypted ${ev.offset} ${frame.seq}`);
  console.log(`frame ${ev.offset} ${frame.seq} ${frame.data.cmdSet} ${frame.data.cmdId}`);
  const bc = osdk.broadcastOf(frame); // null unless a broadcast
  if (bc === null) return undefined;
  for (const item of bc.items) {
    const value = bc.item(item); // null: absent
    if (value === null) console.log(`  ${item} absent`);
    else if (item === 'battery') console.log(`  battery ${bc.battery}`);
    else if (item === 'time_stamp') console.log(`  time_stamp ${bc.timeStamp.time}`);
    else console.log(`  ${item} present`);
  }
  return undefined;
}

const receiver = new osdk.Deframer();
process.stdin.on('data', (chunk) => receiver.feed(chunk).forEach(show));
process.stdin.on('end', () => receiver.finish().forEach(show));
