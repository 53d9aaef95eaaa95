"""The golden vector generator behind tools/gen_vectors.py.

One module per vector file:
  control_mode.py    control_mode.json    classify_control_mode, every byte in every profile
  control_ranges.py  control_ranges.json  check_movement_control: range limits, special setpoints, precedence
  broadcast.py       broadcast.json       decode_payload of the broadcast: items, flag words, bounds
                     (broadcast_errata.py: its hand-written ERRATA cases about items)
  payloads.py        payloads.json        decode_payload of the other commands and ACKs
  frames.py          frames.json          decode_frame
  streams.py         streams.json         decode_stream
  encode.py          encode.json          encode_movement_control, encode_frame

The bug classes of osdk_conformance.harness.vector_tables, shared by the
frames and streams files: precedence.py (pairs of broken frame rules),
stream_errors.py, header_bits.py, acks.py (ACK situations and memory).

Shared: builder.py (Suite: every case is checked against the reference
as it is added), broadcast_values.py (broadcast values packed from the
Construct layout of each profile), wire.py (frames packed field by field),
scalars.py (float bits, enums), driver.py (writing and --check).
"""
