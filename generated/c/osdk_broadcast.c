/* Generated from spec/ by tools/libgen/c.py. Do not edit. */
/* osdk_broadcast.c - see osdk_broadcast.h. */
#include "osdk_broadcast.h"

const osdk_payload_broadcast_t *osdk_broadcast_of_payload(const osdk_payload_t *p)
{
    if (p == NULL || p->body.tag != OSDK_PAYLOAD_BODY_BROADCAST) return NULL;
    return &p->body.u.broadcast;
}

const osdk_payload_broadcast_t *osdk_broadcast_of(const osdk_frame_t *f)
{
    if (f == NULL || !f->data_present || f->data.tag != OSDK_FRAME_DATA_FRAME_DATA) return NULL;
    if (!f->data.u.frame_data.value_present) return NULL;
    return osdk_broadcast_of_payload(&f->data.u.frame_data.value);
}

const osdk_broadcast_items_time_stamp_t *osdk_broadcast_time_stamp(const osdk_payload_broadcast_t *b)
{
    if (b == NULL) return NULL;
    switch (b->data.tag) {
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW2_3: /* m100-fw2.3 */
        return b->data.u.osdk_broadcast_m100_fw2_3.time_stamp_present ? &b->data.u.osdk_broadcast_m100_fw2_3.time_stamp : NULL;
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW3_1: /* m100-fw3.1 */
        return b->data.u.osdk_broadcast_m100_fw3_1.time_stamp_present ? &b->data.u.osdk_broadcast_m100_fw3_1.time_stamp : NULL;
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_A3_FW3_1: /* a3-fw3.1 */
        return b->data.u.osdk_broadcast_a3_fw3_1.time_stamp_present ? &b->data.u.osdk_broadcast_a3_fw3_1.time_stamp : NULL;
    default:
        return NULL;
    }
}

const osdk_broadcast_items_quaternion_t *osdk_broadcast_quaternion(const osdk_payload_broadcast_t *b)
{
    if (b == NULL) return NULL;
    switch (b->data.tag) {
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW2_3: /* m100-fw2.3 */
        return b->data.u.osdk_broadcast_m100_fw2_3.quaternion_present ? &b->data.u.osdk_broadcast_m100_fw2_3.quaternion : NULL;
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW3_1: /* m100-fw3.1 */
        return b->data.u.osdk_broadcast_m100_fw3_1.quaternion_present ? &b->data.u.osdk_broadcast_m100_fw3_1.quaternion : NULL;
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_A3_FW3_1: /* a3-fw3.1 */
        return b->data.u.osdk_broadcast_a3_fw3_1.quaternion_present ? &b->data.u.osdk_broadcast_a3_fw3_1.quaternion : NULL;
    default:
        return NULL;
    }
}

const osdk_broadcast_items_vector3f_t *osdk_broadcast_acceleration(const osdk_payload_broadcast_t *b)
{
    if (b == NULL) return NULL;
    switch (b->data.tag) {
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW2_3: /* m100-fw2.3 */
        return b->data.u.osdk_broadcast_m100_fw2_3.acceleration_present ? &b->data.u.osdk_broadcast_m100_fw2_3.acceleration : NULL;
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW3_1: /* m100-fw3.1 */
        return b->data.u.osdk_broadcast_m100_fw3_1.acceleration_present ? &b->data.u.osdk_broadcast_m100_fw3_1.acceleration : NULL;
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_A3_FW3_1: /* a3-fw3.1 */
        return b->data.u.osdk_broadcast_a3_fw3_1.acceleration_present ? &b->data.u.osdk_broadcast_a3_fw3_1.acceleration : NULL;
    default:
        return NULL;
    }
}

const osdk_broadcast_items_velocity_t *osdk_broadcast_velocity(const osdk_payload_broadcast_t *b)
{
    if (b == NULL) return NULL;
    switch (b->data.tag) {
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW2_3: /* m100-fw2.3 */
        return b->data.u.osdk_broadcast_m100_fw2_3.velocity_present ? &b->data.u.osdk_broadcast_m100_fw2_3.velocity : NULL;
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW3_1: /* m100-fw3.1 */
        return b->data.u.osdk_broadcast_m100_fw3_1.velocity_present ? &b->data.u.osdk_broadcast_m100_fw3_1.velocity : NULL;
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_A3_FW3_1: /* a3-fw3.1 */
        return b->data.u.osdk_broadcast_a3_fw3_1.velocity_present ? &b->data.u.osdk_broadcast_a3_fw3_1.velocity : NULL;
    default:
        return NULL;
    }
}

const osdk_broadcast_items_vector3f_t *osdk_broadcast_angular_rate(const osdk_payload_broadcast_t *b)
{
    if (b == NULL) return NULL;
    switch (b->data.tag) {
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW2_3: /* m100-fw2.3 */
        return b->data.u.osdk_broadcast_m100_fw2_3.angular_rate_present ? &b->data.u.osdk_broadcast_m100_fw2_3.angular_rate : NULL;
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW3_1: /* m100-fw3.1 */
        return b->data.u.osdk_broadcast_m100_fw3_1.angular_rate_present ? &b->data.u.osdk_broadcast_m100_fw3_1.angular_rate : NULL;
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_A3_FW3_1: /* a3-fw3.1 */
        return b->data.u.osdk_broadcast_a3_fw3_1.angular_rate_present ? &b->data.u.osdk_broadcast_a3_fw3_1.angular_rate : NULL;
    default:
        return NULL;
    }
}

const osdk_broadcast_items_position_t *osdk_broadcast_position(const osdk_payload_broadcast_t *b)
{
    if (b == NULL) return NULL;
    switch (b->data.tag) {
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW2_3: /* m100-fw2.3 */
        return b->data.u.osdk_broadcast_m100_fw2_3.position_present ? &b->data.u.osdk_broadcast_m100_fw2_3.position : NULL;
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW3_1: /* m100-fw3.1 */
        return b->data.u.osdk_broadcast_m100_fw3_1.position_present ? &b->data.u.osdk_broadcast_m100_fw3_1.position : NULL;
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_A3_FW3_1: /* a3-fw3.1 */
        return b->data.u.osdk_broadcast_a3_fw3_1.position_present ? &b->data.u.osdk_broadcast_a3_fw3_1.position : NULL;
    default:
        return NULL;
    }
}

const osdk_broadcast_items_magnetometer_t *osdk_broadcast_magnetometer(const osdk_payload_broadcast_t *b)
{
    if (b == NULL) return NULL;
    switch (b->data.tag) {
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW2_3: /* m100-fw2.3 */
        return b->data.u.osdk_broadcast_m100_fw2_3.magnetometer_present ? &b->data.u.osdk_broadcast_m100_fw2_3.magnetometer : NULL;
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW3_1: /* m100-fw3.1 */
        return b->data.u.osdk_broadcast_m100_fw3_1.magnetometer_present ? &b->data.u.osdk_broadcast_m100_fw3_1.magnetometer : NULL;
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_A3_FW3_1: /* a3-fw3.1 */
        return b->data.u.osdk_broadcast_a3_fw3_1.magnetometer_present ? &b->data.u.osdk_broadcast_a3_fw3_1.magnetometer : NULL;
    default:
        return NULL;
    }
}

const osdk_broadcast_items_rc_t *osdk_broadcast_rc(const osdk_payload_broadcast_t *b)
{
    if (b == NULL) return NULL;
    switch (b->data.tag) {
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW2_3: /* m100-fw2.3 */
        return b->data.u.osdk_broadcast_m100_fw2_3.rc_present ? &b->data.u.osdk_broadcast_m100_fw2_3.rc : NULL;
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW3_1: /* m100-fw3.1 */
        return b->data.u.osdk_broadcast_m100_fw3_1.rc_present ? &b->data.u.osdk_broadcast_m100_fw3_1.rc : NULL;
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_A3_FW3_1: /* a3-fw3.1 */
        return b->data.u.osdk_broadcast_a3_fw3_1.rc_present ? &b->data.u.osdk_broadcast_a3_fw3_1.rc : NULL;
    default:
        return NULL;
    }
}

const osdk_broadcast_items_gimbal_t *osdk_broadcast_gimbal(const osdk_payload_broadcast_t *b)
{
    if (b == NULL) return NULL;
    switch (b->data.tag) {
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW2_3: /* m100-fw2.3 */
        return b->data.u.osdk_broadcast_m100_fw2_3.gimbal_present ? &b->data.u.osdk_broadcast_m100_fw2_3.gimbal : NULL;
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW3_1: /* m100-fw3.1 */
        return b->data.u.osdk_broadcast_m100_fw3_1.gimbal_present ? &b->data.u.osdk_broadcast_m100_fw3_1.gimbal : NULL;
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_A3_FW3_1: /* a3-fw3.1 */
        return b->data.u.osdk_broadcast_a3_fw3_1.gimbal_present ? &b->data.u.osdk_broadcast_a3_fw3_1.gimbal : NULL;
    default:
        return NULL;
    }
}

const uint8_t *osdk_broadcast_flight_status(const osdk_payload_broadcast_t *b)
{
    if (b == NULL) return NULL;
    switch (b->data.tag) {
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW2_3: /* m100-fw2.3 */
        return b->data.u.osdk_broadcast_m100_fw2_3.flight_status_present ? &b->data.u.osdk_broadcast_m100_fw2_3.flight_status : NULL;
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW3_1: /* m100-fw3.1 */
        return b->data.u.osdk_broadcast_m100_fw3_1.flight_status_present ? &b->data.u.osdk_broadcast_m100_fw3_1.flight_status : NULL;
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_A3_FW3_1: /* a3-fw3.1 */
        return b->data.u.osdk_broadcast_a3_fw3_1.flight_status_present ? &b->data.u.osdk_broadcast_a3_fw3_1.flight_status : NULL;
    default:
        return NULL;
    }
}

const uint8_t *osdk_broadcast_battery(const osdk_payload_broadcast_t *b)
{
    if (b == NULL) return NULL;
    switch (b->data.tag) {
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW2_3: /* m100-fw2.3 */
        return b->data.u.osdk_broadcast_m100_fw2_3.battery_present ? &b->data.u.osdk_broadcast_m100_fw2_3.battery : NULL;
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW3_1: /* m100-fw3.1 */
        return b->data.u.osdk_broadcast_m100_fw3_1.battery_present ? &b->data.u.osdk_broadcast_m100_fw3_1.battery : NULL;
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_A3_FW3_1: /* a3-fw3.1 */
        return b->data.u.osdk_broadcast_a3_fw3_1.battery_present ? &b->data.u.osdk_broadcast_a3_fw3_1.battery : NULL;
    default:
        return NULL;
    }
}

const osdk_broadcast_items_control_info_t *osdk_broadcast_control_info(const osdk_payload_broadcast_t *b)
{
    if (b == NULL) return NULL;
    switch (b->data.tag) {
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW2_3: /* m100-fw2.3 */
        return b->data.u.osdk_broadcast_m100_fw2_3.control_info_present ? &b->data.u.osdk_broadcast_m100_fw2_3.control_info : NULL;
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW3_1: /* m100-fw3.1 */
        return b->data.u.osdk_broadcast_m100_fw3_1.control_info_present ? &b->data.u.osdk_broadcast_m100_fw3_1.control_info : NULL;
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_A3_FW3_1: /* a3-fw3.1 */
        return b->data.u.osdk_broadcast_a3_fw3_1.control_info_present ? &b->data.u.osdk_broadcast_a3_fw3_1.control_info : NULL;
    default:
        return NULL;
    }
}

const osdk_broadcast_items_gps_detail_t *osdk_broadcast_gps_detail(const osdk_payload_broadcast_t *b)
{
    if (b == NULL) return NULL;
    switch (b->data.tag) {
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_A3_FW3_1: /* a3-fw3.1 */
        return b->data.u.osdk_broadcast_a3_fw3_1.gps_detail_present ? &b->data.u.osdk_broadcast_a3_fw3_1.gps_detail : NULL;
    default:
        return NULL;
    }
}

const osdk_broadcast_items_rtk_detail_t *osdk_broadcast_rtk_detail(const osdk_payload_broadcast_t *b)
{
    if (b == NULL) return NULL;
    switch (b->data.tag) {
    case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_A3_FW3_1: /* a3-fw3.1 */
        return b->data.u.osdk_broadcast_a3_fw3_1.rtk_detail_present ? &b->data.u.osdk_broadcast_a3_fw3_1.rtk_detail : NULL;
    default:
        return NULL;
    }
}


static const char *const item_names[OSDK_BROADCAST_ITEM_COUNT_] = {
    "time_stamp",
    "quaternion",
    "acceleration",
    "velocity",
    "angular_rate",
    "position",
    "magnetometer",
    "rc",
    "gimbal",
    "flight_status",
    "battery",
    "control_info",
    "gps_detail",
    "rtk_detail",
};

const char *osdk_broadcast_item_name(osdk_broadcast_item_t item)
{
    return (unsigned)item < OSDK_BROADCAST_ITEM_COUNT_ ? item_names[(unsigned)item] : NULL;
}

static const osdk_broadcast_item_t items_m100_fw2_3[12] = { /* m100-fw2.3 */
    OSDK_BROADCAST_ITEM_TIME_STAMP,
    OSDK_BROADCAST_ITEM_QUATERNION,
    OSDK_BROADCAST_ITEM_ACCELERATION,
    OSDK_BROADCAST_ITEM_VELOCITY,
    OSDK_BROADCAST_ITEM_ANGULAR_RATE,
    OSDK_BROADCAST_ITEM_POSITION,
    OSDK_BROADCAST_ITEM_MAGNETOMETER,
    OSDK_BROADCAST_ITEM_RC,
    OSDK_BROADCAST_ITEM_GIMBAL,
    OSDK_BROADCAST_ITEM_FLIGHT_STATUS,
    OSDK_BROADCAST_ITEM_BATTERY,
    OSDK_BROADCAST_ITEM_CONTROL_INFO,
};

static const osdk_broadcast_item_t items_m100_fw3_1[12] = { /* m100-fw3.1 */
    OSDK_BROADCAST_ITEM_TIME_STAMP,
    OSDK_BROADCAST_ITEM_QUATERNION,
    OSDK_BROADCAST_ITEM_ACCELERATION,
    OSDK_BROADCAST_ITEM_VELOCITY,
    OSDK_BROADCAST_ITEM_ANGULAR_RATE,
    OSDK_BROADCAST_ITEM_POSITION,
    OSDK_BROADCAST_ITEM_MAGNETOMETER,
    OSDK_BROADCAST_ITEM_RC,
    OSDK_BROADCAST_ITEM_GIMBAL,
    OSDK_BROADCAST_ITEM_FLIGHT_STATUS,
    OSDK_BROADCAST_ITEM_BATTERY,
    OSDK_BROADCAST_ITEM_CONTROL_INFO,
};

static const osdk_broadcast_item_t items_a3_fw3_1[14] = { /* a3-fw3.1 */
    OSDK_BROADCAST_ITEM_TIME_STAMP,
    OSDK_BROADCAST_ITEM_QUATERNION,
    OSDK_BROADCAST_ITEM_ACCELERATION,
    OSDK_BROADCAST_ITEM_VELOCITY,
    OSDK_BROADCAST_ITEM_ANGULAR_RATE,
    OSDK_BROADCAST_ITEM_POSITION,
    OSDK_BROADCAST_ITEM_GPS_DETAIL,
    OSDK_BROADCAST_ITEM_RTK_DETAIL,
    OSDK_BROADCAST_ITEM_MAGNETOMETER,
    OSDK_BROADCAST_ITEM_RC,
    OSDK_BROADCAST_ITEM_GIMBAL,
    OSDK_BROADCAST_ITEM_FLIGHT_STATUS,
    OSDK_BROADCAST_ITEM_BATTERY,
    OSDK_BROADCAST_ITEM_CONTROL_INFO,
};

const osdk_broadcast_item_t *osdk_broadcast_profile_items(uint8_t profile, size_t *count)
{
    switch (profile) {
    case 0: /* m100-fw2.3 */
        if (count) *count = 12;
        return items_m100_fw2_3;
    case 1: /* m100-fw3.1 */
        if (count) *count = 12;
        return items_m100_fw3_1;
    case 2: /* a3-fw3.1 */
        if (count) *count = 14;
        return items_a3_fw3_1;
    default:
        if (count) *count = 0;
        return NULL;
    }
}

const void *osdk_broadcast_item(const osdk_payload_broadcast_t *b, osdk_broadcast_item_t item)
{
    switch (item) {
    case OSDK_BROADCAST_ITEM_TIME_STAMP:
        return osdk_broadcast_time_stamp(b);
    case OSDK_BROADCAST_ITEM_QUATERNION:
        return osdk_broadcast_quaternion(b);
    case OSDK_BROADCAST_ITEM_ACCELERATION:
        return osdk_broadcast_acceleration(b);
    case OSDK_BROADCAST_ITEM_VELOCITY:
        return osdk_broadcast_velocity(b);
    case OSDK_BROADCAST_ITEM_ANGULAR_RATE:
        return osdk_broadcast_angular_rate(b);
    case OSDK_BROADCAST_ITEM_POSITION:
        return osdk_broadcast_position(b);
    case OSDK_BROADCAST_ITEM_MAGNETOMETER:
        return osdk_broadcast_magnetometer(b);
    case OSDK_BROADCAST_ITEM_RC:
        return osdk_broadcast_rc(b);
    case OSDK_BROADCAST_ITEM_GIMBAL:
        return osdk_broadcast_gimbal(b);
    case OSDK_BROADCAST_ITEM_FLIGHT_STATUS:
        return osdk_broadcast_flight_status(b);
    case OSDK_BROADCAST_ITEM_BATTERY:
        return osdk_broadcast_battery(b);
    case OSDK_BROADCAST_ITEM_CONTROL_INFO:
        return osdk_broadcast_control_info(b);
    case OSDK_BROADCAST_ITEM_GPS_DETAIL:
        return osdk_broadcast_gps_detail(b);
    case OSDK_BROADCAST_ITEM_RTK_DETAIL:
        return osdk_broadcast_rtk_detail(b);
    default:
        return NULL;
    }
}
