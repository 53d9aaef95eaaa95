/* check.h - a tiny assertion helper for the C unit tests. */
#ifndef CHECK_H
#define CHECK_H

#include <stdio.h>
#include <stdlib.h>

static int check_failures = 0;
static int check_count = 0;

#define CHECK(cond)                                                                   \
    do {                                                                              \
        check_count++;                                                                \
        if (!(cond)) {                                                                \
            check_failures++;                                                         \
            fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond);  \
        }                                                                             \
    } while (0)

#define CHECK_EQ(a, b)                                                                          \
    do {                                                                                        \
        unsigned long long check_a_ = (unsigned long long)(a), check_b_ = (unsigned long long)(b); \
        check_count++;                                                                          \
        if (check_a_ != check_b_) {                                                             \
            check_failures++;                                                                   \
            fprintf(stderr, "%s:%d: CHECK_EQ failed: %s == %s (0x%llx != 0x%llx)\n", __FILE__,  \
                    __LINE__, #a, #b, check_a_, check_b_);                                      \
        }                                                                                       \
    } while (0)

static inline int check_done(const char *name)
{
    if (check_failures) {
        fprintf(stderr, "%s: %d of %d checks failed\n", name, check_failures, check_count);
        return EXIT_FAILURE;
    }
    printf("%s: %d checks passed\n", name, check_count);
    return EXIT_SUCCESS;
}

/* hex text -> bytes; returns the byte count (out must be large enough). */
static inline size_t unhex(const char *hex, unsigned char *out)
{
    size_t n = 0;
    while (hex[0] && hex[1]) {
        unsigned v;
        if (sscanf(hex, "%2x", &v) != 1) break;
        out[n++] = (unsigned char)v;
        hex += 2;
    }
    return n;
}

#endif
