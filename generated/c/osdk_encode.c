/* Generated from spec/ by tools/libgen/c.py. Do not edit. */
/* osdk_encode.c - see osdk_encode.h. */
#include "osdk_encode.h"

#include "osdk_crc.h"

const char *osdk_encode_status_name(osdk_encode_status_t status)
{
    switch (status) {
    case OSDK_ENCODE_OK: return "ok";
    case OSDK_ENCODE_IMPOSSIBLE_LENGTH: return "impossible_length";
    case OSDK_ENCODE_BAD_SESSION: return "bad_session";
    case OSDK_ENCODE_BUFFER_TOO_SMALL: return "buffer_too_small";
    case OSDK_ENCODE_BAD_ARGUMENT: return "bad_argument";
    }
    return "?";
}

/*@ requires n <= 4 && \valid(p + (0 .. n - 1));
    assigns p[0 .. n - 1]; */
static void put_le(uint8_t *p, uint32_t v, unsigned n)
{
    unsigned i;
    /*@ loop invariant 0 <= i <= n;
        loop assigns i, p[0 .. n - 1];
        loop variant n - i; */
    for (i = 0; i < n; i++) p[i] = (uint8_t)(v >> (8u * i));
}

/* A float's IEEE bits without memcpy (no libc): C99 allows reading the
 * other member of a union. */
/*@ assigns \nothing; */
static uint32_t f32_bits(float v)
{
    union {
        float f;
        uint32_t u;
    } pun;
    pun.f = v;
    return pun.u;
}

/* Sets a header field at its bit position (bit-endian le: bit 0 of byte 0
 * first) in a header whose bytes start at zero. The byte and the bit in it
 * are bit / 8u and bit % 8u, not a shift and a mask: the provers reason
 * about division, not about bitwise operators. */
/*@ requires width <= 32 && bit + width <= 8 * OSDK_ENCODE_HEADER_LEN;
    requires \valid(p + (0 .. OSDK_ENCODE_HEADER_LEN - 1));
    assigns p[0 .. OSDK_ENCODE_HEADER_LEN - 1]; */
static void put_bits(uint8_t *p, unsigned bit, unsigned width, uint32_t v)
{
    unsigned i;
    /*@ loop invariant 0 <= i <= width && bit == \at(bit, Pre) + i;
        loop assigns i, bit, p[0 .. OSDK_ENCODE_HEADER_LEN - 1];
        loop variant width - i; */
    for (i = 0; i < width; i++, bit++) {
        if ((v >> i) & 1u) p[bit / 8u] = (uint8_t)(p[bit / 8u] | (1u << (bit % 8u)));
    }
}

size_t osdk_encode_version_query(uint8_t arbitrary, uint8_t out[OSDK_VERSION_QUERY_SIZE])
{
    out[0] = arbitrary;
    return OSDK_VERSION_QUERY_SIZE;
}

size_t osdk_encode_activation(uint32_t app_id, uint32_t api_level, uint32_t sdk_version, const uint8_t bundle_id[32], uint8_t out[OSDK_ACTIVATION_SIZE])
{
    size_t i;
    put_le(out + 0, app_id, 4);
    put_le(out + 4, api_level, 4);
    put_le(out + 8, sdk_version, 4);
    /*@ loop invariant 0 <= i <= 32;
        loop assigns i, out[12 .. 43];
        loop variant 32 - i; */
    for (i = 0; i < 32; i++) out[12 + i] = bundle_id[i];
    return OSDK_ACTIVATION_SIZE;
}

size_t osdk_encode_set_frequency(const uint8_t codes[16], uint8_t out[OSDK_SET_FREQUENCY_SIZE])
{
    size_t i;
    /*@ loop invariant 0 <= i <= 16;
        loop assigns i, out[0 .. 15];
        loop variant 16 - i; */
    for (i = 0; i < 16; i++) out[0 + i] = codes[i];
    return OSDK_SET_FREQUENCY_SIZE;
}

size_t osdk_encode_control_authority(uint8_t request, uint8_t out[OSDK_CONTROL_AUTHORITY_SIZE])
{
    out[0] = request;
    return OSDK_CONTROL_AUTHORITY_SIZE;
}

size_t osdk_encode_movement_control(uint8_t control_mode, float x, float y, float z, float yaw, uint8_t out[OSDK_MOVEMENT_CONTROL_SIZE])
{
    return osdk_encode_movement_control_bits(control_mode, f32_bits(x), f32_bits(y), f32_bits(z), f32_bits(yaw), out);
}

size_t osdk_encode_movement_control_bits(uint8_t control_mode, uint32_t x, uint32_t y, uint32_t z, uint32_t yaw, uint8_t out[OSDK_MOVEMENT_CONTROL_SIZE])
{
    out[0] = control_mode;
    put_le(out + 1, x, 4);
    put_le(out + 5, y, 4);
    put_le(out + 9, z, 4);
    put_le(out + 13, yaw, 4);
    return OSDK_MOVEMENT_CONTROL_SIZE;
}

osdk_encode_status_t osdk_encode_frame(uint8_t cmd_set, uint8_t cmd_id, bool is_ack, uint8_t session, uint16_t seq,
                                       const uint8_t *value, size_t len, uint8_t *out, size_t cap, size_t *written)
{
    size_t data_len, frame_len, at, i;
    if (written) *written = 0;
    if (session > 31u || (value == NULL && len > 0)) return OSDK_ENCODE_BAD_ARGUMENT;
    if (len > OSDK_ENCODE_FRAME_MAX_LEN) return OSDK_ENCODE_IMPOSSIBLE_LENGTH;
    data_len = len + (is_ack ? 0u : 2u);
    frame_len = data_len ? OSDK_ENCODE_HEADER_LEN + data_len + OSDK_ENCODE_CRC32_LEN : 12u;
    if (frame_len > OSDK_ENCODE_FRAME_MAX_LEN ||
        frame_len <= 11u ||
        (frame_len >= 13u && frame_len <= 15u) ||
        frame_len == 16u) return OSDK_ENCODE_IMPOSSIBLE_LENGTH;
    if (is_ack && session == 0) return OSDK_ENCODE_BAD_SESSION;
    if (written) *written = frame_len;
    if (out == NULL || cap < frame_len) return OSDK_ENCODE_BUFFER_TOO_SMALL;
    /*@ loop invariant 0 <= i <= OSDK_ENCODE_HEADER_LEN;
        loop assigns i, out[0 .. OSDK_ENCODE_HEADER_LEN - 1];
        loop variant OSDK_ENCODE_HEADER_LEN - i; */
    for (i = 0; i < OSDK_ENCODE_HEADER_LEN; i++) out[i] = 0;
    put_bits(out, 0u, 8u, 0xaau); /* sof */
    put_bits(out, 8u, 10u, (uint32_t)frame_len); /* len */
    /* ver: bits 18..23 stay 0 */
    put_bits(out, 24u, 5u, session); /* session */
    put_bits(out, 29u, 1u, is_ack ? 1u : 0u); /* is_ack */
    /* res0: bits 30..31 stay 0 */
    /* padding: bits 32..36 stay 0 */
    /* enc: bits 37..39 stay 0 */
    /* res1: bits 40..63 stay 0 */
    put_bits(out, 64u, 16u, seq); /* seq */
    put_bits(out, 80u, 16u, osdk_crc16(out, 10u)); /* crc16 */
    at = OSDK_ENCODE_HEADER_LEN;
    if (data_len) {
        if (!is_ack) {
            out[at++] = cmd_set;
            out[at++] = cmd_id;
        }
        /*@ loop invariant 0 <= i <= len && at == OSDK_ENCODE_HEADER_LEN + (is_ack ? 0 : 2) + i;
            loop assigns i, at, out[OSDK_ENCODE_HEADER_LEN .. cap - 1];
            loop variant len - i; */
        for (i = 0; i < len; i++) out[at++] = value[i];
        put_le(out + at, osdk_crc32(out, at), OSDK_ENCODE_CRC32_LEN);
    }
    return OSDK_ENCODE_OK;
}
