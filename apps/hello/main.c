/*
 * The smallest program: an ordinary C main, run as a thread once the board
 * (kernel, console, tick) is up. Copy this folder to start a program of your own.
 */
#include <stdio.h>

int main(void)
{
    int x = 42;
    printf("hello from the RoboCube\n");
    printf("%d\n", x);
    return 0;
}
