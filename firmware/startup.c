/* Start-up of the bare-metal Cortex-M4F programs: the vector table, the reset handler and
 * what newlib expects of a program linked with -nostartfiles.
 *
 * The reset handler turns the FPU on before anything can run a float instruction (CPACR:
 * full access to coprocessors 10 and 11), copies .data from flash, clears .bss, opens the
 * semihosting handles newlib's rdimon library prints and exits through, runs the static
 * constructors and calls main; main's status goes back to the host through semihosting,
 * and qemu exits with it. */
#include <stdint.h>
#include <stdlib.h>

extern uint32_t __data_load, __data_start, __data_end, __bss_start__, __bss_end__, __stack_top;
extern void __libc_init_array(void);
extern void initialise_monitor_handles(void);
extern int main(void);

/* __libc_init_array calls _init and __libc_fini_array _fini; crti/crtn would supply them,
 * and -nostartfiles leaves them out. Nothing to do in either. */
void _init(void) {}
void _fini(void) {}
/* Static objects' destructors register against this handle (crtbegin.o would define it). */
void* __dso_handle = 0;

void Reset_Handler(void) {
    volatile uint32_t* const cpacr = (volatile uint32_t*)0xE000ED88u;
    *cpacr |= 0xFu << 20;
    __asm volatile("dsb\n\tisb" ::: "memory");
    for (uint32_t *src = &__data_load, *dst = &__data_start; dst < &__data_end;) *dst++ = *src++;
    for (uint32_t* dst = &__bss_start__; dst < &__bss_end__;) *dst++ = 0;
    initialise_monitor_handles();
    __libc_init_array();
    exit(main());
}

/* Any fault ends the run with a distinct status instead of hanging the emulator. */
static void Fault_Handler(void) { exit(99); }

__attribute__((section(".isr_vector"), used)) static void (*const vector_table[16])(void) = {
    (void (*)(void))(&__stack_top), Reset_Handler, Fault_Handler, Fault_Handler, Fault_Handler,
    Fault_Handler, Fault_Handler, 0, 0, 0, 0, Fault_Handler, Fault_Handler, 0, Fault_Handler, Fault_Handler,
};
