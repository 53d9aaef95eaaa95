/* Generated from spec/ by tools/libgen/c.py. Do not edit. */
/*
 * osdk_broadcast.h - the items of a decoded broadcast (0x02/0x00), one
 * accessor per item of any profile (tools/tables.py library.broadcast_items),
 * so that nobody reads the per-profile union of osdk_decoder.h.
 *
 * Absent is NULL, and only NULL: an accessor returns NULL when the item's
 * flag bit is clear, when the broadcast's profile has no such item, and
 * when it is given NULL. Integer items (battery, flight_status) are
 * returned as pointers too. The pointers point into the decoded struct.
 */
#ifndef OSDK_BROADCAST_H
#define OSDK_BROADCAST_H

#include "osdk_decoder.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The broadcast body of a decoded frame; NULL when the frame is not a
 * plain (unencrypted, non-ACK) broadcast or f is NULL. */
/*@ requires f == \null || \valid_read(f);
    assigns \nothing; */
const osdk_payload_broadcast_t *osdk_broadcast_of(const osdk_frame_t *f);
/* The same for a value decoded with osdk_payload_decode(). */
/*@ requires p == \null || \valid_read(p);
    assigns \nothing; */
const osdk_payload_broadcast_t *osdk_broadcast_of_payload(const osdk_payload_t *p);

/* time_stamp (every profile) */
/*@ requires b == \null || \valid_read(b);
    assigns \nothing; */
const osdk_broadcast_items_time_stamp_t *osdk_broadcast_time_stamp(const osdk_payload_broadcast_t *b);
/* quaternion (every profile) */
/*@ requires b == \null || \valid_read(b);
    assigns \nothing; */
const osdk_broadcast_items_quaternion_t *osdk_broadcast_quaternion(const osdk_payload_broadcast_t *b);
/* acceleration (every profile) */
/*@ requires b == \null || \valid_read(b);
    assigns \nothing; */
const osdk_broadcast_items_vector3f_t *osdk_broadcast_acceleration(const osdk_payload_broadcast_t *b);
/* velocity (every profile) */
/*@ requires b == \null || \valid_read(b);
    assigns \nothing; */
const osdk_broadcast_items_velocity_t *osdk_broadcast_velocity(const osdk_payload_broadcast_t *b);
/* angular_rate (every profile) */
/*@ requires b == \null || \valid_read(b);
    assigns \nothing; */
const osdk_broadcast_items_vector3f_t *osdk_broadcast_angular_rate(const osdk_payload_broadcast_t *b);
/* position (every profile) */
/*@ requires b == \null || \valid_read(b);
    assigns \nothing; */
const osdk_broadcast_items_position_t *osdk_broadcast_position(const osdk_payload_broadcast_t *b);
/* magnetometer (every profile) */
/*@ requires b == \null || \valid_read(b);
    assigns \nothing; */
const osdk_broadcast_items_magnetometer_t *osdk_broadcast_magnetometer(const osdk_payload_broadcast_t *b);
/* rc (every profile) */
/*@ requires b == \null || \valid_read(b);
    assigns \nothing; */
const osdk_broadcast_items_rc_t *osdk_broadcast_rc(const osdk_payload_broadcast_t *b);
/* gimbal (every profile) */
/*@ requires b == \null || \valid_read(b);
    assigns \nothing; */
const osdk_broadcast_items_gimbal_t *osdk_broadcast_gimbal(const osdk_payload_broadcast_t *b);
/* flight_status (every profile) */
/*@ requires b == \null || \valid_read(b);
    assigns \nothing; */
const uint8_t *osdk_broadcast_flight_status(const osdk_payload_broadcast_t *b);
/* battery (every profile) */
/*@ requires b == \null || \valid_read(b);
    assigns \nothing; */
const uint8_t *osdk_broadcast_battery(const osdk_payload_broadcast_t *b);
/* control_info (every profile) */
/*@ requires b == \null || \valid_read(b);
    assigns \nothing; */
const osdk_broadcast_items_control_info_t *osdk_broadcast_control_info(const osdk_payload_broadcast_t *b);
/* gps_detail (a3-fw3.1) */
/*@ requires b == \null || \valid_read(b);
    assigns \nothing; */
const osdk_broadcast_items_gps_detail_t *osdk_broadcast_gps_detail(const osdk_payload_broadcast_t *b);
/* rtk_detail (a3-fw3.1) */
/*@ requires b == \null || \valid_read(b);
    assigns \nothing; */
const osdk_broadcast_items_rtk_detail_t *osdk_broadcast_rtk_detail(const osdk_payload_broadcast_t *b);

/* ---- items by number, for code that walks a profile's items ---------------------------- */

typedef enum {
    OSDK_BROADCAST_ITEM_TIME_STAMP = 0,
    OSDK_BROADCAST_ITEM_QUATERNION = 1,
    OSDK_BROADCAST_ITEM_ACCELERATION = 2,
    OSDK_BROADCAST_ITEM_VELOCITY = 3,
    OSDK_BROADCAST_ITEM_ANGULAR_RATE = 4,
    OSDK_BROADCAST_ITEM_POSITION = 5,
    OSDK_BROADCAST_ITEM_MAGNETOMETER = 6,
    OSDK_BROADCAST_ITEM_RC = 7,
    OSDK_BROADCAST_ITEM_GIMBAL = 8,
    OSDK_BROADCAST_ITEM_FLIGHT_STATUS = 9,
    OSDK_BROADCAST_ITEM_BATTERY = 10,
    OSDK_BROADCAST_ITEM_CONTROL_INFO = 11,
    OSDK_BROADCAST_ITEM_GPS_DETAIL = 12,
    OSDK_BROADCAST_ITEM_RTK_DETAIL = 13,
    OSDK_BROADCAST_ITEM_COUNT_ = 14
} osdk_broadcast_item_t;

/* The item's id as the spec spells it ("time_stamp"), or NULL. */
/*@ assigns \nothing; */
const char *osdk_broadcast_item_name(osdk_broadcast_item_t item);
/* The items of a profile (an osdk_payload_profile_t value) in flag-bit
 * order, *count of them; NULL and 0 for an unknown profile. */
/*@ requires count == \null || \valid(count);
    assigns *count; */
const osdk_broadcast_item_t *osdk_broadcast_profile_items(uint8_t profile, size_t *count);
/* The item as osdk_broadcast_<item>() returns it (cast it to that type),
 * or NULL: absent, not in the profile, or an unknown item. */
/*@ requires b == \null || \valid_read(b);
    assigns \nothing; */
const void *osdk_broadcast_item(const osdk_payload_broadcast_t *b, osdk_broadcast_item_t item);

#ifdef __cplusplus
}
#endif

#endif /* OSDK_BROADCAST_H */
