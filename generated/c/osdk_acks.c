/* Generated from spec/ by tools/cgen/generate.py. Do not edit. */
/* osdk_acks.c - see osdk_acks.h. */
#include "osdk_acks.h"

#include <string.h>

void osdk_ack_table_init(osdk_ack_table_t *t, osdk_pending_t *items, size_t limit)
{
    t->items = items;
    t->count = 0;
    t->limit = limit;
}

static long find(const osdk_ack_table_t *t, uint8_t session, uint16_t seq)
{
    size_t i;
    for (i = 0; i < t->count; i++) {
        if (t->items[i].session == session && t->items[i].seq == seq) return (long)i;
    }
    return -1;
}

static void remove_at(osdk_ack_table_t *t, size_t i)
{
    memmove(&t->items[i], &t->items[i + 1], (t->count - i - 1) * sizeof t->items[0]);
    t->count--;
}

void osdk_ack_table_put(osdk_ack_table_t *t, uint8_t session, uint16_t seq, uint8_t cmd_set, uint8_t cmd_id)
{
    long at = find(t, session, seq);
    if (at >= 0) {
        t->items[at].cmd_set = cmd_set;
        t->items[at].cmd_id = cmd_id;
        return;
    }
    t->items[t->count].session = session;
    t->items[t->count].seq = seq;
    t->items[t->count].cmd_set = cmd_set;
    t->items[t->count].cmd_id = cmd_id;
    t->count++;
    if (t->count > t->limit) remove_at(t, 0);
}

bool osdk_ack_table_take(osdk_ack_table_t *t, uint8_t session, uint16_t seq, uint8_t *cmd_set, uint8_t *cmd_id)
{
    long at = find(t, session, seq);
    if (at < 0) return false;
    *cmd_set = t->items[at].cmd_set;
    *cmd_id = t->items[at].cmd_id;
    remove_at(t, (size_t)at);
    return true;
}
