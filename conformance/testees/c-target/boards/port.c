/*
 * port.c - the testee kit's two ends on a board (okit.h, OKIT_PORT), and
 * the only memory newlib may take.
 *
 * Lines that start with '#' are the board's own (the start line, a fault)
 * and never answers: the bridge (osdk_conformance/board) reads them.
 */
#include <errno.h>
#include <stdint.h>

#include "board.h"
#include "okit.h"

int okit_port_getc(void) { return board_getc(); }
void okit_port_write(const char *text, size_t n) { board_write(text, n); }

/* newlib's printf of a float (the JSON "value" beside a float's bits) takes
 * its Bigints from malloc. This is its heap: HEAP_SIZE bytes after .bss,
 * never more; the library itself allocates nothing. */
extern char __heap_start[], __heap_end[];
static char *g_brk = __heap_start;

void *_sbrk(ptrdiff_t incr);
void *_sbrk(ptrdiff_t incr)
{
    char *old = g_brk;
    if (incr > __heap_end - g_brk || incr < __heap_start - g_brk) {
        errno = ENOMEM;
        return (void *)-1;
    }
    g_brk += incr;
    return old;
}
