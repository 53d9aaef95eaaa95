/*
 * asan_launcher.c - build/osdk-c-testee-asan: starts the sanitized testee
 * (build/osdk-c-testee-asan-bin, -fsanitize=address,undefined) under an
 * address-space limit.
 *
 * AddressSanitizer reserves terabytes of address space for its shadow
 * memory at start, so it cannot start under the RLIMIT_AS the conformance
 * runner sets (1 GiB by default): it would abort before main. This
 * launcher, built without sanitizers, moves the limit: it lifts the soft
 * RLIMIT_AS back to the hard limit (which it cannot and does not raise)
 * and hands the same number of MiB to ASan as hard_rss_limit_mb, so the
 * testee's memory stays capped, then execs the sanitized binary with the
 * same arguments. Every sanitizer finding aborts that process (the runner
 * sees a testee_crash) and the report goes to standard error.
 */
#define _POSIX_C_SOURCE 200809L

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

int main(int argc, char **argv)
{
    static char self[PATH_MAX + 32];
    static char options[4096];
    struct rlimit lim;
    ssize_t n;
    const char *old;
    (void)argc;
    n = readlink("/proc/self/exe", self, PATH_MAX);
    if (n <= 0) {
        fprintf(stderr, "osdk-c-testee-asan: cannot find its own path\n");
        return 127;
    }
    self[n] = '\0';
    strcat(self, "-bin");
    old = getenv("ASAN_OPTIONS");
    if (getrlimit(RLIMIT_AS, &lim) == 0 && lim.rlim_cur != RLIM_INFINITY) {
        unsigned long mb = (unsigned long)(lim.rlim_cur >> 20);
        snprintf(options, sizeof options, "%s%shard_rss_limit_mb=%lu", old ? old : "", old && *old ? ":" : "",
                 mb ? mb : 1ul);
        lim.rlim_cur = lim.rlim_max;
        if (setrlimit(RLIMIT_AS, &lim) != 0) {
            perror("osdk-c-testee-asan: setrlimit");
            return 127;
        }
        if (setenv("ASAN_OPTIONS", options, 1) != 0) {
            perror("osdk-c-testee-asan: setenv");
            return 127;
        }
    }
    argv[0] = self;
    execv(self, argv);
    perror("osdk-c-testee-asan: exec");
    return 127;
}
