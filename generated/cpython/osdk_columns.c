/* Generated from spec/ by tools/cgen/generate.py. Do not edit. */
/* osdk_columns.c - see osdk_columns.h. */
#include "osdk_columns.h"

const uint8_t osdk_col_size[OSDK_COL_TYPE_COUNT] = {1, 1, 2, 4, 8, 1, 2, 4, 8, 4, 8};

/* osdk_broadcast_items::time_stamp: its leaves, in the columns from cols[0] on */
static void osdk_broadcast_items_time_stamp_cols(const osdk_broadcast_items_time_stamp_t *self, bool present, void *const *cols, uint8_t *const *valid, size_t row)
{
    bool p;
    p = present;
    ((uint32_t *)cols[0])[row] = p ? (uint32_t)self->time : 0;
    valid[0][row] = p;
    p = present && self->nano_time_present;
    ((uint32_t *)cols[1])[row] = p ? (uint32_t)self->nano_time : 0;
    valid[1][row] = p;
    p = present && self->sync_flag_present;
    ((uint8_t *)cols[2])[row] = p ? (uint8_t)self->sync_flag : 0;
    valid[2][row] = p;
}

/* osdk_broadcast_items::quaternion: its leaves, in the columns from cols[0] on */
static void osdk_broadcast_items_quaternion_cols(const osdk_broadcast_items_quaternion_t *self, bool present, void *const *cols, uint8_t *const *valid, size_t row)
{
    bool p;
    p = present;
    ((uint32_t *)cols[0])[row] = p ? (uint32_t)self->q0.bits : 0;
    valid[0][row] = p;
    p = present;
    ((uint32_t *)cols[1])[row] = p ? (uint32_t)self->q1.bits : 0;
    valid[1][row] = p;
    p = present;
    ((uint32_t *)cols[2])[row] = p ? (uint32_t)self->q2.bits : 0;
    valid[2][row] = p;
    p = present;
    ((uint32_t *)cols[3])[row] = p ? (uint32_t)self->q3.bits : 0;
    valid[3][row] = p;
}

/* osdk_broadcast_items::vector3f: its leaves, in the columns from cols[0] on */
static void osdk_broadcast_items_vector3f_cols(const osdk_broadcast_items_vector3f_t *self, bool present, void *const *cols, uint8_t *const *valid, size_t row)
{
    bool p;
    p = present;
    ((uint32_t *)cols[0])[row] = p ? (uint32_t)self->x.bits : 0;
    valid[0][row] = p;
    p = present;
    ((uint32_t *)cols[1])[row] = p ? (uint32_t)self->y.bits : 0;
    valid[1][row] = p;
    p = present;
    ((uint32_t *)cols[2])[row] = p ? (uint32_t)self->z.bits : 0;
    valid[2][row] = p;
}

/* osdk_broadcast_items::velocity: its leaves, in the columns from cols[0] on */
static void osdk_broadcast_items_velocity_cols(const osdk_broadcast_items_velocity_t *self, bool present, void *const *cols, uint8_t *const *valid, size_t row)
{
    bool p;
    p = present;
    ((uint32_t *)cols[0])[row] = p ? (uint32_t)self->x.bits : 0;
    valid[0][row] = p;
    p = present;
    ((uint32_t *)cols[1])[row] = p ? (uint32_t)self->y.bits : 0;
    valid[1][row] = p;
    p = present;
    ((uint32_t *)cols[2])[row] = p ? (uint32_t)self->z.bits : 0;
    valid[2][row] = p;
    p = present;
    ((uint8_t *)cols[3])[row] = p ? (uint8_t)self->data_valid : 0;
    valid[3][row] = p;
    p = present;
    ((uint8_t *)cols[4])[row] = p ? (uint8_t)self->sensor_id : 0;
    valid[4][row] = p;
    p = present;
    ((uint8_t *)cols[5])[row] = p ? (uint8_t)self->reserved : 0;
    valid[5][row] = p;
}

/* osdk_broadcast_items::position: its leaves, in the columns from cols[0] on */
static void osdk_broadcast_items_position_cols(const osdk_broadcast_items_position_t *self, bool present, void *const *cols, uint8_t *const *valid, size_t row)
{
    bool p;
    p = present;
    ((uint64_t *)cols[0])[row] = p ? (uint64_t)self->latitude.bits : 0;
    valid[0][row] = p;
    p = present;
    ((uint64_t *)cols[1])[row] = p ? (uint64_t)self->longitude.bits : 0;
    valid[1][row] = p;
    p = present;
    ((uint32_t *)cols[2])[row] = p ? (uint32_t)self->altitude.bits : 0;
    valid[2][row] = p;
    p = present;
    ((uint32_t *)cols[3])[row] = p ? (uint32_t)self->height.bits : 0;
    valid[3][row] = p;
    p = present;
    ((uint8_t *)cols[4])[row] = p ? (uint8_t)self->gps_health : 0;
    valid[4][row] = p;
}

/* osdk_broadcast_items::magnetometer: its leaves, in the columns from cols[0] on */
static void osdk_broadcast_items_magnetometer_cols(const osdk_broadcast_items_magnetometer_t *self, bool present, void *const *cols, uint8_t *const *valid, size_t row)
{
    bool p;
    p = present;
    ((int16_t *)cols[0])[row] = p ? (int16_t)self->x : 0;
    valid[0][row] = p;
    p = present;
    ((int16_t *)cols[1])[row] = p ? (int16_t)self->y : 0;
    valid[1][row] = p;
    p = present;
    ((int16_t *)cols[2])[row] = p ? (int16_t)self->z : 0;
    valid[2][row] = p;
}

/* osdk_broadcast_items::rc: its leaves, in the columns from cols[0] on */
static void osdk_broadcast_items_rc_cols(const osdk_broadcast_items_rc_t *self, bool present, void *const *cols, uint8_t *const *valid, size_t row)
{
    bool p;
    p = present;
    ((int16_t *)cols[0])[row] = p ? (int16_t)self->roll : 0;
    valid[0][row] = p;
    p = present;
    ((int16_t *)cols[1])[row] = p ? (int16_t)self->pitch : 0;
    valid[1][row] = p;
    p = present;
    ((int16_t *)cols[2])[row] = p ? (int16_t)self->yaw : 0;
    valid[2][row] = p;
    p = present;
    ((int16_t *)cols[3])[row] = p ? (int16_t)self->throttle : 0;
    valid[3][row] = p;
    p = present;
    ((int16_t *)cols[4])[row] = p ? (int16_t)self->mode : 0;
    valid[4][row] = p;
    p = present;
    ((int16_t *)cols[5])[row] = p ? (int16_t)self->gear : 0;
    valid[5][row] = p;
}

/* osdk_broadcast_items::gimbal: its leaves, in the columns from cols[0] on */
static void osdk_broadcast_items_gimbal_cols(const osdk_broadcast_items_gimbal_t *self, bool present, void *const *cols, uint8_t *const *valid, size_t row)
{
    bool p;
    p = present;
    ((uint32_t *)cols[0])[row] = p ? (uint32_t)self->roll.bits : 0;
    valid[0][row] = p;
    p = present;
    ((uint32_t *)cols[1])[row] = p ? (uint32_t)self->pitch.bits : 0;
    valid[1][row] = p;
    p = present;
    ((uint32_t *)cols[2])[row] = p ? (uint32_t)self->yaw.bits : 0;
    valid[2][row] = p;
    p = present && self->limit_present;
    ((uint8_t *)cols[3])[row] = p ? (uint8_t)self->limit.pitch_limit : 0;
    valid[3][row] = p;
    p = present && self->limit_present;
    ((uint8_t *)cols[4])[row] = p ? (uint8_t)self->limit.roll_limit : 0;
    valid[4][row] = p;
    p = present && self->limit_present;
    ((uint8_t *)cols[5])[row] = p ? (uint8_t)self->limit.yaw_limit : 0;
    valid[5][row] = p;
    p = present && self->limit_present;
    ((uint8_t *)cols[6])[row] = p ? (uint8_t)self->limit.reserved : 0;
    valid[6][row] = p;
}

/* osdk_broadcast_items::control_info: its leaves, in the columns from cols[0] on */
static void osdk_broadcast_items_control_info_cols(const osdk_broadcast_items_control_info_t *self, bool present, void *const *cols, uint8_t *const *valid, size_t row)
{
    bool p;
    p = present && self->cur_mov_control_mode_present;
    ((uint8_t *)cols[0])[row] = p ? (uint8_t)self->cur_mov_control_mode : 0;
    valid[0][row] = p;
    p = present;
    ((uint8_t *)cols[1])[row] = p ? (uint8_t)self->control_device : 0;
    valid[1][row] = p;
    p = present;
    ((uint8_t *)cols[2])[row] = p ? (uint8_t)self->onboard_requested : 0;
    valid[2][row] = p;
    p = present;
    ((uint8_t *)cols[3])[row] = p ? (uint8_t)self->virtual_rc : 0;
    valid[3][row] = p;
    p = present;
    ((uint8_t *)cols[4])[row] = p ? (uint8_t)self->reserved : 0;
    valid[4][row] = p;
}

/* osdk_broadcast_items::gps_detail: its leaves, in the columns from cols[0] on */
static void osdk_broadcast_items_gps_detail_cols(const osdk_broadcast_items_gps_detail_t *self, bool present, void *const *cols, uint8_t *const *valid, size_t row)
{
    bool p;
    p = present;
    ((uint32_t *)cols[0])[row] = p ? (uint32_t)self->date : 0;
    valid[0][row] = p;
    p = present;
    ((uint32_t *)cols[1])[row] = p ? (uint32_t)self->time : 0;
    valid[1][row] = p;
    p = present;
    ((int32_t *)cols[2])[row] = p ? (int32_t)self->longitude : 0;
    valid[2][row] = p;
    p = present;
    ((int32_t *)cols[3])[row] = p ? (int32_t)self->latitude : 0;
    valid[3][row] = p;
    p = present;
    ((int32_t *)cols[4])[row] = p ? (int32_t)self->height_msl : 0;
    valid[4][row] = p;
    p = present;
    ((uint32_t *)cols[5])[row] = p ? (uint32_t)self->vel_n.bits : 0;
    valid[5][row] = p;
    p = present;
    ((uint32_t *)cols[6])[row] = p ? (uint32_t)self->vel_e.bits : 0;
    valid[6][row] = p;
    p = present;
    ((uint32_t *)cols[7])[row] = p ? (uint32_t)self->vel_d.bits : 0;
    valid[7][row] = p;
}

/* osdk_broadcast_items::rtk_detail: its leaves, in the columns from cols[0] on */
static void osdk_broadcast_items_rtk_detail_cols(const osdk_broadcast_items_rtk_detail_t *self, bool present, void *const *cols, uint8_t *const *valid, size_t row)
{
    bool p;
    p = present;
    ((uint32_t *)cols[0])[row] = p ? (uint32_t)self->date : 0;
    valid[0][row] = p;
    p = present;
    ((uint32_t *)cols[1])[row] = p ? (uint32_t)self->time : 0;
    valid[1][row] = p;
    p = present;
    ((uint64_t *)cols[2])[row] = p ? (uint64_t)self->longitude.bits : 0;
    valid[2][row] = p;
    p = present;
    ((uint64_t *)cols[3])[row] = p ? (uint64_t)self->latitude.bits : 0;
    valid[3][row] = p;
    p = present;
    ((uint32_t *)cols[4])[row] = p ? (uint32_t)self->height_msl.bits : 0;
    valid[4][row] = p;
    p = present;
    ((uint32_t *)cols[5])[row] = p ? (uint32_t)self->vel_n.bits : 0;
    valid[5][row] = p;
    p = present;
    ((uint32_t *)cols[6])[row] = p ? (uint32_t)self->vel_e.bits : 0;
    valid[6][row] = p;
    p = present;
    ((uint32_t *)cols[7])[row] = p ? (uint32_t)self->vel_d.bits : 0;
    valid[7][row] = p;
    p = present;
    ((int16_t *)cols[8])[row] = p ? (int16_t)self->yaw : 0;
    valid[8][row] = p;
    p = present;
    ((uint8_t *)cols[9])[row] = p ? (uint8_t)self->position_flag : 0;
    valid[9][row] = p;
    p = present;
    ((uint8_t *)cols[10])[row] = p ? (uint8_t)self->yaw_flag : 0;
    valid[10][row] = p;
}

/* osdk_broadcast_m100_fw2_3 */
static const osdk_column_t osdk_broadcast_m100_fw2_3_columns[47] = {
    {"time_stamp.time", 0, OSDK_COL_U32, NULL},
    {"time_stamp.nano_time", 0, OSDK_COL_U32, NULL},
    {"time_stamp.sync_flag", 0, OSDK_COL_U8, NULL},
    {"quaternion.q0", 1, OSDK_COL_F32, NULL},
    {"quaternion.q1", 1, OSDK_COL_F32, NULL},
    {"quaternion.q2", 1, OSDK_COL_F32, NULL},
    {"quaternion.q3", 1, OSDK_COL_F32, NULL},
    {"acceleration.x", 2, OSDK_COL_F32, NULL},
    {"acceleration.y", 2, OSDK_COL_F32, NULL},
    {"acceleration.z", 2, OSDK_COL_F32, NULL},
    {"velocity.x", 3, OSDK_COL_F32, NULL},
    {"velocity.y", 3, OSDK_COL_F32, NULL},
    {"velocity.z", 3, OSDK_COL_F32, NULL},
    {"velocity.data_valid", 3, OSDK_COL_BOOL, NULL},
    {"velocity.sensor_id", 3, OSDK_COL_U8, NULL},
    {"velocity.reserved", 3, OSDK_COL_U8, NULL},
    {"angular_rate.x", 4, OSDK_COL_F32, NULL},
    {"angular_rate.y", 4, OSDK_COL_F32, NULL},
    {"angular_rate.z", 4, OSDK_COL_F32, NULL},
    {"position.latitude", 5, OSDK_COL_F64, NULL},
    {"position.longitude", 5, OSDK_COL_F64, NULL},
    {"position.altitude", 5, OSDK_COL_F32, NULL},
    {"position.height", 5, OSDK_COL_F32, NULL},
    {"position.gps_health", 5, OSDK_COL_U8, NULL},
    {"magnetometer.x", 6, OSDK_COL_I16, NULL},
    {"magnetometer.y", 6, OSDK_COL_I16, NULL},
    {"magnetometer.z", 6, OSDK_COL_I16, NULL},
    {"rc.roll", 7, OSDK_COL_I16, NULL},
    {"rc.pitch", 7, OSDK_COL_I16, NULL},
    {"rc.yaw", 7, OSDK_COL_I16, NULL},
    {"rc.throttle", 7, OSDK_COL_I16, NULL},
    {"rc.mode", 7, OSDK_COL_I16, NULL},
    {"rc.gear", 7, OSDK_COL_I16, NULL},
    {"gimbal.roll", 8, OSDK_COL_F32, NULL},
    {"gimbal.pitch", 8, OSDK_COL_F32, NULL},
    {"gimbal.yaw", 8, OSDK_COL_F32, NULL},
    {"gimbal.limit.pitch_limit", 8, OSDK_COL_BOOL, NULL},
    {"gimbal.limit.roll_limit", 8, OSDK_COL_BOOL, NULL},
    {"gimbal.limit.yaw_limit", 8, OSDK_COL_BOOL, NULL},
    {"gimbal.limit.reserved", 8, OSDK_COL_U8, NULL},
    {"flight_status", 9, OSDK_COL_U8, NULL},
    {"battery", 10, OSDK_COL_U8, NULL},
    {"control_info.cur_mov_control_mode", 11, OSDK_COL_U8, "osdk_broadcast_items.cur_mov_control_mode"},
    {"control_info.control_device", 11, OSDK_COL_U8, "osdk_broadcast_items.control_device"},
    {"control_info.onboard_requested", 11, OSDK_COL_BOOL, NULL},
    {"control_info.virtual_rc", 11, OSDK_COL_BOOL, NULL},
    {"control_info.reserved", 11, OSDK_COL_U8, NULL},
};
static const char *const osdk_broadcast_m100_fw2_3_items[12] = {"time_stamp", "quaternion", "acceleration", "velocity", "angular_rate", "position", "magnetometer", "rc", "gimbal", "flight_status", "battery", "control_info"};
static const osdk_column_set_t osdk_broadcast_m100_fw2_3_column_set = {osdk_broadcast_m100_fw2_3_columns, 47, osdk_broadcast_m100_fw2_3_items, 12};

static void osdk_broadcast_m100_fw2_3_row(const osdk_broadcast_m100_fw2_3_t *self, void *const *cols, uint8_t *const *valid, size_t row)
{
    bool p;
    osdk_broadcast_items_time_stamp_cols(&self->time_stamp, self->time_stamp_present, cols + 0, valid + 0, row);
    osdk_broadcast_items_quaternion_cols(&self->quaternion, self->quaternion_present, cols + 3, valid + 3, row);
    osdk_broadcast_items_vector3f_cols(&self->acceleration, self->acceleration_present, cols + 7, valid + 7, row);
    osdk_broadcast_items_velocity_cols(&self->velocity, self->velocity_present, cols + 10, valid + 10, row);
    osdk_broadcast_items_vector3f_cols(&self->angular_rate, self->angular_rate_present, cols + 16, valid + 16, row);
    osdk_broadcast_items_position_cols(&self->position, self->position_present, cols + 19, valid + 19, row);
    osdk_broadcast_items_magnetometer_cols(&self->magnetometer, self->magnetometer_present, cols + 24, valid + 24, row);
    osdk_broadcast_items_rc_cols(&self->rc, self->rc_present, cols + 27, valid + 27, row);
    osdk_broadcast_items_gimbal_cols(&self->gimbal, self->gimbal_present, cols + 33, valid + 33, row);
    p = self->flight_status_present;
    ((uint8_t *)cols[40])[row] = p ? (uint8_t)self->flight_status : 0;
    valid[40][row] = p;
    p = self->battery_present;
    ((uint8_t *)cols[41])[row] = p ? (uint8_t)self->battery : 0;
    valid[41][row] = p;
    osdk_broadcast_items_control_info_cols(&self->control_info, self->control_info_present, cols + 42, valid + 42, row);
}

/* osdk_broadcast_m100_fw3_1 */
static const osdk_column_t osdk_broadcast_m100_fw3_1_columns[47] = {
    {"time_stamp.time", 0, OSDK_COL_U32, NULL},
    {"time_stamp.nano_time", 0, OSDK_COL_U32, NULL},
    {"time_stamp.sync_flag", 0, OSDK_COL_U8, NULL},
    {"quaternion.q0", 1, OSDK_COL_F32, NULL},
    {"quaternion.q1", 1, OSDK_COL_F32, NULL},
    {"quaternion.q2", 1, OSDK_COL_F32, NULL},
    {"quaternion.q3", 1, OSDK_COL_F32, NULL},
    {"acceleration.x", 2, OSDK_COL_F32, NULL},
    {"acceleration.y", 2, OSDK_COL_F32, NULL},
    {"acceleration.z", 2, OSDK_COL_F32, NULL},
    {"velocity.x", 3, OSDK_COL_F32, NULL},
    {"velocity.y", 3, OSDK_COL_F32, NULL},
    {"velocity.z", 3, OSDK_COL_F32, NULL},
    {"velocity.data_valid", 3, OSDK_COL_BOOL, NULL},
    {"velocity.sensor_id", 3, OSDK_COL_U8, NULL},
    {"velocity.reserved", 3, OSDK_COL_U8, NULL},
    {"angular_rate.x", 4, OSDK_COL_F32, NULL},
    {"angular_rate.y", 4, OSDK_COL_F32, NULL},
    {"angular_rate.z", 4, OSDK_COL_F32, NULL},
    {"position.latitude", 5, OSDK_COL_F64, NULL},
    {"position.longitude", 5, OSDK_COL_F64, NULL},
    {"position.altitude", 5, OSDK_COL_F32, NULL},
    {"position.height", 5, OSDK_COL_F32, NULL},
    {"position.gps_health", 5, OSDK_COL_U8, NULL},
    {"magnetometer.x", 6, OSDK_COL_I16, NULL},
    {"magnetometer.y", 6, OSDK_COL_I16, NULL},
    {"magnetometer.z", 6, OSDK_COL_I16, NULL},
    {"rc.roll", 7, OSDK_COL_I16, NULL},
    {"rc.pitch", 7, OSDK_COL_I16, NULL},
    {"rc.yaw", 7, OSDK_COL_I16, NULL},
    {"rc.throttle", 7, OSDK_COL_I16, NULL},
    {"rc.mode", 7, OSDK_COL_I16, NULL},
    {"rc.gear", 7, OSDK_COL_I16, NULL},
    {"gimbal.roll", 8, OSDK_COL_F32, NULL},
    {"gimbal.pitch", 8, OSDK_COL_F32, NULL},
    {"gimbal.yaw", 8, OSDK_COL_F32, NULL},
    {"gimbal.limit.pitch_limit", 8, OSDK_COL_BOOL, NULL},
    {"gimbal.limit.roll_limit", 8, OSDK_COL_BOOL, NULL},
    {"gimbal.limit.yaw_limit", 8, OSDK_COL_BOOL, NULL},
    {"gimbal.limit.reserved", 8, OSDK_COL_U8, NULL},
    {"flight_status", 9, OSDK_COL_U8, NULL},
    {"battery", 10, OSDK_COL_U8, NULL},
    {"control_info.cur_mov_control_mode", 11, OSDK_COL_U8, "osdk_broadcast_items.cur_mov_control_mode"},
    {"control_info.control_device", 11, OSDK_COL_U8, "osdk_broadcast_items.control_device"},
    {"control_info.onboard_requested", 11, OSDK_COL_BOOL, NULL},
    {"control_info.virtual_rc", 11, OSDK_COL_BOOL, NULL},
    {"control_info.reserved", 11, OSDK_COL_U8, NULL},
};
static const char *const osdk_broadcast_m100_fw3_1_items[12] = {"time_stamp", "quaternion", "acceleration", "velocity", "angular_rate", "position", "magnetometer", "rc", "gimbal", "flight_status", "battery", "control_info"};
static const osdk_column_set_t osdk_broadcast_m100_fw3_1_column_set = {osdk_broadcast_m100_fw3_1_columns, 47, osdk_broadcast_m100_fw3_1_items, 12};

static void osdk_broadcast_m100_fw3_1_row(const osdk_broadcast_m100_fw3_1_t *self, void *const *cols, uint8_t *const *valid, size_t row)
{
    bool p;
    osdk_broadcast_items_time_stamp_cols(&self->time_stamp, self->time_stamp_present, cols + 0, valid + 0, row);
    osdk_broadcast_items_quaternion_cols(&self->quaternion, self->quaternion_present, cols + 3, valid + 3, row);
    osdk_broadcast_items_vector3f_cols(&self->acceleration, self->acceleration_present, cols + 7, valid + 7, row);
    osdk_broadcast_items_velocity_cols(&self->velocity, self->velocity_present, cols + 10, valid + 10, row);
    osdk_broadcast_items_vector3f_cols(&self->angular_rate, self->angular_rate_present, cols + 16, valid + 16, row);
    osdk_broadcast_items_position_cols(&self->position, self->position_present, cols + 19, valid + 19, row);
    osdk_broadcast_items_magnetometer_cols(&self->magnetometer, self->magnetometer_present, cols + 24, valid + 24, row);
    osdk_broadcast_items_rc_cols(&self->rc, self->rc_present, cols + 27, valid + 27, row);
    osdk_broadcast_items_gimbal_cols(&self->gimbal, self->gimbal_present, cols + 33, valid + 33, row);
    p = self->flight_status_present;
    ((uint8_t *)cols[40])[row] = p ? (uint8_t)self->flight_status : 0;
    valid[40][row] = p;
    p = self->battery_present;
    ((uint8_t *)cols[41])[row] = p ? (uint8_t)self->battery : 0;
    valid[41][row] = p;
    osdk_broadcast_items_control_info_cols(&self->control_info, self->control_info_present, cols + 42, valid + 42, row);
}

/* osdk_broadcast_a3_fw3_1 */
static const osdk_column_t osdk_broadcast_a3_fw3_1_columns[66] = {
    {"time_stamp.time", 0, OSDK_COL_U32, NULL},
    {"time_stamp.nano_time", 0, OSDK_COL_U32, NULL},
    {"time_stamp.sync_flag", 0, OSDK_COL_U8, NULL},
    {"quaternion.q0", 1, OSDK_COL_F32, NULL},
    {"quaternion.q1", 1, OSDK_COL_F32, NULL},
    {"quaternion.q2", 1, OSDK_COL_F32, NULL},
    {"quaternion.q3", 1, OSDK_COL_F32, NULL},
    {"acceleration.x", 2, OSDK_COL_F32, NULL},
    {"acceleration.y", 2, OSDK_COL_F32, NULL},
    {"acceleration.z", 2, OSDK_COL_F32, NULL},
    {"velocity.x", 3, OSDK_COL_F32, NULL},
    {"velocity.y", 3, OSDK_COL_F32, NULL},
    {"velocity.z", 3, OSDK_COL_F32, NULL},
    {"velocity.data_valid", 3, OSDK_COL_BOOL, NULL},
    {"velocity.sensor_id", 3, OSDK_COL_U8, NULL},
    {"velocity.reserved", 3, OSDK_COL_U8, NULL},
    {"angular_rate.x", 4, OSDK_COL_F32, NULL},
    {"angular_rate.y", 4, OSDK_COL_F32, NULL},
    {"angular_rate.z", 4, OSDK_COL_F32, NULL},
    {"position.latitude", 5, OSDK_COL_F64, NULL},
    {"position.longitude", 5, OSDK_COL_F64, NULL},
    {"position.altitude", 5, OSDK_COL_F32, NULL},
    {"position.height", 5, OSDK_COL_F32, NULL},
    {"position.gps_health", 5, OSDK_COL_U8, NULL},
    {"gps_detail.date", 6, OSDK_COL_U32, NULL},
    {"gps_detail.time", 6, OSDK_COL_U32, NULL},
    {"gps_detail.longitude", 6, OSDK_COL_I32, NULL},
    {"gps_detail.latitude", 6, OSDK_COL_I32, NULL},
    {"gps_detail.height_msl", 6, OSDK_COL_I32, NULL},
    {"gps_detail.vel_n", 6, OSDK_COL_F32, NULL},
    {"gps_detail.vel_e", 6, OSDK_COL_F32, NULL},
    {"gps_detail.vel_d", 6, OSDK_COL_F32, NULL},
    {"rtk_detail.date", 7, OSDK_COL_U32, NULL},
    {"rtk_detail.time", 7, OSDK_COL_U32, NULL},
    {"rtk_detail.longitude", 7, OSDK_COL_F64, NULL},
    {"rtk_detail.latitude", 7, OSDK_COL_F64, NULL},
    {"rtk_detail.height_msl", 7, OSDK_COL_F32, NULL},
    {"rtk_detail.vel_n", 7, OSDK_COL_F32, NULL},
    {"rtk_detail.vel_e", 7, OSDK_COL_F32, NULL},
    {"rtk_detail.vel_d", 7, OSDK_COL_F32, NULL},
    {"rtk_detail.yaw", 7, OSDK_COL_I16, NULL},
    {"rtk_detail.position_flag", 7, OSDK_COL_U8, NULL},
    {"rtk_detail.yaw_flag", 7, OSDK_COL_U8, NULL},
    {"magnetometer.x", 8, OSDK_COL_I16, NULL},
    {"magnetometer.y", 8, OSDK_COL_I16, NULL},
    {"magnetometer.z", 8, OSDK_COL_I16, NULL},
    {"rc.roll", 9, OSDK_COL_I16, NULL},
    {"rc.pitch", 9, OSDK_COL_I16, NULL},
    {"rc.yaw", 9, OSDK_COL_I16, NULL},
    {"rc.throttle", 9, OSDK_COL_I16, NULL},
    {"rc.mode", 9, OSDK_COL_I16, NULL},
    {"rc.gear", 9, OSDK_COL_I16, NULL},
    {"gimbal.roll", 10, OSDK_COL_F32, NULL},
    {"gimbal.pitch", 10, OSDK_COL_F32, NULL},
    {"gimbal.yaw", 10, OSDK_COL_F32, NULL},
    {"gimbal.limit.pitch_limit", 10, OSDK_COL_BOOL, NULL},
    {"gimbal.limit.roll_limit", 10, OSDK_COL_BOOL, NULL},
    {"gimbal.limit.yaw_limit", 10, OSDK_COL_BOOL, NULL},
    {"gimbal.limit.reserved", 10, OSDK_COL_U8, NULL},
    {"flight_status", 11, OSDK_COL_U8, NULL},
    {"battery", 12, OSDK_COL_U8, NULL},
    {"control_info.cur_mov_control_mode", 13, OSDK_COL_U8, "osdk_broadcast_items.cur_mov_control_mode"},
    {"control_info.control_device", 13, OSDK_COL_U8, "osdk_broadcast_items.control_device"},
    {"control_info.onboard_requested", 13, OSDK_COL_BOOL, NULL},
    {"control_info.virtual_rc", 13, OSDK_COL_BOOL, NULL},
    {"control_info.reserved", 13, OSDK_COL_U8, NULL},
};
static const char *const osdk_broadcast_a3_fw3_1_items[14] = {"time_stamp", "quaternion", "acceleration", "velocity", "angular_rate", "position", "gps_detail", "rtk_detail", "magnetometer", "rc", "gimbal", "flight_status", "battery", "control_info"};
static const osdk_column_set_t osdk_broadcast_a3_fw3_1_column_set = {osdk_broadcast_a3_fw3_1_columns, 66, osdk_broadcast_a3_fw3_1_items, 14};

static void osdk_broadcast_a3_fw3_1_row(const osdk_broadcast_a3_fw3_1_t *self, void *const *cols, uint8_t *const *valid, size_t row)
{
    bool p;
    osdk_broadcast_items_time_stamp_cols(&self->time_stamp, self->time_stamp_present, cols + 0, valid + 0, row);
    osdk_broadcast_items_quaternion_cols(&self->quaternion, self->quaternion_present, cols + 3, valid + 3, row);
    osdk_broadcast_items_vector3f_cols(&self->acceleration, self->acceleration_present, cols + 7, valid + 7, row);
    osdk_broadcast_items_velocity_cols(&self->velocity, self->velocity_present, cols + 10, valid + 10, row);
    osdk_broadcast_items_vector3f_cols(&self->angular_rate, self->angular_rate_present, cols + 16, valid + 16, row);
    osdk_broadcast_items_position_cols(&self->position, self->position_present, cols + 19, valid + 19, row);
    osdk_broadcast_items_gps_detail_cols(&self->gps_detail, self->gps_detail_present, cols + 24, valid + 24, row);
    osdk_broadcast_items_rtk_detail_cols(&self->rtk_detail, self->rtk_detail_present, cols + 32, valid + 32, row);
    osdk_broadcast_items_magnetometer_cols(&self->magnetometer, self->magnetometer_present, cols + 43, valid + 43, row);
    osdk_broadcast_items_rc_cols(&self->rc, self->rc_present, cols + 46, valid + 46, row);
    osdk_broadcast_items_gimbal_cols(&self->gimbal, self->gimbal_present, cols + 52, valid + 52, row);
    p = self->flight_status_present;
    ((uint8_t *)cols[59])[row] = p ? (uint8_t)self->flight_status : 0;
    valid[59][row] = p;
    p = self->battery_present;
    ((uint8_t *)cols[60])[row] = p ? (uint8_t)self->battery : 0;
    valid[60][row] = p;
    osdk_broadcast_items_control_info_cols(&self->control_info, self->control_info_present, cols + 61, valid + 61, row);
}

const osdk_column_set_t *osdk_broadcast_columns(uint8_t profile)
{
    switch (profile) {
        case 0: return &osdk_broadcast_m100_fw2_3_column_set;
        case 1: return &osdk_broadcast_m100_fw3_1_column_set;
        case 2: return &osdk_broadcast_a3_fw3_1_column_set;
        default: return NULL;
    }
}

bool osdk_broadcast_row(const osdk_payload_broadcast_t *b, void *const *cols, uint8_t *const *valid, size_t row)
{
    switch (b->data.tag) {
        case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW2_3: osdk_broadcast_m100_fw2_3_row(&b->data.u.osdk_broadcast_m100_fw2_3, cols, valid, row); return true;
        case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW3_1: osdk_broadcast_m100_fw3_1_row(&b->data.u.osdk_broadcast_m100_fw3_1, cols, valid, row); return true;
        case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_A3_FW3_1: osdk_broadcast_a3_fw3_1_row(&b->data.u.osdk_broadcast_a3_fw3_1, cols, valid, row); return true;
        default: return false;
    }
}

