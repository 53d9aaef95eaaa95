meta:
  id: osdk_frame
  title: DJI Onboard SDK OPEN protocol v1 - serial frame
  application: DJI Onboard SDK, UART between onboard device and flight controller
  license: CC0-1.0
  ks-version: '0.11'
  endian: le
  bit-endian: le
  imports:
    - osdk_payload
doc: |
  One frame of the OPEN protocol. A 12-byte header (start byte 0xAA, a u2
  holding the 10-bit whole-frame length and the 6-bit header version,
  session/ACK bits, padding/encryption bits, 3 reserved bytes, a sequence
  number and a CRC-16 over the first 10 bytes) is followed, unless the frame
  is header-only (LEN = 12), by DATA and a CRC-32 over everything before
  it. A command frame's DATA starts with command set and id; an ACK frame's
  DATA is the value alone.

  What this description does not check, and a receiver must: both CRCs (the
  parameters are in rules.yaml, crc), decryption of AES frames (ENC = 1; the
  data is kept as ciphertext here), and the resynchronising search for the
  start of a frame in a byte stream (rules.yaml, frame.receiver).
  LEN 13 to 15 is impossible (a frame with DATA has at least 12 + 0 + 4 bytes
  and LEN = 16 means an empty DATA with a CRC-32, which is also rejected).
doc-ref:
  - osdk-conformance shared/reference/PROTOCOL-FACTS.md section 1
  - https://github.com/dji-sdk/Onboard-SDK/blob/3.1.9/osdk-core/src/DJI_Codec.cpp
  - https://github.com/dji-sdk/Onboard-SDK/blob/3.1.9/doc/en/OPENProtocol.md
params:
  - id: profile
    type: u1
    enum: osdk_payload::profile
    doc: Broadcast wire profile, used to decode flight data frames.
seq:
  - id: sof
    contents: [0xaa]
    doc: Start of frame.
  - id: len
    type: b10
    valid:
      expr: _ == 12 or _ >= 17
    doc: Length of the whole frame in bytes, header and CRC-32 included.
  - id: ver
    type: b6
    valid: 0
    doc: Header version, always 0.
  - id: session
    type: b5
    doc: 0 no ACK wanted; 1 ACK wanted, loss tolerated; 2-31 ACK required.
  - id: is_ack
    type: b1
    valid:
      expr: not _ or session != 0
    doc: |
      true for an ACK frame, false for a command frame. A session-0 command
      wants no ACK, so an ACK never has session 0 (ERRATA E24).
  - id: res0
    type: b2
    valid: 0
    doc: Reserved, 0.
  - id: padding
    type: b5
    doc: Number of AES padding bytes at the end of DATA (0 when plain).
  - id: enc
    type: b3
    enum: encryption
    valid:
      expr: (_ == encryption::plain and padding == 0) or (_ == encryption::aes256 and padding >= 1 and padding <= 16 and len > 16 and (len - 16) % 16 == 0)
    doc: |
      Encryption of DATA. Plain DATA has no padding; AES DATA is whole
      16-byte blocks with 1 to 16 bytes of padding (ERRATA E23).
  - id: res1
    type: b24
    valid: 0
    doc: Reserved, 0.
  - id: seq
    type: u2
    doc: Sequence number; an ACK repeats the SEQ of its command.
  - id: crc16
    type: u2
    doc: CRC-16 over bytes 0-9 (rules.yaml crc.crc16), little-endian.
  - id: data
    size: len - 16
    if: len > 12
    doc: DATA; decoded when plain, kept as ciphertext when encrypted.
    type:
      switch-on: enc
      cases:
        encryption::plain: frame_data
  - id: crc32
    type: u4
    if: len > 12
    doc: CRC-32 over every byte before it (rules.yaml crc.crc32), little-endian.
instances:
  header_only:
    value: len == 12
    doc: true for a 12-byte frame with neither DATA nor CRC-32.
  crc16_covered:
    pos: 0
    size: 10
    doc: The bytes CRC-16 is computed over.
  crc32_covered:
    pos: 0
    size: len - 4
    if: len > 12
    doc: The bytes CRC-32 is computed over.
types:
  frame_data:
    doc: Plain DATA of a command frame (set, id, value) or an ACK frame (value).
    seq:
      - id: cmd_set
        type: u1
        enum: command_set
        if: not _parent.is_ack
        doc: Command set.
      - id: cmd_id
        type: u1
        if: not _parent.is_ack
        doc: Command id within the set.
      - id: value
        # the number read again: Java keeps an enum value without a name as null
        type: osdk_payload(cmd_set_code, cmd_id, false, _root.profile)
        size-eos: true
        if: not _parent.is_ack
        doc: The command's value, typed by set and id.
      - id: ack_value
        size-eos: true
        if: _parent.is_ack
        doc: |
          An ACK's value, raw: only the command it answers (matched by SEQ)
          says its type; decode it with osdk_payload(set, id, true, profile).
    instances:
      cmd_set_code:
        pos: 0
        type: u1
        if: not _parent.is_ack
        doc: The command set byte as a number, named by the enum or not.
enums:
  encryption:
    0:
      id: plain
      doc: DATA is not encrypted.
    1:
      id: aes256
      doc: DATA is AES-256-ECB encrypted and padded to 16-byte blocks.
  command_set:
    0x00:
      id: activation
      doc: Activation and settings commands (version, activation, frequencies).
    0x01:
      id: control
      doc: Control commands (control authority, movement control).
    0x02:
      id: push
      doc: Data pushed by the flight controller (broadcast, lost control).
