/* film.h: the rendered image in linear RGB, the mean of all samples per pixel,
 * and what the AOVs are made from. */
#ifndef ECLAT_FILM_H
#define ECLAT_FILM_H

#include <stddef.h>
#include <stdint.h>

#include "image.h"

typedef struct {
	int width, height;
	long samples;   /* per pixel */
	float *rgb;     /* width * height * 3, row 0 at the top */
	float *heat;    /* width * height: box and primitive tests per sample */
	float *aov;     /* NULL, or the device's aov sums (AOV_FLOAT4S float4 a pixel, shared.h) */
	int64_t *sums;  /* width * height * 4: the device's film, exact sums (FILM_FRACTION_BITS) */
} film;

/* Returns 0, or -1 when memory runs out. with_aov: allocate film.aov. */
int film_init(film *f, int width, int height, int with_aov);
/* Sets the film from per-pixel sums (4 a pixel: rgb in fixed point and tests, as
 * the device's film holds them) of samples samples, and keeps a copy of them. gamma: the working gamma the sums are in (scene.film_gamma): the
 * film holds c ^ gamma, or for 0 (gamma correction off) the colours that the
 * sRGB encoding of 8-bit images turns back into c. */
void film_resolve(film *f, const int64_t *sums, long samples, float gamma);
void film_free(film *f);

/* The alpha channel (width * height): 1 minus the share of the samples that
 * saw the background through (POV-Ray's transmittance), which the kernels
 * sum into film.aov. Returns -1 when film.aov is missing. */
int film_alpha(const film *f, float *alpha);

/* 1 when name is an AOV: albedo, normal, depth, id or heat. */
int film_aov_known(const char *name);
/* Fills rgb (width * height * 3) with the AOV: albedo (of the first surface,
 * averaged over the pixel), normal (components in -1..1), depth (distance to the
 * first surface, inf where none), id (object number of the pixel centre's first
 * sample, -1 where none) and heat (box and primitive tests of the camera ray, per
 * sample). Returns -1 when the AOV needs film.aov and it is missing. */
int film_aov(const film *f, const char *name, float *rgb);

/* Writes f's colours, linear, to an EXR named after target in $TMPDIR (else
 * /tmp, /var/tmp), for when target cannot be written: 0 with its name in
 * where, or -1 (src/film_rescue.c). */
int film_rescue(const film *f, const char *target, const image_meta *meta, char *where, size_t n);

#endif
