/* eval_path.c: the include folder of an installed eclat, PKGDATADIR/include,
 * wherever the installation is now (src/install_path.c). */
#include <limits.h>
#include <stdio.h>

#include "eval_int.h"
#include "install_path.h"

#ifndef ECLAT_PKGDATADIR   /* set by Makefile.am; this keeps other builds compiling */
#define ECLAT_PKGDATADIR "/usr/local/share/eclat"
#endif

const char *eval_installed_include_dir(void)
{
	static char dir[PATH_MAX + 64];
	static int done;
	if (!done) {
		char data[PATH_MAX];
		install_path(ECLAT_PKGDATADIR, data, sizeof data);
		snprintf(dir, sizeof dir, "%s/include", data);
		done = 1;
	}
	return dir;
}
