/*
 * okit.h - the C/C++ testee kit: conformance/PROTOCOL.md's request loop,
 * so that putting a C or C++ implementation under the conformance runner is
 * writing one callback per operation it performs.
 *
 * The kit reads one JSON request per line from stdin and writes exactly one
 * answer line per request to stdout. It answers `capabilities` itself (the
 * name, the operations whose callback is set, the profiles), answers
 * `unsupported` for an operation without a callback or a profile the
 * implementation does not list, and `bad_request` for a line that is not a
 * request. A callback reads its arguments with okit_int/okit_hex/... (each
 * answers `bad_request` itself when the argument is missing or wrong, and
 * returns false: the callback then returns), and answers with okit_result
 * (then writes the result with the osdk_json_* writer of
 * generated/c/osdk_json.h: floats as their IEEE bits, the value model's
 * forms), or okit_error with an error class of docs/VALUE-MODEL.md, or
 * okit_unsupported. A callback that answers nothing gets `internal_error`.
 *
 * Files: okit.c, jsonread.c (the request parser), and from generated/c
 * osdk_json.c; libc only (stdio for the loop). README.md walks through
 * wrapping an implementation; example/encode_only.c is the smallest testee.
 *
 * Built with -DOKIT_PORT (a microcontroller; conformance/testees/c-target)
 * the kit uses neither stdio nor the heap: the program provides
 * okit_port_getc and okit_port_write, a request line holds at most
 * OKIT_LINE_MAX bytes, one request's hex and chunk arguments together
 * OKIT_ARENA_MAX, an answer OKIT_ANSWER_MAX (beyond each, the request is
 * answered `internal_error`), and there is no bench mode.
 */
#ifndef OKIT_H
#define OKIT_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "osdk_json.h"

#ifdef __cplusplus
extern "C" {
#endif

#ifdef OKIT_PORT
#ifndef OKIT_LINE_MAX
#define OKIT_LINE_MAX 4096
#endif
#ifndef OKIT_ARENA_MAX
#define OKIT_ARENA_MAX 16384
#endif
#ifndef OKIT_ANSWER_MAX
#define OKIT_ANSWER_MAX 32768
#endif
/* The next byte of input (blocking), or -1 when input has ended. */
int okit_port_getc(void);
/* Write n bytes of an answer; a line ends with "\n". */
void okit_port_write(const char *text, size_t n);
#endif

typedef struct okit_request okit_request;
typedef void (*okit_op)(okit_request *req);

typedef struct {
    const char *name;              /* capabilities: what the runner calls the implementation */
    const char *const *profiles;   /* NULL-terminated wire profile ids it decodes ("a3-fw3.1", ...) */
    okit_op decode_stream;         /* NULL: not claimed, answered `unsupported` */
    okit_op decode_frame;
    okit_op decode_payload;
    okit_op classify_control_mode;
    okit_op check_movement_control;
    okit_op encode_movement_control;
    okit_op encode_frame;
    int (*bench)(int argc, char **argv); /* optional: run with arguments, the bench mode of PROTOCOL.md */
} okit_testee;

/* The request loop until end of input; with arguments, t->bench (or a usage error). Returns the exit status. */
int okit_main(const okit_testee *t, int argc, char **argv);

/* ---- the request -------------------------------------------------------------------------- */

const char *okit_op_name(const okit_request *req);
/* The request's profile: its index in okit_testee.profiles (every profile operation has one), -1 for the encoders. */
int okit_profile(const okit_request *req);
bool okit_has(const okit_request *req, const char *key);

/* Arguments. On false the kit has answered `bad_request` (naming the argument): return. */
bool okit_int(okit_request *req, const char *key, int64_t lo, int64_t hi, int64_t *out);
bool okit_bool(okit_request *req, const char *key, bool *out);
/* A hex string of whole bytes, into a buffer (at least 1 byte) the caller releases with okit_free. */
bool okit_hex(okit_request *req, const char *key, uint8_t **out, size_t *len);
/* A float given as {"f32": "0x........"}: its IEEE-754 bits, never a rounded value. */
bool okit_f32(okit_request *req, const char *key, uint32_t *bits);
/* A list of non-negative integers (decode_stream's "chunks"), at least 1 element, released with okit_free. */
bool okit_sizes(okit_request *req, const char *key, uint64_t **out, size_t *n);
/* Release what okit_hex or okit_sizes gave (free() on the host, where they come from malloc;
 * nothing with OKIT_PORT, where they last until the next request). NULL is allowed. */
void okit_free(void *p);

/* ---- the answer (exactly one per request) --------------------------------------------------- */

/* {"ok": true, "result": ...}: write the result value with the writer returned, in at most `room`
 * bytes (the kit answers `internal_error` if it overflows). NULL when out of memory (answered). */
osdk_json_t *okit_result(okit_request *req, size_t room);
/* {"ok": false, "error": error_class, "detail": detail}. */
void okit_error(okit_request *req, const char *error_class, const char *detail);
void okit_unsupported(okit_request *req);

#ifdef __cplusplus
}
#endif

#endif /* OKIT_H */
