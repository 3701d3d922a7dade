/*
 * The system calls newlib needs on every board: its stdio on the console, its
 * malloc in the SRAM between .bss and the stack (the linker script's __bss_end,
 * __stack_top and __stack_size), exit and abort as a halt. The RoboCube's
 * newlib (build/newlib, ci/setup.d/m68k/newlib.sh) is built with
 * MISSING_SYSCALL_NAMES and calls them by their POSIX names (write); Debian's
 * newlib for arm-none-eabi calls them by the reserved ones (_write), which
 * call the same functions (at the end). An image that calls no C library
 * function links none of this.
 *
 *   fd 0  console input: canonical lines (edited and echoed by console_in.c),
 *         each returned with its '\n'; read waits for a line (a terminal does)
 *   fd 1, fd 2  console output through the kernel's console hook
 *
 * One thread at a time may use stdio and malloc: newlib's locks are not mapped
 * onto the kernel's mutexes (README, C library).
 */
#include <errno.h>
#include <stddef.h>
#include <stdint.h>
#include <sys/stat.h>
#include <sys/types.h>

#include "kernel.h"
#include "boards/include/board.h"
#include "drivers/console_in.h"
#include "drivers/drv_err.h"

/* newlib reports errors through errno; its declarations of the calls below
 * come from its own headers, which do not declare them all (sbrk, kill). */
int write(int fd, const void *buf, size_t count);
int read(int fd, void *buf, size_t count);
void *sbrk(ptrdiff_t increment);
int close(int fd);
int fstat(int fd, struct stat *st);
int isatty(int fd);
off_t lseek(int fd, off_t offset, int whence);
int kill(int pid, int sig);
int getpid(void);
void _exit(int status) __attribute__((noreturn));

/* The heap: from the end of .bss up to the room the linker script keeps for
 * the supervisor stack (boards/robocube/robocube.ld). */
extern char __bss_end[], __stack_top[], __stack_size[];
static char *heap_end;

/* The console line being handed out by read(0, ...). */
static char line[CONSOLE_IN_LINE_MAX + 2u];
static size_t line_len, line_pos;
static int console_in_ready;

static int is_console(int fd)
{
    return fd >= 0 && fd <= 2;
}

int write(int fd, const void *buf, size_t count)
{
    if (fd != 1 && fd != 2) {
        errno = EBADF;
        return -1;
    }
    if (buf == NULL && count > 0u) {
        errno = EFAULT;
        return -1;
    }
    return (int)k_console_write(buf, count > 0x7FFFFFFFu ? 0x7FFFFFFFu : count);
}

/* Waits for the next console line (echoed and edited as the shell's are). */
static int next_line(void)
{
    int n;
    if (!console_in_ready) {
        n = console_in_init();
        if (n != DRV_OK && n != DRV_ERR_STATE) {   /* DRV_ERR_STATE: set up already */
            errno = EIO;
            return -1;
        }
        console_in_ready = 1;
    }
    do
        n = console_read_line(line, CONSOLE_IN_LINE_MAX + 1u, CONSOLE_IN_TIMEOUT_MAX_MS);
    while (n == DRV_ERR_TIMEOUT || n == DRV_ERR_RANGE);
    if (n < 0) {
        errno = EIO;
        return -1;
    }
    line[n] = '\n';
    line_len = (size_t)n + 1u;
    line_pos = 0;
    return 0;
}

int read(int fd, void *buf, size_t count)
{
    size_t n = 0;
    char *out = buf;
    if (fd != 0) {
        errno = EBADF;
        return -1;
    }
    if (buf == NULL && count > 0u) {
        errno = EFAULT;
        return -1;
    }
    if (count == 0u)
        return 0;
    if (line_pos == line_len && next_line() != 0)
        return -1;
    while (n < count && line_pos < line_len)
        out[n++] = line[line_pos++];
    return (int)n;
}

void *sbrk(ptrdiff_t increment)
{
    char *old;
    if (heap_end == NULL)
        heap_end = __bss_end;
    old = heap_end;
    if (increment > 0 && (size_t)increment > (size_t)((__stack_top - (uintptr_t)__stack_size) - heap_end)) {
        errno = ENOMEM;
        return (void *)-1;
    }
    if (increment < 0 && (size_t)-increment > (size_t)(heap_end - __bss_end)) {
        errno = EINVAL;
        return (void *)-1;
    }
    heap_end += increment;
    return old;
}

int close(int fd)
{
    errno = is_console(fd) ? EPERM : EBADF;
    return -1;
}

int fstat(int fd, struct stat *st)
{
    if (!is_console(fd)) {
        errno = EBADF;
        return -1;
    }
    if (st == NULL) {
        errno = EFAULT;
        return -1;
    }
    *st = (struct stat){ .st_mode = S_IFCHR };   /* a terminal: stdio buffers by line */
    return 0;
}

int isatty(int fd)
{
    if (is_console(fd))
        return 1;
    errno = EBADF;
    return 0;
}

off_t lseek(int fd, off_t offset, int whence)
{
    (void)offset;
    (void)whence;
    errno = is_console(fd) ? ESPIPE : EBADF;
    return -1;
}

int getpid(void)
{
    return 1;
}

/* abort() raises SIGABRT: the program ends, as on a system without handlers. */
int kill(int pid, int sig)
{
    static const char message[] = "killed by a signal (abort)\n";
    if (pid != 1) {
        errno = ESRCH;
        return -1;
    }
    (void)sig;
    board_halt("libc", message);
}

void _exit(int status)
{
    char message[] = "exit -2147483648\n";
    (void)k_snprintf(message, sizeof message, "exit %d\n", status);
    board_halt("libc", message);
}

/* The reserved names Debian's arm-none-eabi newlib calls (see the top): each
 * the function above by its POSIX name. Functions, not aliases, so that each
 * name has its own frame in GCC's call graph (assure/stack.py reads it). */
int _write(int fd, const void *buf, size_t count) { return write(fd, buf, count); }
int _read(int fd, void *buf, size_t count) { return read(fd, buf, count); }
void *_sbrk(ptrdiff_t increment) { return sbrk(increment); }
int _close(int fd) { return close(fd); }
int _fstat(int fd, struct stat *st) { return fstat(fd, st); }
int _isatty(int fd) { return isatty(fd); }
off_t _lseek(int fd, off_t offset, int whence) { return lseek(fd, offset, whence); }
int _getpid(void) { return getpid(); }
int _kill(int pid, int sig) { return kill(pid, sig); }
