/* Generated from spec/ by tools/cgen/generate.py. Do not edit. */
/* osdk_deframer.c - see osdk_deframer.h. */
#include "osdk_deframer.h"

#include <stdarg.h>
#include <string.h>

#include "osdk_crc.h"

#define HEADER_LEN OSDK_FRAME_HEADER_LEN
#define CRC32_LEN 4u

/* The details' own printf subset (%u, %lu, %0Nx, %0Nlx), so that the
 * receiver needs no <stdio.h> on a board without one; truncates like
 * snprintf and always terminates. */
static void osdk_detail(char *buf, size_t cap, const char *fmt, ...)
{
    va_list ap;
    size_t n = 0;
    if (buf == NULL || cap == 0) return;
    va_start(ap, fmt);
    while (*fmt) {
        char digits[24];
        unsigned width = 0, base, k = 0;
        unsigned long v;
        if (*fmt != '%') {
            if (n + 1 < cap) buf[n++] = *fmt;
            fmt++;
            continue;
        }
        fmt++;
        if (*fmt == '0') fmt++;
        while (*fmt >= '0' && *fmt <= '9') width = width * 10u + (unsigned)(*fmt++ - '0');
        if (*fmt == 'l') {
            fmt++;
            v = va_arg(ap, unsigned long);
        } else {
            v = va_arg(ap, unsigned);
        }
        base = *fmt == 'x' ? 16u : 10u;
        if (*fmt) fmt++;
        do {
            digits[k++] = "0123456789abcdef"[v % base];
            v /= base;
        } while (v && k < sizeof digits);
        while (k < width && k < sizeof digits) digits[k++] = '0';
        while (k && n + 1 < cap) buf[n++] = digits[--k];
    }
    buf[n] = '\0';
    va_end(ap);
}

static uint32_t le32(const uint8_t *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

osdk_status_t osdk_frame_header_problem(const uint8_t *header, char *detail, size_t cap)
{
    uint16_t computed = osdk_crc16(header + 0, 10u);
    uint64_t stored = osdk_frame_peek_crc16(header);
    if ((uint64_t)computed != stored) {
        osdk_detail(detail, cap, "CRC-16 is 0x%04x, expected 0x%04x", (unsigned)stored, (unsigned)computed);
        return OSDK_ERR_BAD_CRC16;
    }
    {
        uint64_t v = osdk_frame_peek_ver(header);
        if (!osdk_frame_valid_ver((int64_t)v)) {
            osdk_detail(detail, cap, "header field ver is %lu, which its valid check rejects", (unsigned long)v);
            return OSDK_ERR_BAD_VERSION;
        }
    }
    {
        uint64_t v = osdk_frame_peek_res0(header);
        if (!osdk_frame_valid_res0((int64_t)v)) {
            osdk_detail(detail, cap, "header field res0 is %lu, which its valid check rejects", (unsigned long)v);
            return OSDK_ERR_RESERVED_BITS;
        }
    }
    {
        uint64_t v = osdk_frame_peek_res1(header);
        if (!osdk_frame_valid_res1((int64_t)v)) {
            osdk_detail(detail, cap, "header field res1 is %lu, which its valid check rejects", (unsigned long)v);
            return OSDK_ERR_RESERVED_BITS;
        }
    }
    {
        uint64_t v = osdk_frame_peek_len(header);
        if (!osdk_frame_valid_len((int64_t)v)) {
            osdk_detail(detail, cap, "header field len is %lu, which its valid check rejects", (unsigned long)v);
            return OSDK_ERR_IMPOSSIBLE_LENGTH;
        }
    }
    osdk_detail(detail, cap, "header ok");
    return OSDK_OK;
}

osdk_status_t osdk_frame_problem(const uint8_t *data, size_t len, char *detail, size_t cap)
{
    osdk_status_t st;
    uint64_t length;
    if (len == 0) {
        osdk_detail(detail, cap, "no bytes at all");
        return OSDK_ERR_TRUNCATED_FRAME;
    }
    if (data[0] != OSDK_FRAME_SOF) {
        osdk_detail(detail, cap, "first byte 0x%02x is not the start byte", (unsigned)data[0]);
        return OSDK_ERR_BAD_SOF;
    }
    if (len < HEADER_LEN) {
        osdk_detail(detail, cap, "%lu byte(s), less than the header", (unsigned long)len);
        return OSDK_ERR_TRUNCATED_FRAME;
    }
    st = osdk_frame_header_problem(data, detail, cap);
    if (st != OSDK_OK) return st;
    length = osdk_frame_peek_len(data);
    if (len < length) {
        osdk_detail(detail, cap, "%lu byte(s) of a frame of LEN %lu", (unsigned long)len, (unsigned long)length);
        return OSDK_ERR_TRUNCATED_FRAME;
    }
    if (len > length) {
        osdk_detail(detail, cap, "%lu bytes for a frame of LEN %lu", (unsigned long)len, (unsigned long)length);
        return OSDK_ERR_LENGTH_MISMATCH;
    }
    if (length > HEADER_LEN) {
        uint32_t computed = osdk_crc32(data, (size_t)length - CRC32_LEN);
        uint32_t stored = le32(data + length - CRC32_LEN);
        if (computed != stored) {
            osdk_detail(detail, cap, "CRC-32 is 0x%08lx, expected 0x%08lx", (unsigned long)stored,
                        (unsigned long)computed);
            return OSDK_ERR_BAD_CRC32;
        }
    }
    return OSDK_OK;
}

bool osdk_deframer_init(osdk_deframer_t *d, uint8_t *buf, size_t cap)
{
    memset(d, 0, sizeof *d);
    if (buf == NULL || cap < OSDK_DEFRAMER_MIN_BUFFER) return false;
    d->buf = buf;
    d->cap = cap;
    return true;
}

static void drop(osdk_deframer_t *d, size_t n)
{
    d->start += n;
    d->fill -= n;
    d->base += n;
    if (d->fill == 0) d->start = 0;
}

static void flush_garbage(osdk_deframer_t *d, osdk_event_fn fn, void *user)
{
    osdk_event_t ev;
    if (!d->in_garbage) return;
    memset(&ev, 0, sizeof ev);
    ev.kind = OSDK_EVENT_GARBAGE;
    ev.offset = d->garbage_start;
    ev.length = (size_t)(d->base - d->garbage_start);
    d->in_garbage = false;
    fn(user, &ev);
}

static void reject(osdk_deframer_t *d, osdk_status_t st, size_t length, osdk_event_fn fn, void *user)
{
    osdk_event_t ev;
    memset(&ev, 0, sizeof ev);
    ev.kind = OSDK_EVENT_ERROR;
    ev.offset = d->base;
    ev.length = length;
    ev.error = st;
    ev.detail = d->detail;
    fn(user, &ev);
    drop(d, 1);
}

static void scan(osdk_deframer_t *d, bool final, osdk_event_fn fn, void *user)
{
    while (d->fill > 0) {
        const uint8_t *p = d->buf + d->start;
        osdk_status_t st;
        uint64_t length;
        if (p[0] != OSDK_FRAME_SOF) {
            const uint8_t *next = memchr(p, OSDK_FRAME_SOF, d->fill);
            size_t n = next ? (size_t)(next - p) : d->fill;
            if (!d->in_garbage) {
                d->in_garbage = true;
                d->garbage_start = d->base;
            }
            drop(d, n);
            continue;
        }
        flush_garbage(d, fn, user);
        if (d->fill < HEADER_LEN) {
            if (!final) break;
            osdk_detail(d->detail, sizeof d->detail, "input ended after %lu byte(s) of a header",
                        (unsigned long)d->fill);
            reject(d, OSDK_ERR_TRUNCATED_FRAME, d->fill, fn, user);
            continue;
        }
        st = osdk_frame_header_problem(p, d->detail, sizeof d->detail);
        if (st != OSDK_OK) {
            reject(d, st, 1, fn, user);
            continue;
        }
        length = osdk_frame_peek_len(p);
        if (d->fill < length) {
            if (!final) break;
            osdk_detail(d->detail, sizeof d->detail, "input ended after %lu byte(s) of LEN %lu",
                        (unsigned long)d->fill, (unsigned long)length);
            reject(d, OSDK_ERR_TRUNCATED_FRAME, d->fill, fn, user);
            continue;
        }
        if (length > HEADER_LEN) {
            uint32_t computed = osdk_crc32(p, (size_t)length - CRC32_LEN);
            uint32_t stored = le32(p + length - CRC32_LEN);
            if (computed != stored) {
                osdk_detail(d->detail, sizeof d->detail, "CRC-32 is 0x%08lx, expected 0x%08lx",
                            (unsigned long)stored, (unsigned long)computed);
                reject(d, OSDK_ERR_BAD_CRC32, (size_t)length, fn, user);
                continue;
            }
        }
        {
            osdk_event_t ev;
            memset(&ev, 0, sizeof ev);
            ev.kind = OSDK_EVENT_FRAME;
            ev.offset = d->base;
            ev.length = (size_t)length;
            ev.raw = p;
            fn(user, &ev);
            drop(d, (size_t)length);
        }
    }
    if (final) flush_garbage(d, fn, user);
}

void osdk_deframer_feed(osdk_deframer_t *d, const uint8_t *data, size_t len, osdk_event_fn fn, void *user)
{
    if (d->buf == NULL) return;
    while (len > 0) {
        size_t space, k;
        if (d->start > 0 && d->start + d->fill == d->cap) {
            memmove(d->buf, d->buf + d->start, d->fill);
            d->start = 0;
        }
        space = d->cap - (d->start + d->fill);
        if (space == 0) {
            /* cannot happen: the scan only waits while the window holds less
             * than one maximum-length frame, and the buffer holds one */
            break;
        }
        k = len < space ? len : space;
        memcpy(d->buf + d->start + d->fill, data, k);
        d->fill += k;
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
