/*
 * receive PROFILE: a byte stream on standard input, one line per event of
 * the receiver (the output format is tests/library_examples.py's):
 *   garbage OFFSET LENGTH | error OFFSET LENGTH CLASS | empty OFFSET SEQ |
 *   ack OFFSET SEQ | frame OFFSET SEQ CMD_SET CMD_ID
 * and after a broadcast one line per item of the profile.
 */
#include <stdio.h>

#include "osdk_broadcast.h"
#include "osdk_decoder.h"
#include "osdk_deframer.h"
#include "osdk_tables.h"

static void print_items(const osdk_payload_broadcast_t *bc, uint8_t profile)
{
    size_t i, n;
    const osdk_broadcast_item_t *items = osdk_broadcast_profile_items(profile, &n);
    for (i = 0; i < n; i++) {
        const char *name = osdk_broadcast_item_name(items[i]);
        const uint8_t *battery = osdk_broadcast_battery(bc);
        const osdk_broadcast_items_time_stamp_t *stamp = osdk_broadcast_time_stamp(bc);
        if (osdk_broadcast_item(bc, items[i]) == NULL)
            printf("  %s absent\n", name);
        else if (items[i] == OSDK_BROADCAST_ITEM_BATTERY)
            printf("  battery %u\n", (unsigned)*battery);
        else if (items[i] == OSDK_BROADCAST_ITEM_TIME_STAMP)
            printf("  time_stamp %lu\n", (unsigned long)stamp->time);
        else
            printf("  %s present\n", name);
    }
}

static void on_event(void *user, const osdk_event_t *ev)
{
    static osdk_frame_t f; /* large: not on the stack */
    uint8_t profile = *(const uint8_t *)user;
    unsigned long long at = (unsigned long long)ev->offset;
    osdk_error_t err;
    const osdk_payload_broadcast_t *bc;
    if (ev->kind == OSDK_EVENT_GARBAGE) {
        printf("garbage %llu %lu\n", at, (unsigned long)ev->length);
        return;
    }
    if (ev->kind == OSDK_EVENT_ERROR) {
        printf("error %llu %lu %s\n", at, (unsigned long)ev->length, osdk_status_name(ev->error));
        return;
    }
    if (osdk_frame_decode(ev->raw, ev->length, profile, &f, &err) != OSDK_OK) {
        printf("error %llu %lu %s\n", at, (unsigned long)ev->length, osdk_status_name(err.status));
        return;
    }
    if (!f.data_present) {
        printf("empty %llu %u\n", at, (unsigned)f.seq);
    } else if (f.is_ack) {
        printf("ack %llu %u\n", at, (unsigned)f.seq);
    } else {
        const osdk_frame_frame_data_t *d = &f.data.u.frame_data;
        printf("frame %llu %u %u %u\n", at, (unsigned)f.seq, (unsigned)d->cmd_set, (unsigned)d->cmd_id);
        if ((bc = osdk_broadcast_of(&f)) != NULL) print_items(bc, profile);
    }
}

int main(int argc, char **argv)
{
    static uint8_t window[OSDK_DEFRAMER_MIN_BUFFER];
    uint8_t chunk[4096], profile;
    osdk_deframer_t d;
    size_t n;
    int index = argc == 2 ? osdk_profile_index(argv[1]) : -1;
    if (index < 0) {
        fprintf(stderr, "usage: receive PROFILE (m100-fw2.3, m100-fw3.1 or a3-fw3.1)\n");
        return 2;
    }
    profile = osdk_profile_enum_values[index];
    osdk_deframer_init(&d, window, sizeof window);
    while ((n = fread(chunk, 1, sizeof chunk, stdin)) > 0) osdk_deframer_feed(&d, chunk, n, on_event, &profile);
    osdk_deframer_finish(&d, on_event, &profile);
    return ferror(stdin) ? 1 : 0;
}
