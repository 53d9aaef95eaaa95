meta:
  id: osdk_movement_control
  title: DJI Onboard SDK OPEN protocol - movement control command
  application: DJI Onboard SDK, command set 0x01, id 0x03
  license: CC0-1.0
  ks-version: '0.11'
  endian: le
  imports:
    - osdk_control_mode
doc: |
  The 17-byte value of the movement control command an onboard device sends
  (in session 0, no ACK) while it holds control authority: a control mode
  byte and four float32 setpoints whose meaning and units the mode byte
  selects. Ranges per combination and profile are in rules.yaml
  (control_modes).
doc-ref:
  - osdk-conformance shared/reference/PROTOCOL-FACTS.md section 2
  - https://github.com/dji-sdk/Onboard-SDK/blob/3.1.9/doc/en/OPENProtocol.md
seq:
  - id: control_mode
    type: osdk_control_mode
    doc: How the four setpoints are to be interpreted.
  - id: x
    type: f4
    doc: Roll angle (deg), x velocity (m/s) or x offset (m), per horizontal logic and frame.
  - id: y
    type: f4
    doc: Pitch angle (deg), y velocity (m/s) or y offset (m), per horizontal logic and frame.
  - id: z
    type: f4
    doc: Vertical velocity (m/s), height (m) or thrust (%), per vertical logic.
  - id: yaw
    type: f4
    doc: Yaw angle (deg) or yaw rate (deg/s), per yaw logic.
