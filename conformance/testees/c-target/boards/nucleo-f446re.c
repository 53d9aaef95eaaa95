/*
 * nucleo-f446re.c - ST's NUCLEO-F446RE (STM32F446RE, Cortex-M4F): USART2
 * on PA2/PA3, which the board's ST-LINK turns into a USB serial port
 * (/dev/ttyACM0 on Linux). Register addresses and bits from ST's RM0390.
 *
 * The core runs from the 16 MHz internal oscillator, as it comes out of
 * reset: no PLL set-up to get wrong, and 115200 baud is 16 MHz / 139
 * (0.08 % off). The same file runs on QEMU's netduinoplus2 (STM32F405,
 * whose USART2 and GPIO registers are the same), USART2 there being QEMU's
 * second serial port.
 */
#include "board.h"

#define RCC_AHB1ENR (*(volatile uint32_t *)0x40023830u)
#define RCC_APB1ENR (*(volatile uint32_t *)0x40023840u)
#define GPIOA_MODER (*(volatile uint32_t *)0x40020000u)
#define GPIOA_AFRL (*(volatile uint32_t *)0x40020020u)
#define USART2_SR (*(volatile uint32_t *)0x40004400u)
#define USART2_DR (*(volatile uint32_t *)0x40004404u)
#define USART2_BRR (*(volatile uint32_t *)0x40004408u)
#define USART2_CR1 (*(volatile uint32_t *)0x4000440Cu)
#define SR_RXNE (1u << 5)
#define SR_TXE (1u << 7)
#define CR1_UE (1u << 13)
#define CR1_RXNEIE (1u << 5)
#define CR1_TE (1u << 3)
#define CR1_RE (1u << 2)

#define NVIC_ISER1 (*(volatile uint32_t *)0xE000E104u)
#define NVIC_ICPR1 (*(volatile uint32_t *)0xE000E284u)
#define USART2_IRQ 38u /* RM0390's vector table */

#define HSI_HZ 16000000u
#define BAUD 115200u

const char board_name[] = "nucleo-f446re";

void board_init(void)
{
    RCC_AHB1ENR |= 1u << 0;  /* GPIOA */
    RCC_APB1ENR |= 1u << 17; /* USART2 */
    (void)RCC_APB1ENR;       /* the clock is on before the first register access */
    /* PA2 (TX) and PA3 (RX): alternate function 7, USART2 */
    GPIOA_MODER = (GPIOA_MODER & ~(0xFu << 4)) | (0xAu << 4);
    GPIOA_AFRL = (GPIOA_AFRL & ~(0xFFu << 8)) | (0x77u << 8);
    USART2_BRR = (HSI_HZ + BAUD / 2u) / BAUD;
    __asm volatile("cpsid i"); /* a pending interrupt wakes WFI, none is taken */
    USART2_CR1 = CR1_UE | CR1_TE | CR1_RE | CR1_RXNEIE;
    NVIC_ISER1 = 1u << (USART2_IRQ - 32u);
}

int board_getc(void)
{
    int c;
    /* sleep until a byte is in; an overrun (a byte lost while the testee
     * was busy) clears on reading SR then DR, and the request it broke is
     * answered bad_request */
    while (!(USART2_SR & SR_RXNE)) __asm volatile("wfi");
    c = (int)(USART2_DR & 0xFFu);
    NVIC_ICPR1 = 1u << (USART2_IRQ - 32u);
    return c;
}

void board_write(const char *text, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        while (!(USART2_SR & SR_TXE)) {
        }
        USART2_DR = (uint8_t)text[i];
    }
}
