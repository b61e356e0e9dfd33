/* film.h: the rendered image in linear RGB, the mean of all samples per pixel. */
#ifndef ECLAT_FILM_H
#define ECLAT_FILM_H

typedef struct {
	int width, height;
	long samples;   /* per pixel */
	float *rgb;     /* width * height * 3, row 0 at the top */
} film;

/* Returns 0, or -1 when memory runs out. */
int film_init(film *f, int width, int height);
/* Sets the film from per-pixel sums (4 floats a pixel, the fourth unused) of samples samples. */
void film_resolve(film *f, const float *sums, long samples);
void film_free(film *f);

#endif
