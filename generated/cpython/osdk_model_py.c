/* Generated from spec/ by tools/cgen/generate.py. Do not edit. */
/* osdk_model_py.c - see osdk_model_py.h. */
#include "osdk_model_py.h"

#include <math.h>
#include <string.h>

PyObject *osdk_py_keys[OSDK_PY_KEY_COUNT];

static const char *const key_names[OSDK_PY_KEY_COUNT] = {
     "has_time_stamp", "has_quaternion", "has_acceleration", "has_velocity", "has_angular_rate", "has_position",
     "has_gps_detail", "has_rtk_detail", "has_magnetometer", "has_rc", "has_gimbal", "has_flight_status",
     "has_battery", "has_control_info", "reserved_flags", "time_stamp", "quaternion", "acceleration",
     "velocity", "angular_rate", "position", "gps_detail", "rtk_detail", "magnetometer",
     "rc", "gimbal", "flight_status", "battery", "control_info", "cur_mov_control_mode",
     "control_device", "onboard_requested", "virtual_rc", "reserved", "roll", "pitch",
     "yaw", "limit", "pitch_limit", "roll_limit", "yaw_limit", "date",
     "time", "longitude", "latitude", "height_msl", "vel_n", "vel_e",
     "vel_d", "x", "y", "z", "altitude", "height",
     "gps_health", "q0", "q1", "q2", "q3", "throttle",
     "mode", "gear", "position_flag", "yaw_flag", "nano_time", "sync_flag",
     "data_valid", "sensor_id", "stable_mode", "horizontal_frame", "yaw_logic", "vertical_logic",
     "horizontal_logic", "sof", "len", "ver", "session", "is_ack",
     "res0", "padding", "enc", "res1", "seq", "crc16",
     "data", "crc32", "cmd_set", "cmd_id", "value", "ack_value",
     "control_mode", "body", "ack_code", "app_id", "api_level", "sdk_version",
     "bundle_id", "request", "codes", "reason", "raw", "version_crc",
     "version_id", "version_name", "arbitrary", "name", "f32", "f64"
    };

static PyObject *nan_text, *inf_text, *ninf_text;

int osdk_model_py_init(void)
{
    size_t i;
    for (i = 0; i < OSDK_PY_KEY_COUNT; i++) {
        if (osdk_py_keys[i] == NULL && (osdk_py_keys[i] = PyUnicode_InternFromString(key_names[i])) == NULL)
            return -1;
    }
    if (nan_text == NULL && (nan_text = PyUnicode_InternFromString("NaN")) == NULL) return -1;
    if (inf_text == NULL && (inf_text = PyUnicode_InternFromString("Infinity")) == NULL) return -1;
    if (ninf_text == NULL && (ninf_text = PyUnicode_InternFromString("-Infinity")) == NULL) return -1;
    return 0;
}

int osdk_py_put(PyObject *dict, PyObject *key, PyObject *value)
{
    int r;
    if (value == NULL) return -1;
    r = PyDict_SetItem(dict, key, value);
    Py_DECREF(value);
    return r;
}

/* Names come from the generated tables (string literals), so their
 * addresses are stable: a small open-addressing table keyed by address
 * turns each into one str object for the life of the process. */
#define NAME_SLOTS 1024
static struct {
    const char *name;
    PyObject *text;
} names[NAME_SLOTS];

PyObject *osdk_py_name(const char *name)
{
    size_t h = ((size_t)(uintptr_t)name >> 3) & (NAME_SLOTS - 1), tries;
    for (tries = 0; tries < NAME_SLOTS; tries++, h = (h + 1) & (NAME_SLOTS - 1)) {
        if (names[h].name == name) return Py_NewRef(names[h].text);
        if (names[h].name == NULL) {
            PyObject *text = PyUnicode_InternFromString(name);
            if (text == NULL) return NULL;
            names[h].name = name;
            names[h].text = text;
            return Py_NewRef(text);
        }
    }
    return PyUnicode_FromString(name); /* table full: correct, only slower */
}

PyObject *osdk_py_bool(bool v)
{
    return Py_NewRef(v ? Py_True : Py_False);
}

static const char hex_digits[] = "0123456789abcdef";

PyObject *osdk_py_hex(const uint8_t *p, size_t n)
{
    PyObject *s = PyUnicode_New((Py_ssize_t)(2 * n), 127);
    Py_UCS1 *out;
    size_t i;
    if (s == NULL) return NULL;
    out = PyUnicode_1BYTE_DATA(s);
    for (i = 0; i < n; i++) {
        out[2 * i] = (Py_UCS1)hex_digits[p[i] >> 4];
        out[2 * i + 1] = (Py_UCS1)hex_digits[p[i] & 15];
    }
    return s;
}

PyObject *osdk_py_enum(int64_t value, const char *name)
{
    PyObject *d = OSDK_PY_NEW_DICT(2);
    if (d == NULL) return NULL;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_VALUE], PyLong_FromLongLong((long long)value)) < 0 ||
        osdk_py_put(d, osdk_py_keys[OSDK_PY_K_NAME], name ? osdk_py_name(name) : Py_NewRef(Py_None)) < 0) {
        Py_DECREF(d);
        return NULL;
    }
    return osdk_py_untracked(d);
}

/* "0x" and the bits as `digits` lowercase hex digits. */
static PyObject *bits_hex(uint64_t bits, int digits)
{
    PyObject *s = PyUnicode_New(2 + digits, 127);
    Py_UCS1 *out;
    int i;
    if (s == NULL) return NULL;
    out = PyUnicode_1BYTE_DATA(s);
    out[0] = '0';
    out[1] = 'x';
    for (i = digits - 1; i >= 0; i--, bits >>= 4) out[2 + i] = (Py_UCS1)hex_digits[bits & 15];
    return s;
}

/* The number for people: a float, or the JSON-safe names of the non-finite ones. */
static PyObject *readable(double v)
{
    if (isnan(v)) return Py_NewRef(nan_text);
    if (isinf(v)) return Py_NewRef(v > 0 ? inf_text : ninf_text);
    return PyFloat_FromDouble(v);
}

static PyObject *float_model(int key, uint64_t bits, int digits, double value)
{
    PyObject *d = OSDK_PY_NEW_DICT(2);
    if (d == NULL) return NULL;
    if (osdk_py_put(d, osdk_py_keys[key], bits_hex(bits, digits)) < 0 ||
        osdk_py_put(d, osdk_py_keys[OSDK_PY_K_VALUE], readable(value)) < 0) {
        Py_DECREF(d);
        return NULL;
    }
    return osdk_py_untracked(d);
}

PyObject *osdk_py_f32(uint32_t bits)
{
    return float_model(OSDK_PY_K_F32, bits, 8, (double)osdk_f32_from_bits(bits));
}

PyObject *osdk_py_f64(uint64_t bits)
{
    return float_model(OSDK_PY_K_F64, bits, 16, osdk_f64_from_bits(bits));
}

/* osdk_broadcast_a3_fw3_1 */
PyObject *osdk_broadcast_a3_fw3_1_to_py(const osdk_broadcast_a3_fw3_1_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(29);
    if (d == NULL) return NULL;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_TIME_STAMP], osdk_py_bool(self->has_time_stamp)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_QUATERNION], osdk_py_bool(self->has_quaternion)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_ACCELERATION], osdk_py_bool(self->has_acceleration)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_VELOCITY], osdk_py_bool(self->has_velocity)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_ANGULAR_RATE], osdk_py_bool(self->has_angular_rate)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_POSITION], osdk_py_bool(self->has_position)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_GPS_DETAIL], osdk_py_bool(self->has_gps_detail)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_RTK_DETAIL], osdk_py_bool(self->has_rtk_detail)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_MAGNETOMETER], osdk_py_bool(self->has_magnetometer)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_RC], osdk_py_bool(self->has_rc)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_GIMBAL], osdk_py_bool(self->has_gimbal)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_FLIGHT_STATUS], osdk_py_bool(self->has_flight_status)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_BATTERY], osdk_py_bool(self->has_battery)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_CONTROL_INFO], osdk_py_bool(self->has_control_info)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_RESERVED_FLAGS], PyLong_FromUnsignedLongLong((unsigned long long)self->reserved_flags)) < 0) goto fail;
    if (self->time_stamp_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_TIME_STAMP], osdk_broadcast_items_time_stamp_to_py(&self->time_stamp)) < 0) goto fail;
    }
    if (self->quaternion_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_QUATERNION], osdk_broadcast_items_quaternion_to_py(&self->quaternion)) < 0) goto fail;
    }
    if (self->acceleration_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_ACCELERATION], osdk_broadcast_items_vector3f_to_py(&self->acceleration)) < 0) goto fail;
    }
    if (self->velocity_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_VELOCITY], osdk_broadcast_items_velocity_to_py(&self->velocity)) < 0) goto fail;
    }
    if (self->angular_rate_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_ANGULAR_RATE], osdk_broadcast_items_vector3f_to_py(&self->angular_rate)) < 0) goto fail;
    }
    if (self->position_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_POSITION], osdk_broadcast_items_position_to_py(&self->position)) < 0) goto fail;
    }
    if (self->gps_detail_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_GPS_DETAIL], osdk_broadcast_items_gps_detail_to_py(&self->gps_detail)) < 0) goto fail;
    }
    if (self->rtk_detail_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_RTK_DETAIL], osdk_broadcast_items_rtk_detail_to_py(&self->rtk_detail)) < 0) goto fail;
    }
    if (self->magnetometer_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_MAGNETOMETER], osdk_broadcast_items_magnetometer_to_py(&self->magnetometer)) < 0) goto fail;
    }
    if (self->rc_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_RC], osdk_broadcast_items_rc_to_py(&self->rc)) < 0) goto fail;
    }
    if (self->gimbal_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_GIMBAL], osdk_broadcast_items_gimbal_to_py(&self->gimbal)) < 0) goto fail;
    }
    if (self->flight_status_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_FLIGHT_STATUS], PyLong_FromUnsignedLongLong((unsigned long long)self->flight_status)) < 0) goto fail;
    }
    if (self->battery_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_BATTERY], PyLong_FromUnsignedLongLong((unsigned long long)self->battery)) < 0) goto fail;
    }
    if (self->control_info_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_CONTROL_INFO], osdk_broadcast_items_control_info_to_py(&self->control_info)) < 0) goto fail;
    }
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_broadcast_items::control_info */
PyObject *osdk_broadcast_items_control_info_to_py(const osdk_broadcast_items_control_info_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(5);
    if (d == NULL) return NULL;
    if (self->cur_mov_control_mode_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_CUR_MOV_CONTROL_MODE], osdk_py_enum((int64_t)self->cur_mov_control_mode, osdk_broadcast_items_cur_mov_control_mode_name((int64_t)self->cur_mov_control_mode))) < 0) goto fail;
    }
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_CONTROL_DEVICE], osdk_py_enum((int64_t)self->control_device, osdk_broadcast_items_control_device_name((int64_t)self->control_device))) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_ONBOARD_REQUESTED], osdk_py_bool(self->onboard_requested)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_VIRTUAL_RC], osdk_py_bool(self->virtual_rc)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_RESERVED], PyLong_FromUnsignedLongLong((unsigned long long)self->reserved)) < 0) goto fail;
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_broadcast_items::gimbal */
PyObject *osdk_broadcast_items_gimbal_to_py(const osdk_broadcast_items_gimbal_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(4);
    if (d == NULL) return NULL;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_ROLL], osdk_py_f32(self->roll.bits)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_PITCH], osdk_py_f32(self->pitch.bits)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_YAW], osdk_py_f32(self->yaw.bits)) < 0) goto fail;
    if (self->limit_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_LIMIT], osdk_broadcast_items_gimbal_limit_to_py(&self->limit)) < 0) goto fail;
    }
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_broadcast_items::gimbal_limit */
PyObject *osdk_broadcast_items_gimbal_limit_to_py(const osdk_broadcast_items_gimbal_limit_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(4);
    if (d == NULL) return NULL;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_PITCH_LIMIT], osdk_py_bool(self->pitch_limit)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_ROLL_LIMIT], osdk_py_bool(self->roll_limit)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_YAW_LIMIT], osdk_py_bool(self->yaw_limit)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_RESERVED], PyLong_FromUnsignedLongLong((unsigned long long)self->reserved)) < 0) goto fail;
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_broadcast_items::gps_detail */
PyObject *osdk_broadcast_items_gps_detail_to_py(const osdk_broadcast_items_gps_detail_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(8);
    if (d == NULL) return NULL;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_DATE], PyLong_FromUnsignedLongLong((unsigned long long)self->date)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_TIME], PyLong_FromUnsignedLongLong((unsigned long long)self->time)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_LONGITUDE], PyLong_FromLongLong((long long)self->longitude)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_LATITUDE], PyLong_FromLongLong((long long)self->latitude)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HEIGHT_MSL], PyLong_FromLongLong((long long)self->height_msl)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_VEL_N], osdk_py_f32(self->vel_n.bits)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_VEL_E], osdk_py_f32(self->vel_e.bits)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_VEL_D], osdk_py_f32(self->vel_d.bits)) < 0) goto fail;
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_broadcast_items::magnetometer */
PyObject *osdk_broadcast_items_magnetometer_to_py(const osdk_broadcast_items_magnetometer_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(3);
    if (d == NULL) return NULL;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_X], PyLong_FromLongLong((long long)self->x)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_Y], PyLong_FromLongLong((long long)self->y)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_Z], PyLong_FromLongLong((long long)self->z)) < 0) goto fail;
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_broadcast_items::position */
PyObject *osdk_broadcast_items_position_to_py(const osdk_broadcast_items_position_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(5);
    if (d == NULL) return NULL;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_LATITUDE], osdk_py_f64(self->latitude.bits)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_LONGITUDE], osdk_py_f64(self->longitude.bits)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_ALTITUDE], osdk_py_f32(self->altitude.bits)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HEIGHT], osdk_py_f32(self->height.bits)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_GPS_HEALTH], PyLong_FromUnsignedLongLong((unsigned long long)self->gps_health)) < 0) goto fail;
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_broadcast_items::quaternion */
PyObject *osdk_broadcast_items_quaternion_to_py(const osdk_broadcast_items_quaternion_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(4);
    if (d == NULL) return NULL;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_Q0], osdk_py_f32(self->q0.bits)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_Q1], osdk_py_f32(self->q1.bits)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_Q2], osdk_py_f32(self->q2.bits)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_Q3], osdk_py_f32(self->q3.bits)) < 0) goto fail;
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_broadcast_items::rc */
PyObject *osdk_broadcast_items_rc_to_py(const osdk_broadcast_items_rc_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(6);
    if (d == NULL) return NULL;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_ROLL], PyLong_FromLongLong((long long)self->roll)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_PITCH], PyLong_FromLongLong((long long)self->pitch)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_YAW], PyLong_FromLongLong((long long)self->yaw)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_THROTTLE], PyLong_FromLongLong((long long)self->throttle)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_MODE], PyLong_FromLongLong((long long)self->mode)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_GEAR], PyLong_FromLongLong((long long)self->gear)) < 0) goto fail;
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_broadcast_items::rtk_detail */
PyObject *osdk_broadcast_items_rtk_detail_to_py(const osdk_broadcast_items_rtk_detail_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(11);
    if (d == NULL) return NULL;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_DATE], PyLong_FromUnsignedLongLong((unsigned long long)self->date)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_TIME], PyLong_FromUnsignedLongLong((unsigned long long)self->time)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_LONGITUDE], osdk_py_f64(self->longitude.bits)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_LATITUDE], osdk_py_f64(self->latitude.bits)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HEIGHT_MSL], osdk_py_f32(self->height_msl.bits)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_VEL_N], osdk_py_f32(self->vel_n.bits)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_VEL_E], osdk_py_f32(self->vel_e.bits)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_VEL_D], osdk_py_f32(self->vel_d.bits)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_YAW], PyLong_FromLongLong((long long)self->yaw)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_POSITION_FLAG], PyLong_FromUnsignedLongLong((unsigned long long)self->position_flag)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_YAW_FLAG], PyLong_FromUnsignedLongLong((unsigned long long)self->yaw_flag)) < 0) goto fail;
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_broadcast_items::time_stamp */
PyObject *osdk_broadcast_items_time_stamp_to_py(const osdk_broadcast_items_time_stamp_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(3);
    if (d == NULL) return NULL;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_TIME], PyLong_FromUnsignedLongLong((unsigned long long)self->time)) < 0) goto fail;
    if (self->nano_time_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_NANO_TIME], PyLong_FromUnsignedLongLong((unsigned long long)self->nano_time)) < 0) goto fail;
    }
    if (self->sync_flag_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_SYNC_FLAG], PyLong_FromUnsignedLongLong((unsigned long long)self->sync_flag)) < 0) goto fail;
    }
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_broadcast_items::vector3f */
PyObject *osdk_broadcast_items_vector3f_to_py(const osdk_broadcast_items_vector3f_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(3);
    if (d == NULL) return NULL;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_X], osdk_py_f32(self->x.bits)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_Y], osdk_py_f32(self->y.bits)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_Z], osdk_py_f32(self->z.bits)) < 0) goto fail;
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_broadcast_items::velocity */
PyObject *osdk_broadcast_items_velocity_to_py(const osdk_broadcast_items_velocity_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(6);
    if (d == NULL) return NULL;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_X], osdk_py_f32(self->x.bits)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_Y], osdk_py_f32(self->y.bits)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_Z], osdk_py_f32(self->z.bits)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_DATA_VALID], osdk_py_bool(self->data_valid)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_SENSOR_ID], PyLong_FromUnsignedLongLong((unsigned long long)self->sensor_id)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_RESERVED], PyLong_FromUnsignedLongLong((unsigned long long)self->reserved)) < 0) goto fail;
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_broadcast_m100_fw2_3 */
PyObject *osdk_broadcast_m100_fw2_3_to_py(const osdk_broadcast_m100_fw2_3_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(25);
    if (d == NULL) return NULL;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_TIME_STAMP], osdk_py_bool(self->has_time_stamp)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_QUATERNION], osdk_py_bool(self->has_quaternion)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_ACCELERATION], osdk_py_bool(self->has_acceleration)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_VELOCITY], osdk_py_bool(self->has_velocity)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_ANGULAR_RATE], osdk_py_bool(self->has_angular_rate)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_POSITION], osdk_py_bool(self->has_position)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_MAGNETOMETER], osdk_py_bool(self->has_magnetometer)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_RC], osdk_py_bool(self->has_rc)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_GIMBAL], osdk_py_bool(self->has_gimbal)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_FLIGHT_STATUS], osdk_py_bool(self->has_flight_status)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_BATTERY], osdk_py_bool(self->has_battery)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_CONTROL_INFO], osdk_py_bool(self->has_control_info)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_RESERVED_FLAGS], PyLong_FromUnsignedLongLong((unsigned long long)self->reserved_flags)) < 0) goto fail;
    if (self->time_stamp_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_TIME_STAMP], osdk_broadcast_items_time_stamp_to_py(&self->time_stamp)) < 0) goto fail;
    }
    if (self->quaternion_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_QUATERNION], osdk_broadcast_items_quaternion_to_py(&self->quaternion)) < 0) goto fail;
    }
    if (self->acceleration_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_ACCELERATION], osdk_broadcast_items_vector3f_to_py(&self->acceleration)) < 0) goto fail;
    }
    if (self->velocity_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_VELOCITY], osdk_broadcast_items_velocity_to_py(&self->velocity)) < 0) goto fail;
    }
    if (self->angular_rate_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_ANGULAR_RATE], osdk_broadcast_items_vector3f_to_py(&self->angular_rate)) < 0) goto fail;
    }
    if (self->position_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_POSITION], osdk_broadcast_items_position_to_py(&self->position)) < 0) goto fail;
    }
    if (self->magnetometer_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_MAGNETOMETER], osdk_broadcast_items_magnetometer_to_py(&self->magnetometer)) < 0) goto fail;
    }
    if (self->rc_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_RC], osdk_broadcast_items_rc_to_py(&self->rc)) < 0) goto fail;
    }
    if (self->gimbal_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_GIMBAL], osdk_broadcast_items_gimbal_to_py(&self->gimbal)) < 0) goto fail;
    }
    if (self->flight_status_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_FLIGHT_STATUS], PyLong_FromUnsignedLongLong((unsigned long long)self->flight_status)) < 0) goto fail;
    }
    if (self->battery_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_BATTERY], PyLong_FromUnsignedLongLong((unsigned long long)self->battery)) < 0) goto fail;
    }
    if (self->control_info_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_CONTROL_INFO], osdk_broadcast_items_control_info_to_py(&self->control_info)) < 0) goto fail;
    }
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_broadcast_m100_fw3_1 */
PyObject *osdk_broadcast_m100_fw3_1_to_py(const osdk_broadcast_m100_fw3_1_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(25);
    if (d == NULL) return NULL;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_TIME_STAMP], osdk_py_bool(self->has_time_stamp)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_QUATERNION], osdk_py_bool(self->has_quaternion)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_ACCELERATION], osdk_py_bool(self->has_acceleration)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_VELOCITY], osdk_py_bool(self->has_velocity)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_ANGULAR_RATE], osdk_py_bool(self->has_angular_rate)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_POSITION], osdk_py_bool(self->has_position)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_MAGNETOMETER], osdk_py_bool(self->has_magnetometer)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_RC], osdk_py_bool(self->has_rc)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_GIMBAL], osdk_py_bool(self->has_gimbal)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_FLIGHT_STATUS], osdk_py_bool(self->has_flight_status)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_BATTERY], osdk_py_bool(self->has_battery)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HAS_CONTROL_INFO], osdk_py_bool(self->has_control_info)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_RESERVED_FLAGS], PyLong_FromUnsignedLongLong((unsigned long long)self->reserved_flags)) < 0) goto fail;
    if (self->time_stamp_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_TIME_STAMP], osdk_broadcast_items_time_stamp_to_py(&self->time_stamp)) < 0) goto fail;
    }
    if (self->quaternion_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_QUATERNION], osdk_broadcast_items_quaternion_to_py(&self->quaternion)) < 0) goto fail;
    }
    if (self->acceleration_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_ACCELERATION], osdk_broadcast_items_vector3f_to_py(&self->acceleration)) < 0) goto fail;
    }
    if (self->velocity_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_VELOCITY], osdk_broadcast_items_velocity_to_py(&self->velocity)) < 0) goto fail;
    }
    if (self->angular_rate_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_ANGULAR_RATE], osdk_broadcast_items_vector3f_to_py(&self->angular_rate)) < 0) goto fail;
    }
    if (self->position_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_POSITION], osdk_broadcast_items_position_to_py(&self->position)) < 0) goto fail;
    }
    if (self->magnetometer_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_MAGNETOMETER], osdk_broadcast_items_magnetometer_to_py(&self->magnetometer)) < 0) goto fail;
    }
    if (self->rc_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_RC], osdk_broadcast_items_rc_to_py(&self->rc)) < 0) goto fail;
    }
    if (self->gimbal_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_GIMBAL], osdk_broadcast_items_gimbal_to_py(&self->gimbal)) < 0) goto fail;
    }
    if (self->flight_status_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_FLIGHT_STATUS], PyLong_FromUnsignedLongLong((unsigned long long)self->flight_status)) < 0) goto fail;
    }
    if (self->battery_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_BATTERY], PyLong_FromUnsignedLongLong((unsigned long long)self->battery)) < 0) goto fail;
    }
    if (self->control_info_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_CONTROL_INFO], osdk_broadcast_items_control_info_to_py(&self->control_info)) < 0) goto fail;
    }
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_control_mode */
PyObject *osdk_control_mode_to_py(const osdk_control_mode_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(5);
    if (d == NULL) return NULL;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_STABLE_MODE], osdk_py_enum((int64_t)self->stable_mode, osdk_control_mode_stable_mode_name((int64_t)self->stable_mode))) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HORIZONTAL_FRAME], osdk_py_enum((int64_t)self->horizontal_frame, osdk_control_mode_horizontal_frame_name((int64_t)self->horizontal_frame))) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_YAW_LOGIC], osdk_py_enum((int64_t)self->yaw_logic, osdk_control_mode_yaw_logic_name((int64_t)self->yaw_logic))) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_VERTICAL_LOGIC], osdk_py_enum((int64_t)self->vertical_logic, osdk_control_mode_vertical_logic_name((int64_t)self->vertical_logic))) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_HORIZONTAL_LOGIC], osdk_py_enum((int64_t)self->horizontal_logic, osdk_control_mode_horizontal_logic_name((int64_t)self->horizontal_logic))) < 0) goto fail;
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_frame */
PyObject *osdk_frame_to_py(const osdk_frame_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(13);
    if (d == NULL) return NULL;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_SOF], osdk_py_hex(self->sof.ptr, self->sof.len)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_LEN], PyLong_FromUnsignedLongLong((unsigned long long)self->len)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_VER], PyLong_FromUnsignedLongLong((unsigned long long)self->ver)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_SESSION], PyLong_FromUnsignedLongLong((unsigned long long)self->session)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_IS_ACK], osdk_py_bool(self->is_ack)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_RES0], PyLong_FromUnsignedLongLong((unsigned long long)self->res0)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_PADDING], PyLong_FromUnsignedLongLong((unsigned long long)self->padding)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_ENC], osdk_py_enum((int64_t)self->enc, osdk_frame_encryption_name((int64_t)self->enc))) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_RES1], PyLong_FromUnsignedLongLong((unsigned long long)self->res1)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_SEQ], PyLong_FromUnsignedLongLong((unsigned long long)self->seq)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_CRC16], PyLong_FromUnsignedLongLong((unsigned long long)self->crc16)) < 0) goto fail;
    if (self->data_present) {
        {
            PyObject *v;
            switch (self->data.tag) {
                case OSDK_FRAME_DATA_FRAME_DATA: v = osdk_frame_frame_data_to_py(&self->data.u.frame_data); break;
                case OSDK_FRAME_DATA_RAW: v = osdk_py_hex(self->data.u.raw.ptr, self->data.u.raw.len); break;
                default: v = Py_NewRef(Py_None); break;
            }
            if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_DATA], v) < 0) goto fail;
        }
    }
    if (self->crc32_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_CRC32], PyLong_FromUnsignedLongLong((unsigned long long)self->crc32)) < 0) goto fail;
    }
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_frame::frame_data */
PyObject *osdk_frame_frame_data_to_py(const osdk_frame_frame_data_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(4);
    if (d == NULL) return NULL;
    if (self->cmd_set_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_CMD_SET], osdk_py_enum((int64_t)self->cmd_set, osdk_frame_command_set_name((int64_t)self->cmd_set))) < 0) goto fail;
    }
    if (self->cmd_id_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_CMD_ID], PyLong_FromUnsignedLongLong((unsigned long long)self->cmd_id)) < 0) goto fail;
    }
    if (self->value_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_VALUE], osdk_payload_to_py(&self->value)) < 0) goto fail;
    }
    if (self->ack_value_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_ACK_VALUE], osdk_py_hex(self->ack_value.ptr, self->ack_value.len)) < 0) goto fail;
    }
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_movement_control */
PyObject *osdk_movement_control_to_py(const osdk_movement_control_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(5);
    if (d == NULL) return NULL;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_CONTROL_MODE], osdk_control_mode_to_py(&self->control_mode)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_X], osdk_py_f32(self->x.bits)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_Y], osdk_py_f32(self->y.bits)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_Z], osdk_py_f32(self->z.bits)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_YAW], osdk_py_f32(self->yaw.bits)) < 0) goto fail;
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_payload */
PyObject *osdk_payload_to_py(const osdk_payload_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(1);
    if (d == NULL) return NULL;
    {
        PyObject *v;
        switch (self->body.tag) {
            case OSDK_PAYLOAD_BODY_VERSION_QUERY: v = osdk_payload_version_query_to_py(&self->body.u.version_query); break;
            case OSDK_PAYLOAD_BODY_ACTIVATION_REQUEST: v = osdk_payload_activation_request_to_py(&self->body.u.activation_request); break;
            case OSDK_PAYLOAD_BODY_FREQUENCY_REQUEST: v = osdk_payload_frequency_request_to_py(&self->body.u.frequency_request); break;
            case OSDK_PAYLOAD_BODY_CONTROL_REQUEST: v = osdk_payload_control_request_to_py(&self->body.u.control_request); break;
            case OSDK_PAYLOAD_BODY_OSDK_MOVEMENT_CONTROL: v = osdk_movement_control_to_py(&self->body.u.osdk_movement_control); break;
            case OSDK_PAYLOAD_BODY_BROADCAST: v = osdk_payload_broadcast_to_py(&self->body.u.broadcast); break;
            case OSDK_PAYLOAD_BODY_LOST_CONTROL: v = osdk_payload_lost_control_to_py(&self->body.u.lost_control); break;
            case OSDK_PAYLOAD_BODY_VERSION_ACK_VALUE: v = osdk_payload_version_ack_value_to_py(&self->body.u.version_ack_value); break;
            case OSDK_PAYLOAD_BODY_ACTIVATION_ACK_VALUE: v = osdk_payload_activation_ack_value_to_py(&self->body.u.activation_ack_value); break;
            case OSDK_PAYLOAD_BODY_FREQUENCY_ACK_VALUE: v = osdk_payload_frequency_ack_value_to_py(&self->body.u.frequency_ack_value); break;
            case OSDK_PAYLOAD_BODY_CONTROL_ACK_VALUE: v = osdk_payload_control_ack_value_to_py(&self->body.u.control_ack_value); break;
            case OSDK_PAYLOAD_BODY_LOST_CONTROL_ACK_VALUE: v = osdk_payload_lost_control_ack_value_to_py(&self->body.u.lost_control_ack_value); break;
            case OSDK_PAYLOAD_BODY_UNKNOWN_VALUE: v = osdk_payload_unknown_value_to_py(&self->body.u.unknown_value); break;
            default: v = Py_NewRef(Py_None); break;
        }
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_BODY], v) < 0) goto fail;
    }
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_payload::activation_ack_value */
PyObject *osdk_payload_activation_ack_value_to_py(const osdk_payload_activation_ack_value_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(1);
    if (d == NULL) return NULL;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_ACK_CODE], osdk_py_enum((int64_t)self->ack_code, osdk_payload_activation_result_name((int64_t)self->ack_code))) < 0) goto fail;
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_payload::activation_request */
PyObject *osdk_payload_activation_request_to_py(const osdk_payload_activation_request_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(4);
    if (d == NULL) return NULL;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_APP_ID], PyLong_FromUnsignedLongLong((unsigned long long)self->app_id)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_API_LEVEL], PyLong_FromUnsignedLongLong((unsigned long long)self->api_level)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_SDK_VERSION], PyLong_FromUnsignedLongLong((unsigned long long)self->sdk_version)) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_BUNDLE_ID], osdk_py_hex(self->bundle_id.ptr, self->bundle_id.len)) < 0) goto fail;
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_payload::broadcast */
PyObject *osdk_payload_broadcast_to_py(const osdk_payload_broadcast_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(1);
    if (d == NULL) return NULL;
    {
        PyObject *v;
        switch (self->data.tag) {
            case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW2_3: v = osdk_broadcast_m100_fw2_3_to_py(&self->data.u.osdk_broadcast_m100_fw2_3); break;
            case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW3_1: v = osdk_broadcast_m100_fw3_1_to_py(&self->data.u.osdk_broadcast_m100_fw3_1); break;
            case OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_A3_FW3_1: v = osdk_broadcast_a3_fw3_1_to_py(&self->data.u.osdk_broadcast_a3_fw3_1); break;
            default: v = Py_NewRef(Py_None); break;
        }
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_DATA], v) < 0) goto fail;
    }
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_payload::control_ack_value */
PyObject *osdk_payload_control_ack_value_to_py(const osdk_payload_control_ack_value_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(1);
    if (d == NULL) return NULL;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_ACK_CODE], osdk_py_enum((int64_t)self->ack_code, osdk_payload_control_ack_name((int64_t)self->ack_code))) < 0) goto fail;
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_payload::control_request */
PyObject *osdk_payload_control_request_to_py(const osdk_payload_control_request_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(1);
    if (d == NULL) return NULL;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_REQUEST], osdk_py_enum((int64_t)self->request, osdk_payload_control_request_code_name((int64_t)self->request))) < 0) goto fail;
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_payload::frequency_ack_value */
PyObject *osdk_payload_frequency_ack_value_to_py(const osdk_payload_frequency_ack_value_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(1);
    if (d == NULL) return NULL;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_ACK_CODE], osdk_py_enum((int64_t)self->ack_code, osdk_payload_frequency_ack_name((int64_t)self->ack_code))) < 0) goto fail;
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_payload::frequency_request */
PyObject *osdk_payload_frequency_request_to_py(const osdk_payload_frequency_request_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(1);
    if (d == NULL) return NULL;
    {
        PyObject *list = PyList_New((Py_ssize_t)self->codes_count);
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_CODES], list) < 0) goto fail;
        for (size_t i = 0; i < self->codes_count; i++) {
            PyObject *item = osdk_py_enum((int64_t)self->codes[i], osdk_payload_frequency_code_name((int64_t)self->codes[i]));
            if (item == NULL) goto fail;
            PyList_SET_ITEM(list, (Py_ssize_t)i, item);
        }
    }
    return d;
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_payload::lost_control */
PyObject *osdk_payload_lost_control_to_py(const osdk_payload_lost_control_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(1);
    if (d == NULL) return NULL;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_REASON], PyLong_FromUnsignedLongLong((unsigned long long)self->reason)) < 0) goto fail;
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_payload::lost_control_ack_value */
PyObject *osdk_payload_lost_control_ack_value_to_py(const osdk_payload_lost_control_ack_value_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(1);
    if (d == NULL) return NULL;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_ACK_CODE], PyLong_FromUnsignedLongLong((unsigned long long)self->ack_code)) < 0) goto fail;
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_payload::unknown_value */
PyObject *osdk_payload_unknown_value_to_py(const osdk_payload_unknown_value_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(1);
    if (d == NULL) return NULL;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_RAW], osdk_py_hex(self->raw.ptr, self->raw.len)) < 0) goto fail;
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_payload::version_ack_value */
PyObject *osdk_payload_version_ack_value_to_py(const osdk_payload_version_ack_value_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(4);
    if (d == NULL) return NULL;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_ACK_CODE], osdk_py_enum((int64_t)self->ack_code, osdk_payload_version_ack_name((int64_t)self->ack_code))) < 0) goto fail;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_VERSION_CRC], PyLong_FromUnsignedLongLong((unsigned long long)self->version_crc)) < 0) goto fail;
    if (self->version_id_present) {
        if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_VERSION_ID], osdk_py_hex(self->version_id.ptr, self->version_id.len)) < 0) goto fail;
    }
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_VERSION_NAME], osdk_py_hex(self->version_name.ptr, self->version_name.len)) < 0) goto fail;
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}

/* osdk_payload::version_query */
PyObject *osdk_payload_version_query_to_py(const osdk_payload_version_query_t *self)
{
    PyObject *d = OSDK_PY_NEW_DICT(1);
    if (d == NULL) return NULL;
    if (osdk_py_put(d, osdk_py_keys[OSDK_PY_K_ARBITRARY], PyLong_FromUnsignedLongLong((unsigned long long)self->arbitrary)) < 0) goto fail;
    return osdk_py_untracked(d);
fail:
    Py_DECREF(d);
    return NULL;
}


