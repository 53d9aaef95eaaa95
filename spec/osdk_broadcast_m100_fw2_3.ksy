# Generated from spec/rules.yaml (profiles, broadcast_items) by tools/gen_profile_ksy.py: do not edit.
meta:
  id: osdk_broadcast_m100_fw2_3
  title: DJI Onboard SDK OPEN protocol - flight data broadcast, profile m100-fw2.3
  application: M100 with firmware 2.3 (OSDK 2.3)
  license: CC0-1.0
  ks-version: '0.11'
  endian: le
  bit-endian: le
  imports:
    - osdk_broadcast_items
doc: |
  Payload of the flight data broadcast (command set 0x02, id 0x00) as sent
  by M100 with firmware 2.3 (OSDK 2.3). A u2 flag word says which items follow; the items follow in
  flag-bit order, each only when its bit is set. This profile uses
  the 4-byte time stamp, the 12-byte gimbal item (no limit byte) and the 1-byte control info item (device byte only).
  A flag word that promises more bytes than the payload holds is an error
  (the DJI SDK reads past the end instead; spec/ERRATA.md E25), and so are set
  reserved flag bits and bytes left over after the last item.
doc-ref:
  - osdk-conformance shared/reference/PROTOCOL-FACTS.md section 3 (profile m100-fw2.3)
  - https://github.com/dji-sdk/Onboard-SDK/blob/3.1.9/osdk-core/src/DJI_App.cpp
seq:
  - id: has_time_stamp
    type: b1
    doc: Flag bit 0, the time stamp item is present.
  - id: has_quaternion
    type: b1
    doc: Flag bit 1, the quaternion item is present.
  - id: has_acceleration
    type: b1
    doc: Flag bit 2, the acceleration item is present.
  - id: has_velocity
    type: b1
    doc: Flag bit 3, the velocity item is present.
  - id: has_angular_rate
    type: b1
    doc: Flag bit 4, the angular rate item is present.
  - id: has_position
    type: b1
    doc: Flag bit 5, the position item is present.
  - id: has_magnetometer
    type: b1
    doc: Flag bit 6, the magnetometer item is present.
  - id: has_rc
    type: b1
    doc: Flag bit 7, the rc item is present.
  - id: has_gimbal
    type: b1
    doc: Flag bit 8, the gimbal item is present.
  - id: has_flight_status
    type: b1
    doc: Flag bit 9, the flight status item is present.
  - id: has_battery
    type: b1
    doc: Flag bit 10, the battery item is present.
  - id: has_control_info
    type: b1
    doc: Flag bit 11, the control info item is present.
  - id: reserved_flags
    type: b4
    valid: 0
    doc: Flag bits 12-15 carry no item in this profile and must be 0.
  - id: time_stamp
    type: osdk_broadcast_items::time_stamp(false)
    if: has_time_stamp
    doc: Time stamp.
  - id: quaternion
    type: osdk_broadcast_items::quaternion
    if: has_quaternion
    doc: Attitude quaternion, ground to body.
  - id: acceleration
    type: osdk_broadcast_items::vector3f
    if: has_acceleration
    doc: Linear acceleration (m/s^2 fused, g raw).
  - id: velocity
    type: osdk_broadcast_items::velocity
    if: has_velocity
    doc: Linear velocity in the ground frame, m/s.
  - id: angular_rate
    type: osdk_broadcast_items::vector3f
    if: has_angular_rate
    doc: Angular rate, rad/s.
  - id: position
    type: osdk_broadcast_items::position
    if: has_position
    doc: GPS position, altitude, height and GPS health.
  - id: magnetometer
    type: osdk_broadcast_items::magnetometer
    if: has_magnetometer
    doc: Magnetometer counts.
  - id: rc
    type: osdk_broadcast_items::rc
    if: has_rc
    doc: Remote controller channels.
  - id: gimbal
    type: osdk_broadcast_items::gimbal(false)
    if: has_gimbal
    doc: Gimbal attitude.
  - id: flight_status
    type: u1
    if: has_flight_status
    doc: Flight status; old or new enum by aircraft and firmware (rules.yaml flight_status).
  - id: battery
    type: u1
    if: has_battery
    doc: Battery capacity, percent (0-100).
  - id: control_info
    type: osdk_broadcast_items::control_info(false)
    if: has_control_info
    doc: Source of control.
  - id: trailing
    size-eos: true
    valid:
      expr: _.length == 0
    doc: Bytes after the last present item; a conforming payload has none.
