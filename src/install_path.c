/* install_path.c: where a folder of an installed eclat is now.
 *
 * Found from where the running binary is rather than from the configured path
 * alone, so that an installation staged with "make install DESTDIR=..." or
 * moved as a whole finds its own folders: the binary is BINDIR/eclat, so
 * EXE_DIR minus BINDIR's part after the prefix is where the prefix is now, and
 * the folder's part after the prefix comes after that. Where the configured
 * folders do not share the prefix, the configured folder is used as it is. */
#include <limits.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "install_path.h"

#ifndef ECLAT_PREFIX   /* set by Makefile.am; these keep other builds compiling */
#define ECLAT_PREFIX "/usr/local"
#define ECLAT_BINDIR "/usr/local/bin"
#endif

static const char *after_prefix(const char *dir)
{
	size_t n = strlen(ECLAT_PREFIX);
	return strncmp(dir, ECLAT_PREFIX, n) == 0 && (dir[n] == '/' || dir[n] == '\0') ? dir + n : NULL;
}

int install_exe_dir(char *out, size_t n)
{
	char exe[PATH_MAX];
	ssize_t len = readlink("/proc/self/exe", exe, sizeof exe - 1);
	if (len <= 0)
		return -1;
	exe[len] = '\0';
	char *slash = strrchr(exe, '/');
	if (!slash)
		return -1;
	*slash = '\0';
	return snprintf(out, n, "%s", exe) < (int)n ? 0 : -1;
}

void install_path(const char *configured, char *out, size_t n)
{
	const char *bin_rel = after_prefix(ECLAT_BINDIR), *dir_rel = after_prefix(configured);
	char exe_dir[PATH_MAX];
	if (bin_rel && dir_rel && install_exe_dir(exe_dir, sizeof exe_dir) == 0) {
		size_t len = strlen(exe_dir), rel = strlen(bin_rel);
		if (len >= rel && strcmp(exe_dir + len - rel, bin_rel) == 0) {
			snprintf(out, n, "%.*s%s", (int)(len - rel), exe_dir, dir_rel);
			return;
		}
	}
	snprintf(out, n, "%s", configured);
}
