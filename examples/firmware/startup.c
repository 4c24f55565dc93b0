/* Minimal Cortex-M startup for the mcspec firmware: vector table, .data copy,
 * .bss zeroing, FPU enable, main. Replaces newlib's crt0 so nothing pulls in
 * exit(), atexit or the heap. Symbols come from sections.ld. */
#include <stddef.h>
#include <stdint.h>

/* Linker-script symbols: addresses only. Declared as arrays and compared as
 * integers, since as C objects they are distinct and not comparable. */
extern uint32_t mcs_fw_stack_top[];  /* top of RAM: initial stack pointer */
extern uint32_t mcs_fw_data_load[];  /* .data image in flash */
extern uint32_t mcs_fw_data_start[], mcs_fw_data_end[];
extern uint32_t mcs_fw_bss_start[], mcs_fw_bss_end[];

int main(void);
void Reset_Handler(void);

static void default_handler(void)
{
    for (;;) {
    }
}

void Reset_Handler(void)
{
    size_t data_words = ((uintptr_t)mcs_fw_data_end - (uintptr_t)mcs_fw_data_start) / 4u;
    size_t bss_words = ((uintptr_t)mcs_fw_bss_end - (uintptr_t)mcs_fw_bss_start) / 4u;
    for (size_t i = 0u; i < data_words; ++i)
        mcs_fw_data_start[i] = mcs_fw_data_load[i];
    for (size_t i = 0u; i < bss_words; ++i)
        mcs_fw_bss_start[i] = 0u;
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
    mcs_fw_stack_top,
    {
        Reset_Handler,   default_handler, default_handler, default_handler, /* reset, NMI, HardFault, MemManage */
        default_handler, default_handler, 0,               0,               /* BusFault, UsageFault, reserved */
        0,               0,               default_handler, default_handler, /* reserved, SVCall, DebugMon */
        0,               default_handler, default_handler,                  /* reserved, PendSV, SysTick */
    },
};
