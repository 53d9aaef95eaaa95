/* Generated from spec/ by tools/cgen/generate.py. Do not edit. */
/*
 * osdk_acks.h - matching ACKs to the commands they answer, in a stream
 * (conformance/PROTOCOL.md, "ACK matching"): a command sent in a session
 * (SESSION > 0) waits under its (SESSION, SEQ) until an ACK frame with the
 * same pair arrives. The table is bounded: a command whose key is already
 * waiting keeps its place and takes the new command set and id; past the
 * limit the oldest is forgotten. No heap: the caller supplies the entries.
 */
#ifndef OSDK_ACKS_H
#define OSDK_ACKS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    uint8_t session;
    uint16_t seq;
    uint8_t cmd_set;
    uint8_t cmd_id;
} osdk_pending_t;

typedef struct {
    osdk_pending_t *items; /* limit + 1 entries, oldest first */
    size_t count;
    size_t limit;
} osdk_ack_table_t;

/* items must hold limit + 1 entries; limit at least 1. */
void osdk_ack_table_init(osdk_ack_table_t *t, osdk_pending_t *items, size_t limit);
/* A command sent in a session (callers skip session 0, which is never ACKed). */
void osdk_ack_table_put(osdk_ack_table_t *t, uint8_t session, uint16_t seq, uint8_t cmd_set, uint8_t cmd_id);
/* The command an ACK of (session, seq) answers, taken off the table; false when none waits. */
bool osdk_ack_table_take(osdk_ack_table_t *t, uint8_t session, uint16_t seq, uint8_t *cmd_set, uint8_t *cmd_id);

#ifdef __cplusplus
}
#endif

#endif /* OSDK_ACKS_H */
