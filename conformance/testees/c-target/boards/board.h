/*
 * board.h - what the on-target testee needs from a board: a UART to the
 * runner, a free-running counter for timing, and a way to say it started.
 *
 * Each board file (boards/<board>.c with its boards/<board>.ld) provides
 * these; boards/startup.c is shared by every Cortex-M board.
 */
#ifndef BOARD_H
#define BOARD_H

#include <stddef.h>
#include <stdint.h>

/* Clocks and the UART, before main. */
void board_init(void);
/* The next byte from the runner (blocking). */
int board_getc(void);
/* Bytes to the runner (blocking until the UART has taken them). */
void board_write(const char *text, size_t n);
/* The board's name, for the start line. */
extern const char board_name[];

#endif
