/* What the host port offers the unit tests. */
#ifndef HOST_PORT_H
#define HOST_PORT_H

#include <stddef.h>

#define HOST_CONSOLE_SIZE 8192u
extern char host_console[HOST_CONSOLE_SIZE];
extern size_t host_console_len;
extern unsigned host_irq_routed[256];
/* Console writes made inside an interrupt handler since host_console_clear. */
extern size_t host_console_writes_in_isr;
/* Registers the host console as the kernel's writer and empties it. */
void host_console_clear(void);
/* A tick interrupt at this point of the calling thread. */
void host_tick(void);
/* An interrupt on vector at this point. */
void host_raise_irq(unsigned vector);
int host_irq_disabled(void);
/* Times the kernel halted the system (k_arch_halt) since the program began. */
extern int host_halted;

#endif
