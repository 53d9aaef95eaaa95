meta:
  id: osdk_payload
  title: DJI Onboard SDK OPEN protocol - command and ACK values
  application: DJI Onboard SDK onboard device <-> flight controller link
  license: CC0-1.0
  ks-version: '0.11'
  endian: le
  imports:
    - osdk_movement_control
    # --- generated from rules.yaml profiles by tools/gen_profile_ksy.py (imports): do not edit ---
    - osdk_broadcast_m100_fw2_3
    - osdk_broadcast_m100_fw3_1
    - osdk_broadcast_a3_fw3_1
    # --- end generated ---
doc: |
  The value carried in a frame's DATA, chosen by command set and id. A
  command frame names its set and id itself; an ACK frame does not (it
  repeats the SEQ of the command it answers), so the caller must say which
  command an ACK belongs to. The broadcast's layout depends on the wire
  profile of the flight controller, which the caller also supplies.
  Values of unknown commands are kept as raw bytes. Bytes left over after a
  known value are an error.
doc-ref:
  - osdk-conformance shared/reference/PROTOCOL-FACTS.md section 2
  - https://github.com/dji-sdk/Onboard-SDK/blob/3.1.9/doc/en/OPENProtocol.md
params:
  - id: cmd_set
    type: u1
    doc: Command set of the command (or of the command an ACK answers).
  - id: cmd_id
    type: u1
    doc: Command id within the set.
  - id: is_ack
    type: bool
    doc: true when the value is an ACK frame's value.
  - id: profile
    type: u1
    enum: profile
    doc: Broadcast wire profile of the flight controller.
seq:
  - id: body
    doc: The value, typed by command and direction.
    type:
      switch-on: key
      cases:
        0x0000: version_query
        0x0001: activation_request
        0x0010: frequency_request
        0x0100: control_request
        0x0103: osdk_movement_control
        0x0200: broadcast(profile)
        0x0201: lost_control
        0x10000: version_ack_value(profile)
        0x10001: activation_ack_value
        0x10010: frequency_ack_value
        0x10100: control_ack_value
        0x10201: lost_control_ack_value
        _: unknown_value
  - id: trailing
    size-eos: true
    valid:
      expr: _.length == 0
    doc: Bytes after a known value; a conforming value has none.
instances:
  key:
    # .as<u4> on every term: the Go target would compute in u1 and overflow
    value: '(is_ack ? 0x10000 : 0).as<u4> + cmd_set.as<u4> * 0x100 + cmd_id.as<u4>'
    doc: Dispatch key, 0x1SSII for ACKs and 0x0SSII for commands (SS set, II id).
types:
  version_query:
    doc: Get protocol version (set 0x00, id 0x00); the value is one arbitrary byte.
    seq:
      - id: arbitrary
        type: u1
        doc: Any value; the flight controller ignores it.
  version_ack_value:
    doc: |
      ACK of the version query. FW 3.1 firmware (profiles m100-fw3.1 and
      a3-fw3.1) puts an 11-byte version ID between the CRC and the name;
      M100 FW 2.3 has none (ERRATA E30).
    doc-ref:
      - osdk-conformance shared/reference/PROTOCOL-FACTS.md section 2, "Version reply layout"
      - https://github.com/dji-sdk/Onboard-SDK/blob/3.1.9/osdk-core/src/DJI_API.cpp (CoreAPI::getDroneVersionCallback)
      - https://github.com/dji-sdk/Onboard-SDK/blob/3.9.0/osdk-core/api/src/dji_vehicle.cpp (Vehicle::parseDroneVersionInfo)
      - https://github.com/dji-sdk/Onboard-SDK/blob/3.2.2/osdk-core/test/DJI_APITest.h (the names an M100 and an A3 answer)
    params:
      - id: profile
        type: u1
        enum: profile
        doc: Wire profile of the flight controller; it decides whether the version ID is there.
    seq:
      - id: ack_code
        type: u2
        enum: version_ack
        doc: Activation state of the flight controller.
      - id: version_crc
        type: u4
        doc: CRC of the firmware version.
      - id: version_id
        size: 11
        if: has_version_id
        doc: |
          Version ID (FW 3.1 only), decoded raw. Firmware sends 10 ASCII
          characters and one NUL: the only form that DJI's fixed reader
          (3.1.x: 11 bytes) and its scanning reader (3.3 to 3.9: up to the
          first NUL after the code) read alike (ERRATA E30).
      - id: version_name
        size: 32
        doc: |
          Version name, ASCII, NUL-padded, in DJI's form
          "SDK-v1.0 BETA <hardware>-<a>.<b>.<c>.<d>" (rules.yaml
          profiles.*.version_ack.version_name); 3.3 to 3.9 hosts read the
          firmware version from it (ERRATA E30).
    instances:
      has_version_id:
        doc: true on FW 3.1 profiles, whose reply carries the 11-byte version ID.
        # --- generated from rules.yaml profiles by tools/gen_profile_ksy.py (version id): do not edit ---
        value: profile != profile::m100_fw2_3
        # --- end generated ---
  activation_request:
    doc: Activation (set 0x00, id 0x01).
    seq:
      - id: app_id
        type: u4
        doc: Application id issued by DJI.
      - id: api_level
        type: u4
        doc: API level (reserved in later SDKs).
      - id: sdk_version
        type: u4
        doc: SDK version word, e.g. 0x03010A00 (M100) or 0x03016400 (A3).
      - id: bundle_id
        size: 32
        doc: Bundle id, 32 bytes.
  activation_ack_value:
    doc: ACK of activation.
    seq:
      - id: ack_code
        type: u2
        enum: activation_result
        doc: Activation result.
  frequency_request:
    doc: |
      Set broadcast frequencies (set 0x00, id 0x10): one frequency code per
      item in flag-bit order of the profile; tail bytes past the profile's
      item count are reserved.
    seq:
      - id: codes
        type: u1
        enum: frequency_code
        repeat: expr
        repeat-expr: 16
        doc: Frequency code for flag bit 0, 1, ... 15.
  frequency_ack_value:
    doc: ACK of set broadcast frequencies.
    seq:
      - id: ack_code
        type: u2
        enum: frequency_ack
        doc: Result.
  control_request:
    doc: Obtain or release control authority (set 0x01, id 0x00).
    seq:
      - id: request
        type: u1
        enum: control_request_code
        doc: 1 obtain, 0 release.
  control_ack_value:
    doc: ACK of obtain/release control; the first request answers "in progress".
    seq:
      - id: ack_code
        type: u2
        enum: control_ack
        doc: Result.
  broadcast:
    doc: Flight data broadcast (set 0x02, id 0x00) in the given profile.
    params:
      - id: profile
        type: u1
        enum: profile
        doc: Wire profile that selects the layout.
    seq:
      - id: data
        doc: The broadcast payload.
        type:
          switch-on: profile
          cases:
            # --- generated from rules.yaml profiles by tools/gen_profile_ksy.py (broadcast cases): do not edit ---
            profile::m100_fw2_3: osdk_broadcast_m100_fw2_3
            profile::m100_fw3_1: osdk_broadcast_m100_fw3_1
            profile::a3_fw3_1: osdk_broadcast_a3_fw3_1
            # --- end generated ---
  lost_control:
    doc: Control authority lost, pushed by the flight controller (set 0x02, id 0x01).
    seq:
      - id: reason
        type: u1
        doc: Reason code; 0x04 in the documented firmware.
  lost_control_ack_value:
    doc: The device's answer to a lost-control push sent with session > 0.
    seq:
      - id: ack_code
        type: u2
        doc: Always 0.
  unknown_value:
    doc: Value of a command this spec does not describe, kept raw.
    seq:
      - id: raw
        size-eos: true
        doc: The value bytes.
enums:
  # --- generated from rules.yaml profiles by tools/gen_profile_ksy.py (profile enum): do not edit ---
  profile:
    0:
      id: m100_fw2_3
      doc: m100-fw2.3, M100 with firmware 2.3.
    1:
      id: m100_fw3_1
      doc: m100-fw3.1, M100 with firmware 3.1.
    2:
      id: a3_fw3_1
      doc: a3-fw3.1, A3, N3 and M600 with firmware 3.1.
  # --- end generated ---
  version_ack:
    0x0000: activated
    0xff01: not_activated
  activation_result:
    0: success
    1: invalid_parameters
    2: cannot_recognize_encrypted_package
    3: new_app_id
    4: no_response_from_app
    5: no_internet
    6: server_rejected
    7: level_insufficient
    8: wrong_sdk_version
  frequency_code:
    0: hz_0
    1: hz_1
    2: hz_10
    3: hz_50
    4: hz_100
    5:
      id: keep
      doc: Keep the last setting.
    6:
      id: hz_200
      doc: Later SDKs only.
    7:
      id: hz_400
      doc: Later SDKs only.
  frequency_ack:
    0: success
    1: parameter_error
  control_request_code:
    0: release
    1: obtain
  control_ack:
    0: rc_not_in_f_mode
    1: released
    2: obtained
    3: obtain_in_progress
    4: release_in_progress
    0xc9: in_ioc_mode
