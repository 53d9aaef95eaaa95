/* Generated from spec/ by tools/cgen/generate.py. Do not edit. */
/*
 * osdk_model_py.h - the value model of docs/VALUE-MODEL.md built as Python
 * objects from the structs of osdk_decoder.h: the same model osdk_model_json
 * writes as text and osdk_conformance/core/model.py builds from Construct.
 * Structures are dicts with their seq fields in wire order (absent `if`-false
 * fields, no `trailing`), enums {"value", "name"}, floats {"f32"/"f64": IEEE
 * bits hex, "value": the number, or "NaN", "Infinity", "-Infinity"}, bytes
 * lowercase hex strings, single bits bools.
 *
 * Call osdk_model_py_init() once (with the GIL held) before anything else.
 * Every function returns a new reference, or NULL with a Python exception set.
 */
#ifndef OSDK_MODEL_PY_H
#define OSDK_MODEL_PY_H

#define PY_SSIZE_T_CLEAN
#include <Python.h>

#include "osdk_decoder.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The interned dict keys, one per field id of the spec and per model key. */
enum {
    OSDK_PY_K_HAS_TIME_STAMP = 0,
    OSDK_PY_K_HAS_QUATERNION = 1,
    OSDK_PY_K_HAS_ACCELERATION = 2,
    OSDK_PY_K_HAS_VELOCITY = 3,
    OSDK_PY_K_HAS_ANGULAR_RATE = 4,
    OSDK_PY_K_HAS_POSITION = 5,
    OSDK_PY_K_HAS_GPS_DETAIL = 6,
    OSDK_PY_K_HAS_RTK_DETAIL = 7,
    OSDK_PY_K_HAS_MAGNETOMETER = 8,
    OSDK_PY_K_HAS_RC = 9,
    OSDK_PY_K_HAS_GIMBAL = 10,
    OSDK_PY_K_HAS_FLIGHT_STATUS = 11,
    OSDK_PY_K_HAS_BATTERY = 12,
    OSDK_PY_K_HAS_CONTROL_INFO = 13,
    OSDK_PY_K_RESERVED_FLAGS = 14,
    OSDK_PY_K_TIME_STAMP = 15,
    OSDK_PY_K_QUATERNION = 16,
    OSDK_PY_K_ACCELERATION = 17,
    OSDK_PY_K_VELOCITY = 18,
    OSDK_PY_K_ANGULAR_RATE = 19,
    OSDK_PY_K_POSITION = 20,
    OSDK_PY_K_GPS_DETAIL = 21,
    OSDK_PY_K_RTK_DETAIL = 22,
    OSDK_PY_K_MAGNETOMETER = 23,
    OSDK_PY_K_RC = 24,
    OSDK_PY_K_GIMBAL = 25,
    OSDK_PY_K_FLIGHT_STATUS = 26,
    OSDK_PY_K_BATTERY = 27,
    OSDK_PY_K_CONTROL_INFO = 28,
    OSDK_PY_K_CUR_MOV_CONTROL_MODE = 29,
    OSDK_PY_K_CONTROL_DEVICE = 30,
    OSDK_PY_K_ONBOARD_REQUESTED = 31,
    OSDK_PY_K_VIRTUAL_RC = 32,
    OSDK_PY_K_RESERVED = 33,
    OSDK_PY_K_ROLL = 34,
    OSDK_PY_K_PITCH = 35,
    OSDK_PY_K_YAW = 36,
    OSDK_PY_K_LIMIT = 37,
    OSDK_PY_K_PITCH_LIMIT = 38,
    OSDK_PY_K_ROLL_LIMIT = 39,
    OSDK_PY_K_YAW_LIMIT = 40,
    OSDK_PY_K_DATE = 41,
    OSDK_PY_K_TIME = 42,
    OSDK_PY_K_LONGITUDE = 43,
    OSDK_PY_K_LATITUDE = 44,
    OSDK_PY_K_HEIGHT_MSL = 45,
    OSDK_PY_K_VEL_N = 46,
    OSDK_PY_K_VEL_E = 47,
    OSDK_PY_K_VEL_D = 48,
    OSDK_PY_K_X = 49,
    OSDK_PY_K_Y = 50,
    OSDK_PY_K_Z = 51,
    OSDK_PY_K_ALTITUDE = 52,
    OSDK_PY_K_HEIGHT = 53,
    OSDK_PY_K_GPS_HEALTH = 54,
    OSDK_PY_K_Q0 = 55,
    OSDK_PY_K_Q1 = 56,
    OSDK_PY_K_Q2 = 57,
    OSDK_PY_K_Q3 = 58,
    OSDK_PY_K_THROTTLE = 59,
    OSDK_PY_K_MODE = 60,
    OSDK_PY_K_GEAR = 61,
    OSDK_PY_K_POSITION_FLAG = 62,
    OSDK_PY_K_YAW_FLAG = 63,
    OSDK_PY_K_NANO_TIME = 64,
    OSDK_PY_K_SYNC_FLAG = 65,
    OSDK_PY_K_DATA_VALID = 66,
    OSDK_PY_K_SENSOR_ID = 67,
    OSDK_PY_K_STABLE_MODE = 68,
    OSDK_PY_K_HORIZONTAL_FRAME = 69,
    OSDK_PY_K_YAW_LOGIC = 70,
    OSDK_PY_K_VERTICAL_LOGIC = 71,
    OSDK_PY_K_HORIZONTAL_LOGIC = 72,
    OSDK_PY_K_SOF = 73,
    OSDK_PY_K_LEN = 74,
    OSDK_PY_K_VER = 75,
    OSDK_PY_K_SESSION = 76,
    OSDK_PY_K_IS_ACK = 77,
    OSDK_PY_K_RES0 = 78,
    OSDK_PY_K_PADDING = 79,
    OSDK_PY_K_ENC = 80,
    OSDK_PY_K_RES1 = 81,
    OSDK_PY_K_SEQ = 82,
    OSDK_PY_K_CRC16 = 83,
    OSDK_PY_K_DATA = 84,
    OSDK_PY_K_CRC32 = 85,
    OSDK_PY_K_CMD_SET = 86,
    OSDK_PY_K_CMD_ID = 87,
    OSDK_PY_K_VALUE = 88,
    OSDK_PY_K_ACK_VALUE = 89,
    OSDK_PY_K_CONTROL_MODE = 90,
    OSDK_PY_K_BODY = 91,
    OSDK_PY_K_ACK_CODE = 92,
    OSDK_PY_K_APP_ID = 93,
    OSDK_PY_K_API_LEVEL = 94,
    OSDK_PY_K_SDK_VERSION = 95,
    OSDK_PY_K_BUNDLE_ID = 96,
    OSDK_PY_K_REQUEST = 97,
    OSDK_PY_K_CODES = 98,
    OSDK_PY_K_REASON = 99,
    OSDK_PY_K_RAW = 100,
    OSDK_PY_K_VERSION_CRC = 101,
    OSDK_PY_K_VERSION_ID = 102,
    OSDK_PY_K_VERSION_NAME = 103,
    OSDK_PY_K_ARBITRARY = 104,
    OSDK_PY_K_NAME = 105,
    OSDK_PY_K_F32 = 106,
    OSDK_PY_K_F64 = 107,
    OSDK_PY_KEY_COUNT = 108
};

extern PyObject *osdk_py_keys[OSDK_PY_KEY_COUNT];

/* A dict of n keys, made at its final size (3.13 made the call internal). */
#if PY_VERSION_HEX < 0x030D0000
#define OSDK_PY_NEW_DICT(n) _PyDict_NewPresized(n)
#else
#define OSDK_PY_NEW_DICT(n) PyDict_New()
#endif

/* 0 on success, -1 with an exception set. */
int osdk_model_py_init(void);

/* Store value (a new reference, which this consumes; NULL means a failure
 * already raised) under key; 0 on success, -1 on failure. */
int osdk_py_put(PyObject *dict, PyObject *key, PyObject *value);
/* The cycle collector's view of a finished model: a dict of plain values and
 * other finished dicts cannot be part of a reference cycle, so it is taken
 * off the collector's lists (CPython puts a dict back on them as soon as a
 * container is stored in it). Without this, the hundreds of dicts of every
 * frame make the collector run, over the whole heap, more often than the
 * decoder decodes. The dict of a type with a `repeat` field (a list) stays
 * tracked: a list is not put back when something is appended to it.
 * Returns d. */
static inline PyObject *osdk_py_untracked(PyObject *d)
{
    PyObject_GC_UnTrack(d);
    return d;
}
/* A str for a name of the spec (a string with static storage), cached. */
PyObject *osdk_py_name(const char *name);
PyObject *osdk_py_bool(bool v);
PyObject *osdk_py_hex(const uint8_t *p, size_t n);
PyObject *osdk_py_enum(int64_t value, const char *name);
PyObject *osdk_py_f32(uint32_t bits);
PyObject *osdk_py_f64(uint64_t bits);

/* Model of each ksy type. */
PyObject *osdk_broadcast_a3_fw3_1_to_py(const osdk_broadcast_a3_fw3_1_t *self);
PyObject *osdk_broadcast_items_control_info_to_py(const osdk_broadcast_items_control_info_t *self);
PyObject *osdk_broadcast_items_gimbal_to_py(const osdk_broadcast_items_gimbal_t *self);
PyObject *osdk_broadcast_items_gimbal_limit_to_py(const osdk_broadcast_items_gimbal_limit_t *self);
PyObject *osdk_broadcast_items_gps_detail_to_py(const osdk_broadcast_items_gps_detail_t *self);
PyObject *osdk_broadcast_items_magnetometer_to_py(const osdk_broadcast_items_magnetometer_t *self);
PyObject *osdk_broadcast_items_position_to_py(const osdk_broadcast_items_position_t *self);
PyObject *osdk_broadcast_items_quaternion_to_py(const osdk_broadcast_items_quaternion_t *self);
PyObject *osdk_broadcast_items_rc_to_py(const osdk_broadcast_items_rc_t *self);
PyObject *osdk_broadcast_items_rtk_detail_to_py(const osdk_broadcast_items_rtk_detail_t *self);
PyObject *osdk_broadcast_items_time_stamp_to_py(const osdk_broadcast_items_time_stamp_t *self);
PyObject *osdk_broadcast_items_vector3f_to_py(const osdk_broadcast_items_vector3f_t *self);
PyObject *osdk_broadcast_items_velocity_to_py(const osdk_broadcast_items_velocity_t *self);
PyObject *osdk_broadcast_m100_fw2_3_to_py(const osdk_broadcast_m100_fw2_3_t *self);
PyObject *osdk_broadcast_m100_fw3_1_to_py(const osdk_broadcast_m100_fw3_1_t *self);
PyObject *osdk_control_mode_to_py(const osdk_control_mode_t *self);
PyObject *osdk_frame_to_py(const osdk_frame_t *self);
PyObject *osdk_frame_frame_data_to_py(const osdk_frame_frame_data_t *self);
PyObject *osdk_movement_control_to_py(const osdk_movement_control_t *self);
PyObject *osdk_payload_to_py(const osdk_payload_t *self);
PyObject *osdk_payload_activation_ack_value_to_py(const osdk_payload_activation_ack_value_t *self);
PyObject *osdk_payload_activation_request_to_py(const osdk_payload_activation_request_t *self);
PyObject *osdk_payload_broadcast_to_py(const osdk_payload_broadcast_t *self);
PyObject *osdk_payload_control_ack_value_to_py(const osdk_payload_control_ack_value_t *self);
PyObject *osdk_payload_control_request_to_py(const osdk_payload_control_request_t *self);
PyObject *osdk_payload_frequency_ack_value_to_py(const osdk_payload_frequency_ack_value_t *self);
PyObject *osdk_payload_frequency_request_to_py(const osdk_payload_frequency_request_t *self);
PyObject *osdk_payload_lost_control_to_py(const osdk_payload_lost_control_t *self);
PyObject *osdk_payload_lost_control_ack_value_to_py(const osdk_payload_lost_control_ack_value_t *self);
PyObject *osdk_payload_unknown_value_to_py(const osdk_payload_unknown_value_t *self);
PyObject *osdk_payload_version_ack_value_to_py(const osdk_payload_version_ack_value_t *self);
PyObject *osdk_payload_version_query_to_py(const osdk_payload_version_query_t *self);

#ifdef __cplusplus
}
#endif

#endif /* OSDK_MODEL_PY_H */
