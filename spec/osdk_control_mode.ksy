meta:
  id: osdk_control_mode
  title: DJI Onboard SDK OPEN protocol - control mode byte
  application: DJI Onboard SDK movement control (command set 0x01, id 0x03)
  license: CC0-1.0
  ks-version: '0.11'
  endian: le
  bit-endian: le
doc: |
  The control mode byte says how the flight controller interprets the four
  setpoints of a movement control command: horizontal logic (tilt angle,
  velocity or position offset), vertical logic (velocity, position or
  thrust), yaw logic (angle or rate), the horizontal reference frame and
  the stable-mode flag. Fields are listed from bit 0 upward. Patterns with
  no enum name (horizontal 3, vertical 3, frame 2 and 3) are undefined in
  these firmwares; rules.yaml (control_mode) classifies every byte, and the
  14 documented combinations with their input ranges are in
  rules.yaml (control_modes).
doc-ref:
  - osdk-conformance seed shared/seeds/000_b7658b258220b5c1.txt (Control mode byte)
  - osdk-conformance shared/reference/PROTOCOL-FACTS.md section 4
  - https://github.com/dji-sdk/Onboard-SDK/blob/3.9.0/osdk-core/api/inc/dji_control.hpp
seq:
  - id: stable_mode
    type: b1
    enum: stable_mode
    doc: |
      Bit 0. Stable mode on FW 3.1 profiles; it affects horizontal control
      only. On m100-fw2.3 the same bit selects the yaw frame (0 ground,
      1 body) and must be 0 with yaw angle (ERRATA E15, rules.yaml
      control_mode.bit0_by_profile).
  - id: horizontal_frame
    type: b2
    enum: horizontal_frame
    doc: Bits 2-1. Reference frame of the horizontal setpoints.
  - id: yaw_logic
    type: b1
    enum: yaw_logic
    doc: Bit 3. Yaw setpoint is an angle (ground frame enforced) or a rate.
  - id: vertical_logic
    type: b2
    enum: vertical_logic
    doc: Bits 5-4. Meaning of the vertical (throttle) setpoint.
  - id: horizontal_logic
    type: b2
    enum: horizontal_logic
    doc: Bits 7-6. Meaning of the two horizontal (roll, pitch) setpoints.
enums:
  horizontal_logic:
    0:
      id: hori_atti_tilt_ang
      doc: Roll and pitch tilt angles, degrees.
    1:
      id: hori_vel
      doc: Horizontal velocities, m/s; needs GPS health >= 3 or Guidance.
    2:
      id: hori_pos
      doc: Horizontal position offsets, m; needs GPS health >= 3.
  vertical_logic:
    0:
      id: vert_vel
      doc: Vertical velocity, m/s, upward positive.
    1:
      id: vert_pos
      doc: Height, m.
    2:
      id: vert_thrust
      doc: Thrust, percent.
  yaw_logic:
    0:
      id: yaw_ang
      doc: Yaw angle, degrees, always in the ground frame.
    1:
      id: yaw_rate
      doc: Yaw rate, degrees per second.
  horizontal_frame:
    0:
      id: ground
      doc: Ground (north-east) frame.
    1:
      id: body
      doc: Body frame.
  stable_mode:
    0:
      id: non_stable
      doc: Stable mode off.
    1:
      id: stable
      doc: Stable mode on (horizontal control only).
