/* film_rescue.c: an image that cannot be written where it was asked for (the
 * disk filled up, the folder went away) is not the end of the samples: they
 * are written, linear and whole, to an EXR in the temporary folder, and the
 * user is told where. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "film.h"

int film_rescue(const film *f, const char *target, const image_meta *meta, char *where, size_t n)
{
	const char *base = strrchr(target, '/');
	base = base ? base + 1 : target;
	const char *dot = strrchr(base, '.');
	int stem = dot && dot > base ? (int)(dot - base) : (int)strlen(base);
	const char *dirs[] = { getenv("TMPDIR"), "/tmp", "/var/tmp" };
	for (size_t i = 0; i < sizeof dirs / sizeof *dirs; i++) {
		if (!dirs[i] || !*dirs[i])
			continue;
		snprintf(where, n, "%s/eclat-rescued-%.*s-%ld.exr", dirs[i], stem > 64 ? 64 : stem, base, (long)getpid());
		char err[512];
		if (image_write(where, f->rgb, f->width, f->height, meta, err, sizeof err) == 0)
			return 0;
	}
	return -1;
}
