/*
 * unhex: the hexadecimal command-line arguments of the sample tools the Python
 * comparisons run (fec_sample.c, auth_sample.c). A bad argument ends the tool
 * with status 2.
 */
#ifndef NET_TESTS_SAMPLE_HEX_H
#define NET_TESTS_SAMPLE_HEX_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Decodes text (two digits a byte) into out; returns the byte count. */
static size_t unhex(const char *text, uint8_t *out, size_t size)
{
    size_t i, n = strlen(text) / 2u;
    if (n > size || strlen(text) % 2u != 0u)
        exit(2);
    for (i = 0; i < n; i++) {
        unsigned v;
        if (sscanf(text + 2u * i, "%2x", &v) != 1)
            exit(2);
        out[i] = (uint8_t)v;
    }
    return n;
}

#endif
