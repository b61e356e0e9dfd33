/* install_path.h: the folders of an installed eclat, wherever it was moved
 * (src/install_path.c). */
#ifndef ECLAT_INSTALL_PATH_H
#define ECLAT_INSTALL_PATH_H

#include <stddef.h>

/* The folder the running binary is in. Returns 0, or -1. */
int install_exe_dir(char *out, size_t n);
/* configured (a folder under the configured prefix: PKGDATADIR...) as it is
 * for the running binary: under the prefix the binary's BINDIR now implies. */
void install_path(const char *configured, char *out, size_t n);

#endif
