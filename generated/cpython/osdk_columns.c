/* Generated from spec/ by tools/cgen/generate.py. Do not edit. */
/* osdk_columns.c - see osdk_columns.h. */
#include "osdk_columns.h"

const uint8_t osdk_col_size[OSDK_COL_TYPE_COUNT] = {1, 1, 2, 4, 8, 1, 2, 4, 8, 4, 8};

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
    p = self->time_stamp_present;
    ((uint32_t *)cols[0])[row] = p ? (uint32_t)self->time_stamp.time : 0;
    valid[0][row] = p;
    p = self->time_stamp_present && self->time_stamp.nano_time_present;
    ((uint32_t *)cols[1])[row] = p ? (uint32_t)self->time_stamp.nano_time : 0;
    valid[1][row] = p;
    p = self->time_stamp_present && self->time_stamp.sync_flag_present;
    ((uint8_t *)cols[2])[row] = p ? (uint8_t)self->time_stamp.sync_flag : 0;
    valid[2][row] = p;
    p = self->quaternion_present;
    ((uint32_t *)cols[3])[row] = p ? (uint32_t)self->quaternion.q0.bits : 0;
    valid[3][row] = p;
    p = self->quaternion_present;
    ((uint32_t *)cols[4])[row] = p ? (uint32_t)self->quaternion.q1.bits : 0;
    valid[4][row] = p;
    p = self->quaternion_present;
    ((uint32_t *)cols[5])[row] = p ? (uint32_t)self->quaternion.q2.bits : 0;
    valid[5][row] = p;
    p = self->quaternion_present;
    ((uint32_t *)cols[6])[row] = p ? (uint32_t)self->quaternion.q3.bits : 0;
    valid[6][row] = p;
    p = self->acceleration_present;
    ((uint32_t *)cols[7])[row] = p ? (uint32_t)self->acceleration.x.bits : 0;
    valid[7][row] = p;
    p = self->acceleration_present;
    ((uint32_t *)cols[8])[row] = p ? (uint32_t)self->acceleration.y.bits : 0;
    valid[8][row] = p;
    p = self->acceleration_present;
    ((uint32_t *)cols[9])[row] = p ? (uint32_t)self->acceleration.z.bits : 0;
    valid[9][row] = p;
    p = self->velocity_present;
    ((uint32_t *)cols[10])[row] = p ? (uint32_t)self->velocity.x.bits : 0;
    valid[10][row] = p;
    p = self->velocity_present;
    ((uint32_t *)cols[11])[row] = p ? (uint32_t)self->velocity.y.bits : 0;
    valid[11][row] = p;
    p = self->velocity_present;
    ((uint32_t *)cols[12])[row] = p ? (uint32_t)self->velocity.z.bits : 0;
    valid[12][row] = p;
    p = self->velocity_present;
    ((uint8_t *)cols[13])[row] = p ? (uint8_t)self->velocity.data_valid : 0;
    valid[13][row] = p;
    p = self->velocity_present;
    ((uint8_t *)cols[14])[row] = p ? (uint8_t)self->velocity.sensor_id : 0;
    valid[14][row] = p;
    p = self->velocity_present;
    ((uint8_t *)cols[15])[row] = p ? (uint8_t)self->velocity.reserved : 0;
    valid[15][row] = p;
    p = self->angular_rate_present;
    ((uint32_t *)cols[16])[row] = p ? (uint32_t)self->angular_rate.x.bits : 0;
    valid[16][row] = p;
    p = self->angular_rate_present;
    ((uint32_t *)cols[17])[row] = p ? (uint32_t)self->angular_rate.y.bits : 0;
    valid[17][row] = p;
    p = self->angular_rate_present;
    ((uint32_t *)cols[18])[row] = p ? (uint32_t)self->angular_rate.z.bits : 0;
    valid[18][row] = p;
    p = self->position_present;
    ((uint64_t *)cols[19])[row] = p ? (uint64_t)self->position.latitude.bits : 0;
    valid[19][row] = p;
    p = self->position_present;
    ((uint64_t *)cols[20])[row] = p ? (uint64_t)self->position.longitude.bits : 0;
    valid[20][row] = p;
    p = self->position_present;
    ((uint32_t *)cols[21])[row] = p ? (uint32_t)self->position.altitude.bits : 0;
    valid[21][row] = p;
    p = self->position_present;
    ((uint32_t *)cols[22])[row] = p ? (uint32_t)self->position.height.bits : 0;
    valid[22][row] = p;
    p = self->position_present;
    ((uint8_t *)cols[23])[row] = p ? (uint8_t)self->position.gps_health : 0;
    valid[23][row] = p;
    p = self->magnetometer_present;
    ((int16_t *)cols[24])[row] = p ? (int16_t)self->magnetometer.x : 0;
    valid[24][row] = p;
    p = self->magnetometer_present;
    ((int16_t *)cols[25])[row] = p ? (int16_t)self->magnetometer.y : 0;
    valid[25][row] = p;
    p = self->magnetometer_present;
    ((int16_t *)cols[26])[row] = p ? (int16_t)self->magnetometer.z : 0;
    valid[26][row] = p;
    p = self->rc_present;
    ((int16_t *)cols[27])[row] = p ? (int16_t)self->rc.roll : 0;
    valid[27][row] = p;
    p = self->rc_present;
    ((int16_t *)cols[28])[row] = p ? (int16_t)self->rc.pitch : 0;
    valid[28][row] = p;
    p = self->rc_present;
    ((int16_t *)cols[29])[row] = p ? (int16_t)self->rc.yaw : 0;
    valid[29][row] = p;
    p = self->rc_present;
    ((int16_t *)cols[30])[row] = p ? (int16_t)self->rc.throttle : 0;
    valid[30][row] = p;
    p = self->rc_present;
    ((int16_t *)cols[31])[row] = p ? (int16_t)self->rc.mode : 0;
    valid[31][row] = p;
    p = self->rc_present;
    ((int16_t *)cols[32])[row] = p ? (int16_t)self->rc.gear : 0;
    valid[32][row] = p;
    p = self->gimbal_present;
    ((uint32_t *)cols[33])[row] = p ? (uint32_t)self->gimbal.roll.bits : 0;
    valid[33][row] = p;
    p = self->gimbal_present;
    ((uint32_t *)cols[34])[row] = p ? (uint32_t)self->gimbal.pitch.bits : 0;
    valid[34][row] = p;
    p = self->gimbal_present;
    ((uint32_t *)cols[35])[row] = p ? (uint32_t)self->gimbal.yaw.bits : 0;
    valid[35][row] = p;
    p = self->gimbal_present && self->gimbal.limit_present;
    ((uint8_t *)cols[36])[row] = p ? (uint8_t)self->gimbal.limit.pitch_limit : 0;
    valid[36][row] = p;
    p = self->gimbal_present && self->gimbal.limit_present;
    ((uint8_t *)cols[37])[row] = p ? (uint8_t)self->gimbal.limit.roll_limit : 0;
    valid[37][row] = p;
    p = self->gimbal_present && self->gimbal.limit_present;
    ((uint8_t *)cols[38])[row] = p ? (uint8_t)self->gimbal.limit.yaw_limit : 0;
    valid[38][row] = p;
    p = self->gimbal_present && self->gimbal.limit_present;
    ((uint8_t *)cols[39])[row] = p ? (uint8_t)self->gimbal.limit.reserved : 0;
    valid[39][row] = p;
    p = self->flight_status_present;
    ((uint8_t *)cols[40])[row] = p ? (uint8_t)self->flight_status : 0;
    valid[40][row] = p;
    p = self->battery_present;
    ((uint8_t *)cols[41])[row] = p ? (uint8_t)self->battery : 0;
    valid[41][row] = p;
    p = self->control_info_present && self->control_info.cur_mov_control_mode_present;
    ((uint8_t *)cols[42])[row] = p ? (uint8_t)self->control_info.cur_mov_control_mode : 0;
    valid[42][row] = p;
    p = self->control_info_present;
    ((uint8_t *)cols[43])[row] = p ? (uint8_t)self->control_info.control_device : 0;
    valid[43][row] = p;
    p = self->control_info_present;
    ((uint8_t *)cols[44])[row] = p ? (uint8_t)self->control_info.onboard_requested : 0;
    valid[44][row] = p;
    p = self->control_info_present;
    ((uint8_t *)cols[45])[row] = p ? (uint8_t)self->control_info.virtual_rc : 0;
    valid[45][row] = p;
    p = self->control_info_present;
    ((uint8_t *)cols[46])[row] = p ? (uint8_t)self->control_info.reserved : 0;
    valid[46][row] = p;
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
    p = self->time_stamp_present;
    ((uint32_t *)cols[0])[row] = p ? (uint32_t)self->time_stamp.time : 0;
    valid[0][row] = p;
    p = self->time_stamp_present && self->time_stamp.nano_time_present;
    ((uint32_t *)cols[1])[row] = p ? (uint32_t)self->time_stamp.nano_time : 0;
    valid[1][row] = p;
    p = self->time_stamp_present && self->time_stamp.sync_flag_present;
    ((uint8_t *)cols[2])[row] = p ? (uint8_t)self->time_stamp.sync_flag : 0;
    valid[2][row] = p;
    p = self->quaternion_present;
    ((uint32_t *)cols[3])[row] = p ? (uint32_t)self->quaternion.q0.bits : 0;
    valid[3][row] = p;
    p = self->quaternion_present;
    ((uint32_t *)cols[4])[row] = p ? (uint32_t)self->quaternion.q1.bits : 0;
    valid[4][row] = p;
    p = self->quaternion_present;
    ((uint32_t *)cols[5])[row] = p ? (uint32_t)self->quaternion.q2.bits : 0;
    valid[5][row] = p;
    p = self->quaternion_present;
    ((uint32_t *)cols[6])[row] = p ? (uint32_t)self->quaternion.q3.bits : 0;
    valid[6][row] = p;
    p = self->acceleration_present;
    ((uint32_t *)cols[7])[row] = p ? (uint32_t)self->acceleration.x.bits : 0;
    valid[7][row] = p;
    p = self->acceleration_present;
    ((uint32_t *)cols[8])[row] = p ? (uint32_t)self->acceleration.y.bits : 0;
    valid[8][row] = p;
    p = self->acceleration_present;
    ((uint32_t *)cols[9])[row] = p ? (uint32_t)self->acceleration.z.bits : 0;
    valid[9][row] = p;
    p = self->velocity_present;
    ((uint32_t *)cols[10])[row] = p ? (uint32_t)self->velocity.x.bits : 0;
    valid[10][row] = p;
    p = self->velocity_present;
    ((uint32_t *)cols[11])[row] = p ? (uint32_t)self->velocity.y.bits : 0;
    valid[11][row] = p;
    p = self->velocity_present;
    ((uint32_t *)cols[12])[row] = p ? (uint32_t)self->velocity.z.bits : 0;
    valid[12][row] = p;
    p = self->velocity_present;
    ((uint8_t *)cols[13])[row] = p ? (uint8_t)self->velocity.data_valid : 0;
    valid[13][row] = p;
    p = self->velocity_present;
    ((uint8_t *)cols[14])[row] = p ? (uint8_t)self->velocity.sensor_id : 0;
    valid[14][row] = p;
    p = self->velocity_present;
    ((uint8_t *)cols[15])[row] = p ? (uint8_t)self->velocity.reserved : 0;
    valid[15][row] = p;
    p = self->angular_rate_present;
    ((uint32_t *)cols[16])[row] = p ? (uint32_t)self->angular_rate.x.bits : 0;
    valid[16][row] = p;
    p = self->angular_rate_present;
    ((uint32_t *)cols[17])[row] = p ? (uint32_t)self->angular_rate.y.bits : 0;
    valid[17][row] = p;
    p = self->angular_rate_present;
    ((uint32_t *)cols[18])[row] = p ? (uint32_t)self->angular_rate.z.bits : 0;
    valid[18][row] = p;
    p = self->position_present;
    ((uint64_t *)cols[19])[row] = p ? (uint64_t)self->position.latitude.bits : 0;
    valid[19][row] = p;
    p = self->position_present;
    ((uint64_t *)cols[20])[row] = p ? (uint64_t)self->position.longitude.bits : 0;
    valid[20][row] = p;
    p = self->position_present;
    ((uint32_t *)cols[21])[row] = p ? (uint32_t)self->position.altitude.bits : 0;
    valid[21][row] = p;
    p = self->position_present;
    ((uint32_t *)cols[22])[row] = p ? (uint32_t)self->position.height.bits : 0;
    valid[22][row] = p;
    p = self->position_present;
    ((uint8_t *)cols[23])[row] = p ? (uint8_t)self->position.gps_health : 0;
    valid[23][row] = p;
    p = self->magnetometer_present;
    ((int16_t *)cols[24])[row] = p ? (int16_t)self->magnetometer.x : 0;
    valid[24][row] = p;
    p = self->magnetometer_present;
    ((int16_t *)cols[25])[row] = p ? (int16_t)self->magnetometer.y : 0;
    valid[25][row] = p;
    p = self->magnetometer_present;
    ((int16_t *)cols[26])[row] = p ? (int16_t)self->magnetometer.z : 0;
    valid[26][row] = p;
    p = self->rc_present;
    ((int16_t *)cols[27])[row] = p ? (int16_t)self->rc.roll : 0;
    valid[27][row] = p;
    p = self->rc_present;
    ((int16_t *)cols[28])[row] = p ? (int16_t)self->rc.pitch : 0;
    valid[28][row] = p;
    p = self->rc_present;
    ((int16_t *)cols[29])[row] = p ? (int16_t)self->rc.yaw : 0;
    valid[29][row] = p;
    p = self->rc_present;
    ((int16_t *)cols[30])[row] = p ? (int16_t)self->rc.throttle : 0;
    valid[30][row] = p;
    p = self->rc_present;
    ((int16_t *)cols[31])[row] = p ? (int16_t)self->rc.mode : 0;
    valid[31][row] = p;
    p = self->rc_present;
    ((int16_t *)cols[32])[row] = p ? (int16_t)self->rc.gear : 0;
    valid[32][row] = p;
    p = self->gimbal_present;
    ((uint32_t *)cols[33])[row] = p ? (uint32_t)self->gimbal.roll.bits : 0;
    valid[33][row] = p;
    p = self->gimbal_present;
    ((uint32_t *)cols[34])[row] = p ? (uint32_t)self->gimbal.pitch.bits : 0;
    valid[34][row] = p;
    p = self->gimbal_present;
    ((uint32_t *)cols[35])[row] = p ? (uint32_t)self->gimbal.yaw.bits : 0;
    valid[35][row] = p;
    p = self->gimbal_present && self->gimbal.limit_present;
    ((uint8_t *)cols[36])[row] = p ? (uint8_t)self->gimbal.limit.pitch_limit : 0;
    valid[36][row] = p;
    p = self->gimbal_present && self->gimbal.limit_present;
    ((uint8_t *)cols[37])[row] = p ? (uint8_t)self->gimbal.limit.roll_limit : 0;
    valid[37][row] = p;
    p = self->gimbal_present && self->gimbal.limit_present;
    ((uint8_t *)cols[38])[row] = p ? (uint8_t)self->gimbal.limit.yaw_limit : 0;
    valid[38][row] = p;
    p = self->gimbal_present && self->gimbal.limit_present;
    ((uint8_t *)cols[39])[row] = p ? (uint8_t)self->gimbal.limit.reserved : 0;
    valid[39][row] = p;
    p = self->flight_status_present;
    ((uint8_t *)cols[40])[row] = p ? (uint8_t)self->flight_status : 0;
    valid[40][row] = p;
    p = self->battery_present;
    ((uint8_t *)cols[41])[row] = p ? (uint8_t)self->battery : 0;
    valid[41][row] = p;
    p = self->control_info_present && self->control_info.cur_mov_control_mode_present;
    ((uint8_t *)cols[42])[row] = p ? (uint8_t)self->control_info.cur_mov_control_mode : 0;
    valid[42][row] = p;
    p = self->control_info_present;
    ((uint8_t *)cols[43])[row] = p ? (uint8_t)self->control_info.control_device : 0;
    valid[43][row] = p;
    p = self->control_info_present;
    ((uint8_t *)cols[44])[row] = p ? (uint8_t)self->control_info.onboard_requested : 0;
    valid[44][row] = p;
    p = self->control_info_present;
    ((uint8_t *)cols[45])[row] = p ? (uint8_t)self->control_info.virtual_rc : 0;
    valid[45][row] = p;
    p = self->control_info_present;
    ((uint8_t *)cols[46])[row] = p ? (uint8_t)self->control_info.reserved : 0;
    valid[46][row] = p;
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
    p = self->time_stamp_present;
    ((uint32_t *)cols[0])[row] = p ? (uint32_t)self->time_stamp.time : 0;
    valid[0][row] = p;
    p = self->time_stamp_present && self->time_stamp.nano_time_present;
    ((uint32_t *)cols[1])[row] = p ? (uint32_t)self->time_stamp.nano_time : 0;
    valid[1][row] = p;
    p = self->time_stamp_present && self->time_stamp.sync_flag_present;
    ((uint8_t *)cols[2])[row] = p ? (uint8_t)self->time_stamp.sync_flag : 0;
    valid[2][row] = p;
    p = self->quaternion_present;
    ((uint32_t *)cols[3])[row] = p ? (uint32_t)self->quaternion.q0.bits : 0;
    valid[3][row] = p;
    p = self->quaternion_present;
    ((uint32_t *)cols[4])[row] = p ? (uint32_t)self->quaternion.q1.bits : 0;
    valid[4][row] = p;
    p = self->quaternion_present;
    ((uint32_t *)cols[5])[row] = p ? (uint32_t)self->quaternion.q2.bits : 0;
    valid[5][row] = p;
    p = self->quaternion_present;
    ((uint32_t *)cols[6])[row] = p ? (uint32_t)self->quaternion.q3.bits : 0;
    valid[6][row] = p;
    p = self->acceleration_present;
    ((uint32_t *)cols[7])[row] = p ? (uint32_t)self->acceleration.x.bits : 0;
    valid[7][row] = p;
    p = self->acceleration_present;
    ((uint32_t *)cols[8])[row] = p ? (uint32_t)self->acceleration.y.bits : 0;
    valid[8][row] = p;
    p = self->acceleration_present;
    ((uint32_t *)cols[9])[row] = p ? (uint32_t)self->acceleration.z.bits : 0;
    valid[9][row] = p;
    p = self->velocity_present;
    ((uint32_t *)cols[10])[row] = p ? (uint32_t)self->velocity.x.bits : 0;
    valid[10][row] = p;
    p = self->velocity_present;
    ((uint32_t *)cols[11])[row] = p ? (uint32_t)self->velocity.y.bits : 0;
    valid[11][row] = p;
    p = self->velocity_present;
    ((uint32_t *)cols[12])[row] = p ? (uint32_t)self->velocity.z.bits : 0;
    valid[12][row] = p;
    p = self->velocity_present;
    ((uint8_t *)cols[13])[row] = p ? (uint8_t)self->velocity.data_valid : 0;
    valid[13][row] = p;
    p = self->velocity_present;
    ((uint8_t *)cols[14])[row] = p ? (uint8_t)self->velocity.sensor_id : 0;
    valid[14][row] = p;
    p = self->velocity_present;
    ((uint8_t *)cols[15])[row] = p ? (uint8_t)self->velocity.reserved : 0;
    valid[15][row] = p;
    p = self->angular_rate_present;
    ((uint32_t *)cols[16])[row] = p ? (uint32_t)self->angular_rate.x.bits : 0;
    valid[16][row] = p;
    p = self->angular_rate_present;
    ((uint32_t *)cols[17])[row] = p ? (uint32_t)self->angular_rate.y.bits : 0;
    valid[17][row] = p;
    p = self->angular_rate_present;
    ((uint32_t *)cols[18])[row] = p ? (uint32_t)self->angular_rate.z.bits : 0;
    valid[18][row] = p;
    p = self->position_present;
    ((uint64_t *)cols[19])[row] = p ? (uint64_t)self->position.latitude.bits : 0;
    valid[19][row] = p;
    p = self->position_present;
    ((uint64_t *)cols[20])[row] = p ? (uint64_t)self->position.longitude.bits : 0;
    valid[20][row] = p;
    p = self->position_present;
    ((uint32_t *)cols[21])[row] = p ? (uint32_t)self->position.altitude.bits : 0;
    valid[21][row] = p;
    p = self->position_present;
    ((uint32_t *)cols[22])[row] = p ? (uint32_t)self->position.height.bits : 0;
    valid[22][row] = p;
    p = self->position_present;
    ((uint8_t *)cols[23])[row] = p ? (uint8_t)self->position.gps_health : 0;
    valid[23][row] = p;
    p = self->gps_detail_present;
    ((uint32_t *)cols[24])[row] = p ? (uint32_t)self->gps_detail.date : 0;
    valid[24][row] = p;
    p = self->gps_detail_present;
    ((uint32_t *)cols[25])[row] = p ? (uint32_t)self->gps_detail.time : 0;
    valid[25][row] = p;
    p = self->gps_detail_present;
    ((int32_t *)cols[26])[row] = p ? (int32_t)self->gps_detail.longitude : 0;
    valid[26][row] = p;
    p = self->gps_detail_present;
    ((int32_t *)cols[27])[row] = p ? (int32_t)self->gps_detail.latitude : 0;
    valid[27][row] = p;
    p = self->gps_detail_present;
    ((int32_t *)cols[28])[row] = p ? (int32_t)self->gps_detail.height_msl : 0;
    valid[28][row] = p;
    p = self->gps_detail_present;
    ((uint32_t *)cols[29])[row] = p ? (uint32_t)self->gps_detail.vel_n.bits : 0;
    valid[29][row] = p;
    p = self->gps_detail_present;
    ((uint32_t *)cols[30])[row] = p ? (uint32_t)self->gps_detail.vel_e.bits : 0;
    valid[30][row] = p;
    p = self->gps_detail_present;
    ((uint32_t *)cols[31])[row] = p ? (uint32_t)self->gps_detail.vel_d.bits : 0;
    valid[31][row] = p;
    p = self->rtk_detail_present;
    ((uint32_t *)cols[32])[row] = p ? (uint32_t)self->rtk_detail.date : 0;
    valid[32][row] = p;
    p = self->rtk_detail_present;
    ((uint32_t *)cols[33])[row] = p ? (uint32_t)self->rtk_detail.time : 0;
    valid[33][row] = p;
    p = self->rtk_detail_present;
    ((uint64_t *)cols[34])[row] = p ? (uint64_t)self->rtk_detail.longitude.bits : 0;
    valid[34][row] = p;
    p = self->rtk_detail_present;
    ((uint64_t *)cols[35])[row] = p ? (uint64_t)self->rtk_detail.latitude.bits : 0;
    valid[35][row] = p;
    p = self->rtk_detail_present;
    ((uint32_t *)cols[36])[row] = p ? (uint32_t)self->rtk_detail.height_msl.bits : 0;
    valid[36][row] = p;
    p = self->rtk_detail_present;
    ((uint32_t *)cols[37])[row] = p ? (uint32_t)self->rtk_detail.vel_n.bits : 0;
    valid[37][row] = p;
    p = self->rtk_detail_present;
    ((uint32_t *)cols[38])[row] = p ? (uint32_t)self->rtk_detail.vel_e.bits : 0;
    valid[38][row] = p;
    p = self->rtk_detail_present;
    ((uint32_t *)cols[39])[row] = p ? (uint32_t)self->rtk_detail.vel_d.bits : 0;
    valid[39][row] = p;
    p = self->rtk_detail_present;
    ((int16_t *)cols[40])[row] = p ? (int16_t)self->rtk_detail.yaw : 0;
    valid[40][row] = p;
    p = self->rtk_detail_present;
    ((uint8_t *)cols[41])[row] = p ? (uint8_t)self->rtk_detail.position_flag : 0;
    valid[41][row] = p;
    p = self->rtk_detail_present;
    ((uint8_t *)cols[42])[row] = p ? (uint8_t)self->rtk_detail.yaw_flag : 0;
    valid[42][row] = p;
    p = self->magnetometer_present;
    ((int16_t *)cols[43])[row] = p ? (int16_t)self->magnetometer.x : 0;
    valid[43][row] = p;
    p = self->magnetometer_present;
    ((int16_t *)cols[44])[row] = p ? (int16_t)self->magnetometer.y : 0;
    valid[44][row] = p;
    p = self->magnetometer_present;
    ((int16_t *)cols[45])[row] = p ? (int16_t)self->magnetometer.z : 0;
    valid[45][row] = p;
    p = self->rc_present;
    ((int16_t *)cols[46])[row] = p ? (int16_t)self->rc.roll : 0;
    valid[46][row] = p;
    p = self->rc_present;
    ((int16_t *)cols[47])[row] = p ? (int16_t)self->rc.pitch : 0;
    valid[47][row] = p;
    p = self->rc_present;
    ((int16_t *)cols[48])[row] = p ? (int16_t)self->rc.yaw : 0;
    valid[48][row] = p;
    p = self->rc_present;
    ((int16_t *)cols[49])[row] = p ? (int16_t)self->rc.throttle : 0;
    valid[49][row] = p;
    p = self->rc_present;
    ((int16_t *)cols[50])[row] = p ? (int16_t)self->rc.mode : 0;
    valid[50][row] = p;
    p = self->rc_present;
    ((int16_t *)cols[51])[row] = p ? (int16_t)self->rc.gear : 0;
    valid[51][row] = p;
    p = self->gimbal_present;
    ((uint32_t *)cols[52])[row] = p ? (uint32_t)self->gimbal.roll.bits : 0;
    valid[52][row] = p;
    p = self->gimbal_present;
    ((uint32_t *)cols[53])[row] = p ? (uint32_t)self->gimbal.pitch.bits : 0;
    valid[53][row] = p;
    p = self->gimbal_present;
    ((uint32_t *)cols[54])[row] = p ? (uint32_t)self->gimbal.yaw.bits : 0;
    valid[54][row] = p;
    p = self->gimbal_present && self->gimbal.limit_present;
    ((uint8_t *)cols[55])[row] = p ? (uint8_t)self->gimbal.limit.pitch_limit : 0;
    valid[55][row] = p;
    p = self->gimbal_present && self->gimbal.limit_present;
    ((uint8_t *)cols[56])[row] = p ? (uint8_t)self->gimbal.limit.roll_limit : 0;
    valid[56][row] = p;
    p = self->gimbal_present && self->gimbal.limit_present;
    ((uint8_t *)cols[57])[row] = p ? (uint8_t)self->gimbal.limit.yaw_limit : 0;
    valid[57][row] = p;
    p = self->gimbal_present && self->gimbal.limit_present;
    ((uint8_t *)cols[58])[row] = p ? (uint8_t)self->gimbal.limit.reserved : 0;
    valid[58][row] = p;
    p = self->flight_status_present;
    ((uint8_t *)cols[59])[row] = p ? (uint8_t)self->flight_status : 0;
    valid[59][row] = p;
    p = self->battery_present;
    ((uint8_t *)cols[60])[row] = p ? (uint8_t)self->battery : 0;
    valid[60][row] = p;
    p = self->control_info_present && self->control_info.cur_mov_control_mode_present;
    ((uint8_t *)cols[61])[row] = p ? (uint8_t)self->control_info.cur_mov_control_mode : 0;
    valid[61][row] = p;
    p = self->control_info_present;
    ((uint8_t *)cols[62])[row] = p ? (uint8_t)self->control_info.control_device : 0;
    valid[62][row] = p;
    p = self->control_info_present;
    ((uint8_t *)cols[63])[row] = p ? (uint8_t)self->control_info.onboard_requested : 0;
    valid[63][row] = p;
    p = self->control_info_present;
    ((uint8_t *)cols[64])[row] = p ? (uint8_t)self->control_info.virtual_rc : 0;
    valid[64][row] = p;
    p = self->control_info_present;
    ((uint8_t *)cols[65])[row] = p ? (uint8_t)self->control_info.reserved : 0;
    valid[65][row] = p;
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

