/* Generated from spec/ by tools/cgen/generate.py. Do not edit. */
/*
 * osdk_acks.h - matching ACKs to the commands they answer, in a stream
 * (conformance/PROTOCOL.md, "ACK matching"; ERRATA E32), as DJI's receivers
 * do: one slot per session 2..31. A plain command that decoded, in one of
 * those sessions, takes its session's slot (replacing whatever waited
 * there); an ACK in that session with the same SEQ is matched and empties
 * the slot. Sessions 0 and 1 have no slot: their commands wait for nothing
 * and their ACKs are never matched. No heap: the caller holds the slots.
 */
#ifndef OSDK_ACKS_H
#define OSDK_ACKS_H

#include <stdbool.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define OSDK_ACK_FIRST_SESSION 2u /* sessions OSDK_ACK_FIRST_SESSION..31 have a slot */
#define OSDK_ACK_SESSIONS 32u

typedef struct {
    uint16_t seq;
    uint8_t cmd_set;
    uint8_t cmd_id;
    bool waiting; /* a command is in the slot */
} osdk_ack_slot_t;

typedef struct {
    osdk_ack_slot_t slot[OSDK_ACK_SESSIONS]; /* indexed by session; 0 and 1 unused */
} osdk_acks_t;

/* Every slot empty. */
/*@ requires \valid(t);
    assigns t->slot[0 .. OSDK_ACK_SESSIONS - 1].waiting; */
void osdk_acks_init(osdk_acks_t *t);
/* A plain command frame that decoded: it takes its session's slot (nothing happens in sessions 0 and 1). */
/*@ requires \valid(t);
    assigns t->slot[session]; */
void osdk_acks_command(osdk_acks_t *t, uint8_t session, uint16_t seq, uint8_t cmd_set, uint8_t cmd_id);
/* A plain ACK frame (header-only ones too): the command it answers, taken out of its session's slot;
 * false when its session has no slot, the slot is empty or holds another SEQ (the slot then stays). */
/*@ requires \valid(t) && \valid(cmd_set) && \valid(cmd_id);
    requires \separated(t, cmd_set, cmd_id);
    assigns t->slot[session].waiting, *cmd_set, *cmd_id;
    ensures \result ==> session >= OSDK_ACK_FIRST_SESSION && session < OSDK_ACK_SESSIONS; */
bool osdk_acks_take(osdk_acks_t *t, uint8_t session, uint16_t seq, uint8_t *cmd_set, uint8_t *cmd_id);

#ifdef __cplusplus
}
#endif

#endif /* OSDK_ACKS_H */
