/*
 * send: one frame of each command an onboard computer sends, as
 * "NAME HEX" lines (tests/library_examples.py SENT: the same arguments in
 * every language).
 */
#include <stdio.h>

#include "osdk_encode.h"

static int print_frame(const char *name, uint8_t cmd_set, uint8_t cmd_id, uint8_t session, uint16_t seq,
                       const uint8_t *value, size_t len)
{
    uint8_t frame[OSDK_ENCODE_FRAME_MAX_LEN];
    size_t n, i;
    osdk_encode_status_t st = osdk_encode_frame(cmd_set, cmd_id, false, session, seq, value, len, frame,
                                                sizeof frame, &n);
    if (st != OSDK_ENCODE_OK) {
        fprintf(stderr, "send: %s: %s\n", name, osdk_encode_status_name(st));
        return 1;
    }
    printf("%s ", name);
    for (i = 0; i < n; i++) printf("%02x", frame[i]);
    printf("\n");
    return 0;
}

int main(void)
{
    static const uint8_t bundle_id[32] = "0123456789abcdef0123456789abcdef";
    static const uint8_t codes[16] = {1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 0, 0};
    uint8_t version[OSDK_VERSION_QUERY_SIZE], activation[OSDK_ACTIVATION_SIZE];
    uint8_t frequency[OSDK_SET_FREQUENCY_SIZE], authority[OSDK_CONTROL_AUTHORITY_SIZE];
    uint8_t move[OSDK_MOVEMENT_CONTROL_SIZE];
    int bad = 0;
    osdk_encode_version_query(0, version);
    bad |= print_frame("version_query", OSDK_VERSION_QUERY_CMD_SET, OSDK_VERSION_QUERY_CMD_ID, 2, 1, version,
                       sizeof version);
    osdk_encode_activation(1000001, 2, 0x03016400, bundle_id, activation);
    bad |= print_frame("activation", OSDK_ACTIVATION_CMD_SET, OSDK_ACTIVATION_CMD_ID, 2, 2, activation,
                       sizeof activation);
    osdk_encode_set_frequency(codes, frequency);
    bad |= print_frame("set_frequency", OSDK_SET_FREQUENCY_CMD_SET, OSDK_SET_FREQUENCY_CMD_ID, 2, 3, frequency,
                       sizeof frequency);
    osdk_encode_control_authority(1, authority);
    bad |= print_frame("control_authority", OSDK_CONTROL_AUTHORITY_CMD_SET, OSDK_CONTROL_AUTHORITY_CMD_ID, 2, 4,
                       authority, sizeof authority);
    osdk_encode_movement_control(0x4B, 1.0f, -2.0f, 0.5f, 30.0f, move);
    bad |= print_frame("movement_control", OSDK_MOVEMENT_CONTROL_CMD_SET, OSDK_MOVEMENT_CONTROL_CMD_ID, 0, 0x1234,
                       move, sizeof move);
    return bad;
}
