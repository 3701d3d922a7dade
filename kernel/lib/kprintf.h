/*
 * printf-style formatting for freestanding target code (no libc).
 *
 * Conversions: %c %s %d %i %u %x %X %p %%, flags '-' (left-justify) and
 * '0' (zero-pad), a field width (digits or '*'), length modifiers 'l' and
 * 'h' (accepted; int and long are both 32 bits on m68k). No floating point,
 * no precision. An unknown conversion is printed as is, after a '%'.
 */
#ifndef KERNEL_LIB_KPRINTF_H
#define KERNEL_LIB_KPRINTF_H

#include <stdarg.h>
#include <stddef.h>

/* Receives each output character in order. */
typedef void (*kformat_emit_fn)(void *context, char c);

/* Formats into emit; returns the number of characters emitted. */
int kvformat(kformat_emit_fn emit, void *context, const char *fmt, va_list args);

/* Like snprintf: writes at most size - 1 characters and a NUL (if size > 0);
 * returns the length the full output would have. */
int ksnprintf(char *buf, size_t size, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* Where kprintf output goes: a console driver registers its putc here
 * (boards/robocube/duart_console.c does in console_init). Until then kprintf
 * output is dropped. */
void kprintf_set_output(void (*putc)(char c));

int kprintf(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
int kvprintf(const char *fmt, va_list args);

#endif /* KERNEL_LIB_KPRINTF_H */
