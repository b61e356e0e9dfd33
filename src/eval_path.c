/* eval_path.c: the include folder of an installed eclat, PKGDATADIR/include.
 *
 * It is found from where the running binary is rather than from the configured
 * path alone, so that an installation staged with "make install DESTDIR=..." or
 * moved as a whole finds its own folder: the binary is BINDIR/eclat, so
 * EXE_DIR minus BINDIR's part after the prefix is where the prefix is now, and
 * PKGDATADIR's part after the prefix comes after that. Where the configured
 * folders do not share the prefix, the configured PKGDATADIR is used as it is. */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "eval_int.h"

#ifndef ECLAT_PREFIX   /* set by Makefile.am; these keep other builds compiling */
#define ECLAT_PREFIX "/usr/local"
#define ECLAT_BINDIR "/usr/local/bin"
#define ECLAT_PKGDATADIR "/usr/local/share/eclat"
#endif

static const char *after_prefix(const char *dir)
{
	size_t n = strlen(ECLAT_PREFIX);
	return strncmp(dir, ECLAT_PREFIX, n) == 0 && (dir[n] == '/' || dir[n] == '\0') ? dir + n : NULL;
}

const char *eval_installed_include_dir(void)
{
	static char dir[PATH_MAX + 64];
	static int done;
	if (done)
		return dir[0] ? dir : NULL;
	done = 1;
	const char *bin_rel = after_prefix(ECLAT_BINDIR), *data_rel = after_prefix(ECLAT_PKGDATADIR);
	char exe[PATH_MAX];
	ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
	if (bin_rel && data_rel && n > 0) {
		exe[n] = '\0';
		char *slash = strrchr(exe, '/');
		size_t len = slash ? (size_t)(slash - exe) : 0, rel = strlen(bin_rel);
		if (slash && len >= rel && strncmp(exe + len - rel, bin_rel, rel) == 0) {
			snprintf(dir, sizeof dir, "%.*s%s/include", (int)(len - rel), exe, data_rel);
			return dir;
		}
	}
	snprintf(dir, sizeof dir, "%s/include", ECLAT_PKGDATADIR);
	return dir;
}
