/* Generated from spec/ by tools/cgen/generate.py. Do not edit. */
/* osdk_model_json.c - see osdk_model_json.h. */
#include "osdk_model_json.h"

#include <string.h>

/* ---- model of each ksy type -------------------------------------------------------------- */

/* osdk_broadcast_a3_fw3_1 */
void osdk_broadcast_a3_fw3_1_to_json(const osdk_broadcast_a3_fw3_1_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "has_time_stamp");
    osdk_json_bool(w, self->has_time_stamp);
    osdk_json_key(w, "has_quaternion");
    osdk_json_bool(w, self->has_quaternion);
    osdk_json_key(w, "has_acceleration");
    osdk_json_bool(w, self->has_acceleration);
    osdk_json_key(w, "has_velocity");
    osdk_json_bool(w, self->has_velocity);
    osdk_json_key(w, "has_angular_rate");
    osdk_json_bool(w, self->has_angular_rate);
    osdk_json_key(w, "has_position");
    osdk_json_bool(w, self->has_position);
    osdk_json_key(w, "has_gps_detail");
    osdk_json_bool(w, self->has_gps_detail);
    osdk_json_key(w, "has_rtk_detail");
    osdk_json_bool(w, self->has_rtk_detail);
    osdk_json_key(w, "has_magnetometer");
    osdk_json_bool(w, self->has_magnetometer);
    osdk_json_key(w, "has_rc");
    osdk_json_bool(w, self->has_rc);
    osdk_json_key(w, "has_gimbal");
    osdk_json_bool(w, self->has_gimbal);
    osdk_json_key(w, "has_flight_status");
    osdk_json_bool(w, self->has_flight_status);
    osdk_json_key(w, "has_battery");
    osdk_json_bool(w, self->has_battery);
    osdk_json_key(w, "has_control_info");
    osdk_json_bool(w, self->has_control_info);
    osdk_json_key(w, "reserved_flags");
    osdk_json_uint(w, (uint64_t)self->reserved_flags);
    if (self->time_stamp_present) {
        osdk_json_key(w, "time_stamp");
        osdk_broadcast_items_time_stamp_to_json(&self->time_stamp, w);
    }
    if (self->quaternion_present) {
        osdk_json_key(w, "quaternion");
        osdk_broadcast_items_quaternion_to_json(&self->quaternion, w);
    }
    if (self->acceleration_present) {
        osdk_json_key(w, "acceleration");
        osdk_broadcast_items_vector3f_to_json(&self->acceleration, w);
    }
    if (self->velocity_present) {
        osdk_json_key(w, "velocity");
        osdk_broadcast_items_velocity_to_json(&self->velocity, w);
    }
    if (self->angular_rate_present) {
        osdk_json_key(w, "angular_rate");
        osdk_broadcast_items_vector3f_to_json(&self->angular_rate, w);
    }
    if (self->position_present) {
        osdk_json_key(w, "position");
        osdk_broadcast_items_position_to_json(&self->position, w);
    }
    if (self->gps_detail_present) {
        osdk_json_key(w, "gps_detail");
        osdk_broadcast_items_gps_detail_to_json(&self->gps_detail, w);
    }
    if (self->rtk_detail_present) {
        osdk_json_key(w, "rtk_detail");
        osdk_broadcast_items_rtk_detail_to_json(&self->rtk_detail, w);
    }
    if (self->magnetometer_present) {
        osdk_json_key(w, "magnetometer");
        osdk_broadcast_items_magnetometer_to_json(&self->magnetometer, w);
    }
    if (self->rc_present) {
        osdk_json_key(w, "rc");
        osdk_broadcast_items_rc_to_json(&self->rc, w);
    }
    if (self->gimbal_present) {
        osdk_json_key(w, "gimbal");
        osdk_broadcast_items_gimbal_to_json(&self->gimbal, w);
    }
    if (self->flight_status_present) {
        osdk_json_key(w, "flight_status");
        osdk_json_uint(w, (uint64_t)self->flight_status);
    }
    if (self->battery_present) {
        osdk_json_key(w, "battery");
        osdk_json_uint(w, (uint64_t)self->battery);
    }
    if (self->control_info_present) {
        osdk_json_key(w, "control_info");
        osdk_broadcast_items_control_info_to_json(&self->control_info, w);
    }
    osdk_json_end_object(w);
}

/* osdk_broadcast_a3_fw3_1: the model of one field; false when it has no such field or it is absent */
bool osdk_broadcast_a3_fw3_1_field_to_json(const osdk_broadcast_a3_fw3_1_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "has_time_stamp") == 0) {
        osdk_json_bool(w, self->has_time_stamp);
        return true;
    }
    if (strcmp(field, "has_quaternion") == 0) {
        osdk_json_bool(w, self->has_quaternion);
        return true;
    }
    if (strcmp(field, "has_acceleration") == 0) {
        osdk_json_bool(w, self->has_acceleration);
        return true;
    }
    if (strcmp(field, "has_velocity") == 0) {
        osdk_json_bool(w, self->has_velocity);
        return true;
    }
    if (strcmp(field, "has_angular_rate") == 0) {
        osdk_json_bool(w, self->has_angular_rate);
        return true;
    }
    if (strcmp(field, "has_position") == 0) {
        osdk_json_bool(w, self->has_position);
        return true;
    }
    if (strcmp(field, "has_gps_detail") == 0) {
        osdk_json_bool(w, self->has_gps_detail);
        return true;
    }
    if (strcmp(field, "has_rtk_detail") == 0) {
        osdk_json_bool(w, self->has_rtk_detail);
        return true;
    }
    if (strcmp(field, "has_magnetometer") == 0) {
        osdk_json_bool(w, self->has_magnetometer);
        return true;
    }
    if (strcmp(field, "has_rc") == 0) {
        osdk_json_bool(w, self->has_rc);
        return true;
    }
    if (strcmp(field, "has_gimbal") == 0) {
        osdk_json_bool(w, self->has_gimbal);
        return true;
    }
    if (strcmp(field, "has_flight_status") == 0) {
        osdk_json_bool(w, self->has_flight_status);
        return true;
    }
    if (strcmp(field, "has_battery") == 0) {
        osdk_json_bool(w, self->has_battery);
        return true;
    }
    if (strcmp(field, "has_control_info") == 0) {
        osdk_json_bool(w, self->has_control_info);
        return true;
    }
    if (strcmp(field, "reserved_flags") == 0) {
        osdk_json_uint(w, (uint64_t)self->reserved_flags);
        return true;
    }
    if (strcmp(field, "time_stamp") == 0 && self->time_stamp_present) {
        osdk_broadcast_items_time_stamp_to_json(&self->time_stamp, w);
        return true;
    }
    if (strcmp(field, "quaternion") == 0 && self->quaternion_present) {
        osdk_broadcast_items_quaternion_to_json(&self->quaternion, w);
        return true;
    }
    if (strcmp(field, "acceleration") == 0 && self->acceleration_present) {
        osdk_broadcast_items_vector3f_to_json(&self->acceleration, w);
        return true;
    }
    if (strcmp(field, "velocity") == 0 && self->velocity_present) {
        osdk_broadcast_items_velocity_to_json(&self->velocity, w);
        return true;
    }
    if (strcmp(field, "angular_rate") == 0 && self->angular_rate_present) {
        osdk_broadcast_items_vector3f_to_json(&self->angular_rate, w);
        return true;
    }
    if (strcmp(field, "position") == 0 && self->position_present) {
        osdk_broadcast_items_position_to_json(&self->position, w);
        return true;
    }
    if (strcmp(field, "gps_detail") == 0 && self->gps_detail_present) {
        osdk_broadcast_items_gps_detail_to_json(&self->gps_detail, w);
        return true;
    }
    if (strcmp(field, "rtk_detail") == 0 && self->rtk_detail_present) {
        osdk_broadcast_items_rtk_detail_to_json(&self->rtk_detail, w);
        return true;
    }
    if (strcmp(field, "magnetometer") == 0 && self->magnetometer_present) {
        osdk_broadcast_items_magnetometer_to_json(&self->magnetometer, w);
        return true;
    }
    if (strcmp(field, "rc") == 0 && self->rc_present) {
        osdk_broadcast_items_rc_to_json(&self->rc, w);
        return true;
    }
    if (strcmp(field, "gimbal") == 0 && self->gimbal_present) {
        osdk_broadcast_items_gimbal_to_json(&self->gimbal, w);
        return true;
    }
    if (strcmp(field, "flight_status") == 0 && self->flight_status_present) {
        osdk_json_uint(w, (uint64_t)self->flight_status);
        return true;
    }
    if (strcmp(field, "battery") == 0 && self->battery_present) {
        osdk_json_uint(w, (uint64_t)self->battery);
        return true;
    }
    if (strcmp(field, "control_info") == 0 && self->control_info_present) {
        osdk_broadcast_items_control_info_to_json(&self->control_info, w);
        return true;
    }
    if (strcmp(field, "trailing") == 0) {
        osdk_json_hex(w, self->trailing.ptr, self->trailing.len);
        return true;
    }
    return false;
}

/* osdk_broadcast_items::control_info */
void osdk_broadcast_items_control_info_to_json(const osdk_broadcast_items_control_info_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    if (self->cur_mov_control_mode_present) {
        osdk_json_key(w, "cur_mov_control_mode");
        osdk_json_enum(w, (int64_t)self->cur_mov_control_mode, osdk_broadcast_items_cur_mov_control_mode_name((int64_t)self->cur_mov_control_mode));
    }
    osdk_json_key(w, "control_device");
    osdk_json_enum(w, (int64_t)self->control_device, osdk_broadcast_items_control_device_name((int64_t)self->control_device));
    osdk_json_key(w, "onboard_requested");
    osdk_json_bool(w, self->onboard_requested);
    osdk_json_key(w, "virtual_rc");
    osdk_json_bool(w, self->virtual_rc);
    osdk_json_key(w, "reserved");
    osdk_json_uint(w, (uint64_t)self->reserved);
    osdk_json_end_object(w);
}

/* osdk_broadcast_items::control_info: the model of one field; false when it has no such field or it is absent */
bool osdk_broadcast_items_control_info_field_to_json(const osdk_broadcast_items_control_info_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "cur_mov_control_mode") == 0 && self->cur_mov_control_mode_present) {
        osdk_json_enum(w, (int64_t)self->cur_mov_control_mode, osdk_broadcast_items_cur_mov_control_mode_name((int64_t)self->cur_mov_control_mode));
        return true;
    }
    if (strcmp(field, "control_device") == 0) {
        osdk_json_enum(w, (int64_t)self->control_device, osdk_broadcast_items_control_device_name((int64_t)self->control_device));
        return true;
    }
    if (strcmp(field, "onboard_requested") == 0) {
        osdk_json_bool(w, self->onboard_requested);
        return true;
    }
    if (strcmp(field, "virtual_rc") == 0) {
        osdk_json_bool(w, self->virtual_rc);
        return true;
    }
    if (strcmp(field, "reserved") == 0) {
        osdk_json_uint(w, (uint64_t)self->reserved);
        return true;
    }
    return false;
}

/* osdk_broadcast_items::gimbal */
void osdk_broadcast_items_gimbal_to_json(const osdk_broadcast_items_gimbal_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "roll");
    osdk_json_f32(w, self->roll.bits);
    osdk_json_key(w, "pitch");
    osdk_json_f32(w, self->pitch.bits);
    osdk_json_key(w, "yaw");
    osdk_json_f32(w, self->yaw.bits);
    if (self->limit_present) {
        osdk_json_key(w, "limit");
        osdk_broadcast_items_gimbal_limit_to_json(&self->limit, w);
    }
    osdk_json_end_object(w);
}

/* osdk_broadcast_items::gimbal: the model of one field; false when it has no such field or it is absent */
bool osdk_broadcast_items_gimbal_field_to_json(const osdk_broadcast_items_gimbal_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "roll") == 0) {
        osdk_json_f32(w, self->roll.bits);
        return true;
    }
    if (strcmp(field, "pitch") == 0) {
        osdk_json_f32(w, self->pitch.bits);
        return true;
    }
    if (strcmp(field, "yaw") == 0) {
        osdk_json_f32(w, self->yaw.bits);
        return true;
    }
    if (strcmp(field, "limit") == 0 && self->limit_present) {
        osdk_broadcast_items_gimbal_limit_to_json(&self->limit, w);
        return true;
    }
    return false;
}

/* osdk_broadcast_items::gimbal_limit */
void osdk_broadcast_items_gimbal_limit_to_json(const osdk_broadcast_items_gimbal_limit_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "pitch_limit");
    osdk_json_bool(w, self->pitch_limit);
    osdk_json_key(w, "roll_limit");
    osdk_json_bool(w, self->roll_limit);
    osdk_json_key(w, "yaw_limit");
    osdk_json_bool(w, self->yaw_limit);
    osdk_json_key(w, "reserved");
    osdk_json_uint(w, (uint64_t)self->reserved);
    osdk_json_end_object(w);
}

/* osdk_broadcast_items::gimbal_limit: the model of one field; false when it has no such field or it is absent */
bool osdk_broadcast_items_gimbal_limit_field_to_json(const osdk_broadcast_items_gimbal_limit_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "pitch_limit") == 0) {
        osdk_json_bool(w, self->pitch_limit);
        return true;
    }
    if (strcmp(field, "roll_limit") == 0) {
        osdk_json_bool(w, self->roll_limit);
        return true;
    }
    if (strcmp(field, "yaw_limit") == 0) {
        osdk_json_bool(w, self->yaw_limit);
        return true;
    }
    if (strcmp(field, "reserved") == 0) {
        osdk_json_uint(w, (uint64_t)self->reserved);
        return true;
    }
    return false;
}

/* osdk_broadcast_items::gps_detail */
void osdk_broadcast_items_gps_detail_to_json(const osdk_broadcast_items_gps_detail_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "date");
    osdk_json_uint(w, (uint64_t)self->date);
    osdk_json_key(w, "time");
    osdk_json_uint(w, (uint64_t)self->time);
    osdk_json_key(w, "longitude");
    osdk_json_int(w, (int64_t)self->longitude);
    osdk_json_key(w, "latitude");
    osdk_json_int(w, (int64_t)self->latitude);
    osdk_json_key(w, "height_msl");
    osdk_json_int(w, (int64_t)self->height_msl);
    osdk_json_key(w, "vel_n");
    osdk_json_f32(w, self->vel_n.bits);
    osdk_json_key(w, "vel_e");
    osdk_json_f32(w, self->vel_e.bits);
    osdk_json_key(w, "vel_d");
    osdk_json_f32(w, self->vel_d.bits);
    osdk_json_end_object(w);
}

/* osdk_broadcast_items::gps_detail: the model of one field; false when it has no such field or it is absent */
bool osdk_broadcast_items_gps_detail_field_to_json(const osdk_broadcast_items_gps_detail_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "date") == 0) {
        osdk_json_uint(w, (uint64_t)self->date);
        return true;
    }
    if (strcmp(field, "time") == 0) {
        osdk_json_uint(w, (uint64_t)self->time);
        return true;
    }
    if (strcmp(field, "longitude") == 0) {
        osdk_json_int(w, (int64_t)self->longitude);
        return true;
    }
    if (strcmp(field, "latitude") == 0) {
        osdk_json_int(w, (int64_t)self->latitude);
        return true;
    }
    if (strcmp(field, "height_msl") == 0) {
        osdk_json_int(w, (int64_t)self->height_msl);
        return true;
    }
    if (strcmp(field, "vel_n") == 0) {
        osdk_json_f32(w, self->vel_n.bits);
        return true;
    }
    if (strcmp(field, "vel_e") == 0) {
        osdk_json_f32(w, self->vel_e.bits);
        return true;
    }
    if (strcmp(field, "vel_d") == 0) {
        osdk_json_f32(w, self->vel_d.bits);
        return true;
    }
    return false;
}

/* osdk_broadcast_items::magnetometer */
void osdk_broadcast_items_magnetometer_to_json(const osdk_broadcast_items_magnetometer_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "x");
    osdk_json_int(w, (int64_t)self->x);
    osdk_json_key(w, "y");
    osdk_json_int(w, (int64_t)self->y);
    osdk_json_key(w, "z");
    osdk_json_int(w, (int64_t)self->z);
    osdk_json_end_object(w);
}

/* osdk_broadcast_items::magnetometer: the model of one field; false when it has no such field or it is absent */
bool osdk_broadcast_items_magnetometer_field_to_json(const osdk_broadcast_items_magnetometer_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "x") == 0) {
        osdk_json_int(w, (int64_t)self->x);
        return true;
    }
    if (strcmp(field, "y") == 0) {
        osdk_json_int(w, (int64_t)self->y);
        return true;
    }
    if (strcmp(field, "z") == 0) {
        osdk_json_int(w, (int64_t)self->z);
        return true;
    }
    return false;
}

/* osdk_broadcast_items::position */
void osdk_broadcast_items_position_to_json(const osdk_broadcast_items_position_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "latitude");
    osdk_json_f64(w, self->latitude.bits);
    osdk_json_key(w, "longitude");
    osdk_json_f64(w, self->longitude.bits);
    osdk_json_key(w, "altitude");
    osdk_json_f32(w, self->altitude.bits);
    osdk_json_key(w, "height");
    osdk_json_f32(w, self->height.bits);
    osdk_json_key(w, "gps_health");
    osdk_json_uint(w, (uint64_t)self->gps_health);
    osdk_json_end_object(w);
}

/* osdk_broadcast_items::position: the model of one field; false when it has no such field or it is absent */
bool osdk_broadcast_items_position_field_to_json(const osdk_broadcast_items_position_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "latitude") == 0) {
        osdk_json_f64(w, self->latitude.bits);
        return true;
    }
    if (strcmp(field, "longitude") == 0) {
        osdk_json_f64(w, self->longitude.bits);
        return true;
    }
    if (strcmp(field, "altitude") == 0) {
        osdk_json_f32(w, self->altitude.bits);
        return true;
    }
    if (strcmp(field, "height") == 0) {
        osdk_json_f32(w, self->height.bits);
        return true;
    }
    if (strcmp(field, "gps_health") == 0) {
        osdk_json_uint(w, (uint64_t)self->gps_health);
        return true;
    }
    return false;
}

/* osdk_broadcast_items::quaternion */
void osdk_broadcast_items_quaternion_to_json(const osdk_broadcast_items_quaternion_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "q0");
    osdk_json_f32(w, self->q0.bits);
    osdk_json_key(w, "q1");
    osdk_json_f32(w, self->q1.bits);
    osdk_json_key(w, "q2");
    osdk_json_f32(w, self->q2.bits);
    osdk_json_key(w, "q3");
    osdk_json_f32(w, self->q3.bits);
    osdk_json_end_object(w);
}

/* osdk_broadcast_items::quaternion: the model of one field; false when it has no such field or it is absent */
bool osdk_broadcast_items_quaternion_field_to_json(const osdk_broadcast_items_quaternion_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "q0") == 0) {
        osdk_json_f32(w, self->q0.bits);
        return true;
    }
    if (strcmp(field, "q1") == 0) {
        osdk_json_f32(w, self->q1.bits);
        return true;
    }
    if (strcmp(field, "q2") == 0) {
        osdk_json_f32(w, self->q2.bits);
        return true;
    }
    if (strcmp(field, "q3") == 0) {
        osdk_json_f32(w, self->q3.bits);
        return true;
    }
    return false;
}

/* osdk_broadcast_items::rc */
void osdk_broadcast_items_rc_to_json(const osdk_broadcast_items_rc_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "roll");
    osdk_json_int(w, (int64_t)self->roll);
    osdk_json_key(w, "pitch");
    osdk_json_int(w, (int64_t)self->pitch);
    osdk_json_key(w, "yaw");
    osdk_json_int(w, (int64_t)self->yaw);
    osdk_json_key(w, "throttle");
    osdk_json_int(w, (int64_t)self->throttle);
    osdk_json_key(w, "mode");
    osdk_json_int(w, (int64_t)self->mode);
    osdk_json_key(w, "gear");
    osdk_json_int(w, (int64_t)self->gear);
    osdk_json_end_object(w);
}

/* osdk_broadcast_items::rc: the model of one field; false when it has no such field or it is absent */
bool osdk_broadcast_items_rc_field_to_json(const osdk_broadcast_items_rc_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "roll") == 0) {
        osdk_json_int(w, (int64_t)self->roll);
        return true;
    }
    if (strcmp(field, "pitch") == 0) {
        osdk_json_int(w, (int64_t)self->pitch);
        return true;
    }
    if (strcmp(field, "yaw") == 0) {
        osdk_json_int(w, (int64_t)self->yaw);
        return true;
    }
    if (strcmp(field, "throttle") == 0) {
        osdk_json_int(w, (int64_t)self->throttle);
        return true;
    }
    if (strcmp(field, "mode") == 0) {
        osdk_json_int(w, (int64_t)self->mode);
        return true;
    }
    if (strcmp(field, "gear") == 0) {
        osdk_json_int(w, (int64_t)self->gear);
        return true;
    }
    return false;
}

/* osdk_broadcast_items::rtk_detail */
void osdk_broadcast_items_rtk_detail_to_json(const osdk_broadcast_items_rtk_detail_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "date");
    osdk_json_uint(w, (uint64_t)self->date);
    osdk_json_key(w, "time");
    osdk_json_uint(w, (uint64_t)self->time);
    osdk_json_key(w, "longitude");
    osdk_json_f64(w, self->longitude.bits);
    osdk_json_key(w, "latitude");
    osdk_json_f64(w, self->latitude.bits);
    osdk_json_key(w, "height_msl");
    osdk_json_f32(w, self->height_msl.bits);
    osdk_json_key(w, "vel_n");
    osdk_json_f32(w, self->vel_n.bits);
    osdk_json_key(w, "vel_e");
    osdk_json_f32(w, self->vel_e.bits);
    osdk_json_key(w, "vel_d");
    osdk_json_f32(w, self->vel_d.bits);
    osdk_json_key(w, "yaw");
    osdk_json_int(w, (int64_t)self->yaw);
    osdk_json_key(w, "position_flag");
    osdk_json_uint(w, (uint64_t)self->position_flag);
    osdk_json_key(w, "yaw_flag");
    osdk_json_uint(w, (uint64_t)self->yaw_flag);
    osdk_json_end_object(w);
}

/* osdk_broadcast_items::rtk_detail: the model of one field; false when it has no such field or it is absent */
bool osdk_broadcast_items_rtk_detail_field_to_json(const osdk_broadcast_items_rtk_detail_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "date") == 0) {
        osdk_json_uint(w, (uint64_t)self->date);
        return true;
    }
    if (strcmp(field, "time") == 0) {
        osdk_json_uint(w, (uint64_t)self->time);
        return true;
    }
    if (strcmp(field, "longitude") == 0) {
        osdk_json_f64(w, self->longitude.bits);
        return true;
    }
    if (strcmp(field, "latitude") == 0) {
        osdk_json_f64(w, self->latitude.bits);
        return true;
    }
    if (strcmp(field, "height_msl") == 0) {
        osdk_json_f32(w, self->height_msl.bits);
        return true;
    }
    if (strcmp(field, "vel_n") == 0) {
        osdk_json_f32(w, self->vel_n.bits);
        return true;
    }
    if (strcmp(field, "vel_e") == 0) {
        osdk_json_f32(w, self->vel_e.bits);
        return true;
    }
    if (strcmp(field, "vel_d") == 0) {
        osdk_json_f32(w, self->vel_d.bits);
        return true;
    }
    if (strcmp(field, "yaw") == 0) {
        osdk_json_int(w, (int64_t)self->yaw);
        return true;
    }
    if (strcmp(field, "position_flag") == 0) {
        osdk_json_uint(w, (uint64_t)self->position_flag);
        return true;
    }
    if (strcmp(field, "yaw_flag") == 0) {
        osdk_json_uint(w, (uint64_t)self->yaw_flag);
        return true;
    }
    return false;
}

/* osdk_broadcast_items::time_stamp */
void osdk_broadcast_items_time_stamp_to_json(const osdk_broadcast_items_time_stamp_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "time");
    osdk_json_uint(w, (uint64_t)self->time);
    if (self->nano_time_present) {
        osdk_json_key(w, "nano_time");
        osdk_json_uint(w, (uint64_t)self->nano_time);
    }
    if (self->sync_flag_present) {
        osdk_json_key(w, "sync_flag");
        osdk_json_uint(w, (uint64_t)self->sync_flag);
    }
    osdk_json_end_object(w);
}

/* osdk_broadcast_items::time_stamp: the model of one field; false when it has no such field or it is absent */
bool osdk_broadcast_items_time_stamp_field_to_json(const osdk_broadcast_items_time_stamp_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "time") == 0) {
        osdk_json_uint(w, (uint64_t)self->time);
        return true;
    }
    if (strcmp(field, "nano_time") == 0 && self->nano_time_present) {
        osdk_json_uint(w, (uint64_t)self->nano_time);
        return true;
    }
    if (strcmp(field, "sync_flag") == 0 && self->sync_flag_present) {
        osdk_json_uint(w, (uint64_t)self->sync_flag);
        return true;
    }
    return false;
}

/* osdk_broadcast_items::vector3f */
void osdk_broadcast_items_vector3f_to_json(const osdk_broadcast_items_vector3f_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "x");
    osdk_json_f32(w, self->x.bits);
    osdk_json_key(w, "y");
    osdk_json_f32(w, self->y.bits);
    osdk_json_key(w, "z");
    osdk_json_f32(w, self->z.bits);
    osdk_json_end_object(w);
}

/* osdk_broadcast_items::vector3f: the model of one field; false when it has no such field or it is absent */
bool osdk_broadcast_items_vector3f_field_to_json(const osdk_broadcast_items_vector3f_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "x") == 0) {
        osdk_json_f32(w, self->x.bits);
        return true;
    }
    if (strcmp(field, "y") == 0) {
        osdk_json_f32(w, self->y.bits);
        return true;
    }
    if (strcmp(field, "z") == 0) {
        osdk_json_f32(w, self->z.bits);
        return true;
    }
    return false;
}

/* osdk_broadcast_items::velocity */
void osdk_broadcast_items_velocity_to_json(const osdk_broadcast_items_velocity_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "x");
    osdk_json_f32(w, self->x.bits);
    osdk_json_key(w, "y");
    osdk_json_f32(w, self->y.bits);
    osdk_json_key(w, "z");
    osdk_json_f32(w, self->z.bits);
    osdk_json_key(w, "data_valid");
    osdk_json_bool(w, self->data_valid);
    osdk_json_key(w, "sensor_id");
    osdk_json_uint(w, (uint64_t)self->sensor_id);
    osdk_json_key(w, "reserved");
    osdk_json_uint(w, (uint64_t)self->reserved);
    osdk_json_end_object(w);
}

/* osdk_broadcast_items::velocity: the model of one field; false when it has no such field or it is absent */
bool osdk_broadcast_items_velocity_field_to_json(const osdk_broadcast_items_velocity_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "x") == 0) {
        osdk_json_f32(w, self->x.bits);
        return true;
    }
    if (strcmp(field, "y") == 0) {
        osdk_json_f32(w, self->y.bits);
        return true;
    }
    if (strcmp(field, "z") == 0) {
        osdk_json_f32(w, self->z.bits);
        return true;
    }
    if (strcmp(field, "data_valid") == 0) {
        osdk_json_bool(w, self->data_valid);
        return true;
    }
    if (strcmp(field, "sensor_id") == 0) {
        osdk_json_uint(w, (uint64_t)self->sensor_id);
        return true;
    }
    if (strcmp(field, "reserved") == 0) {
        osdk_json_uint(w, (uint64_t)self->reserved);
        return true;
    }
    return false;
}

/* osdk_broadcast_m100_fw2_3 */
void osdk_broadcast_m100_fw2_3_to_json(const osdk_broadcast_m100_fw2_3_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "has_time_stamp");
    osdk_json_bool(w, self->has_time_stamp);
    osdk_json_key(w, "has_quaternion");
    osdk_json_bool(w, self->has_quaternion);
    osdk_json_key(w, "has_acceleration");
    osdk_json_bool(w, self->has_acceleration);
    osdk_json_key(w, "has_velocity");
    osdk_json_bool(w, self->has_velocity);
    osdk_json_key(w, "has_angular_rate");
    osdk_json_bool(w, self->has_angular_rate);
    osdk_json_key(w, "has_position");
    osdk_json_bool(w, self->has_position);
    osdk_json_key(w, "has_magnetometer");
    osdk_json_bool(w, self->has_magnetometer);
    osdk_json_key(w, "has_rc");
    osdk_json_bool(w, self->has_rc);
    osdk_json_key(w, "has_gimbal");
    osdk_json_bool(w, self->has_gimbal);
    osdk_json_key(w, "has_flight_status");
    osdk_json_bool(w, self->has_flight_status);
    osdk_json_key(w, "has_battery");
    osdk_json_bool(w, self->has_battery);
    osdk_json_key(w, "has_control_info");
    osdk_json_bool(w, self->has_control_info);
    osdk_json_key(w, "reserved_flags");
    osdk_json_uint(w, (uint64_t)self->reserved_flags);
    if (self->time_stamp_present) {
        osdk_json_key(w, "time_stamp");
        osdk_broadcast_items_time_stamp_to_json(&self->time_stamp, w);
    }
    if (self->quaternion_present) {
        osdk_json_key(w, "quaternion");
        osdk_broadcast_items_quaternion_to_json(&self->quaternion, w);
    }
    if (self->acceleration_present) {
        osdk_json_key(w, "acceleration");
        osdk_broadcast_items_vector3f_to_json(&self->acceleration, w);
    }
    if (self->velocity_present) {
        osdk_json_key(w, "velocity");
        osdk_broadcast_items_velocity_to_json(&self->velocity, w);
    }
    if (self->angular_rate_present) {
        osdk_json_key(w, "angular_rate");
        osdk_broadcast_items_vector3f_to_json(&self->angular_rate, w);
    }
    if (self->position_present) {
        osdk_json_key(w, "position");
        osdk_broadcast_items_position_to_json(&self->position, w);
    }
    if (self->magnetometer_present) {
        osdk_json_key(w, "magnetometer");
        osdk_broadcast_items_magnetometer_to_json(&self->magnetometer, w);
    }
    if (self->rc_present) {
        osdk_json_key(w, "rc");
        osdk_broadcast_items_rc_to_json(&self->rc, w);
    }
    if (self->gimbal_present) {
        osdk_json_key(w, "gimbal");
        osdk_broadcast_items_gimbal_to_json(&self->gimbal, w);
    }
    if (self->flight_status_present) {
        osdk_json_key(w, "flight_status");
        osdk_json_uint(w, (uint64_t)self->flight_status);
    }
    if (self->battery_present) {
        osdk_json_key(w, "battery");
        osdk_json_uint(w, (uint64_t)self->battery);
    }
    if (self->control_info_present) {
        osdk_json_key(w, "control_info");
        osdk_broadcast_items_control_info_to_json(&self->control_info, w);
    }
    osdk_json_end_object(w);
}

/* osdk_broadcast_m100_fw2_3: the model of one field; false when it has no such field or it is absent */
bool osdk_broadcast_m100_fw2_3_field_to_json(const osdk_broadcast_m100_fw2_3_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "has_time_stamp") == 0) {
        osdk_json_bool(w, self->has_time_stamp);
        return true;
    }
    if (strcmp(field, "has_quaternion") == 0) {
        osdk_json_bool(w, self->has_quaternion);
        return true;
    }
    if (strcmp(field, "has_acceleration") == 0) {
        osdk_json_bool(w, self->has_acceleration);
        return true;
    }
    if (strcmp(field, "has_velocity") == 0) {
        osdk_json_bool(w, self->has_velocity);
        return true;
    }
    if (strcmp(field, "has_angular_rate") == 0) {
        osdk_json_bool(w, self->has_angular_rate);
        return true;
    }
    if (strcmp(field, "has_position") == 0) {
        osdk_json_bool(w, self->has_position);
        return true;
    }
    if (strcmp(field, "has_magnetometer") == 0) {
        osdk_json_bool(w, self->has_magnetometer);
        return true;
    }
    if (strcmp(field, "has_rc") == 0) {
        osdk_json_bool(w, self->has_rc);
        return true;
    }
    if (strcmp(field, "has_gimbal") == 0) {
        osdk_json_bool(w, self->has_gimbal);
        return true;
    }
    if (strcmp(field, "has_flight_status") == 0) {
        osdk_json_bool(w, self->has_flight_status);
        return true;
    }
    if (strcmp(field, "has_battery") == 0) {
        osdk_json_bool(w, self->has_battery);
        return true;
    }
    if (strcmp(field, "has_control_info") == 0) {
        osdk_json_bool(w, self->has_control_info);
        return true;
    }
    if (strcmp(field, "reserved_flags") == 0) {
        osdk_json_uint(w, (uint64_t)self->reserved_flags);
        return true;
    }
    if (strcmp(field, "time_stamp") == 0 && self->time_stamp_present) {
        osdk_broadcast_items_time_stamp_to_json(&self->time_stamp, w);
        return true;
    }
    if (strcmp(field, "quaternion") == 0 && self->quaternion_present) {
        osdk_broadcast_items_quaternion_to_json(&self->quaternion, w);
        return true;
    }
    if (strcmp(field, "acceleration") == 0 && self->acceleration_present) {
        osdk_broadcast_items_vector3f_to_json(&self->acceleration, w);
        return true;
    }
    if (strcmp(field, "velocity") == 0 && self->velocity_present) {
        osdk_broadcast_items_velocity_to_json(&self->velocity, w);
        return true;
    }
    if (strcmp(field, "angular_rate") == 0 && self->angular_rate_present) {
        osdk_broadcast_items_vector3f_to_json(&self->angular_rate, w);
        return true;
    }
    if (strcmp(field, "position") == 0 && self->position_present) {
        osdk_broadcast_items_position_to_json(&self->position, w);
        return true;
    }
    if (strcmp(field, "magnetometer") == 0 && self->magnetometer_present) {
        osdk_broadcast_items_magnetometer_to_json(&self->magnetometer, w);
        return true;
    }
    if (strcmp(field, "rc") == 0 && self->rc_present) {
        osdk_broadcast_items_rc_to_json(&self->rc, w);
        return true;
    }
    if (strcmp(field, "gimbal") == 0 && self->gimbal_present) {
        osdk_broadcast_items_gimbal_to_json(&self->gimbal, w);
        return true;
    }
    if (strcmp(field, "flight_status") == 0 && self->flight_status_present) {
        osdk_json_uint(w, (uint64_t)self->flight_status);
        return true;
    }
    if (strcmp(field, "battery") == 0 && self->battery_present) {
        osdk_json_uint(w, (uint64_t)self->battery);
        return true;
    }
    if (strcmp(field, "control_info") == 0 && self->control_info_present) {
        osdk_broadcast_items_control_info_to_json(&self->control_info, w);
        return true;
    }
    if (strcmp(field, "trailing") == 0) {
        osdk_json_hex(w, self->trailing.ptr, self->trailing.len);
        return true;
    }
    return false;
}

/* osdk_broadcast_m100_fw3_1 */
void osdk_broadcast_m100_fw3_1_to_json(const osdk_broadcast_m100_fw3_1_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "has_time_stamp");
    osdk_json_bool(w, self->has_time_stamp);
    osdk_json_key(w, "has_quaternion");
    osdk_json_bool(w, self->has_quaternion);
    osdk_json_key(w, "has_acceleration");
    osdk_json_bool(w, self->has_acceleration);
    osdk_json_key(w, "has_velocity");
    osdk_json_bool(w, self->has_velocity);
    osdk_json_key(w, "has_angular_rate");
    osdk_json_bool(w, self->has_angular_rate);
    osdk_json_key(w, "has_position");
    osdk_json_bool(w, self->has_position);
    osdk_json_key(w, "has_magnetometer");
    osdk_json_bool(w, self->has_magnetometer);
    osdk_json_key(w, "has_rc");
    osdk_json_bool(w, self->has_rc);
    osdk_json_key(w, "has_gimbal");
    osdk_json_bool(w, self->has_gimbal);
    osdk_json_key(w, "has_flight_status");
    osdk_json_bool(w, self->has_flight_status);
    osdk_json_key(w, "has_battery");
    osdk_json_bool(w, self->has_battery);
    osdk_json_key(w, "has_control_info");
    osdk_json_bool(w, self->has_control_info);
    osdk_json_key(w, "reserved_flags");
    osdk_json_uint(w, (uint64_t)self->reserved_flags);
    if (self->time_stamp_present) {
        osdk_json_key(w, "time_stamp");
        osdk_broadcast_items_time_stamp_to_json(&self->time_stamp, w);
    }
    if (self->quaternion_present) {
        osdk_json_key(w, "quaternion");
        osdk_broadcast_items_quaternion_to_json(&self->quaternion, w);
    }
    if (self->acceleration_present) {
        osdk_json_key(w, "acceleration");
        osdk_broadcast_items_vector3f_to_json(&self->acceleration, w);
    }
    if (self->velocity_present) {
        osdk_json_key(w, "velocity");
        osdk_broadcast_items_velocity_to_json(&self->velocity, w);
    }
    if (self->angular_rate_present) {
        osdk_json_key(w, "angular_rate");
        osdk_broadcast_items_vector3f_to_json(&self->angular_rate, w);
    }
    if (self->position_present) {
        osdk_json_key(w, "position");
        osdk_broadcast_items_position_to_json(&self->position, w);
    }
    if (self->magnetometer_present) {
        osdk_json_key(w, "magnetometer");
        osdk_broadcast_items_magnetometer_to_json(&self->magnetometer, w);
    }
    if (self->rc_present) {
        osdk_json_key(w, "rc");
        osdk_broadcast_items_rc_to_json(&self->rc, w);
    }
    if (self->gimbal_present) {
        osdk_json_key(w, "gimbal");
        osdk_broadcast_items_gimbal_to_json(&self->gimbal, w);
    }
    if (self->flight_status_present) {
        osdk_json_key(w, "flight_status");
        osdk_json_uint(w, (uint64_t)self->flight_status);
    }
    if (self->battery_present) {
        osdk_json_key(w, "battery");
        osdk_json_uint(w, (uint64_t)self->battery);
    }
    if (self->control_info_present) {
        osdk_json_key(w, "control_info");
        osdk_broadcast_items_control_info_to_json(&self->control_info, w);
    }
    osdk_json_end_object(w);
}

/* osdk_broadcast_m100_fw3_1: the model of one field; false when it has no such field or it is absent */
bool osdk_broadcast_m100_fw3_1_field_to_json(const osdk_broadcast_m100_fw3_1_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "has_time_stamp") == 0) {
        osdk_json_bool(w, self->has_time_stamp);
        return true;
    }
    if (strcmp(field, "has_quaternion") == 0) {
        osdk_json_bool(w, self->has_quaternion);
        return true;
    }
    if (strcmp(field, "has_acceleration") == 0) {
        osdk_json_bool(w, self->has_acceleration);
        return true;
    }
    if (strcmp(field, "has_velocity") == 0) {
        osdk_json_bool(w, self->has_velocity);
        return true;
    }
    if (strcmp(field, "has_angular_rate") == 0) {
        osdk_json_bool(w, self->has_angular_rate);
        return true;
    }
    if (strcmp(field, "has_position") == 0) {
        osdk_json_bool(w, self->has_position);
        return true;
    }
    if (strcmp(field, "has_magnetometer") == 0) {
        osdk_json_bool(w, self->has_magnetometer);
        return true;
    }
    if (strcmp(field, "has_rc") == 0) {
        osdk_json_bool(w, self->has_rc);
        return true;
    }
    if (strcmp(field, "has_gimbal") == 0) {
        osdk_json_bool(w, self->has_gimbal);
        return true;
    }
    if (strcmp(field, "has_flight_status") == 0) {
        osdk_json_bool(w, self->has_flight_status);
        return true;
    }
    if (strcmp(field, "has_battery") == 0) {
        osdk_json_bool(w, self->has_battery);
        return true;
    }
    if (strcmp(field, "has_control_info") == 0) {
        osdk_json_bool(w, self->has_control_info);
        return true;
    }
    if (strcmp(field, "reserved_flags") == 0) {
        osdk_json_uint(w, (uint64_t)self->reserved_flags);
        return true;
    }
    if (strcmp(field, "time_stamp") == 0 && self->time_stamp_present) {
        osdk_broadcast_items_time_stamp_to_json(&self->time_stamp, w);
        return true;
    }
    if (strcmp(field, "quaternion") == 0 && self->quaternion_present) {
        osdk_broadcast_items_quaternion_to_json(&self->quaternion, w);
        return true;
    }
    if (strcmp(field, "acceleration") == 0 && self->acceleration_present) {
        osdk_broadcast_items_vector3f_to_json(&self->acceleration, w);
        return true;
    }
    if (strcmp(field, "velocity") == 0 && self->velocity_present) {
        osdk_broadcast_items_velocity_to_json(&self->velocity, w);
        return true;
    }
    if (strcmp(field, "angular_rate") == 0 && self->angular_rate_present) {
        osdk_broadcast_items_vector3f_to_json(&self->angular_rate, w);
        return true;
    }
    if (strcmp(field, "position") == 0 && self->position_present) {
        osdk_broadcast_items_position_to_json(&self->position, w);
        return true;
    }
    if (strcmp(field, "magnetometer") == 0 && self->magnetometer_present) {
        osdk_broadcast_items_magnetometer_to_json(&self->magnetometer, w);
        return true;
    }
    if (strcmp(field, "rc") == 0 && self->rc_present) {
        osdk_broadcast_items_rc_to_json(&self->rc, w);
        return true;
    }
    if (strcmp(field, "gimbal") == 0 && self->gimbal_present) {
        osdk_broadcast_items_gimbal_to_json(&self->gimbal, w);
        return true;
    }
    if (strcmp(field, "flight_status") == 0 && self->flight_status_present) {
        osdk_json_uint(w, (uint64_t)self->flight_status);
        return true;
    }
    if (strcmp(field, "battery") == 0 && self->battery_present) {
        osdk_json_uint(w, (uint64_t)self->battery);
        return true;
    }
    if (strcmp(field, "control_info") == 0 && self->control_info_present) {
        osdk_broadcast_items_control_info_to_json(&self->control_info, w);
        return true;
    }
    if (strcmp(field, "trailing") == 0) {
        osdk_json_hex(w, self->trailing.ptr, self->trailing.len);
        return true;
    }
    return false;
}

/* osdk_control_mode */
void osdk_control_mode_to_json(const osdk_control_mode_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "stable_mode");
    osdk_json_enum(w, (int64_t)self->stable_mode, osdk_control_mode_stable_mode_name((int64_t)self->stable_mode));
    osdk_json_key(w, "horizontal_frame");
    osdk_json_enum(w, (int64_t)self->horizontal_frame, osdk_control_mode_horizontal_frame_name((int64_t)self->horizontal_frame));
    osdk_json_key(w, "yaw_logic");
    osdk_json_enum(w, (int64_t)self->yaw_logic, osdk_control_mode_yaw_logic_name((int64_t)self->yaw_logic));
    osdk_json_key(w, "vertical_logic");
    osdk_json_enum(w, (int64_t)self->vertical_logic, osdk_control_mode_vertical_logic_name((int64_t)self->vertical_logic));
    osdk_json_key(w, "horizontal_logic");
    osdk_json_enum(w, (int64_t)self->horizontal_logic, osdk_control_mode_horizontal_logic_name((int64_t)self->horizontal_logic));
    osdk_json_end_object(w);
}

/* osdk_control_mode: the model of one field; false when it has no such field or it is absent */
bool osdk_control_mode_field_to_json(const osdk_control_mode_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "stable_mode") == 0) {
        osdk_json_enum(w, (int64_t)self->stable_mode, osdk_control_mode_stable_mode_name((int64_t)self->stable_mode));
        return true;
    }
    if (strcmp(field, "horizontal_frame") == 0) {
        osdk_json_enum(w, (int64_t)self->horizontal_frame, osdk_control_mode_horizontal_frame_name((int64_t)self->horizontal_frame));
        return true;
    }
    if (strcmp(field, "yaw_logic") == 0) {
        osdk_json_enum(w, (int64_t)self->yaw_logic, osdk_control_mode_yaw_logic_name((int64_t)self->yaw_logic));
        return true;
    }
    if (strcmp(field, "vertical_logic") == 0) {
        osdk_json_enum(w, (int64_t)self->vertical_logic, osdk_control_mode_vertical_logic_name((int64_t)self->vertical_logic));
        return true;
    }
    if (strcmp(field, "horizontal_logic") == 0) {
        osdk_json_enum(w, (int64_t)self->horizontal_logic, osdk_control_mode_horizontal_logic_name((int64_t)self->horizontal_logic));
        return true;
    }
    return false;
}

/* osdk_frame */
void osdk_frame_to_json(const osdk_frame_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "sof");
    osdk_json_hex(w, self->sof.ptr, self->sof.len);
    osdk_json_key(w, "len");
    osdk_json_uint(w, (uint64_t)self->len);
    osdk_json_key(w, "ver");
    osdk_json_uint(w, (uint64_t)self->ver);
    osdk_json_key(w, "session");
    osdk_json_uint(w, (uint64_t)self->session);
    osdk_json_key(w, "is_ack");
    osdk_json_bool(w, self->is_ack);
    osdk_json_key(w, "res0");
    osdk_json_uint(w, (uint64_t)self->res0);
    osdk_json_key(w, "padding");
    osdk_json_uint(w, (uint64_t)self->padding);
    osdk_json_key(w, "enc");
    osdk_json_enum(w, (int64_t)self->enc, osdk_frame_encryption_name((int64_t)self->enc));
    osdk_json_key(w, "res1");
    osdk_json_uint(w, (uint64_t)self->res1);
    osdk_json_key(w, "seq");
    osdk_json_uint(w, (uint64_t)self->seq);
    osdk_json_key(w, "crc16");
    osdk_json_uint(w, (uint64_t)self->crc16);
    if (self->data_present) {
        osdk_json_key(w, "data");
        switch (self->data.tag) {
            case OSDK_FRAME_DATA_FRAME_DATA: osdk_frame_frame_data_to_json(&self->data.u.frame_data, w); break;
            case OSDK_FRAME_DATA_RAW: osdk_json_hex(w, self->data.u.raw.ptr, self->data.u.raw.len); break;
            default: osdk_json_null(w); break;
        }
    }
    if (self->crc32_present) {
        osdk_json_key(w, "crc32");
        osdk_json_uint(w, (uint64_t)self->crc32);
    }
    osdk_json_end_object(w);
}

/* osdk_frame: the model of one field; false when it has no such field or it is absent */
bool osdk_frame_field_to_json(const osdk_frame_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "sof") == 0) {
        osdk_json_hex(w, self->sof.ptr, self->sof.len);
        return true;
    }
    if (strcmp(field, "len") == 0) {
        osdk_json_uint(w, (uint64_t)self->len);
        return true;
    }
    if (strcmp(field, "ver") == 0) {
        osdk_json_uint(w, (uint64_t)self->ver);
        return true;
    }
    if (strcmp(field, "session") == 0) {
        osdk_json_uint(w, (uint64_t)self->session);
        return true;
    }
    if (strcmp(field, "is_ack") == 0) {
        osdk_json_bool(w, self->is_ack);
        return true;
    }
    if (strcmp(field, "res0") == 0) {
        osdk_json_uint(w, (uint64_t)self->res0);
        return true;
    }
    if (strcmp(field, "padding") == 0) {
        osdk_json_uint(w, (uint64_t)self->padding);
        return true;
    }
    if (strcmp(field, "enc") == 0) {
        osdk_json_enum(w, (int64_t)self->enc, osdk_frame_encryption_name((int64_t)self->enc));
        return true;
    }
    if (strcmp(field, "res1") == 0) {
        osdk_json_uint(w, (uint64_t)self->res1);
        return true;
    }
    if (strcmp(field, "seq") == 0) {
        osdk_json_uint(w, (uint64_t)self->seq);
        return true;
    }
    if (strcmp(field, "crc16") == 0) {
        osdk_json_uint(w, (uint64_t)self->crc16);
        return true;
    }
    if (strcmp(field, "data") == 0 && self->data_present) {
        switch (self->data.tag) {
            case OSDK_FRAME_DATA_FRAME_DATA: osdk_frame_frame_data_to_json(&self->data.u.frame_data, w); break;
            case OSDK_FRAME_DATA_RAW: osdk_json_hex(w, self->data.u.raw.ptr, self->data.u.raw.len); break;
            default: osdk_json_null(w); break;
        }
        return true;
    }
    if (strcmp(field, "crc32") == 0 && self->crc32_present) {
        osdk_json_uint(w, (uint64_t)self->crc32);
        return true;
    }
    return false;
}

/* osdk_frame::frame_data */
void osdk_frame_frame_data_to_json(const osdk_frame_frame_data_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    if (self->cmd_set_present) {
        osdk_json_key(w, "cmd_set");
        osdk_json_enum(w, (int64_t)self->cmd_set, osdk_frame_command_set_name((int64_t)self->cmd_set));
    }
    if (self->cmd_id_present) {
        osdk_json_key(w, "cmd_id");
        osdk_json_uint(w, (uint64_t)self->cmd_id);
    }
    if (self->value_present) {
        osdk_json_key(w, "value");
        osdk_payload_to_json(&self->value, w);
    }
    if (self->ack_value_present) {
        osdk_json_key(w, "ack_value");
        osdk_json_hex(w, self->ack_value.ptr, self->ack_value.len);
    }
    osdk_json_end_object(w);
}

/* osdk_frame::frame_data: the model of one field; false when it has no such field or it is absent */
bool osdk_frame_frame_data_field_to_json(const osdk_frame_frame_data_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "cmd_set") == 0 && self->cmd_set_present) {
        osdk_json_enum(w, (int64_t)self->cmd_set, osdk_frame_command_set_name((int64_t)self->cmd_set));
        return true;
    }
    if (strcmp(field, "cmd_id") == 0 && self->cmd_id_present) {
        osdk_json_uint(w, (uint64_t)self->cmd_id);
        return true;
    }
    if (strcmp(field, "value") == 0 && self->value_present) {
        osdk_payload_to_json(&self->value, w);
        return true;
    }
    if (strcmp(field, "ack_value") == 0 && self->ack_value_present) {
        osdk_json_hex(w, self->ack_value.ptr, self->ack_value.len);
        return true;
    }
    return false;
}

/* osdk_movement_control */
void osdk_movement_control_to_json(const osdk_movement_control_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "control_mode");
    osdk_control_mode_to_json(&self->control_mode, w);
    osdk_json_key(w, "x");
    osdk_json_f32(w, self->x.bits);
    osdk_json_key(w, "y");
    osdk_json_f32(w, self->y.bits);
    osdk_json_key(w, "z");
    osdk_json_f32(w, self->z.bits);
    osdk_json_key(w, "yaw");
    osdk_json_f32(w, self->yaw.bits);
    osdk_json_end_object(w);
}

/* osdk_movement_control: the model of one field; false when it has no such field or it is absent */
bool osdk_movement_control_field_to_json(const osdk_movement_control_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "control_mode") == 0) {
        osdk_control_mode_to_json(&self->control_mode, w);
        return true;
    }
    if (strcmp(field, "x") == 0) {
        osdk_json_f32(w, self->x.bits);
        return true;
    }
    if (strcmp(field, "y") == 0) {
        osdk_json_f32(w, self->y.bits);
        return true;
    }
    if (strcmp(field, "z") == 0) {
        osdk_json_f32(w, self->z.bits);
        return true;
    }
    if (strcmp(field, "yaw") == 0) {
        osdk_json_f32(w, self->yaw.bits);
        return true;
    }
    return false;
}

/* osdk_payload */
void osdk_payload_to_json(const osdk_payload_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "body");
    switch (self->body.tag) {
        case OSDK_PAYLOAD_BODY_VERSION_QUERY: osdk_payload_version_query_to_json(&self->body.u.version_query, w); break;
        case OSDK_PAYLOAD_BODY_ACTIVATION_REQUEST: osdk_payload_activation_request_to_json(&self->body.u.activation_request, w); break;
        case OSDK_PAYLOAD_BODY_FREQUENCY_REQUEST: osdk_payload_frequency_request_to_json(&self->body.u.frequency_request, w); break;
        case OSDK_PAYLOAD_BODY_CONTROL_REQUEST: osdk_payload_control_request_to_json(&self->body.u.control_request, w); break;
        case OSDK_PAYLOAD_BODY_OSDK_MOVEMENT_CONTROL: osdk_movement_control_to_json(&self->body.u.osdk_movement_control, w); break;
        case OSDK_PAYLOAD_BODY_BROADCAST: osdk_payload_broadcast_to_json(&self->body.u.broadcast, w); break;
        case OSDK_PAYLOAD_BODY_LOST_CONTROL: osdk_payload_lost_control_to_json(&self->body.u.lost_control, w); break;
        case OSDK_PAYLOAD_BODY_VERSION_ACK_VALUE: osdk_payload_version_ack_value_to_json(&self->body.u.version_ack_value, w); break;
        case OSDK_PAYLOAD_BODY_ACTIVATION_ACK_VALUE: osdk_payload_activation_ack_value_to_json(&self->body.u.activation_ack_value, w); break;
        case OSDK_PAYLOAD_BODY_FREQUENCY_ACK_VALUE: osdk_payload_frequency_ack_value_to_json(&self->body.u.frequency_ack_value, w); break;
        case OSDK_PAYLOAD_BODY_CONTROL_ACK_VALUE: osdk_payload_control_ack_value_to_json(&self->body.u.control_ack_value, w); break;
        case OSDK_PAYLOAD_BODY_LOST_CONTROL_ACK_VALUE: osdk_payload_lost_control_ack_value_to_json(&self->body.u.lost_control_ack_value, w); break;
        case OSDK_PAYLOAD_BODY_UNKNOWN_VALUE: osdk_payload_unknown_value_to_json(&self->body.u.unknown_value, w); break;
        default: osdk_json_null(w); break;
    }
    osdk_json_end_object(w);
}

/* osdk_payload: the model of one field; false when it has no such field or it is absent */
bool osdk_payload_field_to_json(const osdk_payload_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "body") == 0) {
        switch (self->body.tag) {
            case OSDK_PAYLOAD_BODY_VERSION_QUERY: osdk_payload_version_query_to_json(&self->body.u.version_query, w); break;
            case OSDK_PAYLOAD_BODY_ACTIVATION_REQUEST: osdk_payload_activation_request_to_json(&self->body.u.activation_request, w); break;
            case OSDK_PAYLOAD_BODY_FREQUENCY_REQUEST: osdk_payload_frequency_request_to_json(&self->body.u.frequency_request, w); break;
            case OSDK_PAYLOAD_BODY_CONTROL_REQUEST: osdk_payload_control_request_to_json(&self->body.u.control_request, w); break;
            case OSDK_PAYLOAD_BODY_OSDK_MOVEMENT_CONTROL: osdk_movement_control_to_json(&self->body.u.osdk_movement_control, w); break;
            case OSDK_PAYLOAD_BODY_BROADCAST: osdk_payload_broadcast_to_json(&self->body.u.broadcast, w); break;
            case OSDK_PAYLOAD_BODY_LOST_CONTROL: osdk_payload_lost_control_to_json(&self->body.u.lost_control, w); break;
            case OSDK_PAYLOAD_BODY_VERSION_ACK_VALUE: osdk_payload_version_ack_value_to_json(&self->body.u.version_ack_value, w); break;
            case OSDK_PAYLOAD_BODY_ACTIVATION_ACK_VALUE: osdk_payload_activation_ack_value_to_json(&self->body.u.activation_ack_value, w); break;
            case OSDK_PAYLOAD_BODY_FREQUENCY_ACK_VALUE: osdk_payload_frequency_ack_value_to_json(&self->body.u.frequency_ack_value, w); break;
            case OSDK_PAYLOAD_BODY_CONTROL_ACK_VALUE: osdk_payload_control_ack_value_to_json(&self->body.u.control_ack_value, w); break;
            case OSDK_PAYLOAD_BODY_LOST_CONTROL_ACK_VALUE: osdk_payload_lost_control_ack_value_to_json(&self->body.u.lost_control_ack_value, w); break;
            case OSDK_PAYLOAD_BODY_UNKNOWN_VALUE: osdk_payload_unknown_value_to_json(&self->body.u.unknown_value, w); break;
            default: osdk_json_null(w); break;
        }
        return true;
    }
    if (strcmp(field, "trailing") == 0) {
        osdk_json_hex(w, self->trailing.ptr, self->trailing.len);
        return true;
    }
    return false;
}

/* osdk_payload::activation_ack_value */
void osdk_payload_activation_ack_value_to_json(const osdk_payload_activation_ack_value_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "ack_code");
    osdk_json_enum(w, (int64_t)self->ack_code, osdk_payload_activation_result_name((int64_t)self->ack_code));
    osdk_json_end_object(w);
}

/* osdk_payload::activation_ack_value: the model of one field; false when it has no such field or it is absent */
bool osdk_payload_activation_ack_value_field_to_json(const osdk_payload_activation_ack_value_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "ack_code") == 0) {
        osdk_json_enum(w, (int64_t)self->ack_code, osdk_payload_activation_result_name((int64_t)self->ack_code));
        return true;
    }
    return false;
}

/* osdk_payload::activation_request */
void osdk_payload_activation_request_to_json(const osdk_payload_activation_request_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "app_id");
    osdk_json_uint(w, (uint64_t)self->app_id);
    osdk_json_key(w, "api_level");
    osdk_json_uint(w, (uint64_t)self->api_level);
    osdk_json_key(w, "sdk_version");
    osdk_json_uint(w, (uint64_t)self->sdk_version);
    osdk_json_key(w, "bundle_id");
    osdk_json_hex(w, self->bundle_id.ptr, self->bundle_id.len);
    osdk_json_end_object(w);
}

/* osdk_payload::activation_request: the model of one field; false when it has no such field or it is absent */
bool osdk_payload_activation_request_field_to_json(const osdk_payload_activation_request_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "app_id") == 0) {
        osdk_json_uint(w, (uint64_t)self->app_id);
        return true;
    }
    if (strcmp(field, "api_level") == 0) {
        osdk_json_uint(w, (uint64_t)self->api_level);
        return true;
    }
    if (strcmp(field, "sdk_version") == 0) {
        osdk_json_uint(w, (uint64_t)self->sdk_version);
        return true;
    }
    if (strcmp(field, "bundle_id") == 0) {
        osdk_json_hex(w, self->bundle_id.ptr, self->bundle_id.len);
        return true;
    }
    return false;
}

/* osdk_payload::broadcast */
void osdk_payload_broadcast_to_json(const osdk_payload_broadcast_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "data");
    switch (self->data.tag) {
        case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW2_3: osdk_broadcast_m100_fw2_3_to_json(&self->data.u.osdk_broadcast_m100_fw2_3, w); break;
        case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW3_1: osdk_broadcast_m100_fw3_1_to_json(&self->data.u.osdk_broadcast_m100_fw3_1, w); break;
        case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_A3_FW3_1: osdk_broadcast_a3_fw3_1_to_json(&self->data.u.osdk_broadcast_a3_fw3_1, w); break;
        default: osdk_json_null(w); break;
    }
    osdk_json_end_object(w);
}

/* osdk_payload::broadcast: the model of one field; false when it has no such field or it is absent */
bool osdk_payload_broadcast_field_to_json(const osdk_payload_broadcast_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "data") == 0) {
        switch (self->data.tag) {
            case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW2_3: osdk_broadcast_m100_fw2_3_to_json(&self->data.u.osdk_broadcast_m100_fw2_3, w); break;
            case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW3_1: osdk_broadcast_m100_fw3_1_to_json(&self->data.u.osdk_broadcast_m100_fw3_1, w); break;
            case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_A3_FW3_1: osdk_broadcast_a3_fw3_1_to_json(&self->data.u.osdk_broadcast_a3_fw3_1, w); break;
            default: osdk_json_null(w); break;
        }
        return true;
    }
    return false;
}

/* osdk_payload::control_ack_value */
void osdk_payload_control_ack_value_to_json(const osdk_payload_control_ack_value_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "ack_code");
    osdk_json_enum(w, (int64_t)self->ack_code, osdk_payload_control_ack_name((int64_t)self->ack_code));
    osdk_json_end_object(w);
}

/* osdk_payload::control_ack_value: the model of one field; false when it has no such field or it is absent */
bool osdk_payload_control_ack_value_field_to_json(const osdk_payload_control_ack_value_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "ack_code") == 0) {
        osdk_json_enum(w, (int64_t)self->ack_code, osdk_payload_control_ack_name((int64_t)self->ack_code));
        return true;
    }
    return false;
}

/* osdk_payload::control_request */
void osdk_payload_control_request_to_json(const osdk_payload_control_request_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "request");
    osdk_json_enum(w, (int64_t)self->request, osdk_payload_control_request_code_name((int64_t)self->request));
    osdk_json_end_object(w);
}

/* osdk_payload::control_request: the model of one field; false when it has no such field or it is absent */
bool osdk_payload_control_request_field_to_json(const osdk_payload_control_request_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "request") == 0) {
        osdk_json_enum(w, (int64_t)self->request, osdk_payload_control_request_code_name((int64_t)self->request));
        return true;
    }
    return false;
}

/* osdk_payload::frequency_ack_value */
void osdk_payload_frequency_ack_value_to_json(const osdk_payload_frequency_ack_value_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "ack_code");
    osdk_json_enum(w, (int64_t)self->ack_code, osdk_payload_frequency_ack_name((int64_t)self->ack_code));
    osdk_json_end_object(w);
}

/* osdk_payload::frequency_ack_value: the model of one field; false when it has no such field or it is absent */
bool osdk_payload_frequency_ack_value_field_to_json(const osdk_payload_frequency_ack_value_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "ack_code") == 0) {
        osdk_json_enum(w, (int64_t)self->ack_code, osdk_payload_frequency_ack_name((int64_t)self->ack_code));
        return true;
    }
    return false;
}

/* osdk_payload::frequency_request */
void osdk_payload_frequency_request_to_json(const osdk_payload_frequency_request_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "codes");
    osdk_json_begin_array(w);
    for (size_t i = 0; i < self->codes_count; i++) {
        osdk_json_enum(w, (int64_t)self->codes[i], osdk_payload_frequency_code_name((int64_t)self->codes[i]));
    }
    osdk_json_end_array(w);
    osdk_json_end_object(w);
}

/* osdk_payload::frequency_request: the model of one field; false when it has no such field or it is absent */
bool osdk_payload_frequency_request_field_to_json(const osdk_payload_frequency_request_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "codes") == 0) {
        osdk_json_begin_array(w);
        for (size_t i = 0; i < self->codes_count; i++) {
            osdk_json_enum(w, (int64_t)self->codes[i], osdk_payload_frequency_code_name((int64_t)self->codes[i]));
        }
        osdk_json_end_array(w);
        return true;
    }
    return false;
}

/* osdk_payload::lost_control */
void osdk_payload_lost_control_to_json(const osdk_payload_lost_control_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "reason");
    osdk_json_uint(w, (uint64_t)self->reason);
    osdk_json_end_object(w);
}

/* osdk_payload::lost_control: the model of one field; false when it has no such field or it is absent */
bool osdk_payload_lost_control_field_to_json(const osdk_payload_lost_control_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "reason") == 0) {
        osdk_json_uint(w, (uint64_t)self->reason);
        return true;
    }
    return false;
}

/* osdk_payload::lost_control_ack_value */
void osdk_payload_lost_control_ack_value_to_json(const osdk_payload_lost_control_ack_value_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "ack_code");
    osdk_json_uint(w, (uint64_t)self->ack_code);
    osdk_json_end_object(w);
}

/* osdk_payload::lost_control_ack_value: the model of one field; false when it has no such field or it is absent */
bool osdk_payload_lost_control_ack_value_field_to_json(const osdk_payload_lost_control_ack_value_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "ack_code") == 0) {
        osdk_json_uint(w, (uint64_t)self->ack_code);
        return true;
    }
    return false;
}

/* osdk_payload::unknown_value */
void osdk_payload_unknown_value_to_json(const osdk_payload_unknown_value_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "raw");
    osdk_json_hex(w, self->raw.ptr, self->raw.len);
    osdk_json_end_object(w);
}

/* osdk_payload::unknown_value: the model of one field; false when it has no such field or it is absent */
bool osdk_payload_unknown_value_field_to_json(const osdk_payload_unknown_value_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "raw") == 0) {
        osdk_json_hex(w, self->raw.ptr, self->raw.len);
        return true;
    }
    return false;
}

/* osdk_payload::version_ack_value */
void osdk_payload_version_ack_value_to_json(const osdk_payload_version_ack_value_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "ack_code");
    osdk_json_enum(w, (int64_t)self->ack_code, osdk_payload_version_ack_name((int64_t)self->ack_code));
    osdk_json_key(w, "version_crc");
    osdk_json_uint(w, (uint64_t)self->version_crc);
    if (self->version_id_present) {
        osdk_json_key(w, "version_id");
        osdk_json_hex(w, self->version_id.ptr, self->version_id.len);
    }
    osdk_json_key(w, "version_name");
    osdk_json_hex(w, self->version_name.ptr, self->version_name.len);
    osdk_json_end_object(w);
}

/* osdk_payload::version_ack_value: the model of one field; false when it has no such field or it is absent */
bool osdk_payload_version_ack_value_field_to_json(const osdk_payload_version_ack_value_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "ack_code") == 0) {
        osdk_json_enum(w, (int64_t)self->ack_code, osdk_payload_version_ack_name((int64_t)self->ack_code));
        return true;
    }
    if (strcmp(field, "version_crc") == 0) {
        osdk_json_uint(w, (uint64_t)self->version_crc);
        return true;
    }
    if (strcmp(field, "version_id") == 0 && self->version_id_present) {
        osdk_json_hex(w, self->version_id.ptr, self->version_id.len);
        return true;
    }
    if (strcmp(field, "version_name") == 0) {
        osdk_json_hex(w, self->version_name.ptr, self->version_name.len);
        return true;
    }
    return false;
}

/* osdk_payload::version_query */
void osdk_payload_version_query_to_json(const osdk_payload_version_query_t *self, osdk_json_t *w)
{
    osdk_json_begin_object(w);
    osdk_json_key(w, "arbitrary");
    osdk_json_uint(w, (uint64_t)self->arbitrary);
    osdk_json_end_object(w);
}

/* osdk_payload::version_query: the model of one field; false when it has no such field or it is absent */
bool osdk_payload_version_query_field_to_json(const osdk_payload_version_query_t *self, const char *field, osdk_json_t *w)
{
    if (strcmp(field, "arbitrary") == 0) {
        osdk_json_uint(w, (uint64_t)self->arbitrary);
        return true;
    }
    return false;
}


