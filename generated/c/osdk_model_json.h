/* Generated from spec/ by tools/cgen/generate.py. Do not edit. */
/*
 * osdk_model_json.h - the JSON value model of docs/VALUE-MODEL.md, written
 * into a caller-supplied char buffer (no heap). Structures are objects with
 * their seq fields in wire order (absent `if`-false fields, no `trailing`),
 * enums {"value", "name"}, floats {"f32"/"f64": IEEE bits hex, "value"},
 * bytes lowercase hex, b1 true/false.
 *
 * The writer is osdk_json.h's.
 */
#ifndef OSDK_MODEL_JSON_H
#define OSDK_MODEL_JSON_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "osdk_decoder.h"
#include "osdk_json.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Model of each ksy type. */
void osdk_broadcast_a3_fw3_1_to_json(const osdk_broadcast_a3_fw3_1_t *self, osdk_json_t *w);
bool osdk_broadcast_a3_fw3_1_field_to_json(const osdk_broadcast_a3_fw3_1_t *self, const char *field, osdk_json_t *w);
void osdk_broadcast_items_control_info_to_json(const osdk_broadcast_items_control_info_t *self, osdk_json_t *w);
bool osdk_broadcast_items_control_info_field_to_json(const osdk_broadcast_items_control_info_t *self, const char *field, osdk_json_t *w);
void osdk_broadcast_items_gimbal_to_json(const osdk_broadcast_items_gimbal_t *self, osdk_json_t *w);
bool osdk_broadcast_items_gimbal_field_to_json(const osdk_broadcast_items_gimbal_t *self, const char *field, osdk_json_t *w);
void osdk_broadcast_items_gimbal_limit_to_json(const osdk_broadcast_items_gimbal_limit_t *self, osdk_json_t *w);
bool osdk_broadcast_items_gimbal_limit_field_to_json(const osdk_broadcast_items_gimbal_limit_t *self, const char *field, osdk_json_t *w);
void osdk_broadcast_items_gps_detail_to_json(const osdk_broadcast_items_gps_detail_t *self, osdk_json_t *w);
bool osdk_broadcast_items_gps_detail_field_to_json(const osdk_broadcast_items_gps_detail_t *self, const char *field, osdk_json_t *w);
void osdk_broadcast_items_magnetometer_to_json(const osdk_broadcast_items_magnetometer_t *self, osdk_json_t *w);
bool osdk_broadcast_items_magnetometer_field_to_json(const osdk_broadcast_items_magnetometer_t *self, const char *field, osdk_json_t *w);
void osdk_broadcast_items_position_to_json(const osdk_broadcast_items_position_t *self, osdk_json_t *w);
bool osdk_broadcast_items_position_field_to_json(const osdk_broadcast_items_position_t *self, const char *field, osdk_json_t *w);
void osdk_broadcast_items_quaternion_to_json(const osdk_broadcast_items_quaternion_t *self, osdk_json_t *w);
bool osdk_broadcast_items_quaternion_field_to_json(const osdk_broadcast_items_quaternion_t *self, const char *field, osdk_json_t *w);
void osdk_broadcast_items_rc_to_json(const osdk_broadcast_items_rc_t *self, osdk_json_t *w);
bool osdk_broadcast_items_rc_field_to_json(const osdk_broadcast_items_rc_t *self, const char *field, osdk_json_t *w);
void osdk_broadcast_items_rtk_detail_to_json(const osdk_broadcast_items_rtk_detail_t *self, osdk_json_t *w);
bool osdk_broadcast_items_rtk_detail_field_to_json(const osdk_broadcast_items_rtk_detail_t *self, const char *field, osdk_json_t *w);
void osdk_broadcast_items_time_stamp_to_json(const osdk_broadcast_items_time_stamp_t *self, osdk_json_t *w);
bool osdk_broadcast_items_time_stamp_field_to_json(const osdk_broadcast_items_time_stamp_t *self, const char *field, osdk_json_t *w);
void osdk_broadcast_items_vector3f_to_json(const osdk_broadcast_items_vector3f_t *self, osdk_json_t *w);
bool osdk_broadcast_items_vector3f_field_to_json(const osdk_broadcast_items_vector3f_t *self, const char *field, osdk_json_t *w);
void osdk_broadcast_items_velocity_to_json(const osdk_broadcast_items_velocity_t *self, osdk_json_t *w);
bool osdk_broadcast_items_velocity_field_to_json(const osdk_broadcast_items_velocity_t *self, const char *field, osdk_json_t *w);
void osdk_broadcast_m100_fw2_3_to_json(const osdk_broadcast_m100_fw2_3_t *self, osdk_json_t *w);
bool osdk_broadcast_m100_fw2_3_field_to_json(const osdk_broadcast_m100_fw2_3_t *self, const char *field, osdk_json_t *w);
void osdk_broadcast_m100_fw3_1_to_json(const osdk_broadcast_m100_fw3_1_t *self, osdk_json_t *w);
bool osdk_broadcast_m100_fw3_1_field_to_json(const osdk_broadcast_m100_fw3_1_t *self, const char *field, osdk_json_t *w);
void osdk_control_mode_to_json(const osdk_control_mode_t *self, osdk_json_t *w);
bool osdk_control_mode_field_to_json(const osdk_control_mode_t *self, const char *field, osdk_json_t *w);
void osdk_frame_to_json(const osdk_frame_t *self, osdk_json_t *w);
bool osdk_frame_field_to_json(const osdk_frame_t *self, const char *field, osdk_json_t *w);
void osdk_frame_frame_data_to_json(const osdk_frame_frame_data_t *self, osdk_json_t *w);
bool osdk_frame_frame_data_field_to_json(const osdk_frame_frame_data_t *self, const char *field, osdk_json_t *w);
void osdk_movement_control_to_json(const osdk_movement_control_t *self, osdk_json_t *w);
bool osdk_movement_control_field_to_json(const osdk_movement_control_t *self, const char *field, osdk_json_t *w);
void osdk_payload_to_json(const osdk_payload_t *self, osdk_json_t *w);
bool osdk_payload_field_to_json(const osdk_payload_t *self, const char *field, osdk_json_t *w);
void osdk_payload_activation_ack_value_to_json(const osdk_payload_activation_ack_value_t *self, osdk_json_t *w);
bool osdk_payload_activation_ack_value_field_to_json(const osdk_payload_activation_ack_value_t *self, const char *field, osdk_json_t *w);
void osdk_payload_activation_request_to_json(const osdk_payload_activation_request_t *self, osdk_json_t *w);
bool osdk_payload_activation_request_field_to_json(const osdk_payload_activation_request_t *self, const char *field, osdk_json_t *w);
void osdk_payload_broadcast_to_json(const osdk_payload_broadcast_t *self, osdk_json_t *w);
bool osdk_payload_broadcast_field_to_json(const osdk_payload_broadcast_t *self, const char *field, osdk_json_t *w);
void osdk_payload_control_ack_value_to_json(const osdk_payload_control_ack_value_t *self, osdk_json_t *w);
bool osdk_payload_control_ack_value_field_to_json(const osdk_payload_control_ack_value_t *self, const char *field, osdk_json_t *w);
void osdk_payload_control_request_to_json(const osdk_payload_control_request_t *self, osdk_json_t *w);
bool osdk_payload_control_request_field_to_json(const osdk_payload_control_request_t *self, const char *field, osdk_json_t *w);
void osdk_payload_frequency_ack_value_to_json(const osdk_payload_frequency_ack_value_t *self, osdk_json_t *w);
bool osdk_payload_frequency_ack_value_field_to_json(const osdk_payload_frequency_ack_value_t *self, const char *field, osdk_json_t *w);
void osdk_payload_frequency_request_to_json(const osdk_payload_frequency_request_t *self, osdk_json_t *w);
bool osdk_payload_frequency_request_field_to_json(const osdk_payload_frequency_request_t *self, const char *field, osdk_json_t *w);
void osdk_payload_lost_control_to_json(const osdk_payload_lost_control_t *self, osdk_json_t *w);
bool osdk_payload_lost_control_field_to_json(const osdk_payload_lost_control_t *self, const char *field, osdk_json_t *w);
void osdk_payload_lost_control_ack_value_to_json(const osdk_payload_lost_control_ack_value_t *self, osdk_json_t *w);
bool osdk_payload_lost_control_ack_value_field_to_json(const osdk_payload_lost_control_ack_value_t *self, const char *field, osdk_json_t *w);
void osdk_payload_unknown_value_to_json(const osdk_payload_unknown_value_t *self, osdk_json_t *w);
bool osdk_payload_unknown_value_field_to_json(const osdk_payload_unknown_value_t *self, const char *field, osdk_json_t *w);
void osdk_payload_version_ack_value_to_json(const osdk_payload_version_ack_value_t *self, osdk_json_t *w);
bool osdk_payload_version_ack_value_field_to_json(const osdk_payload_version_ack_value_t *self, const char *field, osdk_json_t *w);
void osdk_payload_version_query_to_json(const osdk_payload_version_query_t *self, osdk_json_t *w);
bool osdk_payload_version_query_field_to_json(const osdk_payload_version_query_t *self, const char *field, osdk_json_t *w);

#ifdef __cplusplus
}
#endif

#endif /* OSDK_MODEL_JSON_H */
