/* film.h: the rendered image in linear RGB, the mean of all samples per pixel,
 * and what the AOVs are made from. */
#ifndef ECLAT_FILM_H
#define ECLAT_FILM_H

typedef struct {
	int width, height;
	long samples;   /* per pixel */
	float *rgb;     /* width * height * 3, row 0 at the top */
	float *heat;    /* width * height: box and primitive tests per sample */
	float *aov;     /* NULL, or the device's aov sums (AOV_FLOAT4S float4 a pixel, shared.h) */
} film;

/* Returns 0, or -1 when memory runs out. with_aov: allocate film.aov. */
int film_init(film *f, int width, int height, int with_aov);
/* Sets the film from per-pixel sums (4 floats a pixel: rgb and tests) of samples
 * samples. gamma: the working gamma the sums are in (scene.film_gamma): the
 * film holds c ^ gamma, or for 0 (gamma correction off) the colours that the
 * sRGB encoding of 8-bit images turns back into c. */
void film_resolve(film *f, const float *sums, long samples, float gamma);
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

#endif
