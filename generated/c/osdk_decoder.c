/* Generated from spec/ by tools/cgen/generate.py. Do not edit. */
/* osdk_decoder.c - see osdk_decoder.h. */
#include "osdk_decoder.h"

/* ---- runtime ---------------------------------------------------------------------- */

static const char *const osdk_status_names[15] = {"ok", "bad_sof", "bad_crc16", "bad_version", "reserved_bits", "impossible_length", "bad_encryption", "bad_session", "bad_crc32", "truncated_frame", "truncated_payload", "length_mismatch", "undecodable", "undefined_mode", "out_of_range"};

const char *osdk_status_name(osdk_status_t status)
{
    unsigned s = (unsigned)status;   /* a negative one too is then out of the table */
    if (s >= 15u) return "undecodable";
    return osdk_status_names[s];
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
    union { uint32_t u; float f; } v;   /* C99 6.5.2.3: reads the same bytes as a float */
    v.u = bits;
    return v.f;
}

double osdk_f64_from_bits(uint64_t bits)
{
    union { uint64_t u; double f; } v;
    v.u = bits;
    return v.f;
}

/* What a stream given no buffer reads from: one byte, never read (its size is 0). */
static const uint8_t osdk_no_bytes[1];

void osdk_stream_init(osdk_stream_t *io, const uint8_t *data, size_t size)
{
    io->data = data && size ? data : osdk_no_bytes;
    io->size = data ? size : 0;
    io->pos = 0;
    io->base = 0;
    io->bitbuf = 0;
    io->bitcount = 0;
}

/*@ requires \valid(io);
    assigns io->bitbuf, io->bitcount;
    ensures io->bitcount == 0; */
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
    /*@ loop invariant 0 <= i <= nbytes;
        loop assigns i, v;
        loop variant nbytes - i; */
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
    /*@ loop invariant io->pos <= io->size;
        loop assigns io->bitbuf, io->pos, io->bitcount;
        loop variant io->size - io->pos; */
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
    osdk_align(io);
    if ((uint64_t)(io->size - io->pos) < n) return false;
    sub->data = io->data + io->pos;
    sub->size = (size_t)n;
    sub->pos = 0;
    sub->base = io->base + io->pos;
    sub->bitbuf = 0;
    sub->bitcount = 0;
    io->pos += (size_t)n;
    return true;
}

void osdk_substream_eos(osdk_stream_t *io, osdk_stream_t *sub)
{
    osdk_align(io);
    sub->data = io->data + io->pos;
    sub->size = io->size - io->pos;
    sub->pos = 0;
    sub->base = io->base + io->pos;
    sub->bitbuf = 0;
    sub->bitcount = 0;
    io->pos = io->size;
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
    /* No shift by a variable amount, so that the provers see every bound. */
    uint64_t half;   /* 2^(bits - 1): the smallest value that reads negative */
    switch (bits) {
    case 8: half = UINT64_C(0x80); break;
    case 16: half = UINT64_C(0x8000); break;
    case 32: half = UINT64_C(0x80000000); break;
    default:   /* 64 */
        if (value < UINT64_C(0x8000000000000000)) return (int64_t)value;
        return (int64_t)(value - UINT64_C(0x8000000000000000)) - INT64_MAX - 1;
    }
    value %= 2u * half;   /* the low `bits` bits */
    if (value < half) return (int64_t)value;
    return (int64_t)(value - half) - (int64_t)(half - 1u) - 1;
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

/*@ requires \valid_read(self);
    assigns \nothing; */
static int64_t osdk_payload__key(const osdk_payload_t *self)
{
    return ((((int64_t)((self->is_ack ? INT64_C(65536) : INT64_C(0)))) + (((int64_t)(((int64_t)self->cmd_set))) * INT64_C(256))) + ((int64_t)(((int64_t)self->cmd_id))));
}

/*@ requires \valid_read(self);
    assigns \nothing; */
static bool osdk_payload_version_ack_value__has_version_id(const osdk_payload_version_ack_value_t *self)
{
    return ((int64_t)(((int64_t)self->profile)) != (int64_t)(OSDK_PAYLOAD_PROFILE_M100_FW2_3));
}


/* ---- parse functions ------------------------------------------------------------------------ */

/* osdk_broadcast_a3_fw3_1 */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_broadcast_a3_fw3_1__zero(osdk_broadcast_a3_fw3_1_t *self)
{
    static const osdk_broadcast_a3_fw3_1_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_has_time_stamp(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "has_time_stamp", io);
    self->has_time_stamp = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_has_quaternion(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "has_quaternion", io);
    self->has_quaternion = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_has_acceleration(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "has_acceleration", io);
    self->has_acceleration = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_has_velocity(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "has_velocity", io);
    self->has_velocity = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_has_angular_rate(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "has_angular_rate", io);
    self->has_angular_rate = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_has_position(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "has_position", io);
    self->has_position = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_has_gps_detail(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "has_gps_detail", io);
    self->has_gps_detail = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_has_rtk_detail(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "has_rtk_detail", io);
    self->has_rtk_detail = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_has_magnetometer(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "has_magnetometer", io);
    self->has_magnetometer = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_has_rc(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "has_rc", io);
    self->has_rc = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_has_gimbal(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "has_gimbal", io);
    self->has_gimbal = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_has_flight_status(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "has_flight_status", io);
    self->has_flight_status = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_has_battery(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "has_battery", io);
    self->has_battery = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_has_control_info(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "has_control_info", io);
    self->has_control_info = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_reserved_flags(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 2, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "reserved_flags", io);
    self->reserved_flags = (uint8_t)u;
    if (!(osdk_broadcast_a3_fw3_1_valid_reserved_flags(((int64_t)self->reserved_flags)))) return osdk_fail(err, OSDK_ERR_RESERVED_BITS, "osdk_broadcast_a3_fw3_1", "reserved_flags", io);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_time_stamp(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->time_stamp_present = self->has_time_stamp;
    if (self->time_stamp_present) {
        {
            osdk_status_t st = osdk_broadcast_items_time_stamp_parse(io, &self->time_stamp, (bool)(1), err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_quaternion(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->quaternion_present = self->has_quaternion;
    if (self->quaternion_present) {
        {
            osdk_status_t st = osdk_broadcast_items_quaternion_parse(io, &self->quaternion, err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_acceleration(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->acceleration_present = self->has_acceleration;
    if (self->acceleration_present) {
        {
            osdk_status_t st = osdk_broadcast_items_vector3f_parse(io, &self->acceleration, err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_velocity(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->velocity_present = self->has_velocity;
    if (self->velocity_present) {
        {
            osdk_status_t st = osdk_broadcast_items_velocity_parse(io, &self->velocity, err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_angular_rate(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->angular_rate_present = self->has_angular_rate;
    if (self->angular_rate_present) {
        {
            osdk_status_t st = osdk_broadcast_items_vector3f_parse(io, &self->angular_rate, err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_position(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->position_present = self->has_position;
    if (self->position_present) {
        {
            osdk_status_t st = osdk_broadcast_items_position_parse(io, &self->position, err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_gps_detail(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->gps_detail_present = self->has_gps_detail;
    if (self->gps_detail_present) {
        {
            osdk_status_t st = osdk_broadcast_items_gps_detail_parse(io, &self->gps_detail, err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_rtk_detail(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->rtk_detail_present = self->has_rtk_detail;
    if (self->rtk_detail_present) {
        {
            osdk_status_t st = osdk_broadcast_items_rtk_detail_parse(io, &self->rtk_detail, err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_magnetometer(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->magnetometer_present = self->has_magnetometer;
    if (self->magnetometer_present) {
        {
            osdk_status_t st = osdk_broadcast_items_magnetometer_parse(io, &self->magnetometer, err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_rc(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->rc_present = self->has_rc;
    if (self->rc_present) {
        {
            osdk_status_t st = osdk_broadcast_items_rc_parse(io, &self->rc, err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_gimbal(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->gimbal_present = self->has_gimbal;
    if (self->gimbal_present) {
        {
            osdk_status_t st = osdk_broadcast_items_gimbal_parse(io, &self->gimbal, (bool)(1), err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_flight_status(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->flight_status_present = self->has_flight_status;
    if (self->flight_status_present) {
        if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "flight_status", io);
        self->flight_status = (uint8_t)u;
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_battery(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->battery_present = self->has_battery;
    if (self->battery_present) {
        if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_a3_fw3_1", "battery", io);
        self->battery = (uint8_t)u;
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_control_info(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->control_info_present = self->has_control_info;
    if (self->control_info_present) {
        {
            osdk_status_t st = osdk_broadcast_items_control_info_parse(io, &self->control_info, (bool)(1), err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_a3_fw3_1__read_trailing(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    osdk_read_bytes_eos(io, &self->trailing);
    if (!(((int64_t)(((int64_t)(self->trailing).len)) == (int64_t)(INT64_C(0))))) return osdk_fail(err, OSDK_ERR_LENGTH_MISMATCH, "osdk_broadcast_a3_fw3_1", "trailing", io);
    (void)u;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_broadcast_a3_fw3_1_parse(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_broadcast_a3_fw3_1__zero(self);
    st = osdk_broadcast_a3_fw3_1__read_has_time_stamp(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_a3_fw3_1__read_has_quaternion(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_a3_fw3_1__read_has_acceleration(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_a3_fw3_1__read_has_velocity(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_a3_fw3_1__read_has_angular_rate(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_a3_fw3_1__read_has_position(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_a3_fw3_1__read_has_gps_detail(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_a3_fw3_1__read_has_rtk_detail(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_a3_fw3_1__read_has_magnetometer(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_a3_fw3_1__read_has_rc(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_a3_fw3_1__read_has_gimbal(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_a3_fw3_1__read_has_flight_status(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_a3_fw3_1__read_has_battery(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_a3_fw3_1__read_has_control_info(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_a3_fw3_1__read_reserved_flags(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_a3_fw3_1__read_time_stamp(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_a3_fw3_1__read_quaternion(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_a3_fw3_1__read_acceleration(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_a3_fw3_1__read_velocity(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_a3_fw3_1__read_angular_rate(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_a3_fw3_1__read_position(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_a3_fw3_1__read_gps_detail(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_a3_fw3_1__read_rtk_detail(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_a3_fw3_1__read_magnetometer(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_a3_fw3_1__read_rc(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_a3_fw3_1__read_gimbal(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_a3_fw3_1__read_flight_status(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_a3_fw3_1__read_battery(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_a3_fw3_1__read_control_info(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_a3_fw3_1__read_trailing(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_broadcast_items::control_info */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_broadcast_items_control_info__zero(osdk_broadcast_items_control_info_t *self)
{
    static const osdk_broadcast_items_control_info_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_control_info__read_cur_mov_control_mode(osdk_stream_t *io, osdk_broadcast_items_control_info_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->cur_mov_control_mode_present = self->has_mode;
    if (self->cur_mov_control_mode_present) {
        if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::control_info", "cur_mov_control_mode", io);
        self->cur_mov_control_mode = (uint8_t)u;
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_control_info__read_control_device(osdk_stream_t *io, osdk_broadcast_items_control_info_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 3, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::control_info", "control_device", io);
    self->control_device = (uint8_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_control_info__read_onboard_requested(osdk_stream_t *io, osdk_broadcast_items_control_info_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::control_info", "onboard_requested", io);
    self->onboard_requested = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_control_info__read_virtual_rc(osdk_stream_t *io, osdk_broadcast_items_control_info_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::control_info", "virtual_rc", io);
    self->virtual_rc = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_control_info__read_reserved(osdk_stream_t *io, osdk_broadcast_items_control_info_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 3, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::control_info", "reserved", io);
    self->reserved = (uint8_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_broadcast_items_control_info_parse(osdk_stream_t *io, osdk_broadcast_items_control_info_t *self, bool has_mode, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_broadcast_items_control_info__zero(self);
    self->has_mode = has_mode;
    st = osdk_broadcast_items_control_info__read_cur_mov_control_mode(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_control_info__read_control_device(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_control_info__read_onboard_requested(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_control_info__read_virtual_rc(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_control_info__read_reserved(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_broadcast_items::gimbal */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_broadcast_items_gimbal__zero(osdk_broadcast_items_gimbal_t *self)
{
    static const osdk_broadcast_items_gimbal_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_gimbal__read_roll(osdk_stream_t *io, osdk_broadcast_items_gimbal_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gimbal", "roll", io);
    self->roll.bits = (uint32_t)u;
    self->roll.value = osdk_f32_from_bits(self->roll.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_gimbal__read_pitch(osdk_stream_t *io, osdk_broadcast_items_gimbal_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gimbal", "pitch", io);
    self->pitch.bits = (uint32_t)u;
    self->pitch.value = osdk_f32_from_bits(self->pitch.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_gimbal__read_yaw(osdk_stream_t *io, osdk_broadcast_items_gimbal_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gimbal", "yaw", io);
    self->yaw.bits = (uint32_t)u;
    self->yaw.value = osdk_f32_from_bits(self->yaw.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_gimbal__read_limit(osdk_stream_t *io, osdk_broadcast_items_gimbal_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
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

osdk_status_t osdk_broadcast_items_gimbal_parse(osdk_stream_t *io, osdk_broadcast_items_gimbal_t *self, bool has_limit_byte, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_broadcast_items_gimbal__zero(self);
    self->has_limit_byte = has_limit_byte;
    st = osdk_broadcast_items_gimbal__read_roll(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_gimbal__read_pitch(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_gimbal__read_yaw(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_gimbal__read_limit(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_broadcast_items::gimbal_limit */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_broadcast_items_gimbal_limit__zero(osdk_broadcast_items_gimbal_limit_t *self)
{
    static const osdk_broadcast_items_gimbal_limit_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_gimbal_limit__read_pitch_limit(osdk_stream_t *io, osdk_broadcast_items_gimbal_limit_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gimbal_limit", "pitch_limit", io);
    self->pitch_limit = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_gimbal_limit__read_roll_limit(osdk_stream_t *io, osdk_broadcast_items_gimbal_limit_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gimbal_limit", "roll_limit", io);
    self->roll_limit = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_gimbal_limit__read_yaw_limit(osdk_stream_t *io, osdk_broadcast_items_gimbal_limit_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gimbal_limit", "yaw_limit", io);
    self->yaw_limit = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_gimbal_limit__read_reserved(osdk_stream_t *io, osdk_broadcast_items_gimbal_limit_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 5, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gimbal_limit", "reserved", io);
    self->reserved = (uint8_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_broadcast_items_gimbal_limit_parse(osdk_stream_t *io, osdk_broadcast_items_gimbal_limit_t *self, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_broadcast_items_gimbal_limit__zero(self);
    st = osdk_broadcast_items_gimbal_limit__read_pitch_limit(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_gimbal_limit__read_roll_limit(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_gimbal_limit__read_yaw_limit(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_gimbal_limit__read_reserved(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_broadcast_items::gps_detail */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_broadcast_items_gps_detail__zero(osdk_broadcast_items_gps_detail_t *self)
{
    static const osdk_broadcast_items_gps_detail_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_gps_detail__read_date(osdk_stream_t *io, osdk_broadcast_items_gps_detail_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gps_detail", "date", io);
    self->date = (uint32_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_gps_detail__read_time(osdk_stream_t *io, osdk_broadcast_items_gps_detail_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gps_detail", "time", io);
    self->time = (uint32_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_gps_detail__read_longitude(osdk_stream_t *io, osdk_broadcast_items_gps_detail_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gps_detail", "longitude", io);
    self->longitude = (int32_t)osdk_sign_extend(u, 32);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_gps_detail__read_latitude(osdk_stream_t *io, osdk_broadcast_items_gps_detail_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gps_detail", "latitude", io);
    self->latitude = (int32_t)osdk_sign_extend(u, 32);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_gps_detail__read_height_msl(osdk_stream_t *io, osdk_broadcast_items_gps_detail_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gps_detail", "height_msl", io);
    self->height_msl = (int32_t)osdk_sign_extend(u, 32);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_gps_detail__read_vel_n(osdk_stream_t *io, osdk_broadcast_items_gps_detail_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gps_detail", "vel_n", io);
    self->vel_n.bits = (uint32_t)u;
    self->vel_n.value = osdk_f32_from_bits(self->vel_n.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_gps_detail__read_vel_e(osdk_stream_t *io, osdk_broadcast_items_gps_detail_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gps_detail", "vel_e", io);
    self->vel_e.bits = (uint32_t)u;
    self->vel_e.value = osdk_f32_from_bits(self->vel_e.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_gps_detail__read_vel_d(osdk_stream_t *io, osdk_broadcast_items_gps_detail_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::gps_detail", "vel_d", io);
    self->vel_d.bits = (uint32_t)u;
    self->vel_d.value = osdk_f32_from_bits(self->vel_d.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_broadcast_items_gps_detail_parse(osdk_stream_t *io, osdk_broadcast_items_gps_detail_t *self, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_broadcast_items_gps_detail__zero(self);
    st = osdk_broadcast_items_gps_detail__read_date(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_gps_detail__read_time(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_gps_detail__read_longitude(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_gps_detail__read_latitude(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_gps_detail__read_height_msl(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_gps_detail__read_vel_n(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_gps_detail__read_vel_e(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_gps_detail__read_vel_d(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_broadcast_items::magnetometer */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_broadcast_items_magnetometer__zero(osdk_broadcast_items_magnetometer_t *self)
{
    static const osdk_broadcast_items_magnetometer_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_magnetometer__read_x(osdk_stream_t *io, osdk_broadcast_items_magnetometer_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::magnetometer", "x", io);
    self->x = (int16_t)osdk_sign_extend(u, 16);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_magnetometer__read_y(osdk_stream_t *io, osdk_broadcast_items_magnetometer_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::magnetometer", "y", io);
    self->y = (int16_t)osdk_sign_extend(u, 16);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_magnetometer__read_z(osdk_stream_t *io, osdk_broadcast_items_magnetometer_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::magnetometer", "z", io);
    self->z = (int16_t)osdk_sign_extend(u, 16);
    (void)u;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_broadcast_items_magnetometer_parse(osdk_stream_t *io, osdk_broadcast_items_magnetometer_t *self, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_broadcast_items_magnetometer__zero(self);
    st = osdk_broadcast_items_magnetometer__read_x(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_magnetometer__read_y(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_magnetometer__read_z(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_broadcast_items::position */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_broadcast_items_position__zero(osdk_broadcast_items_position_t *self)
{
    static const osdk_broadcast_items_position_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_position__read_latitude(osdk_stream_t *io, osdk_broadcast_items_position_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 8, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::position", "latitude", io);
    self->latitude.bits = u;
    self->latitude.value = osdk_f64_from_bits(self->latitude.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_position__read_longitude(osdk_stream_t *io, osdk_broadcast_items_position_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 8, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::position", "longitude", io);
    self->longitude.bits = u;
    self->longitude.value = osdk_f64_from_bits(self->longitude.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_position__read_altitude(osdk_stream_t *io, osdk_broadcast_items_position_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::position", "altitude", io);
    self->altitude.bits = (uint32_t)u;
    self->altitude.value = osdk_f32_from_bits(self->altitude.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_position__read_height(osdk_stream_t *io, osdk_broadcast_items_position_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::position", "height", io);
    self->height.bits = (uint32_t)u;
    self->height.value = osdk_f32_from_bits(self->height.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_position__read_gps_health(osdk_stream_t *io, osdk_broadcast_items_position_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::position", "gps_health", io);
    self->gps_health = (uint8_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_broadcast_items_position_parse(osdk_stream_t *io, osdk_broadcast_items_position_t *self, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_broadcast_items_position__zero(self);
    st = osdk_broadcast_items_position__read_latitude(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_position__read_longitude(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_position__read_altitude(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_position__read_height(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_position__read_gps_health(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_broadcast_items::quaternion */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_broadcast_items_quaternion__zero(osdk_broadcast_items_quaternion_t *self)
{
    static const osdk_broadcast_items_quaternion_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_quaternion__read_q0(osdk_stream_t *io, osdk_broadcast_items_quaternion_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::quaternion", "q0", io);
    self->q0.bits = (uint32_t)u;
    self->q0.value = osdk_f32_from_bits(self->q0.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_quaternion__read_q1(osdk_stream_t *io, osdk_broadcast_items_quaternion_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::quaternion", "q1", io);
    self->q1.bits = (uint32_t)u;
    self->q1.value = osdk_f32_from_bits(self->q1.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_quaternion__read_q2(osdk_stream_t *io, osdk_broadcast_items_quaternion_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::quaternion", "q2", io);
    self->q2.bits = (uint32_t)u;
    self->q2.value = osdk_f32_from_bits(self->q2.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_quaternion__read_q3(osdk_stream_t *io, osdk_broadcast_items_quaternion_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::quaternion", "q3", io);
    self->q3.bits = (uint32_t)u;
    self->q3.value = osdk_f32_from_bits(self->q3.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_broadcast_items_quaternion_parse(osdk_stream_t *io, osdk_broadcast_items_quaternion_t *self, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_broadcast_items_quaternion__zero(self);
    st = osdk_broadcast_items_quaternion__read_q0(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_quaternion__read_q1(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_quaternion__read_q2(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_quaternion__read_q3(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_broadcast_items::rc */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_broadcast_items_rc__zero(osdk_broadcast_items_rc_t *self)
{
    static const osdk_broadcast_items_rc_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_rc__read_roll(osdk_stream_t *io, osdk_broadcast_items_rc_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rc", "roll", io);
    self->roll = (int16_t)osdk_sign_extend(u, 16);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_rc__read_pitch(osdk_stream_t *io, osdk_broadcast_items_rc_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rc", "pitch", io);
    self->pitch = (int16_t)osdk_sign_extend(u, 16);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_rc__read_yaw(osdk_stream_t *io, osdk_broadcast_items_rc_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rc", "yaw", io);
    self->yaw = (int16_t)osdk_sign_extend(u, 16);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_rc__read_throttle(osdk_stream_t *io, osdk_broadcast_items_rc_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rc", "throttle", io);
    self->throttle = (int16_t)osdk_sign_extend(u, 16);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_rc__read_mode(osdk_stream_t *io, osdk_broadcast_items_rc_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rc", "mode", io);
    self->mode = (int16_t)osdk_sign_extend(u, 16);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_rc__read_gear(osdk_stream_t *io, osdk_broadcast_items_rc_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rc", "gear", io);
    self->gear = (int16_t)osdk_sign_extend(u, 16);
    (void)u;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_broadcast_items_rc_parse(osdk_stream_t *io, osdk_broadcast_items_rc_t *self, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_broadcast_items_rc__zero(self);
    st = osdk_broadcast_items_rc__read_roll(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_rc__read_pitch(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_rc__read_yaw(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_rc__read_throttle(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_rc__read_mode(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_rc__read_gear(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_broadcast_items::rtk_detail */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_broadcast_items_rtk_detail__zero(osdk_broadcast_items_rtk_detail_t *self)
{
    static const osdk_broadcast_items_rtk_detail_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_rtk_detail__read_date(osdk_stream_t *io, osdk_broadcast_items_rtk_detail_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rtk_detail", "date", io);
    self->date = (uint32_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_rtk_detail__read_time(osdk_stream_t *io, osdk_broadcast_items_rtk_detail_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rtk_detail", "time", io);
    self->time = (uint32_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_rtk_detail__read_longitude(osdk_stream_t *io, osdk_broadcast_items_rtk_detail_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 8, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rtk_detail", "longitude", io);
    self->longitude.bits = u;
    self->longitude.value = osdk_f64_from_bits(self->longitude.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_rtk_detail__read_latitude(osdk_stream_t *io, osdk_broadcast_items_rtk_detail_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 8, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rtk_detail", "latitude", io);
    self->latitude.bits = u;
    self->latitude.value = osdk_f64_from_bits(self->latitude.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_rtk_detail__read_height_msl(osdk_stream_t *io, osdk_broadcast_items_rtk_detail_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rtk_detail", "height_msl", io);
    self->height_msl.bits = (uint32_t)u;
    self->height_msl.value = osdk_f32_from_bits(self->height_msl.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_rtk_detail__read_vel_n(osdk_stream_t *io, osdk_broadcast_items_rtk_detail_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rtk_detail", "vel_n", io);
    self->vel_n.bits = (uint32_t)u;
    self->vel_n.value = osdk_f32_from_bits(self->vel_n.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_rtk_detail__read_vel_e(osdk_stream_t *io, osdk_broadcast_items_rtk_detail_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rtk_detail", "vel_e", io);
    self->vel_e.bits = (uint32_t)u;
    self->vel_e.value = osdk_f32_from_bits(self->vel_e.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_rtk_detail__read_vel_d(osdk_stream_t *io, osdk_broadcast_items_rtk_detail_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rtk_detail", "vel_d", io);
    self->vel_d.bits = (uint32_t)u;
    self->vel_d.value = osdk_f32_from_bits(self->vel_d.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_rtk_detail__read_yaw(osdk_stream_t *io, osdk_broadcast_items_rtk_detail_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rtk_detail", "yaw", io);
    self->yaw = (int16_t)osdk_sign_extend(u, 16);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_rtk_detail__read_position_flag(osdk_stream_t *io, osdk_broadcast_items_rtk_detail_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rtk_detail", "position_flag", io);
    self->position_flag = (uint8_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_rtk_detail__read_yaw_flag(osdk_stream_t *io, osdk_broadcast_items_rtk_detail_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::rtk_detail", "yaw_flag", io);
    self->yaw_flag = (uint8_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_broadcast_items_rtk_detail_parse(osdk_stream_t *io, osdk_broadcast_items_rtk_detail_t *self, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_broadcast_items_rtk_detail__zero(self);
    st = osdk_broadcast_items_rtk_detail__read_date(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_rtk_detail__read_time(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_rtk_detail__read_longitude(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_rtk_detail__read_latitude(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_rtk_detail__read_height_msl(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_rtk_detail__read_vel_n(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_rtk_detail__read_vel_e(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_rtk_detail__read_vel_d(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_rtk_detail__read_yaw(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_rtk_detail__read_position_flag(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_rtk_detail__read_yaw_flag(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_broadcast_items::time_stamp */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_broadcast_items_time_stamp__zero(osdk_broadcast_items_time_stamp_t *self)
{
    static const osdk_broadcast_items_time_stamp_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_time_stamp__read_time(osdk_stream_t *io, osdk_broadcast_items_time_stamp_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::time_stamp", "time", io);
    self->time = (uint32_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_time_stamp__read_nano_time(osdk_stream_t *io, osdk_broadcast_items_time_stamp_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->nano_time_present = self->has_ns_and_sync;
    if (self->nano_time_present) {
        if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::time_stamp", "nano_time", io);
        self->nano_time = (uint32_t)u;
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_time_stamp__read_sync_flag(osdk_stream_t *io, osdk_broadcast_items_time_stamp_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->sync_flag_present = self->has_ns_and_sync;
    if (self->sync_flag_present) {
        if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::time_stamp", "sync_flag", io);
        self->sync_flag = (uint8_t)u;
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_broadcast_items_time_stamp_parse(osdk_stream_t *io, osdk_broadcast_items_time_stamp_t *self, bool has_ns_and_sync, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_broadcast_items_time_stamp__zero(self);
    self->has_ns_and_sync = has_ns_and_sync;
    st = osdk_broadcast_items_time_stamp__read_time(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_time_stamp__read_nano_time(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_time_stamp__read_sync_flag(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_broadcast_items::vector3f */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_broadcast_items_vector3f__zero(osdk_broadcast_items_vector3f_t *self)
{
    static const osdk_broadcast_items_vector3f_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_vector3f__read_x(osdk_stream_t *io, osdk_broadcast_items_vector3f_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::vector3f", "x", io);
    self->x.bits = (uint32_t)u;
    self->x.value = osdk_f32_from_bits(self->x.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_vector3f__read_y(osdk_stream_t *io, osdk_broadcast_items_vector3f_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::vector3f", "y", io);
    self->y.bits = (uint32_t)u;
    self->y.value = osdk_f32_from_bits(self->y.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_vector3f__read_z(osdk_stream_t *io, osdk_broadcast_items_vector3f_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::vector3f", "z", io);
    self->z.bits = (uint32_t)u;
    self->z.value = osdk_f32_from_bits(self->z.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_broadcast_items_vector3f_parse(osdk_stream_t *io, osdk_broadcast_items_vector3f_t *self, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_broadcast_items_vector3f__zero(self);
    st = osdk_broadcast_items_vector3f__read_x(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_vector3f__read_y(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_vector3f__read_z(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_broadcast_items::velocity */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_broadcast_items_velocity__zero(osdk_broadcast_items_velocity_t *self)
{
    static const osdk_broadcast_items_velocity_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_velocity__read_x(osdk_stream_t *io, osdk_broadcast_items_velocity_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::velocity", "x", io);
    self->x.bits = (uint32_t)u;
    self->x.value = osdk_f32_from_bits(self->x.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_velocity__read_y(osdk_stream_t *io, osdk_broadcast_items_velocity_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::velocity", "y", io);
    self->y.bits = (uint32_t)u;
    self->y.value = osdk_f32_from_bits(self->y.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_velocity__read_z(osdk_stream_t *io, osdk_broadcast_items_velocity_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::velocity", "z", io);
    self->z.bits = (uint32_t)u;
    self->z.value = osdk_f32_from_bits(self->z.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_velocity__read_data_valid(osdk_stream_t *io, osdk_broadcast_items_velocity_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::velocity", "data_valid", io);
    self->data_valid = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_velocity__read_sensor_id(osdk_stream_t *io, osdk_broadcast_items_velocity_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 4, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::velocity", "sensor_id", io);
    self->sensor_id = (uint8_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_items_velocity__read_reserved(osdk_stream_t *io, osdk_broadcast_items_velocity_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 3, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_items::velocity", "reserved", io);
    self->reserved = (uint8_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_broadcast_items_velocity_parse(osdk_stream_t *io, osdk_broadcast_items_velocity_t *self, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_broadcast_items_velocity__zero(self);
    st = osdk_broadcast_items_velocity__read_x(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_velocity__read_y(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_velocity__read_z(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_velocity__read_data_valid(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_velocity__read_sensor_id(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_items_velocity__read_reserved(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_broadcast_m100_fw2_3 */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_broadcast_m100_fw2_3__zero(osdk_broadcast_m100_fw2_3_t *self)
{
    static const osdk_broadcast_m100_fw2_3_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw2_3__read_has_time_stamp(osdk_stream_t *io, osdk_broadcast_m100_fw2_3_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "has_time_stamp", io);
    self->has_time_stamp = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw2_3__read_has_quaternion(osdk_stream_t *io, osdk_broadcast_m100_fw2_3_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "has_quaternion", io);
    self->has_quaternion = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw2_3__read_has_acceleration(osdk_stream_t *io, osdk_broadcast_m100_fw2_3_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "has_acceleration", io);
    self->has_acceleration = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw2_3__read_has_velocity(osdk_stream_t *io, osdk_broadcast_m100_fw2_3_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "has_velocity", io);
    self->has_velocity = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw2_3__read_has_angular_rate(osdk_stream_t *io, osdk_broadcast_m100_fw2_3_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "has_angular_rate", io);
    self->has_angular_rate = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw2_3__read_has_position(osdk_stream_t *io, osdk_broadcast_m100_fw2_3_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "has_position", io);
    self->has_position = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw2_3__read_has_magnetometer(osdk_stream_t *io, osdk_broadcast_m100_fw2_3_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "has_magnetometer", io);
    self->has_magnetometer = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw2_3__read_has_rc(osdk_stream_t *io, osdk_broadcast_m100_fw2_3_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "has_rc", io);
    self->has_rc = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw2_3__read_has_gimbal(osdk_stream_t *io, osdk_broadcast_m100_fw2_3_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "has_gimbal", io);
    self->has_gimbal = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw2_3__read_has_flight_status(osdk_stream_t *io, osdk_broadcast_m100_fw2_3_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "has_flight_status", io);
    self->has_flight_status = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw2_3__read_has_battery(osdk_stream_t *io, osdk_broadcast_m100_fw2_3_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "has_battery", io);
    self->has_battery = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw2_3__read_has_control_info(osdk_stream_t *io, osdk_broadcast_m100_fw2_3_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "has_control_info", io);
    self->has_control_info = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw2_3__read_reserved_flags(osdk_stream_t *io, osdk_broadcast_m100_fw2_3_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 4, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "reserved_flags", io);
    self->reserved_flags = (uint8_t)u;
    if (!(osdk_broadcast_m100_fw2_3_valid_reserved_flags(((int64_t)self->reserved_flags)))) return osdk_fail(err, OSDK_ERR_RESERVED_BITS, "osdk_broadcast_m100_fw2_3", "reserved_flags", io);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw2_3__read_time_stamp(osdk_stream_t *io, osdk_broadcast_m100_fw2_3_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->time_stamp_present = self->has_time_stamp;
    if (self->time_stamp_present) {
        {
            osdk_status_t st = osdk_broadcast_items_time_stamp_parse(io, &self->time_stamp, (bool)(0), err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw2_3__read_quaternion(osdk_stream_t *io, osdk_broadcast_m100_fw2_3_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->quaternion_present = self->has_quaternion;
    if (self->quaternion_present) {
        {
            osdk_status_t st = osdk_broadcast_items_quaternion_parse(io, &self->quaternion, err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw2_3__read_acceleration(osdk_stream_t *io, osdk_broadcast_m100_fw2_3_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->acceleration_present = self->has_acceleration;
    if (self->acceleration_present) {
        {
            osdk_status_t st = osdk_broadcast_items_vector3f_parse(io, &self->acceleration, err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw2_3__read_velocity(osdk_stream_t *io, osdk_broadcast_m100_fw2_3_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->velocity_present = self->has_velocity;
    if (self->velocity_present) {
        {
            osdk_status_t st = osdk_broadcast_items_velocity_parse(io, &self->velocity, err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw2_3__read_angular_rate(osdk_stream_t *io, osdk_broadcast_m100_fw2_3_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->angular_rate_present = self->has_angular_rate;
    if (self->angular_rate_present) {
        {
            osdk_status_t st = osdk_broadcast_items_vector3f_parse(io, &self->angular_rate, err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw2_3__read_position(osdk_stream_t *io, osdk_broadcast_m100_fw2_3_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->position_present = self->has_position;
    if (self->position_present) {
        {
            osdk_status_t st = osdk_broadcast_items_position_parse(io, &self->position, err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw2_3__read_magnetometer(osdk_stream_t *io, osdk_broadcast_m100_fw2_3_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->magnetometer_present = self->has_magnetometer;
    if (self->magnetometer_present) {
        {
            osdk_status_t st = osdk_broadcast_items_magnetometer_parse(io, &self->magnetometer, err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw2_3__read_rc(osdk_stream_t *io, osdk_broadcast_m100_fw2_3_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->rc_present = self->has_rc;
    if (self->rc_present) {
        {
            osdk_status_t st = osdk_broadcast_items_rc_parse(io, &self->rc, err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw2_3__read_gimbal(osdk_stream_t *io, osdk_broadcast_m100_fw2_3_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->gimbal_present = self->has_gimbal;
    if (self->gimbal_present) {
        {
            osdk_status_t st = osdk_broadcast_items_gimbal_parse(io, &self->gimbal, (bool)(0), err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw2_3__read_flight_status(osdk_stream_t *io, osdk_broadcast_m100_fw2_3_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->flight_status_present = self->has_flight_status;
    if (self->flight_status_present) {
        if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "flight_status", io);
        self->flight_status = (uint8_t)u;
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw2_3__read_battery(osdk_stream_t *io, osdk_broadcast_m100_fw2_3_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->battery_present = self->has_battery;
    if (self->battery_present) {
        if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw2_3", "battery", io);
        self->battery = (uint8_t)u;
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw2_3__read_control_info(osdk_stream_t *io, osdk_broadcast_m100_fw2_3_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->control_info_present = self->has_control_info;
    if (self->control_info_present) {
        {
            osdk_status_t st = osdk_broadcast_items_control_info_parse(io, &self->control_info, (bool)(0), err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw2_3__read_trailing(osdk_stream_t *io, osdk_broadcast_m100_fw2_3_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    osdk_read_bytes_eos(io, &self->trailing);
    if (!(((int64_t)(((int64_t)(self->trailing).len)) == (int64_t)(INT64_C(0))))) return osdk_fail(err, OSDK_ERR_LENGTH_MISMATCH, "osdk_broadcast_m100_fw2_3", "trailing", io);
    (void)u;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_broadcast_m100_fw2_3_parse(osdk_stream_t *io, osdk_broadcast_m100_fw2_3_t *self, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_broadcast_m100_fw2_3__zero(self);
    st = osdk_broadcast_m100_fw2_3__read_has_time_stamp(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw2_3__read_has_quaternion(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw2_3__read_has_acceleration(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw2_3__read_has_velocity(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw2_3__read_has_angular_rate(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw2_3__read_has_position(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw2_3__read_has_magnetometer(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw2_3__read_has_rc(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw2_3__read_has_gimbal(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw2_3__read_has_flight_status(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw2_3__read_has_battery(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw2_3__read_has_control_info(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw2_3__read_reserved_flags(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw2_3__read_time_stamp(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw2_3__read_quaternion(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw2_3__read_acceleration(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw2_3__read_velocity(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw2_3__read_angular_rate(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw2_3__read_position(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw2_3__read_magnetometer(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw2_3__read_rc(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw2_3__read_gimbal(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw2_3__read_flight_status(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw2_3__read_battery(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw2_3__read_control_info(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw2_3__read_trailing(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_broadcast_m100_fw3_1 */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_broadcast_m100_fw3_1__zero(osdk_broadcast_m100_fw3_1_t *self)
{
    static const osdk_broadcast_m100_fw3_1_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw3_1__read_has_time_stamp(osdk_stream_t *io, osdk_broadcast_m100_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "has_time_stamp", io);
    self->has_time_stamp = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw3_1__read_has_quaternion(osdk_stream_t *io, osdk_broadcast_m100_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "has_quaternion", io);
    self->has_quaternion = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw3_1__read_has_acceleration(osdk_stream_t *io, osdk_broadcast_m100_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "has_acceleration", io);
    self->has_acceleration = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw3_1__read_has_velocity(osdk_stream_t *io, osdk_broadcast_m100_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "has_velocity", io);
    self->has_velocity = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw3_1__read_has_angular_rate(osdk_stream_t *io, osdk_broadcast_m100_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "has_angular_rate", io);
    self->has_angular_rate = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw3_1__read_has_position(osdk_stream_t *io, osdk_broadcast_m100_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "has_position", io);
    self->has_position = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw3_1__read_has_magnetometer(osdk_stream_t *io, osdk_broadcast_m100_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "has_magnetometer", io);
    self->has_magnetometer = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw3_1__read_has_rc(osdk_stream_t *io, osdk_broadcast_m100_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "has_rc", io);
    self->has_rc = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw3_1__read_has_gimbal(osdk_stream_t *io, osdk_broadcast_m100_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "has_gimbal", io);
    self->has_gimbal = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw3_1__read_has_flight_status(osdk_stream_t *io, osdk_broadcast_m100_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "has_flight_status", io);
    self->has_flight_status = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw3_1__read_has_battery(osdk_stream_t *io, osdk_broadcast_m100_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "has_battery", io);
    self->has_battery = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw3_1__read_has_control_info(osdk_stream_t *io, osdk_broadcast_m100_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "has_control_info", io);
    self->has_control_info = (u != 0);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw3_1__read_reserved_flags(osdk_stream_t *io, osdk_broadcast_m100_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 4, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "reserved_flags", io);
    self->reserved_flags = (uint8_t)u;
    if (!(osdk_broadcast_m100_fw3_1_valid_reserved_flags(((int64_t)self->reserved_flags)))) return osdk_fail(err, OSDK_ERR_RESERVED_BITS, "osdk_broadcast_m100_fw3_1", "reserved_flags", io);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw3_1__read_time_stamp(osdk_stream_t *io, osdk_broadcast_m100_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->time_stamp_present = self->has_time_stamp;
    if (self->time_stamp_present) {
        {
            osdk_status_t st = osdk_broadcast_items_time_stamp_parse(io, &self->time_stamp, (bool)(1), err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw3_1__read_quaternion(osdk_stream_t *io, osdk_broadcast_m100_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->quaternion_present = self->has_quaternion;
    if (self->quaternion_present) {
        {
            osdk_status_t st = osdk_broadcast_items_quaternion_parse(io, &self->quaternion, err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw3_1__read_acceleration(osdk_stream_t *io, osdk_broadcast_m100_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->acceleration_present = self->has_acceleration;
    if (self->acceleration_present) {
        {
            osdk_status_t st = osdk_broadcast_items_vector3f_parse(io, &self->acceleration, err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw3_1__read_velocity(osdk_stream_t *io, osdk_broadcast_m100_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->velocity_present = self->has_velocity;
    if (self->velocity_present) {
        {
            osdk_status_t st = osdk_broadcast_items_velocity_parse(io, &self->velocity, err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw3_1__read_angular_rate(osdk_stream_t *io, osdk_broadcast_m100_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->angular_rate_present = self->has_angular_rate;
    if (self->angular_rate_present) {
        {
            osdk_status_t st = osdk_broadcast_items_vector3f_parse(io, &self->angular_rate, err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw3_1__read_position(osdk_stream_t *io, osdk_broadcast_m100_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->position_present = self->has_position;
    if (self->position_present) {
        {
            osdk_status_t st = osdk_broadcast_items_position_parse(io, &self->position, err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw3_1__read_magnetometer(osdk_stream_t *io, osdk_broadcast_m100_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->magnetometer_present = self->has_magnetometer;
    if (self->magnetometer_present) {
        {
            osdk_status_t st = osdk_broadcast_items_magnetometer_parse(io, &self->magnetometer, err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw3_1__read_rc(osdk_stream_t *io, osdk_broadcast_m100_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->rc_present = self->has_rc;
    if (self->rc_present) {
        {
            osdk_status_t st = osdk_broadcast_items_rc_parse(io, &self->rc, err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw3_1__read_gimbal(osdk_stream_t *io, osdk_broadcast_m100_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->gimbal_present = self->has_gimbal;
    if (self->gimbal_present) {
        {
            osdk_status_t st = osdk_broadcast_items_gimbal_parse(io, &self->gimbal, (bool)(1), err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw3_1__read_flight_status(osdk_stream_t *io, osdk_broadcast_m100_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->flight_status_present = self->has_flight_status;
    if (self->flight_status_present) {
        if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "flight_status", io);
        self->flight_status = (uint8_t)u;
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw3_1__read_battery(osdk_stream_t *io, osdk_broadcast_m100_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->battery_present = self->has_battery;
    if (self->battery_present) {
        if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_broadcast_m100_fw3_1", "battery", io);
        self->battery = (uint8_t)u;
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw3_1__read_control_info(osdk_stream_t *io, osdk_broadcast_m100_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->control_info_present = self->has_control_info;
    if (self->control_info_present) {
        {
            osdk_status_t st = osdk_broadcast_items_control_info_parse(io, &self->control_info, (bool)(1), err);
            if (st != OSDK_OK) return st;
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_broadcast_m100_fw3_1__read_trailing(osdk_stream_t *io, osdk_broadcast_m100_fw3_1_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    osdk_read_bytes_eos(io, &self->trailing);
    if (!(((int64_t)(((int64_t)(self->trailing).len)) == (int64_t)(INT64_C(0))))) return osdk_fail(err, OSDK_ERR_LENGTH_MISMATCH, "osdk_broadcast_m100_fw3_1", "trailing", io);
    (void)u;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_broadcast_m100_fw3_1_parse(osdk_stream_t *io, osdk_broadcast_m100_fw3_1_t *self, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_broadcast_m100_fw3_1__zero(self);
    st = osdk_broadcast_m100_fw3_1__read_has_time_stamp(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw3_1__read_has_quaternion(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw3_1__read_has_acceleration(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw3_1__read_has_velocity(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw3_1__read_has_angular_rate(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw3_1__read_has_position(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw3_1__read_has_magnetometer(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw3_1__read_has_rc(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw3_1__read_has_gimbal(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw3_1__read_has_flight_status(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw3_1__read_has_battery(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw3_1__read_has_control_info(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw3_1__read_reserved_flags(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw3_1__read_time_stamp(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw3_1__read_quaternion(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw3_1__read_acceleration(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw3_1__read_velocity(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw3_1__read_angular_rate(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw3_1__read_position(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw3_1__read_magnetometer(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw3_1__read_rc(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw3_1__read_gimbal(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw3_1__read_flight_status(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw3_1__read_battery(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw3_1__read_control_info(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_broadcast_m100_fw3_1__read_trailing(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_control_mode */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_control_mode__zero(osdk_control_mode_t *self)
{
    static const osdk_control_mode_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_control_mode__read_stable_mode(osdk_stream_t *io, osdk_control_mode_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_control_mode", "stable_mode", io);
    self->stable_mode = (uint8_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_control_mode__read_horizontal_frame(osdk_stream_t *io, osdk_control_mode_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 2, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_control_mode", "horizontal_frame", io);
    self->horizontal_frame = (uint8_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_control_mode__read_yaw_logic(osdk_stream_t *io, osdk_control_mode_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_control_mode", "yaw_logic", io);
    self->yaw_logic = (uint8_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_control_mode__read_vertical_logic(osdk_stream_t *io, osdk_control_mode_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 2, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_control_mode", "vertical_logic", io);
    self->vertical_logic = (uint8_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_control_mode__read_horizontal_logic(osdk_stream_t *io, osdk_control_mode_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 2, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_control_mode", "horizontal_logic", io);
    self->horizontal_logic = (uint8_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_control_mode_parse(osdk_stream_t *io, osdk_control_mode_t *self, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_control_mode__zero(self);
    st = osdk_control_mode__read_stable_mode(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_control_mode__read_horizontal_frame(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_control_mode__read_yaw_logic(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_control_mode__read_vertical_logic(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_control_mode__read_horizontal_logic(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_frame */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_frame__zero(osdk_frame_t *self)
{
    static const osdk_frame_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_frame__read_sof(osdk_stream_t *io, osdk_frame_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bytes(io, 1, &self->sof)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame", "sof", io);
    if (self->sof.ptr[0] != 0xaa) return osdk_fail(err, OSDK_ERR_BAD_SOF, "osdk_frame", "sof", io);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_frame__read_len(osdk_stream_t *io, osdk_frame_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 10, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame", "len", io);
    self->len = (uint16_t)u;
    if (!(osdk_frame_valid_len(((int64_t)self->len)))) return osdk_fail(err, OSDK_ERR_IMPOSSIBLE_LENGTH, "osdk_frame", "len", io);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_frame__read_ver(osdk_stream_t *io, osdk_frame_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 6, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame", "ver", io);
    self->ver = (uint8_t)u;
    if (!(osdk_frame_valid_ver(((int64_t)self->ver)))) return osdk_fail(err, OSDK_ERR_BAD_VERSION, "osdk_frame", "ver", io);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_frame__read_session(osdk_stream_t *io, osdk_frame_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 5, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame", "session", io);
    self->session = (uint8_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_frame__read_is_ack(osdk_stream_t *io, osdk_frame_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 1, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame", "is_ack", io);
    self->is_ack = (u != 0);
    if (!(((!self->is_ack) || ((int64_t)(((int64_t)self->session)) != (int64_t)(INT64_C(0)))))) return osdk_fail(err, OSDK_ERR_BAD_SESSION, "osdk_frame", "is_ack", io);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_frame__read_res0(osdk_stream_t *io, osdk_frame_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 2, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame", "res0", io);
    self->res0 = (uint8_t)u;
    if (!(osdk_frame_valid_res0(((int64_t)self->res0)))) return osdk_fail(err, OSDK_ERR_RESERVED_BITS, "osdk_frame", "res0", io);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_frame__read_padding(osdk_stream_t *io, osdk_frame_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 5, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame", "padding", io);
    self->padding = (uint8_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_frame__read_enc(osdk_stream_t *io, osdk_frame_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 3, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame", "enc", io);
    self->enc = (uint8_t)u;
    if (!(((((int64_t)(((int64_t)self->enc)) == (int64_t)(OSDK_FRAME_ENCRYPTION_PLAIN)) && ((int64_t)(((int64_t)self->padding)) == (int64_t)(INT64_C(0)))) || ((((((int64_t)(((int64_t)self->enc)) == (int64_t)(OSDK_FRAME_ENCRYPTION_AES256)) && (((int64_t)self->padding) >= INT64_C(1))) && (((int64_t)self->padding) <= INT64_C(16))) && (((int64_t)self->len) > INT64_C(16))) && ((int64_t)(osdk_kmod((((int64_t)self->len) - INT64_C(16)), INT64_C(16))) == (int64_t)(INT64_C(0))))))) return osdk_fail(err, OSDK_ERR_BAD_ENCRYPTION, "osdk_frame", "enc", io);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_frame__read_res1(osdk_stream_t *io, osdk_frame_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_bits_le(io, 24, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame", "res1", io);
    self->res1 = (uint32_t)u;
    if (!(osdk_frame_valid_res1(((int64_t)self->res1)))) return osdk_fail(err, OSDK_ERR_RESERVED_BITS, "osdk_frame", "res1", io);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_frame__read_seq(osdk_stream_t *io, osdk_frame_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame", "seq", io);
    self->seq = (uint16_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_frame__read_crc16(osdk_stream_t *io, osdk_frame_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame", "crc16", io);
    self->crc16 = (uint16_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_frame__read_data(osdk_stream_t *io, osdk_frame_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
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
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_frame__read_crc32(osdk_stream_t *io, osdk_frame_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->crc32_present = (((int64_t)self->len) > INT64_C(12));
    if (self->crc32_present) {
        if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame", "crc32", io);
        self->crc32 = (uint32_t)u;
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_frame_parse(osdk_stream_t *io, osdk_frame_t *self, uint8_t profile, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_frame__zero(self);
    self->profile = profile;
    st = osdk_frame__read_sof(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_frame__read_len(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_frame__read_ver(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_frame__read_session(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_frame__read_is_ack(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_frame__read_res0(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_frame__read_padding(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_frame__read_enc(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_frame__read_res1(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_frame__read_seq(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_frame__read_crc16(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_frame__read_data(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_frame__read_crc32(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_frame::frame_data */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_frame_frame_data__zero(osdk_frame_frame_data_t *self)
{
    static const osdk_frame_frame_data_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    requires \valid_read(parent) && \valid_read(root);
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_frame_frame_data__read_cmd_set(osdk_stream_t *io, osdk_frame_frame_data_t *self, const osdk_frame_t *parent, const osdk_frame_t *root, osdk_error_t *err)
{
    uint64_t u = 0;
    self->cmd_set_present = (!parent->is_ack);
    if (self->cmd_set_present) {
        if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame::frame_data", "cmd_set", io);
        self->cmd_set = (uint8_t)u;
    }
    (void)u;
    (void)parent;
    (void)root;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    requires \valid_read(parent) && \valid_read(root);
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_frame_frame_data__read_cmd_id(osdk_stream_t *io, osdk_frame_frame_data_t *self, const osdk_frame_t *parent, const osdk_frame_t *root, osdk_error_t *err)
{
    uint64_t u = 0;
    self->cmd_id_present = (!parent->is_ack);
    if (self->cmd_id_present) {
        if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_frame::frame_data", "cmd_id", io);
        self->cmd_id = (uint8_t)u;
    }
    (void)u;
    (void)parent;
    (void)root;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    requires \valid_read(parent) && \valid_read(root);
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_frame_frame_data__read_value(osdk_stream_t *io, osdk_frame_frame_data_t *self, const osdk_frame_t *parent, const osdk_frame_t *root, osdk_error_t *err)
{
    uint64_t u = 0;
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
    (void)u;
    (void)parent;
    (void)root;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    requires \valid_read(parent) && \valid_read(root);
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_frame_frame_data__read_ack_value(osdk_stream_t *io, osdk_frame_frame_data_t *self, const osdk_frame_t *parent, const osdk_frame_t *root, osdk_error_t *err)
{
    uint64_t u = 0;
    self->ack_value_present = parent->is_ack;
    if (self->ack_value_present) {
        osdk_read_bytes_eos(io, &self->ack_value);
    }
    (void)u;
    (void)parent;
    (void)root;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_frame_frame_data_parse(osdk_stream_t *io, osdk_frame_frame_data_t *self, const osdk_frame_t *parent, const osdk_frame_t *root, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_frame_frame_data__zero(self);
    st = osdk_frame_frame_data__read_cmd_set(io, self, parent, root, err);
    if (st != OSDK_OK) return st;
    st = osdk_frame_frame_data__read_cmd_id(io, self, parent, root, err);
    if (st != OSDK_OK) return st;
    st = osdk_frame_frame_data__read_value(io, self, parent, root, err);
    if (st != OSDK_OK) return st;
    st = osdk_frame_frame_data__read_ack_value(io, self, parent, root, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_movement_control */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_movement_control__zero(osdk_movement_control_t *self)
{
    static const osdk_movement_control_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_movement_control__read_control_mode(osdk_stream_t *io, osdk_movement_control_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    {
        osdk_status_t st = osdk_control_mode_parse(io, &self->control_mode, err);
        if (st != OSDK_OK) return st;
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_movement_control__read_x(osdk_stream_t *io, osdk_movement_control_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_movement_control", "x", io);
    self->x.bits = (uint32_t)u;
    self->x.value = osdk_f32_from_bits(self->x.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_movement_control__read_y(osdk_stream_t *io, osdk_movement_control_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_movement_control", "y", io);
    self->y.bits = (uint32_t)u;
    self->y.value = osdk_f32_from_bits(self->y.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_movement_control__read_z(osdk_stream_t *io, osdk_movement_control_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_movement_control", "z", io);
    self->z.bits = (uint32_t)u;
    self->z.value = osdk_f32_from_bits(self->z.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_movement_control__read_yaw(osdk_stream_t *io, osdk_movement_control_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_movement_control", "yaw", io);
    self->yaw.bits = (uint32_t)u;
    self->yaw.value = osdk_f32_from_bits(self->yaw.bits);
    (void)u;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_movement_control_parse(osdk_stream_t *io, osdk_movement_control_t *self, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_movement_control__zero(self);
    st = osdk_movement_control__read_control_mode(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_movement_control__read_x(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_movement_control__read_y(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_movement_control__read_z(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_movement_control__read_yaw(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_payload */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_payload__zero(osdk_payload_t *self)
{
    static const osdk_payload_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_payload__read_body(osdk_stream_t *io, osdk_payload_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
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
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_payload__read_trailing(osdk_stream_t *io, osdk_payload_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    osdk_read_bytes_eos(io, &self->trailing);
    if (!(((int64_t)(((int64_t)(self->trailing).len)) == (int64_t)(INT64_C(0))))) return osdk_fail(err, OSDK_ERR_LENGTH_MISMATCH, "osdk_payload", "trailing", io);
    (void)u;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_payload_parse(osdk_stream_t *io, osdk_payload_t *self, uint8_t cmd_set, uint8_t cmd_id, bool is_ack, uint8_t profile, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_payload__zero(self);
    self->cmd_set = cmd_set;
    self->cmd_id = cmd_id;
    self->is_ack = is_ack;
    self->profile = profile;
    st = osdk_payload__read_body(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_payload__read_trailing(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_payload::activation_ack_value */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_payload_activation_ack_value__zero(osdk_payload_activation_ack_value_t *self)
{
    static const osdk_payload_activation_ack_value_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_payload_activation_ack_value__read_ack_code(osdk_stream_t *io, osdk_payload_activation_ack_value_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::activation_ack_value", "ack_code", io);
    self->ack_code = (uint16_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_payload_activation_ack_value_parse(osdk_stream_t *io, osdk_payload_activation_ack_value_t *self, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_payload_activation_ack_value__zero(self);
    st = osdk_payload_activation_ack_value__read_ack_code(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_payload::activation_request */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_payload_activation_request__zero(osdk_payload_activation_request_t *self)
{
    static const osdk_payload_activation_request_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_payload_activation_request__read_app_id(osdk_stream_t *io, osdk_payload_activation_request_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::activation_request", "app_id", io);
    self->app_id = (uint32_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_payload_activation_request__read_api_level(osdk_stream_t *io, osdk_payload_activation_request_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::activation_request", "api_level", io);
    self->api_level = (uint32_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_payload_activation_request__read_sdk_version(osdk_stream_t *io, osdk_payload_activation_request_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::activation_request", "sdk_version", io);
    self->sdk_version = (uint32_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_payload_activation_request__read_bundle_id(osdk_stream_t *io, osdk_payload_activation_request_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    {
        int64_t n = INT64_C(32);
        if (n < 0) return osdk_fail(err, OSDK_ERR_UNDECODABLE, "osdk_payload::activation_request", "bundle_id", io);
        if (!osdk_read_bytes(io, (uint64_t)n, &self->bundle_id)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::activation_request", "bundle_id", io);
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_payload_activation_request_parse(osdk_stream_t *io, osdk_payload_activation_request_t *self, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_payload_activation_request__zero(self);
    st = osdk_payload_activation_request__read_app_id(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_payload_activation_request__read_api_level(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_payload_activation_request__read_sdk_version(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_payload_activation_request__read_bundle_id(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_payload::broadcast */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_payload_broadcast__zero(osdk_payload_broadcast_t *self)
{
    static const osdk_payload_broadcast_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_payload_broadcast__read_data(osdk_stream_t *io, osdk_payload_broadcast_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
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

osdk_status_t osdk_payload_broadcast_parse(osdk_stream_t *io, osdk_payload_broadcast_t *self, uint8_t profile, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_payload_broadcast__zero(self);
    self->profile = profile;
    st = osdk_payload_broadcast__read_data(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_payload::control_ack_value */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_payload_control_ack_value__zero(osdk_payload_control_ack_value_t *self)
{
    static const osdk_payload_control_ack_value_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_payload_control_ack_value__read_ack_code(osdk_stream_t *io, osdk_payload_control_ack_value_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::control_ack_value", "ack_code", io);
    self->ack_code = (uint16_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_payload_control_ack_value_parse(osdk_stream_t *io, osdk_payload_control_ack_value_t *self, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_payload_control_ack_value__zero(self);
    st = osdk_payload_control_ack_value__read_ack_code(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_payload::control_request */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_payload_control_request__zero(osdk_payload_control_request_t *self)
{
    static const osdk_payload_control_request_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_payload_control_request__read_request(osdk_stream_t *io, osdk_payload_control_request_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::control_request", "request", io);
    self->request = (uint8_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_payload_control_request_parse(osdk_stream_t *io, osdk_payload_control_request_t *self, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_payload_control_request__zero(self);
    st = osdk_payload_control_request__read_request(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_payload::frequency_ack_value */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_payload_frequency_ack_value__zero(osdk_payload_frequency_ack_value_t *self)
{
    static const osdk_payload_frequency_ack_value_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_payload_frequency_ack_value__read_ack_code(osdk_stream_t *io, osdk_payload_frequency_ack_value_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::frequency_ack_value", "ack_code", io);
    self->ack_code = (uint16_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_payload_frequency_ack_value_parse(osdk_stream_t *io, osdk_payload_frequency_ack_value_t *self, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_payload_frequency_ack_value__zero(self);
    st = osdk_payload_frequency_ack_value__read_ack_code(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_payload::frequency_request */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_payload_frequency_request__zero(osdk_payload_frequency_request_t *self)
{
    static const osdk_payload_frequency_request_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_payload_frequency_request__read_codes(osdk_stream_t *io, osdk_payload_frequency_request_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->codes_count = 16;
    /*@ loop invariant 0 <= i <= 16 && osdk_stream_ok(io);
        loop invariant osdk_stream_on(io, \at(io->data, Pre), \at(io->size, Pre));
        loop assigns i, u, *io, *self;
        loop variant 16 - i; */
    for (size_t i = 0; i < 16; i++) {
        if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::frequency_request", "codes", io);
        self->codes[i] = (uint8_t)u;
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_payload_frequency_request_parse(osdk_stream_t *io, osdk_payload_frequency_request_t *self, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_payload_frequency_request__zero(self);
    st = osdk_payload_frequency_request__read_codes(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_payload::lost_control */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_payload_lost_control__zero(osdk_payload_lost_control_t *self)
{
    static const osdk_payload_lost_control_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_payload_lost_control__read_reason(osdk_stream_t *io, osdk_payload_lost_control_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::lost_control", "reason", io);
    self->reason = (uint8_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_payload_lost_control_parse(osdk_stream_t *io, osdk_payload_lost_control_t *self, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_payload_lost_control__zero(self);
    st = osdk_payload_lost_control__read_reason(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_payload::lost_control_ack_value */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_payload_lost_control_ack_value__zero(osdk_payload_lost_control_ack_value_t *self)
{
    static const osdk_payload_lost_control_ack_value_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_payload_lost_control_ack_value__read_ack_code(osdk_stream_t *io, osdk_payload_lost_control_ack_value_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::lost_control_ack_value", "ack_code", io);
    self->ack_code = (uint16_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_payload_lost_control_ack_value_parse(osdk_stream_t *io, osdk_payload_lost_control_ack_value_t *self, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_payload_lost_control_ack_value__zero(self);
    st = osdk_payload_lost_control_ack_value__read_ack_code(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_payload::unknown_value */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_payload_unknown_value__zero(osdk_payload_unknown_value_t *self)
{
    static const osdk_payload_unknown_value_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_payload_unknown_value__read_raw(osdk_stream_t *io, osdk_payload_unknown_value_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    osdk_read_bytes_eos(io, &self->raw);
    (void)u;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_payload_unknown_value_parse(osdk_stream_t *io, osdk_payload_unknown_value_t *self, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_payload_unknown_value__zero(self);
    st = osdk_payload_unknown_value__read_raw(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_payload::version_ack_value */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_payload_version_ack_value__zero(osdk_payload_version_ack_value_t *self)
{
    static const osdk_payload_version_ack_value_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_payload_version_ack_value__read_ack_code(osdk_stream_t *io, osdk_payload_version_ack_value_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 2, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::version_ack_value", "ack_code", io);
    self->ack_code = (uint16_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_payload_version_ack_value__read_version_crc(osdk_stream_t *io, osdk_payload_version_ack_value_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 4, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::version_ack_value", "version_crc", io);
    self->version_crc = (uint32_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_payload_version_ack_value__read_version_id(osdk_stream_t *io, osdk_payload_version_ack_value_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    self->version_id_present = osdk_payload_version_ack_value__has_version_id(self);
    if (self->version_id_present) {
        {
            int64_t n = INT64_C(11);
            if (n < 0) return osdk_fail(err, OSDK_ERR_UNDECODABLE, "osdk_payload::version_ack_value", "version_id", io);
            if (!osdk_read_bytes(io, (uint64_t)n, &self->version_id)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::version_ack_value", "version_id", io);
        }
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_payload_version_ack_value__read_version_name(osdk_stream_t *io, osdk_payload_version_ack_value_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    {
        int64_t n = INT64_C(32);
        if (n < 0) return osdk_fail(err, OSDK_ERR_UNDECODABLE, "osdk_payload::version_ack_value", "version_name", io);
        if (!osdk_read_bytes(io, (uint64_t)n, &self->version_name)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::version_ack_value", "version_name", io);
    }
    (void)u;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_payload_version_ack_value_parse(osdk_stream_t *io, osdk_payload_version_ack_value_t *self, uint8_t profile, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_payload_version_ack_value__zero(self);
    self->profile = profile;
    st = osdk_payload_version_ack_value__read_ack_code(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_payload_version_ack_value__read_version_crc(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_payload_version_ack_value__read_version_id(io, self, err);
    if (st != OSDK_OK) return st;
    st = osdk_payload_version_ack_value__read_version_name(io, self, err);
    if (st != OSDK_OK) return st;
    return OSDK_OK;
}

/* osdk_payload::version_query */
/*@ requires \valid(self);
    assigns *self; */
static void osdk_payload_version_query__zero(osdk_payload_version_query_t *self)
{
    static const osdk_payload_version_query_t zero;
    *self = zero;
}

/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
static osdk_status_t osdk_payload_version_query__read_arbitrary(osdk_stream_t *io, osdk_payload_version_query_t *self, osdk_error_t *err)
{
    uint64_t u = 0;
    if (!osdk_read_uint(io, 1, 0, &u)) return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, "osdk_payload::version_query", "arbitrary", io);
    self->arbitrary = (uint8_t)u;
    (void)u;
    (void)err;
    return OSDK_OK;
}

osdk_status_t osdk_payload_version_query_parse(osdk_stream_t *io, osdk_payload_version_query_t *self, osdk_error_t *err)
{
    osdk_status_t st;
    osdk_payload_version_query__zero(self);
    st = osdk_payload_version_query__read_arbitrary(io, self, err);
    if (st != OSDK_OK) return st;
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


