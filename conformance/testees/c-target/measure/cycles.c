/*
 * cycles.c - the time the library takes per frame on the board, and the
 * stack it used, for `osdkc bench --only footprint` (docs/PERFORMANCE.md).
 *
 * The capture to time sits in memory at __input (the Makefile places it;
 * QEMU's generic loader puts it there before reset, a debugger would on a
 * real board): a little-endian header of two words, the byte count and
 * what to do (1: deframe only, 2: deframe and decode every frame for its
 * profile, as footprint.c's FEATURE 2 does), then the bytes. Reading it
 * from memory keeps the UART, at a few KB/s under QEMU, out of the run.
 * The firmware answers with one line and waits:
 *
 *   #cycles bytes=B frames=F errors=E ticks=T max=M calib=C stack=S
 *
 * T counts SysTick on the processor clock over the whole stream, M the
 * most between two frames (one frame's deframing, and its decoding), and C
 * a loop of CALIB_LOOPS iterations of CALIB_INSNS instructions each. On a
 * real Cortex-M4 a tick is a cycle. Under QEMU it is the virtual clock,
 * which with -icount shift=0 advances one nanosecond per instruction
 * executed, whatever the instruction: C tells the bench how many
 * instructions a tick is, and it reports instructions, not cycles. S is
 * the deepest the stack went since reset, from a pattern painted over it.
 */
#include <stdint.h>

#include "board.h"
#include "osdk_deframer.h"

#ifndef PROFILE
#define PROFILE OSDK_PAYLOAD_PROFILE_A3_FW3_1
#endif

#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)
#define SYST_ENABLE_CPUCLK 0x5u /* ENABLE | CLKSOURCE (processor clock), no interrupt */
#define SYST_MASK 0xFFFFFFu
#define PAINT 0xA5u
#define CALIB_LOOPS 100000u
#define CALIB_INSNS 4u /* the loop in calibrate() */

extern uint8_t __stack_limit[], __stack_top[];
extern const uint32_t __input[];

static uint8_t g_window[OSDK_DEFRAMER_MIN_BUFFER];
static osdk_deframer_t g_rx;
static uint32_t g_frames, g_errors, g_ticks, g_last, g_mark, g_max, g_decode;
static volatile uint32_t g_sink;

/* SysTick counts down and wraps at 24 bits: read often enough (each event,
 * far below 2^24 ticks apart), the differences add up to the elapsed time. */
static void tick(void)
{
    uint32_t now = SYST_CVR;
    g_ticks += (g_last - now) & SYST_MASK;
    g_last = now;
}

static void on_event(void *user, const osdk_event_t *ev)
{
    (void)user;
    if (ev->kind == OSDK_EVENT_FRAME) {
        if (g_decode) {
            osdk_frame_t f;
            osdk_error_t err;
            if (osdk_frame_decode(ev->raw, ev->length, PROFILE, &f, &err) == OSDK_OK)
                g_sink += f.len;
            else
                g_errors++;
        }
        g_frames++;
    } else if (ev->kind == OSDK_EVENT_ERROR) {
        g_errors++;
    }
    tick();
    if (ev->kind == OSDK_EVENT_FRAME && g_ticks - g_mark > g_max) g_max = g_ticks - g_mark;
    g_mark = g_ticks;
}

/* CALIB_LOOPS turns of four instructions (subs, nop, nop, bne): what a
 * tick is worth in instructions, measured rather than assumed. */
static uint32_t calibrate(void)
{
    uint32_t n = CALIB_LOOPS, before;
    g_ticks = 0;
    g_last = SYST_CVR;
    before = g_ticks;
    __asm volatile("1: subs %0, %0, #1\n\tnop\n\tnop\n\tbne 1b" : "+r"(n) : : "cc");
    tick();
    return g_ticks - before;
}

static void put_number(const char *label, uint32_t v)
{
    char text[12];
    unsigned i = sizeof text;
    do {
        text[--i] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v && i);
    while (*label) board_write(label++, 1);
    board_write(text + i, sizeof text - i);
}

/* Bytes of the stack in use at its deepest since reset: from its top down
 * to the lowest byte the paint no longer holds. */
static uint32_t stack_used(void)
{
    const uint8_t *p = __stack_limit;
    while (p < __stack_top && *p == PAINT) p++;
    return (uint32_t)(__stack_top - p);
}

/* Everything below the stack pointer (less a margin for this function's
 * own frame) gets the pattern. */
static void paint(void)
{
    uint8_t *sp, *p;
    __asm volatile("mov %0, sp" : "=r"(sp));
    for (p = __stack_limit; p < sp - 32; p++) *p = PAINT;
}

int main(void)
{
    uint32_t calib;
    paint();
    osdk_deframer_init(&g_rx, g_window, sizeof g_window);
    SYST_RVR = SYST_MASK;
    SYST_CVR = 0;
    SYST_CSR = SYST_ENABLE_CPUCLK;
    calib = calibrate();
    g_decode = __input[1] == 2u;
    g_frames = g_errors = g_ticks = g_mark = g_max = 0;
    g_last = SYST_CVR;
    osdk_deframer_feed(&g_rx, (const uint8_t *)&__input[2], __input[0], on_event, NULL);
    osdk_deframer_finish(&g_rx, on_event, NULL);
    tick();
    put_number("#cycles bytes=", __input[0]);
    put_number(" frames=", g_frames);
    put_number(" errors=", g_errors);
    put_number(" ticks=", g_ticks);
    put_number(" max=", g_max);
    put_number(" calib=", calib);
    put_number(" stack=", stack_used());
    board_write("\n", 1);
    for (;;) __asm volatile("wfi");
}
