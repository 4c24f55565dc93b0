/* Minimal Cortex-M startup for the mcspec firmware: vector table, .data copy,
 * .bss zeroing, FPU enable, main. Replaces newlib's crt0 so nothing pulls in
 * exit(), atexit or the heap. Symbols come from sections.ld. */
#include <stdint.h>

extern uint32_t _estack;   /* top of RAM: initial stack pointer */
extern uint32_t _sidata;   /* .data load address in flash */
extern uint32_t _sdata, _edata;
extern uint32_t _sbss, _ebss;

int main(void);
void Reset_Handler(void);

static void default_handler(void)
{
    for (;;) {
    }
}

void Reset_Handler(void)
{
    const uint32_t *src = &_sidata;
    for (uint32_t *dst = &_sdata; dst < &_edata;)
        *dst++ = *src++;
    for (uint32_t *dst = &_sbss; dst < &_ebss;)
        *dst++ = 0u;
    /* CPACR: full access to CP10 and CP11 before any floating-point
     * instruction (the library is built for the hard-float ABI). */
    *(volatile uint32_t *)0xE000ED88u |= 0xFu << 20;
    __asm__ volatile("dsb\n\tisb" ::: "memory");
    (void)main();
    default_handler();
}

/* Cortex-M core exceptions: reset and 14 more slots (some reserved). No
 * peripheral interrupts are used. */
typedef struct {
    uint32_t *initial_sp;
    void (*handler[15])(void);
} vector_table;

__attribute__((section(".isr_vector"), used)) static const vector_table vectors = {
    &_estack,
    {
        Reset_Handler,   default_handler, default_handler, default_handler, /* reset, NMI, HardFault, MemManage */
        default_handler, default_handler, 0,               0,               /* BusFault, UsageFault, reserved */
        0,               0,               default_handler, default_handler, /* reserved, SVCall, DebugMon */
        0,               default_handler, default_handler,                  /* reserved, PendSV, SysTick */
    },
};
