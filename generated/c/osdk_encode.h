/* Generated from spec/ by tools/libgen/c.py. Do not edit. */
/*
 * osdk_encode.h - the commands an onboard computer sends, as bytes: one
 * encoder per command value (layouts from spec/osdk_payload.ksy through
 * tools/tables.py library.sent_commands) and osdk_encode_frame(), which
 * wraps a value in a frame with LEN and both CRCs (conformance/PROTOCOL.md,
 * "encode_movement_control and encode_frame").
 *
 * No heap, no stdio, no libc call: every function writes into the
 * caller's buffer. Floats go out as their IEEE bits; the _bits variants
 * take the bits themselves, so a NaN payload or -0.0 goes out exactly even
 * where a float argument would not carry it.
 */
#ifndef OSDK_ENCODE_H
#define OSDK_ENCODE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* A frame's fixed header, its CRC-32 and the largest LEN (10 bits). */
#define OSDK_ENCODE_HEADER_LEN 12u
#define OSDK_ENCODE_CRC32_LEN 4u
#define OSDK_ENCODE_FRAME_MAX_LEN 1023u
/* The largest value a command frame carries (DATA less cmd_set and cmd_id). */
#define OSDK_ENCODE_MAX_VALUE_LEN (OSDK_ENCODE_FRAME_MAX_LEN - OSDK_ENCODE_HEADER_LEN - OSDK_ENCODE_CRC32_LEN - 2u)

typedef enum {
    OSDK_ENCODE_OK = 0,
    OSDK_ENCODE_IMPOSSIBLE_LENGTH = 1, /* the frame would be longer than LEN can say (class impossible_length) */
    OSDK_ENCODE_BAD_SESSION = 2,       /* an ACK in session 0 (class bad_session) */
    OSDK_ENCODE_BUFFER_TOO_SMALL = 3,  /* out has fewer than *written bytes */
    OSDK_ENCODE_BAD_ARGUMENT = 4       /* session above 31, or value NULL with len > 0 */
} osdk_encode_status_t;

/* "ok", the error class of docs/VALUE-MODEL.md ("impossible_length",
 * "bad_session"), or "buffer_too_small" / "bad_argument". */
/*@ assigns \nothing; */
const char *osdk_encode_status_name(osdk_encode_status_t status);

/* ---- command values ----------------------------------------------------------------- */
/* version_query: command 0x00/0x00, value osdk_payload.version_query:
 * arbitrary (u1), little-endian. */
#define OSDK_VERSION_QUERY_CMD_SET 0x00u
#define OSDK_VERSION_QUERY_CMD_ID 0x00u
#define OSDK_VERSION_QUERY_SIZE 1u
/* Writes the value into out; returns its size. */
/*@ requires \valid(out + (0 .. OSDK_VERSION_QUERY_SIZE - 1));
    assigns out[0 .. OSDK_VERSION_QUERY_SIZE - 1];
    ensures \result == OSDK_VERSION_QUERY_SIZE; */
size_t osdk_encode_version_query(uint8_t arbitrary, uint8_t out[OSDK_VERSION_QUERY_SIZE]);

/* activation: command 0x00/0x01, value osdk_payload.activation_request:
 * app_id (u4), api_level (u4), sdk_version (u4), bundle_id (bytes 32), little-endian. */
#define OSDK_ACTIVATION_CMD_SET 0x00u
#define OSDK_ACTIVATION_CMD_ID 0x01u
#define OSDK_ACTIVATION_SIZE 44u
/* Writes the value into out; returns its size. */
/*@ requires \valid(out + (0 .. OSDK_ACTIVATION_SIZE - 1));
    requires \valid_read(bundle_id + (0 .. 31));
    assigns out[0 .. OSDK_ACTIVATION_SIZE - 1];
    ensures \result == OSDK_ACTIVATION_SIZE; */
size_t osdk_encode_activation(uint32_t app_id, uint32_t api_level, uint32_t sdk_version, const uint8_t bundle_id[32], uint8_t out[OSDK_ACTIVATION_SIZE]);

/* set_frequency: command 0x00/0x10, value osdk_payload.frequency_request:
 * codes (u1 x16), little-endian. */
#define OSDK_SET_FREQUENCY_CMD_SET 0x00u
#define OSDK_SET_FREQUENCY_CMD_ID 0x10u
#define OSDK_SET_FREQUENCY_SIZE 16u
/* Writes the value into out; returns its size. */
/*@ requires \valid(out + (0 .. OSDK_SET_FREQUENCY_SIZE - 1));
    requires \valid_read(codes + (0 .. 15));
    assigns out[0 .. OSDK_SET_FREQUENCY_SIZE - 1];
    ensures \result == OSDK_SET_FREQUENCY_SIZE; */
size_t osdk_encode_set_frequency(const uint8_t codes[16], uint8_t out[OSDK_SET_FREQUENCY_SIZE]);

/* control_authority: command 0x01/0x00, value osdk_payload.control_request:
 * request (u1), little-endian. */
#define OSDK_CONTROL_AUTHORITY_CMD_SET 0x01u
#define OSDK_CONTROL_AUTHORITY_CMD_ID 0x00u
#define OSDK_CONTROL_AUTHORITY_SIZE 1u
/* Writes the value into out; returns its size. */
/*@ requires \valid(out + (0 .. OSDK_CONTROL_AUTHORITY_SIZE - 1));
    assigns out[0 .. OSDK_CONTROL_AUTHORITY_SIZE - 1];
    ensures \result == OSDK_CONTROL_AUTHORITY_SIZE; */
size_t osdk_encode_control_authority(uint8_t request, uint8_t out[OSDK_CONTROL_AUTHORITY_SIZE]);

/* movement_control: command 0x01/0x03, value osdk_movement_control:
 * control_mode (u1), x (f4), y (f4), z (f4), yaw (f4), little-endian. */
#define OSDK_MOVEMENT_CONTROL_CMD_SET 0x01u
#define OSDK_MOVEMENT_CONTROL_CMD_ID 0x03u
#define OSDK_MOVEMENT_CONTROL_SIZE 17u
/* Writes the value into out; returns its size. */
/*@ requires \valid(out + (0 .. OSDK_MOVEMENT_CONTROL_SIZE - 1));
    assigns out[0 .. OSDK_MOVEMENT_CONTROL_SIZE - 1];
    ensures \result == OSDK_MOVEMENT_CONTROL_SIZE; */
size_t osdk_encode_movement_control(uint8_t control_mode, float x, float y, float z, float yaw, uint8_t out[OSDK_MOVEMENT_CONTROL_SIZE]);
/* The floats as their IEEE bits. */
/*@ requires \valid(out + (0 .. OSDK_MOVEMENT_CONTROL_SIZE - 1));
    assigns out[0 .. OSDK_MOVEMENT_CONTROL_SIZE - 1];
    ensures \result == OSDK_MOVEMENT_CONTROL_SIZE; */
size_t osdk_encode_movement_control_bits(uint8_t control_mode, uint32_t x, uint32_t y, uint32_t z, uint32_t yaw, uint8_t out[OSDK_MOVEMENT_CONTROL_SIZE]);

/* ---- frames --------------------------------------------------------------------------- */

/* A plain frame (VER, RES0, RES1, PADDING and ENC 0): DATA is cmd_set,
 * cmd_id and the value for a command, the value alone for an ACK (cmd_set
 * and cmd_id are then ignored); LEN is 12 when DATA is empty. Checked in
 * this order: arguments, impossible_length, bad_session, then the room
 * in out. On OSDK_ENCODE_OK and OSDK_ENCODE_BUFFER_TOO_SMALL, *written
 * (when not NULL) is the frame's length; otherwise 0. The comments that
 * open with an @ are ACSL contracts: what `make prove` proves the
 * functions against (docs/VERIFICATION.md). */
/*@ requires value == \null || len == 0 || \valid_read(value + (0 .. len - 1));
    requires out == \null || cap == 0 || \valid(out + (0 .. cap - 1));
    requires written == \null || \valid(written);
    requires written == \null || out == \null || \separated(written, out + (0 .. cap - 1));
    assigns out[0 .. cap - 1], *written; */
osdk_encode_status_t osdk_encode_frame(uint8_t cmd_set, uint8_t cmd_id, bool is_ack, uint8_t session, uint16_t seq,
                                       const uint8_t *value, size_t len, uint8_t *out, size_t cap, size_t *written);

#ifdef __cplusplus
}
#endif

#endif /* OSDK_ENCODE_H */
