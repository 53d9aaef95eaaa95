/* The generated encoders (osdk_encode.h): the worked frame of
 * PROTOCOL-FACTS, float bits kept exactly, the order of the frame's
 * checks and the statuses the bytes cannot show (buffer, arguments).
 * tests/test_lib_c.py compares the bytes with the reference encoder. */
#include <string.h>

#include "check.h"
#include "osdk_broadcast.h"
#include "osdk_decoder.h"
#include "osdk_encode.h"

static uint8_t frame[OSDK_ENCODE_FRAME_MAX_LEN + 8];
static uint8_t value[OSDK_ENCODE_FRAME_MAX_LEN + 8];

static void worked(void)
{
    static const char *const hex = "aa230000000000003412e17201034b0000803f000000c00000003f0000f041fcdb01ba";
    uint8_t mc[OSDK_MOVEMENT_CONTROL_SIZE], bits_mc[OSDK_MOVEMENT_CONTROL_SIZE];
    size_t n = 0, i;
    char got[2 * sizeof frame + 1];
    CHECK_EQ(osdk_encode_movement_control(0x4B, 1.0f, -2.0f, 0.5f, 30.0f, mc), 17);
    CHECK_EQ(osdk_encode_movement_control_bits(0x4B, 0x3f800000u, 0xc0000000u, 0x3f000000u, 0x41f00000u, bits_mc), 17);
    CHECK(memcmp(mc, bits_mc, sizeof mc) == 0);
    CHECK_EQ(osdk_encode_frame(OSDK_MOVEMENT_CONTROL_CMD_SET, OSDK_MOVEMENT_CONTROL_CMD_ID, false, 0, 0x1234, mc,
                               sizeof mc, frame, sizeof frame, &n), OSDK_ENCODE_OK);
    for (i = 0; i < n; i++) {
        static const char digits[] = "0123456789abcdef";
        got[2 * i] = digits[frame[i] >> 4];
        got[2 * i + 1] = digits[frame[i] & 15];
    }
    got[2 * n] = '\0';
    CHECK(strcmp(got, hex) == 0);
}

static void floats(void)
{
    uint8_t mc[OSDK_MOVEMENT_CONTROL_SIZE];
    osdk_encode_movement_control_bits(0, 0x7f800001u, 0x80000000u, 0xffc12345u, 0x00000001u, mc);
    CHECK_EQ(mc[1] | mc[2] << 8 | mc[3] << 16 | (uint32_t)mc[4] << 24, 0x7f800001u);
    CHECK_EQ(mc[5] | mc[6] << 8 | mc[7] << 16 | (uint32_t)mc[8] << 24, 0x80000000u);
    CHECK_EQ(mc[9] | mc[10] << 8 | mc[11] << 16 | (uint32_t)mc[12] << 24, 0xffc12345u);
    osdk_encode_movement_control(0xFF, -0.0f, 0.0f, 0.0f, 0.0f, mc);
    CHECK_EQ(mc[0], 0xFF);
    CHECK_EQ(mc[4], 0x80);
}

static void limits(void)
{
    size_t n = 99;
    /* a command: 12 + 2 + value + 4 <= 1023 */
    CHECK_EQ(osdk_encode_frame(255, 255, false, 31, 0xFFFF, value, 1005, frame, sizeof frame, &n), OSDK_ENCODE_OK);
    CHECK_EQ(n, 1023);
    CHECK_EQ(osdk_encode_frame(255, 255, false, 31, 0xFFFF, value, 1006, frame, sizeof frame, &n),
             OSDK_ENCODE_IMPOSSIBLE_LENGTH);
    CHECK_EQ(n, 0);
    CHECK_EQ(osdk_encode_frame(0, 0, true, 1, 0, value, 1007, frame, sizeof frame, &n), OSDK_ENCODE_OK);
    CHECK_EQ(n, 1023);
    /* impossible_length comes before bad_session */
    CHECK_EQ(osdk_encode_frame(0, 0, true, 0, 0, value, 1008, frame, sizeof frame, &n), OSDK_ENCODE_IMPOSSIBLE_LENGTH);
    CHECK_EQ(osdk_encode_frame(0, 0, true, 0, 0, value, 2, frame, sizeof frame, &n), OSDK_ENCODE_BAD_SESSION);
    CHECK_EQ(osdk_encode_frame(0, 0, true, 0, 0, NULL, 0, frame, sizeof frame, &n), OSDK_ENCODE_BAD_SESSION);
    CHECK_EQ(osdk_encode_frame(0, 0, true, 1, 7, NULL, 0, frame, sizeof frame, &n), OSDK_ENCODE_OK);
    CHECK_EQ(n, 12);
    CHECK_EQ(osdk_encode_frame(0, 0, false, 0, 7, NULL, 0, frame, sizeof frame, &n), OSDK_ENCODE_OK);
    CHECK_EQ(n, 18);
    CHECK_EQ(osdk_encode_frame(0, 0, false, 32, 0, NULL, 0, frame, sizeof frame, &n), OSDK_ENCODE_BAD_ARGUMENT);
    CHECK_EQ(osdk_encode_frame(0, 0, false, 1, 0, NULL, 3, frame, sizeof frame, &n), OSDK_ENCODE_BAD_ARGUMENT);
    /* the room is checked last and says how much is needed; nothing past cap is written */
    frame[17] = 0x5A;
    CHECK_EQ(osdk_encode_frame(0, 0, false, 1, 0, NULL, 0, frame, 17, &n), OSDK_ENCODE_BUFFER_TOO_SMALL);
    CHECK_EQ(n, 18);
    CHECK_EQ(frame[17], 0x5A);
    CHECK_EQ(osdk_encode_frame(0, 0, false, 1, 0, NULL, 0, NULL, 0, NULL), OSDK_ENCODE_BUFFER_TOO_SMALL);
    CHECK(strcmp(osdk_encode_status_name(OSDK_ENCODE_BAD_SESSION), "bad_session") == 0);
    CHECK(strcmp(osdk_encode_status_name(OSDK_ENCODE_IMPOSSIBLE_LENGTH), "impossible_length") == 0);
}

/* An encoded frame decodes; the accessors of a non-broadcast are NULL. */
static void round_trip(void)
{
    static osdk_frame_t f;
    osdk_error_t err;
    uint8_t authority[OSDK_CONTROL_AUTHORITY_SIZE];
    size_t n;
    osdk_encode_control_authority(1, authority);
    CHECK_EQ(osdk_encode_frame(OSDK_CONTROL_AUTHORITY_CMD_SET, OSDK_CONTROL_AUTHORITY_CMD_ID, false, 2, 4, authority,
                               sizeof authority, frame, sizeof frame, &n), OSDK_ENCODE_OK);
    CHECK_EQ(osdk_frame_decode(frame, n, OSDK_PAYLOAD_PROFILE_A3_FW3_1, &f, &err), OSDK_OK);
    CHECK(osdk_broadcast_of(&f) == NULL);
    CHECK(osdk_broadcast_battery(osdk_broadcast_of(&f)) == NULL);
    CHECK(osdk_broadcast_of(NULL) == NULL);
}

int main(void)
{
    worked();
    floats();
    limits();
    round_trip();
    return check_done("test_encode");
}
