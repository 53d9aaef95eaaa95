/* Generated from spec/ by tools/cgen/generate.py. Do not edit. */
/*
 * osdk_deframer.h - find frames in a byte stream the way the SDK's
 * receiver does, on a fixed caller-supplied buffer (no heap).
 *
 * The receiver hunts for the start byte, checks the 12-byte header
 * (CRC-16 first, then the header checks of rules.yaml frame.receiver, each
 * with the field's `valid` from the .ksy) and on any failure drops that ONE
 * byte and hunts again. With a good header it waits for LEN bytes and
 * checks the CRC-32; on failure it rescans from the byte after the rejected
 * start byte. Unlike the SDK, every rejection is reported as an event, with
 * its absolute offset; bytes before a start byte are reported as garbage.
 * At the end of input (osdk_deframer_finish) a started frame is reported
 * as truncated_frame and scanning resumes after its start byte.
 *
 * Events do not depend on how the input is cut into feed() calls.
 */
#ifndef OSDK_DEFRAMER_H
#define OSDK_DEFRAMER_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "osdk_decoder.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The smallest buffer a deframer accepts: one maximum-length frame. */
#define OSDK_DEFRAMER_MIN_BUFFER OSDK_FRAME_MAX_LEN

typedef enum {
    OSDK_EVENT_FRAME = 0,   /* a frame whose header and CRCs check out */
    OSDK_EVENT_ERROR = 1,   /* bytes the receiver rejected */
    OSDK_EVENT_GARBAGE = 2  /* a run of bytes that held no start byte */
} osdk_event_kind_t;

typedef struct {
    osdk_event_kind_t kind;
    uint64_t offset;       /* absolute offset of the first byte */
    size_t length;         /* bytes covered (frame length, garbage run, rejection) */
    osdk_status_t error;   /* OSDK_EVENT_ERROR: the error class */
    const char *detail;    /* OSDK_EVENT_ERROR: for people; valid during the callback */
    const uint8_t *raw;    /* OSDK_EVENT_FRAME: the frame's bytes; valid during the callback */
} osdk_event_t;

/* The room for an error event's detail sentence, its terminating NUL included. */
#define OSDK_DEFRAMER_DETAIL_LEN 160u

typedef void (*osdk_event_fn)(void *user, const osdk_event_t *ev);

typedef struct {
    uint8_t *buf;
    size_t cap;
    size_t start;          /* window is buf[start .. start + fill) */
    size_t fill;
    uint64_t base;         /* absolute offset of buf[start] */
    bool in_garbage;
    uint64_t garbage_start;
    size_t pending;        /* the frame last reported: dropped when the next event is looked for */
    char detail[OSDK_DEFRAMER_DETAIL_LEN];
} osdk_deframer_t;

/* The comments that open with an @ are ACSL contracts: what `make prove`
 * proves the functions against (docs/VERIFICATION.md). A deframer is
 * usable when its window lies in its buffer and the buffer holds one
 * maximum-length frame (or it has no buffer: init failed). */
/*@ predicate osdk_deframer_ok(osdk_deframer_t *d) =
      \valid(d) &&
      (d->buf == \null ||
       (d->cap >= OSDK_DEFRAMER_MIN_BUFFER && d->start + d->fill <= d->cap &&
        \valid(d->buf + (0 .. d->cap - 1)) && \separated(d, d->buf + (0 .. d->cap - 1))));
*/

/* buf must hold at least OSDK_DEFRAMER_MIN_BUFFER bytes; false otherwise. */
/*@ requires \valid(d);
    requires buf == \null || cap == 0 || \valid(buf + (0 .. cap - 1));
    requires buf == \null || \separated(d, buf + (0 .. cap - 1));
    assigns *d;
    ensures osdk_deframer_ok(d) && d->pending == 0; */
bool osdk_deframer_init(osdk_deframer_t *d, uint8_t *buf, size_t cap);
#ifdef __FRAMAC__
/* What the proof assumes of the caller's event callback (docs/VERIFICATION.md):
 * it reads the event and writes nothing the deframer owns. The contracts
 * below name this model as fn; it is declared for Frama-C only, and no
 * program defines it. */
/*@ requires \valid_read(ev);
    assigns \nothing; */
void osdk_event_model(void *user, const osdk_event_t *ev);
#endif

/* Feed any number of bytes; fn is called for every event they complete.
 * data must not lie in the deframer's own buffer, and fn must not call
 * back into the same deframer (d->pending is 0 between calls, never
 * during a callback). */
/*@ requires osdk_deframer_ok(d) && d->pending == 0;
    requires len == 0 || \valid_read(data + (0 .. len - 1));
    requires d->buf == \null || len == 0 || \separated(data + (0 .. len - 1), d->buf + (0 .. d->cap - 1));
    requires fn == &osdk_event_model;
    assigns d->buf[0 .. d->cap - 1], d->start, d->fill, d->base, d->pending, d->in_garbage, d->garbage_start,
            d->detail[0 .. OSDK_DEFRAMER_DETAIL_LEN - 1];
    ensures osdk_deframer_ok(d) && d->pending == 0; */
void osdk_deframer_feed(osdk_deframer_t *d, const uint8_t *data, size_t len, osdk_event_fn fn, void *user);
/* The input has ended: report what is left. */
/*@ requires osdk_deframer_ok(d) && d->pending == 0;
    requires fn == &osdk_event_model;
    assigns d->start, d->fill, d->base, d->pending, d->in_garbage, d->garbage_start,
            d->detail[0 .. OSDK_DEFRAMER_DETAIL_LEN - 1];
    ensures osdk_deframer_ok(d) && d->pending == 0; */
void osdk_deframer_finish(osdk_deframer_t *d, osdk_event_fn fn, void *user);

/* The first thing wrong with a 12-byte header, in the receiver's order,
 * or OSDK_OK. detail (may be NULL) receives a sentence for people. */
/*@ requires \valid_read(header + (0 .. OSDK_FRAME_HEADER_LEN - 1));
    requires detail == \null || cap == 0 || \valid(detail + (0 .. cap - 1));
    assigns detail[0 .. cap - 1]; */
osdk_status_t osdk_frame_header_problem(const uint8_t *header, char *detail, size_t cap);

/* The checks a receiver makes on bytes handed over as exactly one frame,
 * before its DATA is parsed: start byte (bad_sof), fewer than a header
 * (truncated_frame), the header, byte count against LEN (truncated_frame /
 * length_mismatch) and CRC-32 (bad_crc32). OSDK_OK when all pass. */
/*@ requires len == 0 || \valid_read(data + (0 .. len - 1));
    requires detail == \null || cap == 0 || \valid(detail + (0 .. cap - 1));
    assigns detail[0 .. cap - 1]; */
osdk_status_t osdk_frame_problem(const uint8_t *data, size_t len, char *detail, size_t cap);

#ifdef __cplusplus
}
#endif

#endif /* OSDK_DEFRAMER_H */
