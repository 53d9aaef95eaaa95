/*
 * peak_rss.c - run a command and write its peak resident set size.
 *
 *   osdk-peak-rss RESULT_FILE COMMAND [ARG...]
 *
 * Runs COMMAND as a child, waits for it with wait4 and writes
 * "<exit status or -signal> <ru_maxrss KiB> <user+system seconds>" to
 * RESULT_FILE; exits with the child's status. `osdkc bench` starts
 * implementations through it because Linux counts the RSS a process had
 * before exec into its ru_maxrss: a child forked by the Python harness
 * would report the harness's tens of MiB, a child of this small program
 * reports its own.
 */
#define _DEFAULT_SOURCE /* wait4 */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

int main(int argc, char **argv)
{
    struct rusage ru;
    int status, code;
    pid_t pid;
    FILE *out;
    if (argc < 3) {
        fputs("usage: osdk-peak-rss RESULT_FILE COMMAND [ARG...]\n", stderr);
        return 2;
    }
    pid = fork();
    if (pid < 0) {
        fprintf(stderr, "osdk-peak-rss: fork: %s\n", strerror(errno));
        return 2;
    }
    if (pid == 0) {
        execvp(argv[2], argv + 2);
        fprintf(stderr, "osdk-peak-rss: cannot run %s: %s\n", argv[2], strerror(errno));
        _exit(127);
    }
    while (wait4(pid, &status, 0, &ru) < 0) {
        if (errno != EINTR) {
            fprintf(stderr, "osdk-peak-rss: wait4: %s\n", strerror(errno));
            return 2;
        }
    }
    code = WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
    out = fopen(argv[1], "w");
    if (!out) {
        fprintf(stderr, "osdk-peak-rss: cannot write %s: %s\n", argv[1], strerror(errno));
        return 2;
    }
    fprintf(out, "%d %ld %.6f\n", code, ru.ru_maxrss,
            (double)ru.ru_utime.tv_sec + (double)ru.ru_utime.tv_usec / 1e6 + (double)ru.ru_stime.tv_sec +
                (double)ru.ru_stime.tv_usec / 1e6);
    fclose(out);
    return code >= 0 ? code : 128 - code;
}
