/* film.c: turns the device's per-pixel sums into mean radiance. */
#include <stdlib.h>

#include "film.h"

int film_init(film *f, int width, int height)
{
	f->width = width;
	f->height = height;
	f->samples = 0;
	f->rgb = calloc((size_t)width * height * 3, sizeof *f->rgb);
	return f->rgb ? 0 : -1;
}

void film_resolve(film *f, const float *sums, long samples)
{
	size_t n = (size_t)f->width * f->height;
	float inv = samples > 0 ? 1.0f / (float)samples : 0.0f;
	for (size_t i = 0; i < n; i++)
		for (int c = 0; c < 3; c++)
			f->rgb[3 * i + c] = sums[4 * i + c] * inv;
	f->samples = samples;
}

void film_free(film *f)
{
	free(f->rgb);
	f->rgb = NULL;
}
