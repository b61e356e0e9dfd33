/* host_memory.h: how much memory the host can give eclat, and the sizes the
 * command line writes ("512M"), for the checks that come before a large
 * allocation (an image, a mesh, a height field): the numbers in an error, never
 * an OOM kill. */
#ifndef ECLAT_HOST_MEMORY_H
#define ECLAT_HOST_MEMORY_H

/* The bytes the host has available now (Linux's MemAvailable, else free and
 * buffer memory from sysinfo), or 0 when it cannot tell. */
double host_memory_available(void);

/* A size: a number of bytes with an optional K, M, G or T (powers of 1024).
 * Returns 0, or -1 when s is none. */
int host_memory_parse(const char *s, double *bytes);

/* "1.5 GiB", "12.0 MiB", "800 KiB" into out. */
void host_memory_format(double bytes, char *out, int n);

#endif
