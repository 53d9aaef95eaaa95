/*
 * startup.c - the reset path every Cortex-M board shares: the vector
 * table, .data and .bss set up, the FPU switched on, main called.
 *
 * The board's linker script provides the symbols below. A fault writes one
 * line naming it and resets the board (SYSRESETREQ): the host-side bridge
 * sees the start line again and reports the testee as crashed, as the
 * runner does for a host testee that dies.
 */
#include <stdint.h>

#include "board.h"

extern uint32_t __data_load[], __data_start[], __data_end[], __bss_start[], __bss_end[], __stack_top[];
int main(void);

#define SCB_CPACR (*(volatile uint32_t *)0xE000ED88u)
#define SCB_AIRCR (*(volatile uint32_t *)0xE000ED0Cu)

void reset_handler(void);
void fault_handler(void);

void reset_handler(void)
{
    uint32_t *s, *d;
    for (s = __data_load, d = __data_start; d < __data_end;) *d++ = *s++;
    for (d = __bss_start; d < __bss_end;) *d++ = 0;
#if defined(__ARM_FP)
    SCB_CPACR |= 0xFu << 20; /* CP10 and CP11: full access */
    __asm volatile("dsb\n\tisb");
#endif
    board_init();
    board_write("#start ", 7);
    {
        const char *n = board_name;
        while (*n) board_write(n++, 1);
    }
    board_write("\n", 1);
    main();
    for (;;) {
    }
}

void fault_handler(void)
{
    static const char line[] = "#fault\n";
    board_write(line, sizeof line - 1);
    SCB_AIRCR = 0x05FA0004u; /* VECTKEY | SYSRESETREQ */
    for (;;) {
    }
}

__attribute__((section(".vectors"), used)) static void (*const vectors[16])(void) = {
    (void (*)(void))(uintptr_t)__stack_top,
    reset_handler,
    fault_handler, /* NMI */
    fault_handler, /* HardFault */
    fault_handler, /* MemManage */
    fault_handler, /* BusFault */
    fault_handler, /* UsageFault */
};
