/* Generated from spec/ by tools/cgen/generate.py. Do not edit. */
/* osdk_decoder.c - see osdk_decoder.h. */
#include "osdk_decoder.h"

#include <string.h>

/* ---- runtime ---------------------------------------------------------------------- */

static const char *const osdk_status_names[15] = {"ok", "bad_sof", "bad_crc16", "bad_version", "reserved_bits", "impossible_length", "bad_encryption", "bad_session", "bad_crc32", "truncated_frame", "truncated_payload", "length_mismatch", "undecodable", "undefined_mode", "out_of_range"};

const char *osdk_status_name(osdk_status_t status)
{
    if ((int)status < 0 || (int)status >= 15) return "undecodable";
    return osdk_status_names[status];
}

void osdk_error_clear(osdk_error_t *err)
{
    err->status = OSDK_OK;
    err->type = NULL;
    err->field = NULL;
    err->offset = 0;
}

float osdk_f32_from_bits(uint32_t bits)
{
    float f;
    memcpy(&f, &bits, sizeof f);
    return f;
}

double osdk_f64_from_bits(uint64_t bits)
{
    double d;
    memcpy(&d, &bits, sizeof d);
    return d;
}

/* What a stream given no buffer reads from: one byte, never read (its size is 0). */
static const uint8_t osdk_no_bytes[1];

void osdk_stream_init(osdk_stream_t *io, const uint8_t *data, size_t size)
{
    io->data = data ? data : osdk_no_bytes;
    io->size = data ? size : 0;
    io->pos = 0;
    io->base = 0;
    io->bitbuf = 0;
    io->bitcount = 0;
}

static void osdk_align(osdk_stream_t *io)
{
    io->bitbuf = 0;
    io->bitcount = 0;
}

bool osdk_read_uint(osdk_stream_t *io, unsigned nbytes, int big_endian, uint64_t *out)
{
    uint64_t v = 0;
    unsigned i;
    osdk_align(io);
    if (nbytes > 8 || io->size - io->pos < nbytes) return false;
    for (i = 0; i < nbytes; i++) {
        unsigned shift = big_endian ? 8u * (nbytes - 1u - i) : 8u * i;
        v |= (uint64_t)io->data[io->pos + i] << shift;
    }
    io->pos += nbytes;
    *out = v;
    return true;
}

bool osdk_read_bits_le(osdk_stream_t *io, unsigned nbits, uint64_t *out)
{
    if (nbits == 0 || nbits > 56) return false;
    while (io->bitcount < nbits) {
        if (io->pos >= io->size) return false;
        io->bitbuf |= (uint64_t)io->data[io->pos] << io->bitcount;
        io->pos++;
        io->bitcount += 8;
    }
    *out = io->bitbuf & ((UINT64_C(1) << nbits) - 1u);
    io->bitbuf >>= nbits;
    io->bitcount -= nbits;
    return true;
}

bool osdk_read_bytes(osdk_stream_t *io, uint64_t n, osdk_bytes_t *out)
{
    osdk_align(io);
    if ((uint64_t)(io->size - io->pos) < n) return false;
    out->ptr = io->data + io->pos;
    out->len = (size_t)n;
    io->pos += (size_t)n;
    return true;
}

void osdk_read_bytes_eos(osdk_stream_t *io, osdk_bytes_t *out)
{
    osdk_align(io);
    out->ptr = io->data + io->pos;
    out->len = io->size - io->pos;
    io->pos = io->size;
}

bool osdk_substream(osdk_stream_t *io, uint64_t n, osdk_stream_t *sub)
{
    osdk_bytes_t b;
    size_t at = io->pos;
    if (!osdk_read_bytes(io, n, &b)) return false;
    sub->data = b.ptr;
    sub->size = b.len;
    sub->pos = 0;
    sub->base = io->base + at;
    sub->bitbuf = 0;
    sub->bitcount = 0;
    return true;
}

void osdk_substream_eos(osdk_stream_t *io, osdk_stream_t *sub)
{
    osdk_bytes_t b;
    size_t at;
    osdk_align(io);
    at = io->pos;
    osdk_read_bytes_eos(io, &b);
    sub->data = b.ptr;
    sub->size = b.len;
    sub->pos = 0;
    sub->base = io->base + at;
    sub->bitbuf = 0;
    sub->bitcount = 0;
}

bool osdk_stream_at(const osdk_stream_t *io, uint64_t pos, osdk_stream_t *at)
{
    if (pos > (uint64_t)io->size) return false;
    *at = *io;
    at->pos = (size_t)pos;
    at->bitbuf = 0;
    at->bitcount = 0;
    return true;
}

int64_t osdk_sign_extend(uint64_t value, unsigned bits)
{
    uint64_t sign;
    if (bits == 0 || bits >= 64) return (int64_t)value;
    sign = UINT64_C(1) << (bits - 1u);
    value &= (UINT64_C(1) << bits) - 1u;
    if (value & sign) return -(int64_t)((~value & ((UINT64_C(1) << bits) - 1u)) + 1u);
    return (int64_t)value;
}

uint64_t osdk_peek_bits_le(const uint8_t *buf, unsigned bit_offset, unsigned nbits)
{
    uint64_t v = 0;
    unsigned i;
    /*@ loop invariant 0 <= i <= nbits;
        loop assigns i, v;
        loop variant nbits - i; */
    for (i = 0; i < nbits; i++) {
        unsigned b = bit_offset + i;
        v |= (uint64_t)((buf[b / 8u] >> (b % 8u)) & 1u) << i;
    }
    return v;
}

osdk_status_t osdk_fail(osdk_error_t *err, osdk_status_t status, const char *type, const char *field,
                        const osdk_stream_t *io)
{
    if (err) {
        err->status = status;
        err->type = type;
        err->field = field;
        err->offset = io ? io->base + io->pos : 0;
    }
    return status;
}

/* ---- enum names ------------------------------------------------------------------------ */

const char *osdk_broadcast_items_control_device_name(int64_t value)
{
    switch (value) {
        case 0: return "rc";
        case 1: return "mobile_device";
        case 2: return "onboard_device";
        default: return NULL;
    }
}

const char *osdk_broadcast_items_cur_mov_control_mode_name(int64_t value)
{
    switch (value) {
        case 0: return "atti_stop";
        case 1: return "horiz_ang_vert_vel_yaw_ang";
        case 2: return "horiz_ang_vert_vel_yaw_rate";
        case 3: return "horiz_vel_vert_vel_yaw_ang";
        case 4: return "horiz_vel_vert_vel_yaw_rate";
        case 5: return "horiz_pos_vert_vel_yaw_ang";
        case 6: return "horiz_pos_vert_vel_yaw_rate";
        case 7: return "horiz_ang_vert_pos_yaw_ang";
        case 8: return "horiz_ang_vert_pos_yaw_rate";
        case 9: return "horiz_vel_vert_pos_yaw_ang";
        case 10: return "horiz_vel_vert_pos_yaw_rate";
        case 11: return "horiz_pos_vert_pos_yaw_ang";
        case 12: return "horiz_pos_vert_pos_yaw_rate";
        case 13: return "horiz_ang_vert_thr_yaw_ang";
        case 14: return "horiz_ang_vert_thr_yaw_rate";
        case 15: return "horiz_vel_vert_thr_yaw_ang";
        case 16: return "horiz_vel_vert_thr_yaw_rate";
        case 17: return "horiz_pos_vert_thr_yaw_ang";
        case 18: return "horiz_pos_vert_thr_yaw_rate";
        case 97: return "gps_atti_ctrl_cl_yaw_rate";
        case 98: return "gps_atti_ctrl_yaw_rate";
        case 99: return "atti_ctrl_yaw_rate";
        case 100: return "atti_ctrl_stop";
        default: return NULL;
    }
}

const char *osdk_control_mode_horizontal_frame_name(int64_t value)
{
    switch (value) {
        case 0: return "ground";
        case 1: return "body";
        default: return NULL;
    }
}

const char *osdk_control_mode_horizontal_logic_name(int64_t value)
{
    switch (value) {
        case 0: return "hori_atti_tilt_ang";
        case 1: return "hori_vel";
        case 2: return "hori_pos";
        default: return NULL;
    }
}

const char *osdk_control_mode_stable_mode_name(int64_t value)
{
    switch (value) {
        case 0: return "non_stable";
        case 1: return "stable";
        default: return NULL;
    }
}

const char *osdk_control_mode_vertical_logic_name(int64_t value)
{
    switch (value) {
        case 0: return "vert_vel";
        case 1: return "vert_pos";
        case 2: return "vert_thrust";
        default: return NULL;
    }
}

const char *osdk_control_mode_yaw_logic_name(int64_t value)
{
    switch (value) {
        case 0: return "yaw_ang";
        case 1: return "yaw_rate";
        default: return NULL;
    }
}

const char *osdk_frame_command_set_name(int64_t value)
{
    switch (value) {
        case 0: return "activation";
        case 1: return "control";
        case 2: return "push";
        default: return NULL;
    }
}

const char *osdk_frame_encryption_name(int64_t value)
{
    switch (value) {
        case 0: return "plain";
        case 1: return "aes256";
        default: return NULL;
    }
}

const char *osdk_payload_activation_result_name(int64_t value)
{
    switch (value) {
        case 0: return "success";
        case 1: return "invalid_parameters";
        case 2: return "cannot_recognize_encrypted_package";
        case 3: return "new_app_id";
        case 4: return "no_response_from_app";
        case 5: return "no_internet";
        case 6: return "server_rejected";
        case 7: return "level_insufficient";
        case 8: return "wrong_sdk_version";
        default: return NULL;
    }
}

const char *osdk_payload_control_ack_name(int64_t value)
{
    switch (value) {
        case 0: return "rc_not_in_f_mode";
        case 1: return "released";
        case 2: return "obtained";
        case 3: return "obtain_in_progress";
        case 4: return "release_in_progress";
        case 201: return "in_ioc_mode";
        default: return NULL;
    }
}

const char *osdk_payload_control_request_code_name(int64_t value)
{
    switch (value) {
        case 0: return "release";
        case 1: return "obtain";
        default: return NULL;
    }
}

const char *osdk_payload_frequency_ack_name(int64_t value)
{
    switch (value) {
        case 0: return "success";
        case 1: return "parameter_error";
        default: return NULL;
    }
}

const char *osdk_payload_frequency_code_name(int64_t value)
{
    switch (value) {
        case 0: return "hz_0";
        case 1: return "hz_1";
        case 2: return "hz_10";
        case 3: return "hz_50";
        case 4: return "hz_100";
        case 5: return "keep";
        case 6: return "hz_200";
        case 7: return "hz_400";
        default: return NULL;
    }
}

const char *osdk_payload_profile_name(int64_t value)
{
    switch (value) {
        case 0: return "m100_fw2_3";
        case 1: return "m100_fw3_1";
        case 2: return "a3_fw3_1";
        default: return NULL;
    }
}

const char *osdk_payload_version_ack_name(int64_t value)
{
    switch (value) {
        case 0: return "activated";
        case 65281: return "not_activated";
        default: return NULL;
    }
}


/* ---- `valid` predicates -------------------------------------------------------------------- */

bool osdk_broadcast_a3_fw3_1_valid_reserved_flags(int64_t v)
{
    return ((int64_t)(v) == (int64_t)(INT64_C(0)));
}

bool osdk_broadcast_m100_fw2_3_valid_reserved_flags(int64_t v)
{
    return ((int64_t)(v) == (int64_t)(INT64_C(0)));
}

bool osdk_broadcast_m100_fw3_1_valid_reserved_flags(int64_t v)
{
    return ((int64_t)(v) == (int64_t)(INT64_C(0)));
}

bool osdk_frame_valid_len(int64_t v)
{
    return (((int64_t)(v) == (int64_t)(INT64_C(12))) || (v >= INT64_C(17)));
}

bool osdk_frame_valid_ver(int64_t v)
{
    return ((int64_t)(v) == (int64_t)(INT64_C(0)));
}

bool osdk_frame_valid_res0(int64_t v)
{
    return ((int64_t)(v) == (int64_t)(INT64_C(0)));
}

bool osdk_frame_valid_res1(int64_t v)
{
    return ((int64_t)(v) == (int64_t)(INT64_C(0)));
}


/* ---- value instances used by the parsers ------------------------------------------------ */

static int64_t osdk_payload__key(const osdk_payload_t *self)
{
    return ((((int64_t)((self->is_ack ? INT64_C(65536) : INT64_C(0)))) + (((int64_t)(((int64_t)self->cmd_set))) * INT64_C(256))) + ((int64_t)(((int64_t)self->cmd_id))));
}

static bool osdk_payload_version_ack_value__has_version_id(const osdk_payload_version_ack_value_t *self)
{
    return ((int64_t)(((int64_t)self->profile)) != (int64_t)(OSDK_PAYLOAD_PROFILE_M100_FW2_3));
}


/* ---- parse functions ------------------------------------------------------------------------ */

/* osdk_broadcast_a3_fw3_1 */
osdk_status_t osdk_broadcast_a3_fw3_1_parse(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    /* has_time_stamp */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "has_time_stamp", io);
    self->has_time_stamp = (u != 0);
    /* has_quaternion */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "has_quaternion", io);
    self->has_quaternion = (u != 0);
    /* has_acceleration */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "has_acceleration", io);
    self->has_acceleration = (u != 0);
    /* has_velocity */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "has_velocity", io);
    self->has_velocity = (u != 0);
    /* has_angular_rate */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "has_angular_rate", io);
    self->has_angular_rate = (u != 0);
    /* has_position */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "has_position", io);
    self->has_position = (u != 0);
    /* has_gps_detail */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "has_gps_detail", io);
    self->has_gps_detail = (u != 0);
    /* has_rtk_detail */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "has_rtk_detail", io);
    self->has_rtk_detail = (u != 0);
    /* has_magnetometer */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "has_magnetometer", io);
    self->has_magnetometer = (u != 0);
    /* has_rc */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "has_rc", io);
    self->has_rc = (u != 0);
    /* has_gimbal */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "has_gimbal", io);
    self->has_gimbal = (u != 0);
    /* has_flight_status */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "has_flight_status", io);
    self->has_flight_status = (u != 0);
    /* has_battery */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "has_battery", io);
    self->has_battery = (u != 0);
    /* has_control_info */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "has_control_info", io);
    self->has_control_info = (u != 0);
    /* reserved_flags */
    if (!osdk_read_bits_le(io, 2, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "reserved_flags", io);
    self->reserved_flags = (uint8_t)u;
    if (!(osdk_broadcast_a3_fw3_1_valid_reserved_flags(((int64_t)self->reserved_flags)))) return osdk_fail(err, OSDK_ERR_RESERVED_BITS, "osdk_broadcast_a3_fw3_1", "reserved_flags", io);
    /* time_stamp */
    self->time_stamp_present = self->has_time_stamp;
    if (self->time_stamp_present) {
        {
            osdk_status_t st = osdk_broadcast_items_time_stamp_parse(io, &self->time_stamp, (bool)(1), err);
            if (st != OSDK_OK) return st;
        }
    }
    /* quaternion */
    self->quaternion_present = self->has_quaternion;
    if (self->quaternion_present) {
        {
            osdk_status_t st = osdk_broadcast_items_quaternion_parse(io, &self->quaternion, err);
            if (st != OSDK_OK) return st;
        }
    }
    /* acceleration */
    self->acceleration_present = self->has_acceleration;
    if (self->acceleration_present) {
        {
            osdk_status_t st = osdk_broadcast_items_vector3f_parse(io, &self->acceleration, err);
            if (st != OSDK_OK) return st;
        }
    }
    /* velocity */
    self->velocity_present = self->has_velocity;
    if (self->velocity_present) {
        {
            osdk_status_t st = osdk_broadcast_items_velocity_parse(io, &self->velocity, err);
            if (st != OSDK_OK) return st;
        }
    }
    /* angular_rate */
    self->angular_rate_present = self->has_angular_rate;
    if (self->angular_rate_present) {
        {
            osdk_status_t st = osdk_broadcast_items_vector3f_parse(io, &self->angular_rate, err);
            if (st != OSDK_OK) return st;
        }
    }
    /* position */
    self->position_present = self->has_position;
    if (self->position_present) {
        {
            osdk_status_t st = osdk_broadcast_items_position_parse(io, &self->position, err);
            if (st != OSDK_OK) return st;
        }
    }
    /* gps_detail */
    self->gps_detail_present = self->has_gps_detail;
    if (self->gps_detail_present) {
        {
            osdk_status_t st = osdk_broadcast_items_gps_detail_parse(io, &self->gps_detail, err);
            if (st != OSDK_OK) return st;
        }
    }
    /* rtk_detail */
    self->rtk_detail_present = self->has_rtk_detail;
    if (self->rtk_detail_present) {
        {
            osdk_status_t st = osdk_broadcast_items_rtk_detail_parse(io, &self->rtk_detail, err);
            if (st != OSDK_OK) return st;
        }
    }
    /* magnetometer */
    self->magnetometer_present = self->has_magnetometer;
    if (self->magnetometer_present) {
        {
            osdk_status_t st = osdk_broadcast_items_magnetometer_parse(io, &self->magnetometer, err);
            if (st != OSDK_OK) return st;
        }
    }
    /* rc */
    self->rc_present = self->has_rc;
    if (self->rc_present) {
        {
            osdk_status_t st = osdk_broadcast_items_rc_parse(io, &self->rc, err);
            if (st != OSDK_OK) return st;
        }
    }
    /* gimbal */
    self->gimbal_present = self->has_gimbal;
    if (self->gimbal_present) {
        {
            osdk_status_t st = osdk_broadcast_items_gimbal_parse(io, &self->gimbal, (bool)(1), err);
            if (st != OSDK_OK) return st;
        }
    }
    /* flight_status */
    self->flight_status_present = self->has_flight_status;
    if (self->flight_status_present) {
        if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "flight_status", io);
        self->flight_status = (uint8_t)u;
    }
    /* battery */
    self->battery_present = self->has_battery;
    if (self->battery_present) {
        if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "battery", io);
        self->battery = (uint8_t)u;
    }
    /* control_info */
    self->control_info_present = self->has_control_info;
    if (self->control_info_present) {
        {
            osdk_status_t st = osdk_broadcast_items_control_info_parse(io, &self->control_info, (bool)(1), err);
            if (st != OSDK_OK) return st;
        }
    }
    /* trailing */
    osdk_read_bytes_eos(io, &self->trailing);
    if (!(((int64_t)(((int64_t)(self->trailing).len)) == (int64_t)(INT64_C(0))))) return osdk_fail(err, OSDK_ERR_LENGTH_MISMATCH, "osdk_broadcast_a3_fw3_1", "trailing", io);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_broadcast_items::control_info */
osdk_status_t osdk_broadcast_items_control_info_parse(osdk_stream_t *io, osdk_broadcast_items_control_info_t *self, bool has_mode, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    self->has_mode = has_mode;
    /* cur_mov_control_mode */
    self->cur_mov_control_mode_present = self->has_mode;
    if (self->cur_mov_control_mode_present) {
        if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::control_info", "cur_mov_control_mode", io);
        self->cur_mov_control_mode = (uint8_t)u;
    }
    /* control_device */
    if (!osdk_read_bits_le(io, 3, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::control_info", "control_device", io);
    self->control_device = (uint8_t)u;
    /* onboard_requested */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::control_info", "onboard_requested", io);
    self->onboard_requested = (u != 0);
    /* virtual_rc */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::control_info", "virtual_rc", io);
    self->virtual_rc = (u != 0);
    /* reserved */
    if (!osdk_read_bits_le(io, 3, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::control_info", "reserved", io);
    self->reserved = (uint8_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_broadcast_items::gimbal */
osdk_status_t osdk_broadcast_items_gimbal_parse(osdk_stream_t *io, osdk_broadcast_items_gimbal_t *self, bool has_limit_byte, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    self->has_limit_byte = has_limit_byte;
    /* roll */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gimbal", "roll", io);
    self->roll.bits = (uint32_t)u;
    self->roll.value = osdk_f32_from_bits(self->roll.bits);
    /* pitch */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gimbal", "pitch", io);
    self->pitch.bits = (uint32_t)u;
    self->pitch.value = osdk_f32_from_bits(self->pitch.bits);
    /* yaw */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gimbal", "yaw", io);
    self->yaw.bits = (uint32_t)u;
    self->yaw.value = osdk_f32_from_bits(self->yaw.bits);
    /* limit */
    self->limit_present = self->has_limit_byte;
    if (self->limit_present) {
        {
            osdk_status_t st = osdk_broadcast_items_gimbal_limit_parse(io, &self->limit, err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_broadcast_items::gimbal_limit */
osdk_status_t osdk_broadcast_items_gimbal_limit_parse(osdk_stream_t *io, osdk_broadcast_items_gimbal_limit_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    /* pitch_limit */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gimbal_limit", "pitch_limit", io);
    self->pitch_limit = (u != 0);
    /* roll_limit */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gimbal_limit", "roll_limit", io);
    self->roll_limit = (u != 0);
    /* yaw_limit */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gimbal_limit", "yaw_limit", io);
    self->yaw_limit = (u != 0);
    /* reserved */
    if (!osdk_read_bits_le(io, 5, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gimbal_limit", "reserved", io);
    self->reserved = (uint8_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_broadcast_items::gps_detail */
osdk_status_t osdk_broadcast_items_gps_detail_parse(osdk_stream_t *io, osdk_broadcast_items_gps_detail_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    /* date */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gps_detail", "date", io);
    self->date = (uint32_t)u;
    /* time */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gps_detail", "time", io);
    self->time = (uint32_t)u;
    /* longitude */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gps_detail", "longitude", io);
    self->longitude = (int32_t)osdk_sign_extend(u, 32);
    /* latitude */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gps_detail", "latitude", io);
    self->latitude = (int32_t)osdk_sign_extend(u, 32);
    /* height_msl */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gps_detail", "height_msl", io);
    self->height_msl = (int32_t)osdk_sign_extend(u, 32);
    /* vel_n */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gps_detail", "vel_n", io);
    self->vel_n.bits = (uint32_t)u;
    self->vel_n.value = osdk_f32_from_bits(self->vel_n.bits);
    /* vel_e */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gps_detail", "vel_e", io);
    self->vel_e.bits = (uint32_t)u;
    self->vel_e.value = osdk_f32_from_bits(self->vel_e.bits);
    /* vel_d */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gps_detail", "vel_d", io);
    self->vel_d.bits = (uint32_t)u;
    self->vel_d.value = osdk_f32_from_bits(self->vel_d.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_broadcast_items::magnetometer */
osdk_status_t osdk_broadcast_items_magnetometer_parse(osdk_stream_t *io, osdk_broadcast_items_magnetometer_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    /* x */
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::magnetometer", "x", io);
    self->x = (int16_t)osdk_sign_extend(u, 16);
    /* y */
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::magnetometer", "y", io);
    self->y = (int16_t)osdk_sign_extend(u, 16);
    /* z */
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::magnetometer", "z", io);
    self->z = (int16_t)osdk_sign_extend(u, 16);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_broadcast_items::position */
osdk_status_t osdk_broadcast_items_position_parse(osdk_stream_t *io, osdk_broadcast_items_position_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    /* latitude */
    if (!osdk_read_uint(io, 8, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::position", "latitude", io);
    self->latitude.bits = u;
    self->latitude.value = osdk_f64_from_bits(self->latitude.bits);
    /* longitude */
    if (!osdk_read_uint(io, 8, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::position", "longitude", io);
    self->longitude.bits = u;
    self->longitude.value = osdk_f64_from_bits(self->longitude.bits);
    /* altitude */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::position", "altitude", io);
    self->altitude.bits = (uint32_t)u;
    self->altitude.value = osdk_f32_from_bits(self->altitude.bits);
    /* height */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::position", "height", io);
    self->height.bits = (uint32_t)u;
    self->height.value = osdk_f32_from_bits(self->height.bits);
    /* gps_health */
    if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::position", "gps_health", io);
    self->gps_health = (uint8_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_broadcast_items::quaternion */
osdk_status_t osdk_broadcast_items_quaternion_parse(osdk_stream_t *io, osdk_broadcast_items_quaternion_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    /* q0 */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::quaternion", "q0", io);
    self->q0.bits = (uint32_t)u;
    self->q0.value = osdk_f32_from_bits(self->q0.bits);
    /* q1 */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::quaternion", "q1", io);
    self->q1.bits = (uint32_t)u;
    self->q1.value = osdk_f32_from_bits(self->q1.bits);
    /* q2 */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::quaternion", "q2", io);
    self->q2.bits = (uint32_t)u;
    self->q2.value = osdk_f32_from_bits(self->q2.bits);
    /* q3 */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::quaternion", "q3", io);
    self->q3.bits = (uint32_t)u;
    self->q3.value = osdk_f32_from_bits(self->q3.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_broadcast_items::rc */
osdk_status_t osdk_broadcast_items_rc_parse(osdk_stream_t *io, osdk_broadcast_items_rc_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    /* roll */
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rc", "roll", io);
    self->roll = (int16_t)osdk_sign_extend(u, 16);
    /* pitch */
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rc", "pitch", io);
    self->pitch = (int16_t)osdk_sign_extend(u, 16);
    /* yaw */
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rc", "yaw", io);
    self->yaw = (int16_t)osdk_sign_extend(u, 16);
    /* throttle */
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rc", "throttle", io);
    self->throttle = (int16_t)osdk_sign_extend(u, 16);
    /* mode */
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rc", "mode", io);
    self->mode = (int16_t)osdk_sign_extend(u, 16);
    /* gear */
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rc", "gear", io);
    self->gear = (int16_t)osdk_sign_extend(u, 16);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_broadcast_items::rtk_detail */
osdk_status_t osdk_broadcast_items_rtk_detail_parse(osdk_stream_t *io, osdk_broadcast_items_rtk_detail_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    /* date */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rtk_detail", "date", io);
    self->date = (uint32_t)u;
    /* time */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rtk_detail", "time", io);
    self->time = (uint32_t)u;
    /* longitude */
    if (!osdk_read_uint(io, 8, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rtk_detail", "longitude", io);
    self->longitude.bits = u;
    self->longitude.value = osdk_f64_from_bits(self->longitude.bits);
    /* latitude */
    if (!osdk_read_uint(io, 8, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rtk_detail", "latitude", io);
    self->latitude.bits = u;
    self->latitude.value = osdk_f64_from_bits(self->latitude.bits);
    /* height_msl */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rtk_detail", "height_msl", io);
    self->height_msl.bits = (uint32_t)u;
    self->height_msl.value = osdk_f32_from_bits(self->height_msl.bits);
    /* vel_n */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rtk_detail", "vel_n", io);
    self->vel_n.bits = (uint32_t)u;
    self->vel_n.value = osdk_f32_from_bits(self->vel_n.bits);
    /* vel_e */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rtk_detail", "vel_e", io);
    self->vel_e.bits = (uint32_t)u;
    self->vel_e.value = osdk_f32_from_bits(self->vel_e.bits);
    /* vel_d */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rtk_detail", "vel_d", io);
    self->vel_d.bits = (uint32_t)u;
    self->vel_d.value = osdk_f32_from_bits(self->vel_d.bits);
    /* yaw */
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rtk_detail", "yaw", io);
    self->yaw = (int16_t)osdk_sign_extend(u, 16);
    /* position_flag */
    if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rtk_detail", "position_flag", io);
    self->position_flag = (uint8_t)u;
    /* yaw_flag */
    if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rtk_detail", "yaw_flag", io);
    self->yaw_flag = (uint8_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_broadcast_items::time_stamp */
osdk_status_t osdk_broadcast_items_time_stamp_parse(osdk_stream_t *io, osdk_broadcast_items_time_stamp_t *self, bool has_ns_and_sync, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    self->has_ns_and_sync = has_ns_and_sync;
    /* time */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::time_stamp", "time", io);
    self->time = (uint32_t)u;
    /* nano_time */
    self->nano_time_present = self->has_ns_and_sync;
    if (self->nano_time_present) {
        if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::time_stamp", "nano_time", io);
        self->nano_time = (uint32_t)u;
    }
    /* sync_flag */
    self->sync_flag_present = self->has_ns_and_sync;
    if (self->sync_flag_present) {
        if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::time_stamp", "sync_flag", io);
        self->sync_flag = (uint8_t)u;
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_broadcast_items::vector3f */
osdk_status_t osdk_broadcast_items_vector3f_parse(osdk_stream_t *io, osdk_broadcast_items_vector3f_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    /* x */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::vector3f", "x", io);
    self->x.bits = (uint32_t)u;
    self->x.value = osdk_f32_from_bits(self->x.bits);
    /* y */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::vector3f", "y", io);
    self->y.bits = (uint32_t)u;
    self->y.value = osdk_f32_from_bits(self->y.bits);
    /* z */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::vector3f", "z", io);
    self->z.bits = (uint32_t)u;
    self->z.value = osdk_f32_from_bits(self->z.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_broadcast_items::velocity */
osdk_status_t osdk_broadcast_items_velocity_parse(osdk_stream_t *io, osdk_broadcast_items_velocity_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    /* x */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::velocity", "x", io);
    self->x.bits = (uint32_t)u;
    self->x.value = osdk_f32_from_bits(self->x.bits);
    /* y */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::velocity", "y", io);
    self->y.bits = (uint32_t)u;
    self->y.value = osdk_f32_from_bits(self->y.bits);
    /* z */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::velocity", "z", io);
    self->z.bits = (uint32_t)u;
    self->z.value = osdk_f32_from_bits(self->z.bits);
    /* data_valid */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::velocity", "data_valid", io);
    self->data_valid = (u != 0);
    /* sensor_id */
    if (!osdk_read_bits_le(io, 4, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::velocity", "sensor_id", io);
    self->sensor_id = (uint8_t)u;
    /* reserved */
    if (!osdk_read_bits_le(io, 3, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::velocity", "reserved", io);
    self->reserved = (uint8_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_broadcast_m100_fw2_3 */
osdk_status_t osdk_broadcast_m100_fw2_3_parse(osdk_stream_t *io, osdk_broadcast_m100_fw2_3_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    /* has_time_stamp */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "has_time_stamp", io);
    self->has_time_stamp = (u != 0);
    /* has_quaternion */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "has_quaternion", io);
    self->has_quaternion = (u != 0);
    /* has_acceleration */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "has_acceleration", io);
    self->has_acceleration = (u != 0);
    /* has_velocity */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "has_velocity", io);
    self->has_velocity = (u != 0);
    /* has_angular_rate */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "has_angular_rate", io);
    self->has_angular_rate = (u != 0);
    /* has_position */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "has_position", io);
    self->has_position = (u != 0);
    /* has_magnetometer */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "has_magnetometer", io);
    self->has_magnetometer = (u != 0);
    /* has_rc */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "has_rc", io);
    self->has_rc = (u != 0);
    /* has_gimbal */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "has_gimbal", io);
    self->has_gimbal = (u != 0);
    /* has_flight_status */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "has_flight_status", io);
    self->has_flight_status = (u != 0);
    /* has_battery */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "has_battery", io);
    self->has_battery = (u != 0);
    /* has_control_info */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "has_control_info", io);
    self->has_control_info = (u != 0);
    /* reserved_flags */
    if (!osdk_read_bits_le(io, 4, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "reserved_flags", io);
    self->reserved_flags = (uint8_t)u;
    if (!(osdk_broadcast_m100_fw2_3_valid_reserved_flags(((int64_t)self->reserved_flags)))) return osdk_fail(err, OSDK_ERR_RESERVED_BITS, "osdk_broadcast_m100_fw2_3", "reserved_flags", io);
    /* time_stamp */
    self->time_stamp_present = self->has_time_stamp;
    if (self->time_stamp_present) {
        {
            osdk_status_t st = osdk_broadcast_items_time_stamp_parse(io, &self->time_stamp, (bool)(0), err);
            if (st != OSDK_OK) return st;
        }
    }
    /* quaternion */
    self->quaternion_present = self->has_quaternion;
    if (self->quaternion_present) {
        {
            osdk_status_t st = osdk_broadcast_items_quaternion_parse(io, &self->quaternion, err);
            if (st != OSDK_OK) return st;
        }
    }
    /* acceleration */
    self->acceleration_present = self->has_acceleration;
    if (self->acceleration_present) {
        {
            osdk_status_t st = osdk_broadcast_items_vector3f_parse(io, &self->acceleration, err);
            if (st != OSDK_OK) return st;
        }
    }
    /* velocity */
    self->velocity_present = self->has_velocity;
    if (self->velocity_present) {
        {
            osdk_status_t st = osdk_broadcast_items_velocity_parse(io, &self->velocity, err);
            if (st != OSDK_OK) return st;
        }
    }
    /* angular_rate */
    self->angular_rate_present = self->has_angular_rate;
    if (self->angular_rate_present) {
        {
            osdk_status_t st = osdk_broadcast_items_vector3f_parse(io, &self->angular_rate, err);
            if (st != OSDK_OK) return st;
        }
    }
    /* position */
    self->position_present = self->has_position;
    if (self->position_present) {
        {
            osdk_status_t st = osdk_broadcast_items_position_parse(io, &self->position, err);
            if (st != OSDK_OK) return st;
        }
    }
    /* magnetometer */
    self->magnetometer_present = self->has_magnetometer;
    if (self->magnetometer_present) {
        {
            osdk_status_t st = osdk_broadcast_items_magnetometer_parse(io, &self->magnetometer, err);
            if (st != OSDK_OK) return st;
        }
    }
    /* rc */
    self->rc_present = self->has_rc;
    if (self->rc_present) {
        {
            osdk_status_t st = osdk_broadcast_items_rc_parse(io, &self->rc, err);
            if (st != OSDK_OK) return st;
        }
    }
    /* gimbal */
    self->gimbal_present = self->has_gimbal;
    if (self->gimbal_present) {
        {
            osdk_status_t st = osdk_broadcast_items_gimbal_parse(io, &self->gimbal, (bool)(0), err);
            if (st != OSDK_OK) return st;
        }
    }
    /* flight_status */
    self->flight_status_present = self->has_flight_status;
    if (self->flight_status_present) {
        if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "flight_status", io);
        self->flight_status = (uint8_t)u;
    }
    /* battery */
    self->battery_present = self->has_battery;
    if (self->battery_present) {
        if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "battery", io);
        self->battery = (uint8_t)u;
    }
    /* control_info */
    self->control_info_present = self->has_control_info;
    if (self->control_info_present) {
        {
            osdk_status_t st = osdk_broadcast_items_control_info_parse(io, &self->control_info, (bool)(0), err);
            if (st != OSDK_OK) return st;
        }
    }
    /* trailing */
    osdk_read_bytes_eos(io, &self->trailing);
    if (!(((int64_t)(((int64_t)(self->trailing).len)) == (int64_t)(INT64_C(0))))) return osdk_fail(err, OSDK_ERR_LENGTH_MISMATCH, "osdk_broadcast_m100_fw2_3", "trailing", io);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_broadcast_m100_fw3_1 */
osdk_status_t osdk_broadcast_m100_fw3_1_parse(osdk_stream_t *io, osdk_broadcast_m100_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    /* has_time_stamp */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "has_time_stamp", io);
    self->has_time_stamp = (u != 0);
    /* has_quaternion */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "has_quaternion", io);
    self->has_quaternion = (u != 0);
    /* has_acceleration */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "has_acceleration", io);
    self->has_acceleration = (u != 0);
    /* has_velocity */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "has_velocity", io);
    self->has_velocity = (u != 0);
    /* has_angular_rate */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "has_angular_rate", io);
    self->has_angular_rate = (u != 0);
    /* has_position */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "has_position", io);
    self->has_position = (u != 0);
    /* has_magnetometer */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "has_magnetometer", io);
    self->has_magnetometer = (u != 0);
    /* has_rc */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "has_rc", io);
    self->has_rc = (u != 0);
    /* has_gimbal */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "has_gimbal", io);
    self->has_gimbal = (u != 0);
    /* has_flight_status */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "has_flight_status", io);
    self->has_flight_status = (u != 0);
    /* has_battery */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "has_battery", io);
    self->has_battery = (u != 0);
    /* has_control_info */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "has_control_info", io);
    self->has_control_info = (u != 0);
    /* reserved_flags */
    if (!osdk_read_bits_le(io, 4, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "reserved_flags", io);
    self->reserved_flags = (uint8_t)u;
    if (!(osdk_broadcast_m100_fw3_1_valid_reserved_flags(((int64_t)self->reserved_flags)))) return osdk_fail(err, OSDK_ERR_RESERVED_BITS, "osdk_broadcast_m100_fw3_1", "reserved_flags", io);
    /* time_stamp */
    self->time_stamp_present = self->has_time_stamp;
    if (self->time_stamp_present) {
        {
            osdk_status_t st = osdk_broadcast_items_time_stamp_parse(io, &self->time_stamp, (bool)(1), err);
            if (st != OSDK_OK) return st;
        }
    }
    /* quaternion */
    self->quaternion_present = self->has_quaternion;
    if (self->quaternion_present) {
        {
            osdk_status_t st = osdk_broadcast_items_quaternion_parse(io, &self->quaternion, err);
            if (st != OSDK_OK) return st;
        }
    }
    /* acceleration */
    self->acceleration_present = self->has_acceleration;
    if (self->acceleration_present) {
        {
            osdk_status_t st = osdk_broadcast_items_vector3f_parse(io, &self->acceleration, err);
            if (st != OSDK_OK) return st;
        }
    }
    /* velocity */
    self->velocity_present = self->has_velocity;
    if (self->velocity_present) {
        {
            osdk_status_t st = osdk_broadcast_items_velocity_parse(io, &self->velocity, err);
            if (st != OSDK_OK) return st;
        }
    }
    /* angular_rate */
    self->angular_rate_present = self->has_angular_rate;
    if (self->angular_rate_present) {
        {
            osdk_status_t st = osdk_broadcast_items_vector3f_parse(io, &self->angular_rate, err);
            if (st != OSDK_OK) return st;
        }
    }
    /* position */
    self->position_present = self->has_position;
    if (self->position_present) {
        {
            osdk_status_t st = osdk_broadcast_items_position_parse(io, &self->position, err);
            if (st != OSDK_OK) return st;
        }
    }
    /* magnetometer */
    self->magnetometer_present = self->has_magnetometer;
    if (self->magnetometer_present) {
        {
            osdk_status_t st = osdk_broadcast_items_magnetometer_parse(io, &self->magnetometer, err);
            if (st != OSDK_OK) return st;
        }
    }
    /* rc */
    self->rc_present = self->has_rc;
    if (self->rc_present) {
        {
            osdk_status_t st = osdk_broadcast_items_rc_parse(io, &self->rc, err);
            if (st != OSDK_OK) return st;
        }
    }
    /* gimbal */
    self->gimbal_present = self->has_gimbal;
    if (self->gimbal_present) {
        {
            osdk_status_t st = osdk_broadcast_items_gimbal_parse(io, &self->gimbal, (bool)(1), err);
            if (st != OSDK_OK) return st;
        }
    }
    /* flight_status */
    self->flight_status_present = self->has_flight_status;
    if (self->flight_status_present) {
        if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "flight_status", io);
        self->flight_status = (uint8_t)u;
    }
    /* battery */
    self->battery_present = self->has_battery;
    if (self->battery_present) {
        if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "battery", io);
        self->battery = (uint8_t)u;
    }
    /* control_info */
    self->control_info_present = self->has_control_info;
    if (self->control_info_present) {
        {
            osdk_status_t st = osdk_broadcast_items_control_info_parse(io, &self->control_info, (bool)(1), err);
            if (st != OSDK_OK) return st;
        }
    }
    /* trailing */
    osdk_read_bytes_eos(io, &self->trailing);
    if (!(((int64_t)(((int64_t)(self->trailing).len)) == (int64_t)(INT64_C(0))))) return osdk_fail(err, OSDK_ERR_LENGTH_MISMATCH, "osdk_broadcast_m100_fw3_1", "trailing", io);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_control_mode */
osdk_status_t osdk_control_mode_parse(osdk_stream_t *io, osdk_control_mode_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    /* stable_mode */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_control_mode", "stable_mode", io);
    self->stable_mode = (uint8_t)u;
    /* horizontal_frame */
    if (!osdk_read_bits_le(io, 2, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_control_mode", "horizontal_frame", io);
    self->horizontal_frame = (uint8_t)u;
    /* yaw_logic */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_control_mode", "yaw_logic", io);
    self->yaw_logic = (uint8_t)u;
    /* vertical_logic */
    if (!osdk_read_bits_le(io, 2, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_control_mode", "vertical_logic", io);
    self->vertical_logic = (uint8_t)u;
    /* horizontal_logic */
    if (!osdk_read_bits_le(io, 2, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_control_mode", "horizontal_logic", io);
    self->horizontal_logic = (uint8_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_frame */
osdk_status_t osdk_frame_parse(osdk_stream_t *io, osdk_frame_t *self, uint8_t profile, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    self->profile = profile;
    /* sof */
    if (!osdk_read_bytes(io, 1, &self->sof)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame", "sof", io);
    { static const uint8_t expected[1] = {0xaa};
      if (memcmp(self->sof.ptr, expected, 1) != 0) return osdk_fail(err, OSDK_ERR_BAD_SOF, "osdk_frame", "sof", io); }
    /* len */
    if (!osdk_read_bits_le(io, 10, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame", "len", io);
    self->len = (uint16_t)u;
    if (!(osdk_frame_valid_len(((int64_t)self->len)))) return osdk_fail(err, OSDK_ERR_IMPOSSIBLE_LENGTH, "osdk_frame", "len", io);
    /* ver */
    if (!osdk_read_bits_le(io, 6, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame", "ver", io);
    self->ver = (uint8_t)u;
    if (!(osdk_frame_valid_ver(((int64_t)self->ver)))) return osdk_fail(err, OSDK_ERR_BAD_VERSION, "osdk_frame", "ver", io);
    /* session */
    if (!osdk_read_bits_le(io, 5, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame", "session", io);
    self->session = (uint8_t)u;
    /* is_ack */
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame", "is_ack", io);
    self->is_ack = (u != 0);
    if (!(((!self->is_ack) || ((int64_t)(((int64_t)self->session)) != (int64_t)(INT64_C(0)))))) return osdk_fail(err, OSDK_ERR_BAD_SESSION, "osdk_frame", "is_ack", io);
    /* res0 */
    if (!osdk_read_bits_le(io, 2, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame", "res0", io);
    self->res0 = (uint8_t)u;
    if (!(osdk_frame_valid_res0(((int64_t)self->res0)))) return osdk_fail(err, OSDK_ERR_RESERVED_BITS, "osdk_frame", "res0", io);
    /* padding */
    if (!osdk_read_bits_le(io, 5, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame", "padding", io);
    self->padding = (uint8_t)u;
    /* enc */
    if (!osdk_read_bits_le(io, 3, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame", "enc", io);
    self->enc = (uint8_t)u;
    if (!(((((int64_t)(((int64_t)self->enc)) == (int64_t)(OSDK_FRAME_ENCRYPTION_PLAIN)) && ((int64_t)(((int64_t)self->padding)) == (int64_t)(INT64_C(0)))) || ((((((int64_t)(((int64_t)self->enc)) == (int64_t)(OSDK_FRAME_ENCRYPTION_AES256)) && (((int64_t)self->padding) >= INT64_C(1))) && (((int64_t)self->padding) <= INT64_C(16))) && (((int64_t)self->len) > INT64_C(16))) && ((int64_t)(osdk_kmod((((int64_t)self->len) - INT64_C(16)), INT64_C(16))) == (int64_t)(INT64_C(0))))))) return osdk_fail(err, OSDK_ERR_BAD_ENCRYPTION, "osdk_frame", "enc", io);
    /* res1 */
    if (!osdk_read_bits_le(io, 24, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame", "res1", io);
    self->res1 = (uint32_t)u;
    if (!(osdk_frame_valid_res1(((int64_t)self->res1)))) return osdk_fail(err, OSDK_ERR_RESERVED_BITS, "osdk_frame", "res1", io);
    /* seq */
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame", "seq", io);
    self->seq = (uint16_t)u;
    /* crc16 */
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame", "crc16", io);
    self->crc16 = (uint16_t)u;
    /* data */
    self->data_present = (((int64_t)self->len) > INT64_C(12));
    if (self->data_present) {
        {
            osdk_stream_t sub;
            int64_t n = (((int64_t)self->len) - INT64_C(16));
            if (n < 0) return osdk_fail(err, OSDK_ERR_UNDECODABLE, "osdk_frame", "data", io);
            if (!osdk_substream(io, (uint64_t)n, &sub)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame", "data", io);
            int64_t on = ((int64_t)self->enc);
            if (on == OSDK_FRAME_ENCRYPTION_PLAIN) {
                osdk_status_t st;
                self->data.tag = OSDK_FRAME_DATA_FRAME_DATA;
                st = osdk_frame_frame_data_parse(&sub, &self->data.u.frame_data, self, self, err);
                if (st != OSDK_OK) return st;
            } else {
                self->data.tag = OSDK_FRAME_DATA_RAW;
                self->data.u.raw.ptr = sub.data;
                self->data.u.raw.len = sub.size;
            }
        }
    }
    /* crc32 */
    self->crc32_present = (((int64_t)self->len) > INT64_C(12));
    if (self->crc32_present) {
        if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame", "crc32", io);
        self->crc32 = (uint32_t)u;
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_frame::frame_data */
osdk_status_t osdk_frame_frame_data_parse(osdk_stream_t *io, osdk_frame_frame_data_t *self, const osdk_frame_t *parent, const osdk_frame_t *root, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    (void)parent;
    (void)root;
    /* cmd_set */
    self->cmd_set_present = (!parent->is_ack);
    if (self->cmd_set_present) {
        if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame::frame_data", "cmd_set", io);
        self->cmd_set = (uint8_t)u;
    }
    /* cmd_id */
    self->cmd_id_present = (!parent->is_ack);
    if (self->cmd_id_present) {
        if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame::frame_data", "cmd_id", io);
        self->cmd_id = (uint8_t)u;
    }
    /* value */
    self->value_present = (!parent->is_ack);
    if (self->value_present) {
        /* instance cmd_set_code (pos 0) */
        self->cmd_set_code_present = (!parent->is_ack);
        if (self->cmd_set_code_present) {
            osdk_stream_t at;
            int64_t pos = INT64_C(0);
            if (pos < 0 || !osdk_stream_at(io, (uint64_t)pos, &at)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame::frame_data", "cmd_set_code", io);
            if (!osdk_read_uint(&at, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame::frame_data", "cmd_set_code", io);
            self->cmd_set_code = (uint8_t)u;
        }
        {
            osdk_stream_t sub;
            osdk_substream_eos(io, &sub);
            osdk_status_t st = osdk_payload_parse(&sub, &self->value, (uint8_t)(((int64_t)self->cmd_set_code)), (uint8_t)(((int64_t)self->cmd_id)), (bool)(0), (uint8_t)(((int64_t)root->profile)), err);
            if (st != OSDK_OK) return st;
        }
    }
    /* ack_value */
    self->ack_value_present = parent->is_ack;
    if (self->ack_value_present) {
        osdk_read_bytes_eos(io, &self->ack_value);
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_movement_control */
osdk_status_t osdk_movement_control_parse(osdk_stream_t *io, osdk_movement_control_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    /* control_mode */
    {
        osdk_status_t st = osdk_control_mode_parse(io, &self->control_mode, err);
        if (st != OSDK_OK) return st;
    }
    /* x */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_movement_control", "x", io);
    self->x.bits = (uint32_t)u;
    self->x.value = osdk_f32_from_bits(self->x.bits);
    /* y */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_movement_control", "y", io);
    self->y.bits = (uint32_t)u;
    self->y.value = osdk_f32_from_bits(self->y.bits);
    /* z */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_movement_control", "z", io);
    self->z.bits = (uint32_t)u;
    self->z.value = osdk_f32_from_bits(self->z.bits);
    /* yaw */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_movement_control", "yaw", io);
    self->yaw.bits = (uint32_t)u;
    self->yaw.value = osdk_f32_from_bits(self->yaw.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_payload */
osdk_status_t osdk_payload_parse(osdk_stream_t *io, osdk_payload_t *self, uint8_t cmd_set, uint8_t cmd_id, bool is_ack, uint8_t profile, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    self->cmd_set = cmd_set;
    self->cmd_id = cmd_id;
    self->is_ack = is_ack;
    self->profile = profile;
    /* body */
    {
        int64_t on = osdk_payload__key(self);
        if (on == INT64_C(0)) {
            osdk_status_t st;
            self->body.tag = OSDK_PAYLOAD_BODY_VERSION_QUERY;
            st = osdk_payload_version_query_parse(io, &self->body.u.version_query, err);
            if (st != OSDK_OK) return st;
        } else if (on == INT64_C(1)) {
            osdk_status_t st;
            self->body.tag = OSDK_PAYLOAD_BODY_ACTIVATION_REQUEST;
            st = osdk_payload_activation_request_parse(io, &self->body.u.activation_request, err);
            if (st != OSDK_OK) return st;
        } else if (on == INT64_C(16)) {
            osdk_status_t st;
            self->body.tag = OSDK_PAYLOAD_BODY_FREQUENCY_REQUEST;
            st = osdk_payload_frequency_request_parse(io, &self->body.u.frequency_request, err);
            if (st != OSDK_OK) return st;
        } else if (on == INT64_C(256)) {
            osdk_status_t st;
            self->body.tag = OSDK_PAYLOAD_BODY_CONTROL_REQUEST;
            st = osdk_payload_control_request_parse(io, &self->body.u.control_request, err);
            if (st != OSDK_OK) return st;
        } else if (on == INT64_C(259)) {
            osdk_status_t st;
            self->body.tag = OSDK_PAYLOAD_BODY_OSDK_MOVEMENT_CONTROL;
            st = osdk_movement_control_parse(io, &self->body.u.osdk_movement_control, err);
            if (st != OSDK_OK) return st;
        } else if (on == INT64_C(512)) {
            osdk_status_t st;
            self->body.tag = OSDK_PAYLOAD_BODY_BROADCAST;
            st = osdk_payload_broadcast_parse(io, &self->body.u.broadcast, (uint8_t)(((int64_t)self->profile)), err);
            if (st != OSDK_OK) return st;
        } else if (on == INT64_C(513)) {
            osdk_status_t st;
            self->body.tag = OSDK_PAYLOAD_BODY_LOST_CONTROL;
            st = osdk_payload_lost_control_parse(io, &self->body.u.lost_control, err);
            if (st != OSDK_OK) return st;
        } else if (on == INT64_C(65536)) {
            osdk_status_t st;
            self->body.tag = OSDK_PAYLOAD_BODY_VERSION_ACK_VALUE;
            st = osdk_payload_version_ack_value_parse(io, &self->body.u.version_ack_value, (uint8_t)(((int64_t)self->profile)), err);
            if (st != OSDK_OK) return st;
        } else if (on == INT64_C(65537)) {
            osdk_status_t st;
            self->body.tag = OSDK_PAYLOAD_BODY_ACTIVATION_ACK_VALUE;
            st = osdk_payload_activation_ack_value_parse(io, &self->body.u.activation_ack_value, err);
            if (st != OSDK_OK) return st;
        } else if (on == INT64_C(65552)) {
            osdk_status_t st;
            self->body.tag = OSDK_PAYLOAD_BODY_FREQUENCY_ACK_VALUE;
            st = osdk_payload_frequency_ack_value_parse(io, &self->body.u.frequency_ack_value, err);
            if (st != OSDK_OK) return st;
        } else if (on == INT64_C(65792)) {
            osdk_status_t st;
            self->body.tag = OSDK_PAYLOAD_BODY_CONTROL_ACK_VALUE;
            st = osdk_payload_control_ack_value_parse(io, &self->body.u.control_ack_value, err);
            if (st != OSDK_OK) return st;
        } else if (on == INT64_C(66049)) {
            osdk_status_t st;
            self->body.tag = OSDK_PAYLOAD_BODY_LOST_CONTROL_ACK_VALUE;
            st = osdk_payload_lost_control_ack_value_parse(io, &self->body.u.lost_control_ack_value, err);
            if (st != OSDK_OK) return st;
        } else {
            osdk_status_t st;
            self->body.tag = OSDK_PAYLOAD_BODY_UNKNOWN_VALUE;
            st = osdk_payload_unknown_value_parse(io, &self->body.u.unknown_value, err);
            if (st != OSDK_OK) return st;
        }
        (void)on;
    }
    /* trailing */
    osdk_read_bytes_eos(io, &self->trailing);
    if (!(((int64_t)(((int64_t)(self->trailing).len)) == (int64_t)(INT64_C(0))))) return osdk_fail(err, OSDK_ERR_LENGTH_MISMATCH, "osdk_payload", "trailing", io);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_payload::activation_ack_value */
osdk_status_t osdk_payload_activation_ack_value_parse(osdk_stream_t *io, osdk_payload_activation_ack_value_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    /* ack_code */
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::activation_ack_value", "ack_code", io);
    self->ack_code = (uint16_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_payload::activation_request */
osdk_status_t osdk_payload_activation_request_parse(osdk_stream_t *io, osdk_payload_activation_request_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    /* app_id */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::activation_request", "app_id", io);
    self->app_id = (uint32_t)u;
    /* api_level */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::activation_request", "api_level", io);
    self->api_level = (uint32_t)u;
    /* sdk_version */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::activation_request", "sdk_version", io);
    self->sdk_version = (uint32_t)u;
    /* bundle_id */
    {
        int64_t n = INT64_C(32);
        if (n < 0) return osdk_fail(err, OSDK_ERR_UNDECODABLE, "osdk_payload::activation_request", "bundle_id", io);
        if (!osdk_read_bytes(io, (uint64_t)n, &self->bundle_id)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::activation_request", "bundle_id", io);
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_payload::broadcast */
osdk_status_t osdk_payload_broadcast_parse(osdk_stream_t *io, osdk_payload_broadcast_t *self, uint8_t profile, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    self->profile = profile;
    /* data */
    {
        int64_t on = ((int64_t)self->profile);
        if (on == OSDK_PAYLOAD_PROFILE_M100_FW2_3) {
            osdk_status_t st;
            self->data.tag = OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW2_3;
            st = osdk_broadcast_m100_fw2_3_parse(io, &self->data.u.osdk_broadcast_m100_fw2_3, err);
            if (st != OSDK_OK) return st;
        } else if (on == OSDK_PAYLOAD_PROFILE_M100_FW3_1) {
            osdk_status_t st;
            self->data.tag = OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW3_1;
            st = osdk_broadcast_m100_fw3_1_parse(io, &self->data.u.osdk_broadcast_m100_fw3_1, err);
            if (st != OSDK_OK) return st;
        } else if (on == OSDK_PAYLOAD_PROFILE_A3_FW3_1) {
            osdk_status_t st;
            self->data.tag = OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_A3_FW3_1;
            st = osdk_broadcast_a3_fw3_1_parse(io, &self->data.u.osdk_broadcast_a3_fw3_1, err);
            if (st != OSDK_OK) return st;
        } else {
            self->data.tag = OSDK_PAYLOAD_BROADCAST_DATA_NONE;
        }
        (void)on;
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_payload::control_ack_value */
osdk_status_t osdk_payload_control_ack_value_parse(osdk_stream_t *io, osdk_payload_control_ack_value_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    /* ack_code */
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::control_ack_value", "ack_code", io);
    self->ack_code = (uint16_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_payload::control_request */
osdk_status_t osdk_payload_control_request_parse(osdk_stream_t *io, osdk_payload_control_request_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    /* request */
    if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::control_request", "request", io);
    self->request = (uint8_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_payload::frequency_ack_value */
osdk_status_t osdk_payload_frequency_ack_value_parse(osdk_stream_t *io, osdk_payload_frequency_ack_value_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    /* ack_code */
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::frequency_ack_value", "ack_code", io);
    self->ack_code = (uint16_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_payload::frequency_request */
osdk_status_t osdk_payload_frequency_request_parse(osdk_stream_t *io, osdk_payload_frequency_request_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    /* codes */
    self->codes_count = 16;
    for (size_t i = 0; i < 16; i++) {
        if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::frequency_request", "codes", io);
        self->codes[i] = (uint8_t)u;
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_payload::lost_control */
osdk_status_t osdk_payload_lost_control_parse(osdk_stream_t *io, osdk_payload_lost_control_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    /* reason */
    if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::lost_control", "reason", io);
    self->reason = (uint8_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_payload::lost_control_ack_value */
osdk_status_t osdk_payload_lost_control_ack_value_parse(osdk_stream_t *io, osdk_payload_lost_control_ack_value_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    /* ack_code */
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::lost_control_ack_value", "ack_code", io);
    self->ack_code = (uint16_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_payload::unknown_value */
osdk_status_t osdk_payload_unknown_value_parse(osdk_stream_t *io, osdk_payload_unknown_value_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    /* raw */
    osdk_read_bytes_eos(io, &self->raw);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_payload::version_ack_value */
osdk_status_t osdk_payload_version_ack_value_parse(osdk_stream_t *io, osdk_payload_version_ack_value_t *self, uint8_t profile, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    self->profile = profile;
    /* ack_code */
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::version_ack_value", "ack_code", io);
    self->ack_code = (uint16_t)u;
    /* version_crc */
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::version_ack_value", "version_crc", io);
    self->version_crc = (uint32_t)u;
    /* version_id */
    self->version_id_present = osdk_payload_version_ack_value__has_version_id(self);
    if (self->version_id_present) {
        {
            int64_t n = INT64_C(11);
            if (n < 0) return osdk_fail(err, OSDK_ERR_UNDECODABLE, "osdk_payload::version_ack_value", "version_id", io);
            if (!osdk_read_bytes(io, (uint64_t)n, &self->version_id)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::version_ack_value", "version_id", io);
        }
    }
    /* version_name */
    {
        int64_t n = INT64_C(32);
        if (n < 0) return osdk_fail(err, OSDK_ERR_UNDECODABLE, "osdk_payload::version_ack_value", "version_name", io);
        if (!osdk_read_bytes(io, (uint64_t)n, &self->version_name)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::version_ack_value", "version_name", io);
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/* osdk_payload::version_query */
osdk_status_t osdk_payload_version_query_parse(osdk_stream_t *io, osdk_payload_version_query_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    memset(self, 0, sizeof *self);
    /* arbitrary */
    if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::version_query", "arbitrary", io);
    self->arbitrary = (uint8_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}


/* ---- whole-buffer decoders ------------------------------------------------------------------ */

osdk_status_t osdk_broadcast_a3_fw3_1_decode(const uint8_t *buf, size_t len, osdk_broadcast_a3_fw3_1_t *out, osdk_error_t *err)
{
    osdk_stream_t io;
    osdk_stream_init(&io, buf, len);
    if (err) osdk_error_clear(err);
    return osdk_broadcast_a3_fw3_1_parse(&io, out, err);
}

osdk_status_t osdk_broadcast_m100_fw2_3_decode(const uint8_t *buf, size_t len, osdk_broadcast_m100_fw2_3_t *out, osdk_error_t *err)
{
    osdk_stream_t io;
    osdk_stream_init(&io, buf, len);
    if (err) osdk_error_clear(err);
    return osdk_broadcast_m100_fw2_3_parse(&io, out, err);
}

osdk_status_t osdk_broadcast_m100_fw3_1_decode(const uint8_t *buf, size_t len, osdk_broadcast_m100_fw3_1_t *out, osdk_error_t *err)
{
    osdk_stream_t io;
    osdk_stream_init(&io, buf, len);
    if (err) osdk_error_clear(err);
    return osdk_broadcast_m100_fw3_1_parse(&io, out, err);
}

osdk_status_t osdk_control_mode_decode(const uint8_t *buf, size_t len, osdk_control_mode_t *out, osdk_error_t *err)
{
    osdk_stream_t io;
    osdk_stream_init(&io, buf, len);
    if (err) osdk_error_clear(err);
    return osdk_control_mode_parse(&io, out, err);
}

osdk_status_t osdk_frame_decode(const uint8_t *buf, size_t len, uint8_t profile, osdk_frame_t *out, osdk_error_t *err)
{
    osdk_stream_t io;
    osdk_stream_init(&io, buf, len);
    if (err) osdk_error_clear(err);
    return osdk_frame_parse(&io, out, profile, err);
}

osdk_status_t osdk_movement_control_decode(const uint8_t *buf, size_t len, osdk_movement_control_t *out, osdk_error_t *err)
{
    osdk_stream_t io;
    osdk_stream_init(&io, buf, len);
    if (err) osdk_error_clear(err);
    return osdk_movement_control_parse(&io, out, err);
}

osdk_status_t osdk_payload_decode(const uint8_t *buf, size_t len, uint8_t cmd_set, uint8_t cmd_id, bool is_ack, uint8_t profile, osdk_payload_t *out, osdk_error_t *err)
{
    osdk_stream_t io;
    osdk_stream_init(&io, buf, len);
    if (err) osdk_error_clear(err);
    return osdk_payload_parse(&io, out, cmd_set, cmd_id, is_ack, profile, err);
}


/* ---- frame header peeks ---------------------------------------------------------------------- */

uint64_t osdk_frame_peek_sof(const uint8_t *header)
{
    return osdk_peek_bits_le(header, 0, 8);
}

uint64_t osdk_frame_peek_len(const uint8_t *header)
{
    return osdk_peek_bits_le(header, 8, 10);
}

uint64_t osdk_frame_peek_ver(const uint8_t *header)
{
    return osdk_peek_bits_le(header, 18, 6);
}

uint64_t osdk_frame_peek_session(const uint8_t *header)
{
    return osdk_peek_bits_le(header, 24, 5);
}

uint64_t osdk_frame_peek_is_ack(const uint8_t *header)
{
    return osdk_peek_bits_le(header, 29, 1);
}

uint64_t osdk_frame_peek_res0(const uint8_t *header)
{
    return osdk_peek_bits_le(header, 30, 2);
}

uint64_t osdk_frame_peek_padding(const uint8_t *header)
{
    return osdk_peek_bits_le(header, 32, 5);
}

uint64_t osdk_frame_peek_enc(const uint8_t *header)
{
    return osdk_peek_bits_le(header, 37, 3);
}

uint64_t osdk_frame_peek_res1(const uint8_t *header)
{
    return osdk_peek_bits_le(header, 40, 24);
}

uint64_t osdk_frame_peek_seq(const uint8_t *header)
{
    return osdk_peek_bits_le(header, 64, 16);
}

uint64_t osdk_frame_peek_crc16(const uint8_t *header)
{
    return osdk_peek_bits_le(header, 80, 16);
}


