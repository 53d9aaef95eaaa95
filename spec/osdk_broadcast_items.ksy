meta:
  id: osdk_broadcast_items
  title: DJI Onboard SDK OPEN protocol - flight data (broadcast) item types
  application: DJI Onboard SDK flight controllers (M100, A3, N3, M600)
  license: CC0-1.0
  ks-version: '0.11'
  endian: le
  bit-endian: le
doc: |
  Item types shared by the broadcast profiles. A broadcast payload is a u2
  presence-flag word followed by each present item in flag-bit order; which
  bit carries which item, and which variant of an item (through the params
  below) a profile uses, is decided by the profile's entry in spec/rules.yaml,
  from which the osdk_broadcast_<profile>.ksy files are generated. All structures are packed,
  little-endian; bit fields are numbered from the least significant bit.
  This file has no seq of its own: it only provides types and enums.
doc-ref:
  - osdk-conformance seed shared/seeds/000_b7658b258220b5c1.txt (Flight Data table)
  - osdk-conformance shared/reference/PROTOCOL-FACTS.md section 3
  - https://github.com/dji-sdk/Onboard-SDK/blob/3.1.9/doc/en/Appendix.md
types:
  time_stamp:
    doc: |
      Time stamp item (flag bit 0). FW 2.3 sends only the 4-byte tick
      counter; FW 3.1 adds the nanosecond counter and the sync flag (9 bytes).
    params:
      - id: has_ns_and_sync
        type: bool
        doc: true for the 9-byte FW 3.1 form, false for the 4-byte FW 2.3 form
    seq:
      - id: time
        type: u4
        doc: Free-running time stamp, in ticks of 1/400 s.
      - id: nano_time
        type: u4
        if: has_ns_and_sync
        doc: Time stamp in nanoseconds (FW 3.1 only).
      - id: sync_flag
        type: u1
        if: has_ns_and_sync
        doc: Hardware sync signal flag (FW 3.1 only).
  quaternion:
    doc: Attitude quaternion from the ground frame to the body frame (flag bit 1).
    seq:
      - id: q0
        type: f4
        doc: Scalar part.
      - id: q1
        type: f4
        doc: Vector part, x.
      - id: q2
        type: f4
        doc: Vector part, y.
      - id: q3
        type: f4
        doc: Vector part, z.
  vector3f:
    doc: |
      Three float32 components. Used for linear acceleration (m/s^2 when
      fused, g when raw) and angular rate (rad/s); which of raw or fusion is
      sent is a setting of the flight controller, not visible on the wire.
    seq:
      - id: x
        type: f4
        doc: x component.
      - id: y
        type: f4
        doc: y component.
      - id: z
        type: f4
        doc: z component.
  velocity:
    doc: Linear velocity in the ground frame, m/s, with a status byte (flag bit 3).
    seq:
      - id: x
        type: f4
        doc: Velocity along ground-frame x, m/s.
      - id: y
        type: f4
        doc: Velocity along ground-frame y, m/s.
      - id: z
        type: f4
        doc: Velocity along ground-frame z, m/s.
      - id: data_valid
        type: b1
        doc: Status bit 0, true when the velocity is valid.
      - id: sensor_id
        type: b4
        doc: |
          Status bits 1-4. The seed calls them reserved; the M100 SDK struct
          names them the sensor id (ERRATA E04). Informative only.
      - id: reserved
        type: b3
        doc: Status bits 5-7, reserved; a receiver ignores them.
  position:
    doc: |
      GPS position and altitude (flag bit 5). Latitude comes first on the
      wire although the seed's table lists longitude first (ERRATA E01).
    seq:
      - id: latitude
        type: f8
        doc: Latitude, radians.
      - id: longitude
        type: f8
        doc: Longitude, radians.
      - id: altitude
        type: f4
        doc: Altitude (barometer and IMU when fused, barometer when raw), m.
      - id: height
        type: f4
        doc: Height above ground (fusion with ultrasound when below 3 m), m.
      - id: gps_health
        type: u1
        doc: GPS health, 0 (no fix) to 5 (best).
  gps_detail:
    doc: Detailed GPS information, A3 family only (flag bit 6 in a3-fw3.1).
    seq:
      - id: date
        type: u4
        doc: UTC date as the decimal number yyyymmdd.
      - id: time
        type: u4
        doc: UTC time as the decimal number hhmmss.
      - id: longitude
        type: s4
        doc: Longitude, degrees times 1e7. Longitude comes first in this item.
      - id: latitude
        type: s4
        doc: Latitude, degrees times 1e7.
      - id: height_msl
        type: s4
        doc: Height above mean sea level, mm.
      - id: vel_n
        type: f4
        doc: Velocity towards north, cm/s.
      - id: vel_e
        type: f4
        doc: Velocity towards east, cm/s.
      - id: vel_d
        type: f4
        doc: Velocity downwards, cm/s.
  rtk_detail:
    doc: Detailed RTK information, A3 family only (flag bit 7 in a3-fw3.1).
    seq:
      - id: date
        type: u4
        doc: UTC date as the decimal number yyyymmdd.
      - id: time
        type: u4
        doc: UTC time as the decimal number hhmmss.
      - id: longitude
        type: f8
        doc: Longitude by RTK, degrees.
      - id: latitude
        type: f8
        doc: Latitude by RTK, degrees.
      - id: height_msl
        type: f4
        doc: Height above mean sea level by RTK, m.
      - id: vel_n
        type: f4
        doc: Velocity towards north, cm/s.
      - id: vel_e
        type: f4
        doc: Velocity towards east, cm/s.
      - id: vel_d
        type: f4
        doc: Velocity downwards, cm/s.
      - id: yaw
        type: s2
        doc: Angle between the antenna baseline and south, degrees.
      - id: position_flag
        type: u1
        doc: RTK positioning solution flag.
      - id: yaw_flag
        type: u1
        doc: RTK heading solution flag.
  magnetometer:
    doc: Raw magnetometer reading, unitless counts.
    seq:
      - id: x
        type: s2
        doc: x axis.
      - id: y
        type: s2
        doc: y axis.
      - id: z
        type: s2
        doc: z axis.
  rc:
    doc: |
      Remote controller sticks and switches. Sticks range -10000..10000;
      mode is -8000 (P), 0 (A) or 8000 (F); gear is -4545 or -10000.
    seq:
      - id: roll
        type: s2
        doc: Roll stick, -10000 (left) to 10000 (right).
      - id: pitch
        type: s2
        doc: Pitch stick, -10000 (down) to 10000 (up).
      - id: yaw
        type: s2
        doc: Yaw stick, -10000 (left) to 10000 (right).
      - id: throttle
        type: s2
        doc: Throttle stick, -10000 (down) to 10000 (up).
      - id: mode
        type: s2
        doc: Flight mode switch, -8000 P, 0 A, 8000 F.
      - id: gear
        type: s2
        doc: Gear switch, -4545 or -10000 (see rules.yaml rc_channels).
  gimbal:
    doc: |
      Gimbal attitude in degrees. FW 2.3 sends the three angles only
      (12 bytes); FW 3.1 appends a limit byte (13 bytes).
    params:
      - id: has_limit_byte
        type: bool
        doc: true for the 13-byte FW 3.1 form
    seq:
      - id: roll
        type: f4
        doc: Gimbal roll, degrees.
      - id: pitch
        type: f4
        doc: Gimbal pitch, degrees.
      - id: yaw
        type: f4
        doc: Gimbal yaw, degrees.
      - id: limit
        type: gimbal_limit
        if: has_limit_byte
        doc: Which axes are at their mechanical limit (FW 3.1 only).
  gimbal_limit:
    doc: The gimbal limit byte.
    seq:
      - id: pitch_limit
        type: b1
        doc: Bit 0, pitch at its limit.
      - id: roll_limit
        type: b1
        doc: Bit 1, roll at its limit.
      - id: yaw_limit
        type: b1
        doc: Bit 2, yaw at its limit.
      - id: reserved
        type: b5
        doc: Bits 3-7, reserved; a receiver ignores them.
  control_info:
    doc: |
      Source of control. FW 2.3 sends the device byte alone (1 byte); FW 3.1
      sends the current API control mode first, then the device byte.
    params:
      - id: has_mode
        type: bool
        doc: true for the 2-byte FW 3.1 form
    seq:
      - id: cur_mov_control_mode
        type: u1
        enum: cur_mov_control_mode
        if: has_mode
        doc: Movement control mode the flight controller is executing (FW 3.1 only).
      - id: control_device
        type: b3
        enum: control_device
        doc: Device byte bits 0-2, who is in control.
      - id: onboard_requested
        type: b1
        doc: Device byte bit 3, the onboard device has requested control.
      - id: virtual_rc
        type: b1
        doc: Device byte bit 4, virtual RC is enabled.
      - id: reserved
        type: b3
        doc: Device byte bits 5-7, reserved; a receiver ignores them.
enums:
  control_device:
    0:
      id: rc
      doc: Remote controller.
    1:
      id: mobile_device
      doc: Mobile device (DJI app).
    2:
      id: onboard_device
      doc: Onboard embedded system (the onboard SDK device).
  cur_mov_control_mode:
    # Seed's enum is garbled; values from OSDK 3.1.9 doc/en/Appendix.md
    # (ERRATA E02). 1..18 run vertical-major, then horizontal, then yaw.
    0: atti_stop
    1: horiz_ang_vert_vel_yaw_ang
    2: horiz_ang_vert_vel_yaw_rate
    3: horiz_vel_vert_vel_yaw_ang
    4: horiz_vel_vert_vel_yaw_rate
    5: horiz_pos_vert_vel_yaw_ang
    6: horiz_pos_vert_vel_yaw_rate
    7: horiz_ang_vert_pos_yaw_ang
    8: horiz_ang_vert_pos_yaw_rate
    9: horiz_vel_vert_pos_yaw_ang
    10: horiz_vel_vert_pos_yaw_rate
    11: horiz_pos_vert_pos_yaw_ang
    12: horiz_pos_vert_pos_yaw_rate
    13: horiz_ang_vert_thr_yaw_ang
    14: horiz_ang_vert_thr_yaw_rate
    15: horiz_vel_vert_thr_yaw_ang
    16: horiz_vel_vert_thr_yaw_rate
    17: horiz_pos_vert_thr_yaw_ang
    18: horiz_pos_vert_thr_yaw_rate
    97: gps_atti_ctrl_cl_yaw_rate
    98: gps_atti_ctrl_yaw_rate
    99: atti_ctrl_yaw_rate
    100: atti_ctrl_stop
