/*
 * mps2-an386.c - Arm's MPS2 board with the AN386 image (Cortex-M4 with
 * FPU), as QEMU emulates it (`qemu-system-arm -machine mps2-an386`).
 *
 * UART0 is a CMSDK APB UART at 0x40004000 (QEMU's first serial port). Its
 * registers: DATA 0x00, STATE 0x04 (bit 0 TX full, bit 1 RX full), CTRL
 * 0x08 (bit 0 TX enable, bit 1 RX enable), BAUDDIV 0x10. The divider is
 * the 25 MHz system clock over the baud rate; QEMU does not pace the
 * line by it, but wants it at least 16.
 *
 * Waiting for a byte sleeps (WFI) until the UART's receive interrupt (IRQ
 * 0) is pending; interrupts stay masked, so none is taken. Polling instead
 * keeps a host core busy emulating the loop and slows the very link it
 * waits on.
 */
#include "board.h"

#define UART0_BASE 0x40004000u
#define UART_DATA (*(volatile uint32_t *)(UART0_BASE + 0x00u))
#define UART_STATE (*(volatile uint32_t *)(UART0_BASE + 0x04u))
#define UART_CTRL (*(volatile uint32_t *)(UART0_BASE + 0x08u))
#define UART_INTCLEAR (*(volatile uint32_t *)(UART0_BASE + 0x0Cu))
#define UART_BAUDDIV (*(volatile uint32_t *)(UART0_BASE + 0x10u))
#define STATE_TX_FULL 0x1u
#define STATE_RX_FULL 0x2u
#define CTRL_TX_EN 0x1u
#define CTRL_RX_EN 0x2u
#define CTRL_RX_IRQ_EN 0x8u
#define INT_RX 0x2u
#define NVIC_ISER0 (*(volatile uint32_t *)0xE000E100u)
#define NVIC_ICPR0 (*(volatile uint32_t *)0xE000E280u)
#define UART0_RX_IRQ 0u

#define SYSCLK_HZ 25000000u
#define BAUD 115200u

const char board_name[] = "mps2-an386";

void board_init(void)
{
    __asm volatile("cpsid i"); /* a pending interrupt wakes WFI, none is taken */
    UART_BAUDDIV = SYSCLK_HZ / BAUD;
    UART_CTRL = CTRL_TX_EN | CTRL_RX_EN | CTRL_RX_IRQ_EN;
    NVIC_ISER0 = 1u << UART0_RX_IRQ;
}

int board_getc(void)
{
    int c;
    while (!(UART_STATE & STATE_RX_FULL)) __asm volatile("wfi");
    c = (int)(UART_DATA & 0xFFu);
    UART_INTCLEAR = INT_RX; /* the line drops, then the pending bit can clear */
    NVIC_ICPR0 = 1u << UART0_RX_IRQ;
    return c;
}

void board_write(const char *text, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        while (UART_STATE & STATE_TX_FULL) {
        }
        UART_DATA = (uint8_t)text[i];
    }
}
