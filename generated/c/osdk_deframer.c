/* Generated from spec/ by tools/cgen/generate.py. Do not edit. */
/* osdk_deframer.c - see osdk_deframer.h.
 *
 * Shaped for the proof (docs/VERIFICATION.md): no libc call (copies and
 * scans are loops over bytes, structs are zeroed by assignment), the
 * detail formatter takes its arguments as plain parameters, and every
 * state change happens in next_event(); the three functions that hand
 * events to the caller's callback only loop over it, and are proved with
 * the callback's model (osdk_event_model in the header). */
#include "osdk_deframer.h"

#include "osdk_crc.h"

#define HEADER_LEN OSDK_FRAME_HEADER_LEN
#define CRC32_LEN 4u
#define DIGITS 24u   /* of a number in the details: more than 2^64 has in base 10 */

/* The details' own printf subset (%u, %lu, %0Nx, %0Nlx, at most two
 * conversions, each taking the next of a and b), so that the receiver needs
 * no <stdio.h> on a board without one; truncates like snprintf and always
 * terminates. fmt is a literal: DETAIL passes its length. */
/*@ requires buf == \null || cap == 0 || \valid(buf + (0 .. cap - 1));
    requires \valid_read(fmt + (0 .. flen - 1));
    assigns buf[0 .. cap - 1]; */
static void osdk_detail(char *buf, size_t cap, const char *fmt, size_t flen, unsigned long a, unsigned long b)
{
    size_t n = 0, i = 0;
    unsigned arg = 0;
    if (buf == NULL || cap == 0) return;
    /*@ loop invariant 0 <= i <= flen && n < cap && arg <= 2;
        loop assigns i, n, arg, buf[0 .. cap - 1];
        loop variant flen - i; */
    while (i < flen) {
        char digits[DIGITS];
        unsigned width = 0, base;
        size_t k = 0;
        unsigned long v;
        if (fmt[i] != '%') {
            if (n + 1 < cap) buf[n++] = fmt[i];
            i++;
        } else {
            i++;
            if (i < flen && fmt[i] == '0') i++;
            /*@ loop invariant \at(i, LoopEntry) <= i <= flen;
                loop assigns i, width;
                loop variant flen - i; */
            while (i < flen && fmt[i] >= '0' && fmt[i] <= '9') {
                width = width * 10u + (unsigned)(fmt[i] - '0');
                i++;
            }
            if (i < flen && fmt[i] == 'l') i++;
            v = arg == 0 ? a : arg == 1 ? b : 0u;
            if (arg < 2) arg++;
            base = (i < flen && fmt[i] == 'x') ? 16u : 10u;
            if (i < flen) i++;
            /* digits, lowest first: a computed digit, not an index into a literal */
            /*@ loop invariant 0 <= k < DIGITS;
                loop assigns k, v, digits[0 .. DIGITS - 1];
                loop variant DIGITS - k; */
            for (;;) {
                unsigned digit = (unsigned)(v % base);
                digits[k++] = (char)(digit < 10u ? '0' + digit : 'a' + (digit - 10u));
                v /= base;
                if (v == 0 || k == DIGITS) break;
            }
            /*@ loop invariant 0 <= k <= DIGITS;
                loop assigns k, digits[0 .. DIGITS - 1];
                loop variant DIGITS - k; */
            while (k < width && k < DIGITS) digits[k++] = '0';
            /*@ loop invariant 0 <= k <= DIGITS && n < cap;
                loop assigns k, n, buf[0 .. cap - 1];
                loop variant k; */
            while (k > 0 && n + 1 < cap) buf[n++] = digits[--k];
        }
    }
    buf[n] = '\0';
}

#define DETAIL(buf, cap, fmt, a, b) \
    osdk_detail((buf), (cap), (fmt), sizeof(fmt) - 1u, (unsigned long)(a), (unsigned long)(b))

/*@ requires \valid_read(p + (0 .. 3));
    assigns \nothing; */
static uint32_t le32(const uint8_t *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

osdk_status_t osdk_frame_header_problem(const uint8_t *header, char *detail, size_t cap)
{
    uint16_t computed = osdk_crc16(header + 0, 10u);
    uint64_t stored = osdk_frame_peek_crc16(header);
    if ((uint64_t)computed != stored) {
        DETAIL(detail, cap, "CRC-16 is 0x%04x, expected 0x%04x", stored, computed);
        return OSDK_ERR_BAD_CRC16;
    }
    {
        uint64_t v = osdk_frame_peek_ver(header);
        if (!osdk_frame_valid_ver((int64_t)v)) {
            DETAIL(detail, cap, "header field ver is %lu, which its valid check rejects", v, 0);
            return OSDK_ERR_BAD_VERSION;
        }
    }
    {
        uint64_t v = osdk_frame_peek_res0(header);
        if (!osdk_frame_valid_res0((int64_t)v)) {
            DETAIL(detail, cap, "header field res0 is %lu, which its valid check rejects", v, 0);
            return OSDK_ERR_RESERVED_BITS;
        }
    }
    {
        uint64_t v = osdk_frame_peek_res1(header);
        if (!osdk_frame_valid_res1((int64_t)v)) {
            DETAIL(detail, cap, "header field res1 is %lu, which its valid check rejects", v, 0);
            return OSDK_ERR_RESERVED_BITS;
        }
    }
    {
        uint64_t v = osdk_frame_peek_len(header);
        if (!osdk_frame_valid_len((int64_t)v)) {
            DETAIL(detail, cap, "header field len is %lu, which its valid check rejects", v, 0);
            return OSDK_ERR_IMPOSSIBLE_LENGTH;
        }
    }
    DETAIL(detail, cap, "header ok", 0, 0);
    return OSDK_OK;
}

osdk_status_t osdk_frame_problem(const uint8_t *data, size_t len, char *detail, size_t cap)
{
    osdk_status_t st;
    uint64_t length;
    if (len == 0) {
        DETAIL(detail, cap, "no bytes at all", 0, 0);
        return OSDK_ERR_TRUNCATED_FRAME;
    }
    if (data[0] != OSDK_FRAME_SOF) {
        DETAIL(detail, cap, "first byte 0x%02x is not the start byte", data[0], 0);
        return OSDK_ERR_BAD_SOF;
    }
    if (len < HEADER_LEN) {
        DETAIL(detail, cap, "%lu byte(s), less than the header", len, 0);
        return OSDK_ERR_TRUNCATED_FRAME;
    }
    st = osdk_frame_header_problem(data, detail, cap);
    if (st != OSDK_OK) return st;
    length = osdk_frame_peek_len(data);
    if (len < length) {
        DETAIL(detail, cap, "%lu byte(s) of a frame of LEN %lu", len, length);
        return OSDK_ERR_TRUNCATED_FRAME;
    }
    if (len > length) {
        DETAIL(detail, cap, "%lu bytes for a frame of LEN %lu", len, length);
        return OSDK_ERR_LENGTH_MISMATCH;
    }
    if (length > HEADER_LEN) {
        uint32_t computed = osdk_crc32(data, (size_t)length - CRC32_LEN);
        uint32_t stored = le32(data + length - CRC32_LEN);
        if (computed != stored) {
            DETAIL(detail, cap, "CRC-32 is 0x%08lx, expected 0x%08lx", stored, computed);
            return OSDK_ERR_BAD_CRC32;
        }
    }
    return OSDK_OK;
}

bool osdk_deframer_init(osdk_deframer_t *d, uint8_t *buf, size_t cap)
{
    static const osdk_deframer_t empty;
    *d = empty;
    if (buf == NULL || cap < OSDK_DEFRAMER_MIN_BUFFER) return false;
    d->buf = buf;
    d->cap = cap;
    return true;
}

/*@ requires osdk_deframer_ok(d) && d->buf != \null && n <= d->fill;
    assigns d->start, d->fill, d->base;
    ensures osdk_deframer_ok(d) && d->fill == \old(d->fill) - n; */
static void drop(osdk_deframer_t *d, size_t n)
{
    d->start += n;
    d->fill -= n;
    d->base += n;
    if (d->fill == 0) d->start = 0;
}

/* How many of the n bytes at p come before the first start byte. */
/*@ requires \valid_read(p + (0 .. n - 1));
    assigns \nothing;
    ensures \result <= n;
    ensures n > 0 && p[0] != OSDK_FRAME_SOF ==> \result > 0; */
static size_t before_sof(const uint8_t *p, size_t n)
{
    size_t i = 0;
    /*@ loop invariant 0 <= i <= n;
        loop invariant \forall integer j; 0 <= j < i ==> p[j] != OSDK_FRAME_SOF;
        loop assigns i;
        loop variant n - i; */
    while (i < n && p[i] != OSDK_FRAME_SOF) i++;
    return i;
}

/* A rejection: the event for bytes at the window's start, then the receiver
 * moves on by one byte. */
/*@ requires osdk_deframer_ok(d) && d->buf != \null && d->fill >= 1;
    requires \valid(ev) && \separated(ev, d);
    assigns *ev, d->start, d->fill, d->base;
    ensures osdk_deframer_ok(d) && ev->kind == OSDK_EVENT_ERROR; */
static void reject(osdk_deframer_t *d, osdk_event_t *ev, osdk_status_t st, size_t length)
{
    static const osdk_event_t none;
    *ev = none;
    ev->kind = OSDK_EVENT_ERROR;
    ev->offset = d->base;
    ev->length = length;
    ev->error = st;
    ev->detail = d->detail;
    drop(d, 1);
}

/*@ requires \valid(d) && \valid(ev) && \separated(ev, d);
    assigns *ev, d->in_garbage;
    ensures ev->kind == OSDK_EVENT_GARBAGE; */
static void garbage(osdk_deframer_t *d, osdk_event_t *ev)
{
    static const osdk_event_t none;
    *ev = none;
    ev->kind = OSDK_EVENT_GARBAGE;
    ev->offset = d->garbage_start;
    ev->length = (size_t)(d->base - d->garbage_start);
    d->in_garbage = false;
}

/* The next event the window holds, into *ev; false when it needs more input
 * (or, final, holds nothing more). A frame stays in the window until the
 * next call, so that ev->raw stays valid while the caller uses it. */
/*@ requires osdk_deframer_ok(d) && d->buf != \null && d->pending <= d->fill;
    requires \valid(ev) && \separated(ev, d, d->buf + (0 .. d->cap - 1));
    assigns *ev, d->start, d->fill, d->base, d->pending, d->in_garbage, d->garbage_start, d->detail[0 .. OSDK_DEFRAMER_DETAIL_LEN - 1];
    ensures osdk_deframer_ok(d);
    ensures d->pending <= d->fill;
    ensures !\result ==> d->pending == 0; */
/* (That a frame event's raw[0 .. length) is readable is proved as an
 * assertion where the frame is reported: as a postcondition over every
 * return, the provers ran out of time.) */
static bool next_event(osdk_deframer_t *d, bool final, osdk_event_t *ev)
{
    drop(d, d->pending);
    d->pending = 0;
    /*@ loop invariant osdk_deframer_ok(d) && d->pending == 0;
        loop assigns d->start, d->fill, d->base, d->in_garbage, d->garbage_start;
        loop variant d->fill; */
    while (d->fill > 0) {
        const uint8_t *p = d->buf + d->start;
        osdk_status_t st;
        uint64_t length;
        if (p[0] != OSDK_FRAME_SOF) {
            size_t n = before_sof(p, d->fill);
            if (!d->in_garbage) {
                d->in_garbage = true;
                d->garbage_start = d->base;
            }
            drop(d, n);
            continue;
        }
        if (d->in_garbage) {
            garbage(d, ev);
            /*@ assert osdk_deframer_ok(d) && d->pending <= d->fill; */
            /*@ assert ev->kind == OSDK_EVENT_FRAME ==> \valid_read(ev->raw + (0 .. ev->length - 1)); */
            return true;
        }
        if (d->fill < HEADER_LEN) {
            if (!final) return false;
            DETAIL(d->detail, sizeof d->detail, "input ended after %lu byte(s) of a header", d->fill, 0);
            reject(d, ev, OSDK_ERR_TRUNCATED_FRAME, d->fill);
            /*@ assert osdk_deframer_ok(d) && d->pending <= d->fill; */
            /*@ assert ev->kind == OSDK_EVENT_FRAME ==> \valid_read(ev->raw + (0 .. ev->length - 1)); */
            return true;
        }
        st = osdk_frame_header_problem(p, d->detail, sizeof d->detail);
        if (st != OSDK_OK) {
            reject(d, ev, st, 1);
            /*@ assert osdk_deframer_ok(d) && d->pending <= d->fill; */
            /*@ assert ev->kind == OSDK_EVENT_FRAME ==> \valid_read(ev->raw + (0 .. ev->length - 1)); */
            return true;
        }
        length = osdk_frame_peek_len(p);
        if (d->fill < length) {
            if (!final) return false;
            DETAIL(d->detail, sizeof d->detail, "input ended after %lu byte(s) of LEN %lu", d->fill, length);
            reject(d, ev, OSDK_ERR_TRUNCATED_FRAME, d->fill);
            /*@ assert osdk_deframer_ok(d) && d->pending <= d->fill; */
            /*@ assert ev->kind == OSDK_EVENT_FRAME ==> \valid_read(ev->raw + (0 .. ev->length - 1)); */
            return true;
        }
        if (length > HEADER_LEN) {
            uint32_t computed = osdk_crc32(p, (size_t)length - CRC32_LEN);
            uint32_t stored = le32(p + length - CRC32_LEN);
            if (computed != stored) {
                DETAIL(d->detail, sizeof d->detail, "CRC-32 is 0x%08lx, expected 0x%08lx", stored, computed);
                reject(d, ev, OSDK_ERR_BAD_CRC32, (size_t)length);
                /*@ assert osdk_deframer_ok(d) && d->pending <= d->fill; */
                /*@ assert ev->kind == OSDK_EVENT_FRAME ==> \valid_read(ev->raw + (0 .. ev->length - 1)); */
                return true;
            }
        }
        {
            static const osdk_event_t none;
            *ev = none;
            ev->kind = OSDK_EVENT_FRAME;
            ev->offset = d->base;
            ev->length = (size_t)length;
            ev->raw = p;
            d->pending = (size_t)length;
            /*@ assert osdk_deframer_ok(d) && d->pending <= d->fill; */
            /*@ assert ev->kind == OSDK_EVENT_FRAME ==> \valid_read(ev->raw + (0 .. ev->length - 1)); */
            return true;
        }
    }
    if (final && d->in_garbage) {
        garbage(d, ev);
        /*@ assert osdk_deframer_ok(d) && d->pending <= d->fill; */
        /*@ assert ev->kind == OSDK_EVENT_FRAME ==> \valid_read(ev->raw + (0 .. ev->length - 1)); */
        return true;
    }
    /*@ assert osdk_deframer_ok(d) && d->pending <= d->fill; */
    return false;
}

/* Appends as much of data as the window has room for (moving the window to
 * the buffer's start when it reaches the end); how many bytes it took. */
/*@ requires osdk_deframer_ok(d) && d->buf != \null && d->pending == 0;
    requires \valid_read(data + (0 .. len - 1));
    requires \separated(data + (0 .. len - 1), d->buf + (0 .. d->cap - 1));
    assigns d->buf[0 .. d->cap - 1], d->start, d->fill;
    ensures osdk_deframer_ok(d) && d->pending == 0 && \result <= len; */
static size_t take(osdk_deframer_t *d, const uint8_t *restrict data, size_t len)
{
    /* The window in locals and the bytes through restrict pointers: else a
     * byte store may alias d, the compiler reads d's fields again after each
     * one, and the copy is about a fifth slower than memcpy (gcc -O2 makes
     * this loop a memcpy call). */
    uint8_t *restrict buf = d->buf;
    size_t start = d->start, fill = d->fill, space, k, i;
    if (start > 0 && start + fill == d->cap) {
        /*@ loop invariant 0 <= i <= fill;
            loop assigns i, buf[0 .. d->cap - 1];
            loop variant fill - i; */
        for (i = 0; i < fill; i++) buf[i] = buf[start + i];   /* forward: the source is above */
        start = 0;
    }
    space = d->cap - (start + fill);
    k = len < space ? len : space;
    /*@ loop invariant 0 <= i <= k;
        loop assigns i, buf[0 .. d->cap - 1];
        loop variant k - i; */
    for (i = 0; i < k; i++) buf[start + fill + i] = data[i];
    d->start = start;
    d->fill = fill + k;
    return k;
}

/* Every event the window holds, to the callback. (No loop variant: that
 * each event consumes input is next_event's, and not stated in its
 * contract.) */
/*@ requires osdk_deframer_ok(d) && d->buf != \null && d->pending == 0;
    requires fn == &osdk_event_model;
    assigns d->start, d->fill, d->base, d->pending, d->in_garbage, d->garbage_start,
            d->detail[0 .. OSDK_DEFRAMER_DETAIL_LEN - 1];
    ensures osdk_deframer_ok(d) && d->pending == 0; */
static void scan(osdk_deframer_t *d, bool final, osdk_event_fn fn, void *user)
{
    osdk_event_t ev;
    /*@ loop invariant osdk_deframer_ok(d) && d->pending <= d->fill;
        loop assigns ev, d->start, d->fill, d->base, d->pending, d->in_garbage, d->garbage_start,
                     d->detail[0 .. OSDK_DEFRAMER_DETAIL_LEN - 1]; */
    while (next_event(d, final, &ev)) {
        /*@ calls osdk_event_model; */
        fn(user, &ev);
    }
}

void osdk_deframer_feed(osdk_deframer_t *d, const uint8_t *data, size_t len, osdk_event_fn fn, void *user)
{
    if (d->buf == NULL) return;
    /*@ loop invariant osdk_deframer_ok(d) && d->buf != \null && d->pending == 0;
        loop invariant len == 0 || \valid_read(data + (0 .. len - 1));
        loop invariant len == 0 || \separated(data + (0 .. len - 1), d->buf + (0 .. d->cap - 1));
        loop assigns data, len, d->buf[0 .. d->cap - 1], d->start, d->fill, d->base, d->pending, d->in_garbage,
                     d->garbage_start, d->detail[0 .. OSDK_DEFRAMER_DETAIL_LEN - 1];
        loop variant len; */
    while (len > 0) {
        /* room runs out only if the scan waited on more than one maximum-length
         * frame, which the buffer holds: cannot happen */
        size_t k = take(d, data, len);
        if (k == 0) break;
        data += k;
        len -= k;
        scan(d, false, fn, user);
    }
}

void osdk_deframer_finish(osdk_deframer_t *d, osdk_event_fn fn, void *user)
{
    if (d->buf == NULL) return;
    scan(d, true, fn, user);
}
