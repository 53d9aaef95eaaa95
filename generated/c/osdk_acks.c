/* Generated from spec/ by tools/cgen/generate.py. Do not edit. */
/* osdk_acks.c - see osdk_acks.h. */
#include "osdk_acks.h"

void osdk_acks_init(osdk_acks_t *t)
{
    unsigned i;
    /*@ loop invariant 0 <= i <= OSDK_ACK_SESSIONS;
        loop assigns i, t->slot[0 .. OSDK_ACK_SESSIONS - 1].waiting;
        loop variant OSDK_ACK_SESSIONS - i; */
    for (i = 0; i < OSDK_ACK_SESSIONS; i++) t->slot[i].waiting = false;
}

void osdk_acks_command(osdk_acks_t *t, uint8_t session, uint16_t seq, uint8_t cmd_set, uint8_t cmd_id)
{
    osdk_ack_slot_t *s;
    if (session < OSDK_ACK_FIRST_SESSION || session >= OSDK_ACK_SESSIONS) return;
    s = &t->slot[session];
    s->seq = seq;
    s->cmd_set = cmd_set;
    s->cmd_id = cmd_id;
    s->waiting = true;
}

bool osdk_acks_take(osdk_acks_t *t, uint8_t session, uint16_t seq, uint8_t *cmd_set, uint8_t *cmd_id)
{
    osdk_ack_slot_t *s;
    if (session < OSDK_ACK_FIRST_SESSION || session >= OSDK_ACK_SESSIONS) return false;
    s = &t->slot[session];
    if (!s->waiting || s->seq != seq) return false;
    *cmd_set = s->cmd_set;
    *cmd_id = s->cmd_id;
    s->waiting = false;
    return true;
}
