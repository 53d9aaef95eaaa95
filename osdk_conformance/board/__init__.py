"""The generated C library on a microcontroller: the bridge between the
runner's testee protocol on standard input and output and a board's UART
(a real one on a serial port, or QEMU's emulated Cortex-M)."""
