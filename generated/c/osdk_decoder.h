/* Generated from spec/ by tools/cgen/generate.py. Do not edit. */
/*
 * osdk_decoder.h - C99 decoder of the DJI Onboard SDK OPEN protocol,
 * one struct and one parse function per type of the spec's .ksy files.
 *
 * Guarantees: no heap (nothing here calls malloc), no dependency beyond
 * libc, every read bounds-checked against the stream it reads from. A
 * parse fills a caller-supplied struct; byte fields (osdk_bytes_t) point
 * into the caller's buffer, which must outlive the struct. Failures return
 * an osdk_status_t (the error classes of docs/VALUE-MODEL.md) and, when
 * err is not NULL, name the ksy type and field that failed and the
 * absolute byte offset where the stream stood.
 */
#ifndef OSDK_DECODER_H
#define OSDK_DECODER_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---- error classes ---------------------------------------------------------- */

typedef enum {
    OSDK_OK = 0,
    OSDK_ERR_BAD_SOF = 1,
    OSDK_ERR_BAD_CRC16 = 2,
    OSDK_ERR_BAD_VERSION = 3,
    OSDK_ERR_RESERVED_BITS = 4,
    OSDK_ERR_IMPOSSIBLE_LENGTH = 5,
    OSDK_ERR_BAD_ENCRYPTION = 6,
    OSDK_ERR_BAD_SESSION = 7,
    OSDK_ERR_BAD_CRC32 = 8,
    OSDK_ERR_TRUNCATED_FRAME = 9,
    OSDK_ERR_TRUNCATED_PAYLOAD = 10,
    OSDK_ERR_LENGTH_MISMATCH = 11,
    OSDK_ERR_UNDECODABLE = 12,
    OSDK_ERR_UNDEFINED_MODE = 13,
    OSDK_ERR_OUT_OF_RANGE = 14,
    OSDK_STATUS_COUNT_ = 15
} osdk_status_t;

/* The error class as docs/VALUE-MODEL.md spells it ("ok" for OSDK_OK). */
/*@ assigns \nothing; */
const char *osdk_status_name(osdk_status_t status);

typedef struct {
    osdk_status_t status;
    const char *type;   /* ksy type whose read failed, e.g. "osdk_frame" */
    const char *field;  /* ksy field id, e.g. "enc" */
    size_t offset;      /* absolute offset in the decoded buffer */
} osdk_error_t;

/*@ requires \valid(err);
    assigns *err; */
void osdk_error_clear(osdk_error_t *err);

/* ---- values ------------------------------------------------------------------------ */

/* Raw bytes: a view into the caller's buffer. */
typedef struct {
    const uint8_t *ptr;
    size_t len;
} osdk_bytes_t;

/* Floats keep their IEEE bits (normative: NaN payloads, -0.0) and the value. */
typedef struct {
    uint32_t bits;
    float value;
} osdk_f32_t;

typedef struct {
    uint64_t bits;
    double value;
} osdk_f64_t;

/*@ assigns \nothing; */
float osdk_f32_from_bits(uint32_t bits);
/*@ assigns \nothing; */
double osdk_f64_from_bits(uint64_t bits);

/* ---- streams ------------------------------------------------------------------------- */

/* A bounds-checked reader over data[0..size); bit reads are little-endian
 * (bit 0 first), any byte-aligned read drops unread bits, as Kaitai does. */
typedef struct {
    const uint8_t *data;
    size_t size;
    size_t pos;
    size_t base;        /* absolute offset of data[0] */
    uint64_t bitbuf;
    unsigned bitcount;
} osdk_stream_t;

/* data may be NULL (then size is taken as 0): the stream then reads from a
 * static empty buffer, so that no decoder ever does arithmetic on a null
 * pointer (NULL + 0 is undefined in C99, 6.5.6). */
/* The comments that open with an @ are ACSL contracts: what `make prove`
 * proves the functions do, and what they may assume (docs/VERIFICATION.md).
 * A stream is fit to read when its bytes are readable and its position is
 * within them; a parse leaves it on the same bytes (said of the pointer and
 * the size alone: whether the bytes are readable is the caller's to know,
 * and the provers lose it where a parse function's own substream ends);
 * byte fields point to readable bytes. */
/*@ predicate osdk_stream_ok(osdk_stream_t *io) =
      \valid(io) && io->pos <= io->size &&
      \valid_read(io->data + (0 .. io->size - 1)) &&
      \object_pointer(io->data) && \object_pointer(io->data + io->size);
    predicate osdk_stream_on(osdk_stream_t *io, uint8_t *data, integer size) =
      io->data == data && io->size == size && io->pos <= io->size;
    predicate osdk_bytes_ok(osdk_bytes_t *b) =
      \valid_read(b->ptr + (0 .. b->len - 1)) && \object_pointer(b->ptr) && \object_pointer(b->ptr + b->len);
*/
/*@ requires \valid(io);
    requires data == \null || size == 0 || \valid_read(data + (0 .. size - 1));
    assigns *io;
    ensures osdk_stream_ok(io); */
void osdk_stream_init(osdk_stream_t *io, const uint8_t *data, size_t size);
/*@ requires osdk_stream_ok(io) && \valid(out) && \separated(io, out);
    assigns *io, *out;
    ensures osdk_stream_ok(io) && osdk_stream_on(io, \old(io->data), \old(io->size)); */
bool osdk_read_uint(osdk_stream_t *io, unsigned nbytes, int big_endian, uint64_t *out);
/*@ requires osdk_stream_ok(io) && \valid(out) && \separated(io, out);
    assigns *io, *out;
    ensures osdk_stream_ok(io) && osdk_stream_on(io, \old(io->data), \old(io->size)); */
bool osdk_read_bits_le(osdk_stream_t *io, unsigned nbits, uint64_t *out);
/*@ requires osdk_stream_ok(io) && \valid(out) && \separated(io, out);
    assigns *io, *out;
    ensures osdk_stream_ok(io) && osdk_stream_on(io, \old(io->data), \old(io->size));
    ensures \result ==> osdk_bytes_ok(out) && out->len == n; */
bool osdk_read_bytes(osdk_stream_t *io, uint64_t n, osdk_bytes_t *out);
/*@ requires osdk_stream_ok(io) && \valid(out) && \separated(io, out);
    assigns *io, *out;
    ensures osdk_stream_ok(io) && osdk_stream_on(io, \old(io->data), \old(io->size)) && osdk_bytes_ok(out); */
void osdk_read_bytes_eos(osdk_stream_t *io, osdk_bytes_t *out);
/*@ requires osdk_stream_ok(io) && \valid(sub) && \separated(io, sub);
    assigns *io, *sub;
    ensures osdk_stream_ok(io) && osdk_stream_on(io, \old(io->data), \old(io->size));
    ensures \result ==> osdk_stream_ok(sub); */
bool osdk_substream(osdk_stream_t *io, uint64_t n, osdk_stream_t *sub);
/*@ requires osdk_stream_ok(io) && \valid(sub) && \separated(io, sub);
    assigns *io, *sub;
    ensures osdk_stream_ok(io) && osdk_stream_on(io, \old(io->data), \old(io->size)) && osdk_stream_ok(sub); */
void osdk_substream_eos(osdk_stream_t *io, osdk_stream_t *sub);
/* A reader over the same bytes as io, at pos (for `pos` instances). */
/*@ requires osdk_stream_ok((osdk_stream_t *)io) && \valid(at) && \separated(io, at);
    assigns *at;
    ensures \result ==> osdk_stream_ok(at); */
bool osdk_stream_at(const osdk_stream_t *io, uint64_t pos, osdk_stream_t *at);
/* The two's complement value of the low `bits` bits of value; bits is the
 * width of a Kaitai signed integer, 8, 16 or 32, and any other is taken as 64. */
/*@ assigns \nothing; */
int64_t osdk_sign_extend(uint64_t value, unsigned bits);
/* Bits [bit_offset, bit_offset + nbits) of buf, bit 0 of byte 0 first. */
/*@ requires nbits <= 64 && bit_offset <= 65536;
    requires nbits == 0 || \valid_read(buf + (0 .. (bit_offset + nbits - 1) / 8));
    assigns \nothing; */
uint64_t osdk_peek_bits_le(const uint8_t *buf, unsigned bit_offset, unsigned nbits);
/*@ requires err == \null || \valid(err);
    requires io == \null || \valid_read(io);
    assigns *err;
    ensures \result == status; */
osdk_status_t osdk_fail(osdk_error_t *err, osdk_status_t status, const char *type, const char *field,
                        const osdk_stream_t *io);

/* Kaitai integer division and modulo (floor semantics), defined for every
 * pair of arguments: a divisor of 0 gives 0, and INT64_MIN / -1, whose
 * quotient 2^63 has no int64_t, gives INT64_MIN (two's complement
 * wrap-around); C leaves a / b and a % b undefined there. Any remainder
 * by -1 is 0. */
/*@ assigns \nothing; */
static inline int64_t osdk_kdiv(int64_t a, int64_t b)
{
    int64_t q;
    if (b == 0) return 0;
    if (b == -1) return a == INT64_MIN ? INT64_MIN : -a;
    q = a / b;
    if ((a % b != 0) && ((a < 0) != (b < 0))) q--;
    return q;
}

/*@ assigns \nothing; */
static inline int64_t osdk_kmod(int64_t a, int64_t b)
{
    int64_t r;
    if (b == 0 || b == -1) return 0;
    r = a % b;
    if (r != 0 && ((r < 0) != (b < 0))) r += b;
    return r;
}

/* ---- enums --------------------------------------------------------------------------- */

/* enum osdk_broadcast_items::control_device */
typedef enum {
    OSDK_BROADCAST_ITEMS_CONTROL_DEVICE_RC = 0,
    OSDK_BROADCAST_ITEMS_CONTROL_DEVICE_MOBILE_DEVICE = 1,
    OSDK_BROADCAST_ITEMS_CONTROL_DEVICE_ONBOARD_DEVICE = 2
} osdk_broadcast_items_control_device_t;
/* The spec's name of a control_device value, or NULL when it has none. */
/*@ assigns \nothing; */
const char *osdk_broadcast_items_control_device_name(int64_t value);

/* enum osdk_broadcast_items::cur_mov_control_mode */
typedef enum {
    OSDK_BROADCAST_ITEMS_CUR_MOV_CONTROL_MODE_ATTI_STOP = 0,
    OSDK_BROADCAST_ITEMS_CUR_MOV_CONTROL_MODE_HORIZ_ANG_VERT_VEL_YAW_ANG = 1,
    OSDK_BROADCAST_ITEMS_CUR_MOV_CONTROL_MODE_HORIZ_ANG_VERT_VEL_YAW_RATE = 2,
    OSDK_BROADCAST_ITEMS_CUR_MOV_CONTROL_MODE_HORIZ_VEL_VERT_VEL_YAW_ANG = 3,
    OSDK_BROADCAST_ITEMS_CUR_MOV_CONTROL_MODE_HORIZ_VEL_VERT_VEL_YAW_RATE = 4,
    OSDK_BROADCAST_ITEMS_CUR_MOV_CONTROL_MODE_HORIZ_POS_VERT_VEL_YAW_ANG = 5,
    OSDK_BROADCAST_ITEMS_CUR_MOV_CONTROL_MODE_HORIZ_POS_VERT_VEL_YAW_RATE = 6,
    OSDK_BROADCAST_ITEMS_CUR_MOV_CONTROL_MODE_HORIZ_ANG_VERT_POS_YAW_ANG = 7,
    OSDK_BROADCAST_ITEMS_CUR_MOV_CONTROL_MODE_HORIZ_ANG_VERT_POS_YAW_RATE = 8,
    OSDK_BROADCAST_ITEMS_CUR_MOV_CONTROL_MODE_HORIZ_VEL_VERT_POS_YAW_ANG = 9,
    OSDK_BROADCAST_ITEMS_CUR_MOV_CONTROL_MODE_HORIZ_VEL_VERT_POS_YAW_RATE = 10,
    OSDK_BROADCAST_ITEMS_CUR_MOV_CONTROL_MODE_HORIZ_POS_VERT_POS_YAW_ANG = 11,
    OSDK_BROADCAST_ITEMS_CUR_MOV_CONTROL_MODE_HORIZ_POS_VERT_POS_YAW_RATE = 12,
    OSDK_BROADCAST_ITEMS_CUR_MOV_CONTROL_MODE_HORIZ_ANG_VERT_THR_YAW_ANG = 13,
    OSDK_BROADCAST_ITEMS_CUR_MOV_CONTROL_MODE_HORIZ_ANG_VERT_THR_YAW_RATE = 14,
    OSDK_BROADCAST_ITEMS_CUR_MOV_CONTROL_MODE_HORIZ_VEL_VERT_THR_YAW_ANG = 15,
    OSDK_BROADCAST_ITEMS_CUR_MOV_CONTROL_MODE_HORIZ_VEL_VERT_THR_YAW_RATE = 16,
    OSDK_BROADCAST_ITEMS_CUR_MOV_CONTROL_MODE_HORIZ_POS_VERT_THR_YAW_ANG = 17,
    OSDK_BROADCAST_ITEMS_CUR_MOV_CONTROL_MODE_HORIZ_POS_VERT_THR_YAW_RATE = 18,
    OSDK_BROADCAST_ITEMS_CUR_MOV_CONTROL_MODE_GPS_ATTI_CTRL_CL_YAW_RATE = 97,
    OSDK_BROADCAST_ITEMS_CUR_MOV_CONTROL_MODE_GPS_ATTI_CTRL_YAW_RATE = 98,
    OSDK_BROADCAST_ITEMS_CUR_MOV_CONTROL_MODE_ATTI_CTRL_YAW_RATE = 99,
    OSDK_BROADCAST_ITEMS_CUR_MOV_CONTROL_MODE_ATTI_CTRL_STOP = 100
} osdk_broadcast_items_cur_mov_control_mode_t;
/* The spec's name of a cur_mov_control_mode value, or NULL when it has none. */
/*@ assigns \nothing; */
const char *osdk_broadcast_items_cur_mov_control_mode_name(int64_t value);

/* enum osdk_control_mode::horizontal_frame */
typedef enum {
    OSDK_CONTROL_MODE_HORIZONTAL_FRAME_GROUND = 0,
    OSDK_CONTROL_MODE_HORIZONTAL_FRAME_BODY = 1
} osdk_control_mode_horizontal_frame_t;
/* The spec's name of a horizontal_frame value, or NULL when it has none. */
/*@ assigns \nothing; */
const char *osdk_control_mode_horizontal_frame_name(int64_t value);

/* enum osdk_control_mode::horizontal_logic */
typedef enum {
    OSDK_CONTROL_MODE_HORIZONTAL_LOGIC_HORI_ATTI_TILT_ANG = 0,
    OSDK_CONTROL_MODE_HORIZONTAL_LOGIC_HORI_VEL = 1,
    OSDK_CONTROL_MODE_HORIZONTAL_LOGIC_HORI_POS = 2
} osdk_control_mode_horizontal_logic_t;
/* The spec's name of a horizontal_logic value, or NULL when it has none. */
/*@ assigns \nothing; */
const char *osdk_control_mode_horizontal_logic_name(int64_t value);

/* enum osdk_control_mode::stable_mode */
typedef enum {
    OSDK_CONTROL_MODE_STABLE_MODE_NON_STABLE = 0,
    OSDK_CONTROL_MODE_STABLE_MODE_STABLE = 1
} osdk_control_mode_stable_mode_t;
/* The spec's name of a stable_mode value, or NULL when it has none. */
/*@ assigns \nothing; */
const char *osdk_control_mode_stable_mode_name(int64_t value);

/* enum osdk_control_mode::vertical_logic */
typedef enum {
    OSDK_CONTROL_MODE_VERTICAL_LOGIC_VERT_VEL = 0,
    OSDK_CONTROL_MODE_VERTICAL_LOGIC_VERT_POS = 1,
    OSDK_CONTROL_MODE_VERTICAL_LOGIC_VERT_THRUST = 2
} osdk_control_mode_vertical_logic_t;
/* The spec's name of a vertical_logic value, or NULL when it has none. */
/*@ assigns \nothing; */
const char *osdk_control_mode_vertical_logic_name(int64_t value);

/* enum osdk_control_mode::yaw_logic */
typedef enum {
    OSDK_CONTROL_MODE_YAW_LOGIC_YAW_ANG = 0,
    OSDK_CONTROL_MODE_YAW_LOGIC_YAW_RATE = 1
} osdk_control_mode_yaw_logic_t;
/* The spec's name of a yaw_logic value, or NULL when it has none. */
/*@ assigns \nothing; */
const char *osdk_control_mode_yaw_logic_name(int64_t value);

/* enum osdk_frame::command_set */
typedef enum {
    OSDK_FRAME_COMMAND_SET_ACTIVATION = 0,
    OSDK_FRAME_COMMAND_SET_CONTROL = 1,
    OSDK_FRAME_COMMAND_SET_PUSH = 2
} osdk_frame_command_set_t;
/* The spec's name of a command_set value, or NULL when it has none. */
/*@ assigns \nothing; */
const char *osdk_frame_command_set_name(int64_t value);

/* enum osdk_frame::encryption */
typedef enum {
    OSDK_FRAME_ENCRYPTION_PLAIN = 0,
    OSDK_FRAME_ENCRYPTION_AES256 = 1
} osdk_frame_encryption_t;
/* The spec's name of a encryption value, or NULL when it has none. */
/*@ assigns \nothing; */
const char *osdk_frame_encryption_name(int64_t value);

/* enum osdk_payload::activation_result */
typedef enum {
    OSDK_PAYLOAD_ACTIVATION_RESULT_SUCCESS = 0,
    OSDK_PAYLOAD_ACTIVATION_RESULT_INVALID_PARAMETERS = 1,
    OSDK_PAYLOAD_ACTIVATION_RESULT_CANNOT_RECOGNIZE_ENCRYPTED_PACKAGE = 2,
    OSDK_PAYLOAD_ACTIVATION_RESULT_NEW_APP_ID = 3,
    OSDK_PAYLOAD_ACTIVATION_RESULT_NO_RESPONSE_FROM_APP = 4,
    OSDK_PAYLOAD_ACTIVATION_RESULT_NO_INTERNET = 5,
    OSDK_PAYLOAD_ACTIVATION_RESULT_SERVER_REJECTED = 6,
    OSDK_PAYLOAD_ACTIVATION_RESULT_LEVEL_INSUFFICIENT = 7,
    OSDK_PAYLOAD_ACTIVATION_RESULT_WRONG_SDK_VERSION = 8
} osdk_payload_activation_result_t;
/* The spec's name of a activation_result value, or NULL when it has none. */
/*@ assigns \nothing; */
const char *osdk_payload_activation_result_name(int64_t value);

/* enum osdk_payload::control_ack */
typedef enum {
    OSDK_PAYLOAD_CONTROL_ACK_RC_NOT_IN_F_MODE = 0,
    OSDK_PAYLOAD_CONTROL_ACK_RELEASED = 1,
    OSDK_PAYLOAD_CONTROL_ACK_OBTAINED = 2,
    OSDK_PAYLOAD_CONTROL_ACK_OBTAIN_IN_PROGRESS = 3,
    OSDK_PAYLOAD_CONTROL_ACK_RELEASE_IN_PROGRESS = 4,
    OSDK_PAYLOAD_CONTROL_ACK_IN_IOC_MODE = 201
} osdk_payload_control_ack_t;
/* The spec's name of a control_ack value, or NULL when it has none. */
/*@ assigns \nothing; */
const char *osdk_payload_control_ack_name(int64_t value);

/* enum osdk_payload::control_request_code */
typedef enum {
    OSDK_PAYLOAD_CONTROL_REQUEST_CODE_RELEASE = 0,
    OSDK_PAYLOAD_CONTROL_REQUEST_CODE_OBTAIN = 1
} osdk_payload_control_request_code_t;
/* The spec's name of a control_request_code value, or NULL when it has none. */
/*@ assigns \nothing; */
const char *osdk_payload_control_request_code_name(int64_t value);

/* enum osdk_payload::frequency_ack */
typedef enum {
    OSDK_PAYLOAD_FREQUENCY_ACK_SUCCESS = 0,
    OSDK_PAYLOAD_FREQUENCY_ACK_PARAMETER_ERROR = 1
} osdk_payload_frequency_ack_t;
/* The spec's name of a frequency_ack value, or NULL when it has none. */
/*@ assigns \nothing; */
const char *osdk_payload_frequency_ack_name(int64_t value);

/* enum osdk_payload::frequency_code */
typedef enum {
    OSDK_PAYLOAD_FREQUENCY_CODE_HZ_0 = 0,
    OSDK_PAYLOAD_FREQUENCY_CODE_HZ_1 = 1,
    OSDK_PAYLOAD_FREQUENCY_CODE_HZ_10 = 2,
    OSDK_PAYLOAD_FREQUENCY_CODE_HZ_50 = 3,
    OSDK_PAYLOAD_FREQUENCY_CODE_HZ_100 = 4,
    OSDK_PAYLOAD_FREQUENCY_CODE_KEEP = 5,
    OSDK_PAYLOAD_FREQUENCY_CODE_HZ_200 = 6,
    OSDK_PAYLOAD_FREQUENCY_CODE_HZ_400 = 7
} osdk_payload_frequency_code_t;
/* The spec's name of a frequency_code value, or NULL when it has none. */
/*@ assigns \nothing; */
const char *osdk_payload_frequency_code_name(int64_t value);

/* enum osdk_payload::profile */
typedef enum {
    OSDK_PAYLOAD_PROFILE_M100_FW2_3 = 0,
    OSDK_PAYLOAD_PROFILE_M100_FW3_1 = 1,
    OSDK_PAYLOAD_PROFILE_A3_FW3_1 = 2
} osdk_payload_profile_t;
/* The spec's name of a profile value, or NULL when it has none. */
/*@ assigns \nothing; */
const char *osdk_payload_profile_name(int64_t value);

/* enum osdk_payload::version_ack */
typedef enum {
    OSDK_PAYLOAD_VERSION_ACK_ACTIVATED = 0,
    OSDK_PAYLOAD_VERSION_ACK_NOT_ACTIVATED = 65281
} osdk_payload_version_ack_t;
/* The spec's name of a version_ack value, or NULL when it has none. */
/*@ assigns \nothing; */
const char *osdk_payload_version_ack_name(int64_t value);


/* ---- types (one per ksy type) -------------------------------------------------------- */

/* osdk_broadcast_items::time_stamp */
typedef struct osdk_broadcast_items_time_stamp {
    bool has_ns_and_sync; /* param */
    uint32_t time;
    uint32_t nano_time; /* if has_ns_and_sync */
    bool nano_time_present;
    uint8_t sync_flag; /* if has_ns_and_sync */
    bool sync_flag_present;
} osdk_broadcast_items_time_stamp_t;

/* osdk_broadcast_items::quaternion */
typedef struct osdk_broadcast_items_quaternion {
    osdk_f32_t q0;
    osdk_f32_t q1;
    osdk_f32_t q2;
    osdk_f32_t q3;
} osdk_broadcast_items_quaternion_t;

/* osdk_broadcast_items::vector3f */
typedef struct osdk_broadcast_items_vector3f {
    osdk_f32_t x;
    osdk_f32_t y;
    osdk_f32_t z;
} osdk_broadcast_items_vector3f_t;

/* osdk_broadcast_items::velocity */
typedef struct osdk_broadcast_items_velocity {
    osdk_f32_t x;
    osdk_f32_t y;
    osdk_f32_t z;
    bool data_valid; /* b1 */
    uint8_t sensor_id; /* b4 */
    uint8_t reserved; /* b3 */
} osdk_broadcast_items_velocity_t;

/* osdk_broadcast_items::position */
typedef struct osdk_broadcast_items_position {
    osdk_f64_t latitude;
    osdk_f64_t longitude;
    osdk_f32_t altitude;
    osdk_f32_t height;
    uint8_t gps_health;
} osdk_broadcast_items_position_t;

/* osdk_broadcast_items::gps_detail */
typedef struct osdk_broadcast_items_gps_detail {
    uint32_t date;
    uint32_t time;
    int32_t longitude;
    int32_t latitude;
    int32_t height_msl;
    osdk_f32_t vel_n;
    osdk_f32_t vel_e;
    osdk_f32_t vel_d;
} osdk_broadcast_items_gps_detail_t;

/* osdk_broadcast_items::rtk_detail */
typedef struct osdk_broadcast_items_rtk_detail {
    uint32_t date;
    uint32_t time;
    osdk_f64_t longitude;
    osdk_f64_t latitude;
    osdk_f32_t height_msl;
    osdk_f32_t vel_n;
    osdk_f32_t vel_e;
    osdk_f32_t vel_d;
    int16_t yaw;
    uint8_t position_flag;
    uint8_t yaw_flag;
} osdk_broadcast_items_rtk_detail_t;

/* osdk_broadcast_items::magnetometer */
typedef struct osdk_broadcast_items_magnetometer {
    int16_t x;
    int16_t y;
    int16_t z;
} osdk_broadcast_items_magnetometer_t;

/* osdk_broadcast_items::rc */
typedef struct osdk_broadcast_items_rc {
    int16_t roll;
    int16_t pitch;
    int16_t yaw;
    int16_t throttle;
    int16_t mode;
    int16_t gear;
} osdk_broadcast_items_rc_t;

/* osdk_broadcast_items::gimbal_limit */
typedef struct osdk_broadcast_items_gimbal_limit {
    bool pitch_limit; /* b1 */
    bool roll_limit; /* b1 */
    bool yaw_limit; /* b1 */
    uint8_t reserved; /* b5 */
} osdk_broadcast_items_gimbal_limit_t;

/* osdk_broadcast_items::gimbal */
typedef struct osdk_broadcast_items_gimbal {
    bool has_limit_byte; /* param */
    osdk_f32_t roll;
    osdk_f32_t pitch;
    osdk_f32_t yaw;
    osdk_broadcast_items_gimbal_limit_t limit; /* if has_limit_byte */
    bool limit_present;
} osdk_broadcast_items_gimbal_t;

/* osdk_broadcast_items::control_info */
typedef struct osdk_broadcast_items_control_info {
    bool has_mode; /* param */
    uint8_t cur_mov_control_mode; /* enum osdk_broadcast_items.cur_mov_control_mode; if has_mode */
    bool cur_mov_control_mode_present;
    uint8_t control_device; /* enum osdk_broadcast_items.control_device; b3 */
    bool onboard_requested; /* b1 */
    bool virtual_rc; /* b1 */
    uint8_t reserved; /* b3 */
} osdk_broadcast_items_control_info_t;

/* osdk_broadcast_a3_fw3_1 */
typedef struct osdk_broadcast_a3_fw3_1 {
    bool has_time_stamp; /* b1 */
    bool has_quaternion; /* b1 */
    bool has_acceleration; /* b1 */
    bool has_velocity; /* b1 */
    bool has_angular_rate; /* b1 */
    bool has_position; /* b1 */
    bool has_gps_detail; /* b1 */
    bool has_rtk_detail; /* b1 */
    bool has_magnetometer; /* b1 */
    bool has_rc; /* b1 */
    bool has_gimbal; /* b1 */
    bool has_flight_status; /* b1 */
    bool has_battery; /* b1 */
    bool has_control_info; /* b1 */
    uint8_t reserved_flags; /* b2 */
    osdk_broadcast_items_time_stamp_t time_stamp; /* if has_time_stamp */
    bool time_stamp_present;
    osdk_broadcast_items_quaternion_t quaternion; /* if has_quaternion */
    bool quaternion_present;
    osdk_broadcast_items_vector3f_t acceleration; /* if has_acceleration */
    bool acceleration_present;
    osdk_broadcast_items_velocity_t velocity; /* if has_velocity */
    bool velocity_present;
    osdk_broadcast_items_vector3f_t angular_rate; /* if has_angular_rate */
    bool angular_rate_present;
    osdk_broadcast_items_position_t position; /* if has_position */
    bool position_present;
    osdk_broadcast_items_gps_detail_t gps_detail; /* if has_gps_detail */
    bool gps_detail_present;
    osdk_broadcast_items_rtk_detail_t rtk_detail; /* if has_rtk_detail */
    bool rtk_detail_present;
    osdk_broadcast_items_magnetometer_t magnetometer; /* if has_magnetometer */
    bool magnetometer_present;
    osdk_broadcast_items_rc_t rc; /* if has_rc */
    bool rc_present;
    osdk_broadcast_items_gimbal_t gimbal; /* if has_gimbal */
    bool gimbal_present;
    uint8_t flight_status; /* if has_flight_status */
    bool flight_status_present;
    uint8_t battery; /* if has_battery */
    bool battery_present;
    osdk_broadcast_items_control_info_t control_info; /* if has_control_info */
    bool control_info_present;
    osdk_bytes_t trailing;
} osdk_broadcast_a3_fw3_1_t;

/* osdk_broadcast_m100_fw2_3 */
typedef struct osdk_broadcast_m100_fw2_3 {
    bool has_time_stamp; /* b1 */
    bool has_quaternion; /* b1 */
    bool has_acceleration; /* b1 */
    bool has_velocity; /* b1 */
    bool has_angular_rate; /* b1 */
    bool has_position; /* b1 */
    bool has_magnetometer; /* b1 */
    bool has_rc; /* b1 */
    bool has_gimbal; /* b1 */
    bool has_flight_status; /* b1 */
    bool has_battery; /* b1 */
    bool has_control_info; /* b1 */
    uint8_t reserved_flags; /* b4 */
    osdk_broadcast_items_time_stamp_t time_stamp; /* if has_time_stamp */
    bool time_stamp_present;
    osdk_broadcast_items_quaternion_t quaternion; /* if has_quaternion */
    bool quaternion_present;
    osdk_broadcast_items_vector3f_t acceleration; /* if has_acceleration */
    bool acceleration_present;
    osdk_broadcast_items_velocity_t velocity; /* if has_velocity */
    bool velocity_present;
    osdk_broadcast_items_vector3f_t angular_rate; /* if has_angular_rate */
    bool angular_rate_present;
    osdk_broadcast_items_position_t position; /* if has_position */
    bool position_present;
    osdk_broadcast_items_magnetometer_t magnetometer; /* if has_magnetometer */
    bool magnetometer_present;
    osdk_broadcast_items_rc_t rc; /* if has_rc */
    bool rc_present;
    osdk_broadcast_items_gimbal_t gimbal; /* if has_gimbal */
    bool gimbal_present;
    uint8_t flight_status; /* if has_flight_status */
    bool flight_status_present;
    uint8_t battery; /* if has_battery */
    bool battery_present;
    osdk_broadcast_items_control_info_t control_info; /* if has_control_info */
    bool control_info_present;
    osdk_bytes_t trailing;
} osdk_broadcast_m100_fw2_3_t;

/* osdk_broadcast_m100_fw3_1 */
typedef struct osdk_broadcast_m100_fw3_1 {
    bool has_time_stamp; /* b1 */
    bool has_quaternion; /* b1 */
    bool has_acceleration; /* b1 */
    bool has_velocity; /* b1 */
    bool has_angular_rate; /* b1 */
    bool has_position; /* b1 */
    bool has_magnetometer; /* b1 */
    bool has_rc; /* b1 */
    bool has_gimbal; /* b1 */
    bool has_flight_status; /* b1 */
    bool has_battery; /* b1 */
    bool has_control_info; /* b1 */
    uint8_t reserved_flags; /* b4 */
    osdk_broadcast_items_time_stamp_t time_stamp; /* if has_time_stamp */
    bool time_stamp_present;
    osdk_broadcast_items_quaternion_t quaternion; /* if has_quaternion */
    bool quaternion_present;
    osdk_broadcast_items_vector3f_t acceleration; /* if has_acceleration */
    bool acceleration_present;
    osdk_broadcast_items_velocity_t velocity; /* if has_velocity */
    bool velocity_present;
    osdk_broadcast_items_vector3f_t angular_rate; /* if has_angular_rate */
    bool angular_rate_present;
    osdk_broadcast_items_position_t position; /* if has_position */
    bool position_present;
    osdk_broadcast_items_magnetometer_t magnetometer; /* if has_magnetometer */
    bool magnetometer_present;
    osdk_broadcast_items_rc_t rc; /* if has_rc */
    bool rc_present;
    osdk_broadcast_items_gimbal_t gimbal; /* if has_gimbal */
    bool gimbal_present;
    uint8_t flight_status; /* if has_flight_status */
    bool flight_status_present;
    uint8_t battery; /* if has_battery */
    bool battery_present;
    osdk_broadcast_items_control_info_t control_info; /* if has_control_info */
    bool control_info_present;
    osdk_bytes_t trailing;
} osdk_broadcast_m100_fw3_1_t;

/* osdk_control_mode */
typedef struct osdk_control_mode {
    uint8_t stable_mode; /* enum osdk_control_mode.stable_mode; b1 */
    uint8_t horizontal_frame; /* enum osdk_control_mode.horizontal_frame; b2 */
    uint8_t yaw_logic; /* enum osdk_control_mode.yaw_logic; b1 */
    uint8_t vertical_logic; /* enum osdk_control_mode.vertical_logic; b2 */
    uint8_t horizontal_logic; /* enum osdk_control_mode.horizontal_logic; b2 */
} osdk_control_mode_t;

/* osdk_payload::version_query */
typedef struct osdk_payload_version_query {
    uint8_t arbitrary;
} osdk_payload_version_query_t;

/* osdk_payload::activation_request */
typedef struct osdk_payload_activation_request {
    uint32_t app_id;
    uint32_t api_level;
    uint32_t sdk_version;
    osdk_bytes_t bundle_id;
} osdk_payload_activation_request_t;

/* osdk_payload::frequency_request */
typedef struct osdk_payload_frequency_request {
    uint8_t codes[16]; /* enum osdk_payload.frequency_code */
    size_t codes_count;
} osdk_payload_frequency_request_t;

/* osdk_payload::control_request */
typedef struct osdk_payload_control_request {
    uint8_t request; /* enum osdk_payload.control_request_code */
} osdk_payload_control_request_t;

/* osdk_movement_control */
typedef struct osdk_movement_control {
    osdk_control_mode_t control_mode;
    osdk_f32_t x;
    osdk_f32_t y;
    osdk_f32_t z;
    osdk_f32_t yaw;
} osdk_movement_control_t;

/* osdk_payload::broadcast.data: which case was read */
enum {
    OSDK_PAYLOAD_BROADCAST_DATA_NONE = 0,
    OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW2_3 = 1,
    OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_M100_FW3_1 = 2,
    OSDK_PAYLOAD_BROADCAST_DATA_OSDK_BROADCAST_A3_FW3_1 = 3
};
typedef struct {
    int tag;
    union {
        osdk_broadcast_m100_fw2_3_t osdk_broadcast_m100_fw2_3;
        osdk_broadcast_m100_fw3_1_t osdk_broadcast_m100_fw3_1;
        osdk_broadcast_a3_fw3_1_t osdk_broadcast_a3_fw3_1;
    } u;
} osdk_payload_broadcast_data_switch_t;

/* osdk_payload::broadcast */
typedef struct osdk_payload_broadcast {
    uint8_t profile; /* param, enum osdk_payload.profile */
    osdk_payload_broadcast_data_switch_t data;
} osdk_payload_broadcast_t;

/* osdk_payload::lost_control */
typedef struct osdk_payload_lost_control {
    uint8_t reason;
} osdk_payload_lost_control_t;

/* osdk_payload::version_ack_value */
typedef struct osdk_payload_version_ack_value {
    uint8_t profile; /* param, enum osdk_payload.profile */
    uint16_t ack_code; /* enum osdk_payload.version_ack */
    uint32_t version_crc;
    osdk_bytes_t version_id; /* if has_version_id */
    bool version_id_present;
    osdk_bytes_t version_name;
} osdk_payload_version_ack_value_t;

/* osdk_payload::activation_ack_value */
typedef struct osdk_payload_activation_ack_value {
    uint16_t ack_code; /* enum osdk_payload.activation_result */
} osdk_payload_activation_ack_value_t;

/* osdk_payload::frequency_ack_value */
typedef struct osdk_payload_frequency_ack_value {
    uint16_t ack_code; /* enum osdk_payload.frequency_ack */
} osdk_payload_frequency_ack_value_t;

/* osdk_payload::control_ack_value */
typedef struct osdk_payload_control_ack_value {
    uint16_t ack_code; /* enum osdk_payload.control_ack */
} osdk_payload_control_ack_value_t;

/* osdk_payload::lost_control_ack_value */
typedef struct osdk_payload_lost_control_ack_value {
    uint16_t ack_code;
} osdk_payload_lost_control_ack_value_t;

/* osdk_payload::unknown_value */
typedef struct osdk_payload_unknown_value {
    osdk_bytes_t raw;
} osdk_payload_unknown_value_t;

/* osdk_payload.body: which case was read */
enum {
    OSDK_PAYLOAD_BODY_NONE = 0,
    OSDK_PAYLOAD_BODY_VERSION_QUERY = 1,
    OSDK_PAYLOAD_BODY_ACTIVATION_REQUEST = 2,
    OSDK_PAYLOAD_BODY_FREQUENCY_REQUEST = 3,
    OSDK_PAYLOAD_BODY_CONTROL_REQUEST = 4,
    OSDK_PAYLOAD_BODY_OSDK_MOVEMENT_CONTROL = 5,
    OSDK_PAYLOAD_BODY_BROADCAST = 6,
    OSDK_PAYLOAD_BODY_LOST_CONTROL = 7,
    OSDK_PAYLOAD_BODY_VERSION_ACK_VALUE = 8,
    OSDK_PAYLOAD_BODY_ACTIVATION_ACK_VALUE = 9,
    OSDK_PAYLOAD_BODY_FREQUENCY_ACK_VALUE = 10,
    OSDK_PAYLOAD_BODY_CONTROL_ACK_VALUE = 11,
    OSDK_PAYLOAD_BODY_LOST_CONTROL_ACK_VALUE = 12,
    OSDK_PAYLOAD_BODY_UNKNOWN_VALUE = 13
};
typedef struct {
    int tag;
    union {
        osdk_payload_version_query_t version_query;
        osdk_payload_activation_request_t activation_request;
        osdk_payload_frequency_request_t frequency_request;
        osdk_payload_control_request_t control_request;
        osdk_movement_control_t osdk_movement_control;
        osdk_payload_broadcast_t broadcast;
        osdk_payload_lost_control_t lost_control;
        osdk_payload_version_ack_value_t version_ack_value;
        osdk_payload_activation_ack_value_t activation_ack_value;
        osdk_payload_frequency_ack_value_t frequency_ack_value;
        osdk_payload_control_ack_value_t control_ack_value;
        osdk_payload_lost_control_ack_value_t lost_control_ack_value;
        osdk_payload_unknown_value_t unknown_value;
    } u;
} osdk_payload_body_switch_t;

/* osdk_payload */
typedef struct osdk_payload {
    uint8_t cmd_set; /* param */
    uint8_t cmd_id; /* param */
    bool is_ack; /* param */
    uint8_t profile; /* param, enum osdk_payload.profile */
    osdk_payload_body_switch_t body;
    osdk_bytes_t trailing;
} osdk_payload_t;

/* osdk_frame::frame_data */
typedef struct osdk_frame_frame_data {
    uint8_t cmd_set; /* enum osdk_frame.command_set; if not _parent.is_ack */
    bool cmd_set_present;
    uint8_t cmd_id; /* if not _parent.is_ack */
    bool cmd_id_present;
    osdk_payload_t value; /* if not _parent.is_ack */
    bool value_present;
    osdk_bytes_t ack_value; /* if _parent.is_ack */
    bool ack_value_present;
    uint8_t cmd_set_code; /* instance, pos 0 */
    bool cmd_set_code_present;
} osdk_frame_frame_data_t;

/* osdk_frame.data: which case was read */
enum {
    OSDK_FRAME_DATA_NONE = 0,
    OSDK_FRAME_DATA_FRAME_DATA = 1,
    OSDK_FRAME_DATA_RAW = 2
};
typedef struct {
    int tag;
    union {
        osdk_frame_frame_data_t frame_data;
        osdk_bytes_t raw; /* no case matched: the bytes, unparsed */
    } u;
} osdk_frame_data_switch_t;

/* osdk_frame */
typedef struct osdk_frame {
    uint8_t profile; /* param, enum osdk_payload.profile */
    osdk_bytes_t sof;
    uint16_t len; /* b10 */
    uint8_t ver; /* b6 */
    uint8_t session; /* b5 */
    bool is_ack; /* b1 */
    uint8_t res0; /* b2 */
    uint8_t padding; /* b5 */
    uint8_t enc; /* enum osdk_frame.encryption; b3 */
    uint32_t res1; /* b24 */
    uint16_t seq;
    uint16_t crc16;
    osdk_frame_data_switch_t data; /* if len > 12 */
    bool data_present;
    uint32_t crc32; /* if len > 12 */
    bool crc32_present;
} osdk_frame_t;


/* ---- `valid` predicates of value-only checks ----------------------------------------- */

/* `valid` of osdk_broadcast_a3_fw3_1.reserved_flags: 0 */
/*@ assigns \nothing; */
bool osdk_broadcast_a3_fw3_1_valid_reserved_flags(int64_t v);
/* `valid` of osdk_broadcast_m100_fw2_3.reserved_flags: 0 */
/*@ assigns \nothing; */
bool osdk_broadcast_m100_fw2_3_valid_reserved_flags(int64_t v);
/* `valid` of osdk_broadcast_m100_fw3_1.reserved_flags: 0 */
/*@ assigns \nothing; */
bool osdk_broadcast_m100_fw3_1_valid_reserved_flags(int64_t v);
/* `valid` of osdk_frame.len: {'expr': '_ == 12 or _ >= 17'} */
/*@ assigns \nothing; */
bool osdk_frame_valid_len(int64_t v);
/* `valid` of osdk_frame.ver: 0 */
/*@ assigns \nothing; */
bool osdk_frame_valid_ver(int64_t v);
/* `valid` of osdk_frame.res0: 0 */
/*@ assigns \nothing; */
bool osdk_frame_valid_res0(int64_t v);
/* `valid` of osdk_frame.res1: 0 */
/*@ assigns \nothing; */
bool osdk_frame_valid_res1(int64_t v);

/* ---- parsing ------------------------------------------------------------------------- */

/* Parse functions, one per ksy type: read from io into *self (zeroed
 * first). params are the ksy params; parent/root exist where the type's
 * expressions use _parent/_root. Fields whose `if` is false have
 * <field>_present == false. */
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_broadcast_a3_fw3_1_parse(osdk_stream_t *io, osdk_broadcast_a3_fw3_1_t *self, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_broadcast_items_control_info_parse(osdk_stream_t *io, osdk_broadcast_items_control_info_t *self, bool has_mode, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_broadcast_items_gimbal_parse(osdk_stream_t *io, osdk_broadcast_items_gimbal_t *self, bool has_limit_byte, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_broadcast_items_gimbal_limit_parse(osdk_stream_t *io, osdk_broadcast_items_gimbal_limit_t *self, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_broadcast_items_gps_detail_parse(osdk_stream_t *io, osdk_broadcast_items_gps_detail_t *self, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_broadcast_items_magnetometer_parse(osdk_stream_t *io, osdk_broadcast_items_magnetometer_t *self, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_broadcast_items_position_parse(osdk_stream_t *io, osdk_broadcast_items_position_t *self, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_broadcast_items_quaternion_parse(osdk_stream_t *io, osdk_broadcast_items_quaternion_t *self, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_broadcast_items_rc_parse(osdk_stream_t *io, osdk_broadcast_items_rc_t *self, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_broadcast_items_rtk_detail_parse(osdk_stream_t *io, osdk_broadcast_items_rtk_detail_t *self, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_broadcast_items_time_stamp_parse(osdk_stream_t *io, osdk_broadcast_items_time_stamp_t *self, bool has_ns_and_sync, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_broadcast_items_vector3f_parse(osdk_stream_t *io, osdk_broadcast_items_vector3f_t *self, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_broadcast_items_velocity_parse(osdk_stream_t *io, osdk_broadcast_items_velocity_t *self, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_broadcast_m100_fw2_3_parse(osdk_stream_t *io, osdk_broadcast_m100_fw2_3_t *self, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_broadcast_m100_fw3_1_parse(osdk_stream_t *io, osdk_broadcast_m100_fw3_1_t *self, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_control_mode_parse(osdk_stream_t *io, osdk_control_mode_t *self, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_frame_parse(osdk_stream_t *io, osdk_frame_t *self, uint8_t profile, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    requires \valid_read(parent) && \valid_read(root);
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_frame_frame_data_parse(osdk_stream_t *io, osdk_frame_frame_data_t *self, const osdk_frame_t *parent, const osdk_frame_t *root, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_movement_control_parse(osdk_stream_t *io, osdk_movement_control_t *self, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_payload_parse(osdk_stream_t *io, osdk_payload_t *self, uint8_t cmd_set, uint8_t cmd_id, bool is_ack, uint8_t profile, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_payload_activation_ack_value_parse(osdk_stream_t *io, osdk_payload_activation_ack_value_t *self, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_payload_activation_request_parse(osdk_stream_t *io, osdk_payload_activation_request_t *self, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_payload_broadcast_parse(osdk_stream_t *io, osdk_payload_broadcast_t *self, uint8_t profile, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_payload_control_ack_value_parse(osdk_stream_t *io, osdk_payload_control_ack_value_t *self, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_payload_control_request_parse(osdk_stream_t *io, osdk_payload_control_request_t *self, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_payload_frequency_ack_value_parse(osdk_stream_t *io, osdk_payload_frequency_ack_value_t *self, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_payload_frequency_request_parse(osdk_stream_t *io, osdk_payload_frequency_request_t *self, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_payload_lost_control_parse(osdk_stream_t *io, osdk_payload_lost_control_t *self, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_payload_lost_control_ack_value_parse(osdk_stream_t *io, osdk_payload_lost_control_ack_value_t *self, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_payload_unknown_value_parse(osdk_stream_t *io, osdk_payload_unknown_value_t *self, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_payload_version_ack_value_parse(osdk_stream_t *io, osdk_payload_version_ack_value_t *self, uint8_t profile, osdk_error_t *err);
/*@ requires osdk_stream_ok(io) && \valid(self) && \separated(io, self);
    requires err == \null || (\valid(err) && \separated(err, io, self));
    assigns *io, *self, *err;
    ensures \result == OSDK_OK ==> osdk_stream_on(io, \old(io->data), \old(io->size)); */
osdk_status_t osdk_payload_version_query_parse(osdk_stream_t *io, osdk_payload_version_query_t *self, osdk_error_t *err);

/* Decode a whole osdk_broadcast_a3_fw3_1 from buf[0..len). */
/*@ requires buf == \null || len == 0 || \valid_read(buf + (0 .. len - 1));
    requires \valid(out) && (err == \null || (\valid(err) && \separated(err, out)));
    assigns *out, *err; */
osdk_status_t osdk_broadcast_a3_fw3_1_decode(const uint8_t *buf, size_t len, osdk_broadcast_a3_fw3_1_t *out, osdk_error_t *err);
/* Decode a whole osdk_broadcast_m100_fw2_3 from buf[0..len). */
/*@ requires buf == \null || len == 0 || \valid_read(buf + (0 .. len - 1));
    requires \valid(out) && (err == \null || (\valid(err) && \separated(err, out)));
    assigns *out, *err; */
osdk_status_t osdk_broadcast_m100_fw2_3_decode(const uint8_t *buf, size_t len, osdk_broadcast_m100_fw2_3_t *out, osdk_error_t *err);
/* Decode a whole osdk_broadcast_m100_fw3_1 from buf[0..len). */
/*@ requires buf == \null || len == 0 || \valid_read(buf + (0 .. len - 1));
    requires \valid(out) && (err == \null || (\valid(err) && \separated(err, out)));
    assigns *out, *err; */
osdk_status_t osdk_broadcast_m100_fw3_1_decode(const uint8_t *buf, size_t len, osdk_broadcast_m100_fw3_1_t *out, osdk_error_t *err);
/* Decode a whole osdk_control_mode from buf[0..len). */
/*@ requires buf == \null || len == 0 || \valid_read(buf + (0 .. len - 1));
    requires \valid(out) && (err == \null || (\valid(err) && \separated(err, out)));
    assigns *out, *err; */
osdk_status_t osdk_control_mode_decode(const uint8_t *buf, size_t len, osdk_control_mode_t *out, osdk_error_t *err);
/* Decode a whole osdk_frame from buf[0..len). */
/*@ requires buf == \null || len == 0 || \valid_read(buf + (0 .. len - 1));
    requires \valid(out) && (err == \null || (\valid(err) && \separated(err, out)));
    assigns *out, *err; */
osdk_status_t osdk_frame_decode(const uint8_t *buf, size_t len, uint8_t profile, osdk_frame_t *out, osdk_error_t *err);
/* Decode a whole osdk_movement_control from buf[0..len). */
/*@ requires buf == \null || len == 0 || \valid_read(buf + (0 .. len - 1));
    requires \valid(out) && (err == \null || (\valid(err) && \separated(err, out)));
    assigns *out, *err; */
osdk_status_t osdk_movement_control_decode(const uint8_t *buf, size_t len, osdk_movement_control_t *out, osdk_error_t *err);
/* Decode a whole osdk_payload from buf[0..len). */
/*@ requires buf == \null || len == 0 || \valid_read(buf + (0 .. len - 1));
    requires \valid(out) && (err == \null || (\valid(err) && \separated(err, out)));
    assigns *out, *err; */
osdk_status_t osdk_payload_decode(const uint8_t *buf, size_t len, uint8_t cmd_set, uint8_t cmd_id, bool is_ack, uint8_t profile, osdk_payload_t *out, osdk_error_t *err);

/* ---- frame header, as the receiver reads it ------------------------------------------ */

/* The fixed-size prefix (header) of osdk_frame: 12 bytes. */
#define OSDK_FRAME_HEADER_LEN 12u
/* start byte (sof contents) */
#define OSDK_FRAME_SOF 0xaau
/* sof: bits 0..7 of the header, read without checks. */
/*@ requires \valid_read(header + (0 .. OSDK_FRAME_HEADER_LEN - 1));
    assigns \nothing; */
uint64_t osdk_frame_peek_sof(const uint8_t *header);
/* len: bits 8..17 of the header, read without checks. */
/*@ requires \valid_read(header + (0 .. OSDK_FRAME_HEADER_LEN - 1));
    assigns \nothing; */
uint64_t osdk_frame_peek_len(const uint8_t *header);
/* ver: bits 18..23 of the header, read without checks. */
/*@ requires \valid_read(header + (0 .. OSDK_FRAME_HEADER_LEN - 1));
    assigns \nothing; */
uint64_t osdk_frame_peek_ver(const uint8_t *header);
/* session: bits 24..28 of the header, read without checks. */
/*@ requires \valid_read(header + (0 .. OSDK_FRAME_HEADER_LEN - 1));
    assigns \nothing; */
uint64_t osdk_frame_peek_session(const uint8_t *header);
/* is_ack: bits 29..29 of the header, read without checks. */
/*@ requires \valid_read(header + (0 .. OSDK_FRAME_HEADER_LEN - 1));
    assigns \nothing; */
uint64_t osdk_frame_peek_is_ack(const uint8_t *header);
/* res0: bits 30..31 of the header, read without checks. */
/*@ requires \valid_read(header + (0 .. OSDK_FRAME_HEADER_LEN - 1));
    assigns \nothing; */
uint64_t osdk_frame_peek_res0(const uint8_t *header);
/* padding: bits 32..36 of the header, read without checks. */
/*@ requires \valid_read(header + (0 .. OSDK_FRAME_HEADER_LEN - 1));
    assigns \nothing; */
uint64_t osdk_frame_peek_padding(const uint8_t *header);
/* enc: bits 37..39 of the header, read without checks. */
/*@ requires \valid_read(header + (0 .. OSDK_FRAME_HEADER_LEN - 1));
    assigns \nothing; */
uint64_t osdk_frame_peek_enc(const uint8_t *header);
/* res1: bits 40..63 of the header, read without checks. */
/*@ requires \valid_read(header + (0 .. OSDK_FRAME_HEADER_LEN - 1));
    assigns \nothing; */
uint64_t osdk_frame_peek_res1(const uint8_t *header);
/* seq: bits 64..79 of the header, read without checks. */
/*@ requires \valid_read(header + (0 .. OSDK_FRAME_HEADER_LEN - 1));
    assigns \nothing; */
uint64_t osdk_frame_peek_seq(const uint8_t *header);
/* crc16: bits 80..95 of the header, read without checks. */
/*@ requires \valid_read(header + (0 .. OSDK_FRAME_HEADER_LEN - 1));
    assigns \nothing; */
uint64_t osdk_frame_peek_crc16(const uint8_t *header);
#define OSDK_FRAME_MAX_LEN 1023u

#ifdef __cplusplus
}
#endif

#endif /* OSDK_DECODER_H */
