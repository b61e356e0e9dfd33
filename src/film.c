/* film.c: turns the device's per-pixel sums into mean radiance and AOVs. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../kernels/shared.h"
#include "film.h"

int film_init(film *f, int width, int height, int with_aov)
{
	size_t n = (size_t)width * height;
	*f = (film){ .width = width, .height = height };
	f->rgb = calloc(n * 3, sizeof *f->rgb);
	f->heat = calloc(n, sizeof *f->heat);
	f->aov = with_aov ? calloc(n * AOV_FLOAT4S * 4, sizeof *f->aov) : NULL;
	f->sums = calloc(n * 4, sizeof *f->sums);
	if (f->rgb && f->heat && f->sums && (f->aov || !with_aov))
		return 0;
	film_free(f);
	return -1;
}

/* The sRGB decoding: what an 8-bit value's sRGB encoding stands for. */
static float srgb_decode(float c)
{
	return c <= 0.04045f ? c / 12.92f : powf((c + 0.055f) / 1.055f, 2.4f);
}

static float to_linear(float c, float gamma)
{
	if (gamma == 1 || c <= 0)
		return c;
	return gamma == 0 ? srgb_decode(c) : powf(c, gamma);
}

void film_resolve(film *f, const int64_t *sums, long samples, float gamma)
{
	size_t n = (size_t)f->width * f->height;
	double inv = samples > 0 ? 1.0 / (double)samples : 0.0, unit = ldexp(inv, -FILM_FRACTION_BITS);
	if (sums != f->sums)
		memcpy(f->sums, sums, n * 4 * sizeof *sums);
	for (size_t i = 0; i < n; i++) {
		for (int c = 0; c < 3; c++)
			f->rgb[3 * i + c] = to_linear((float)((double)sums[4 * i + c] * unit), gamma);
		f->heat[i] = (float)((double)sums[4 * i + 3] * inv);
	}
	f->samples = samples;
}

void film_free(film *f)
{
	free(f->rgb);
	free(f->heat);
	free(f->aov);
	free(f->sums);
	f->rgb = f->heat = f->aov = NULL;
	f->sums = NULL;
}

static const char *const aov_names[] = { "albedo", "normal", "depth", "id", "heat" };

int film_aov_known(const char *name)
{
	for (size_t i = 0; i < sizeof aov_names / sizeof *aov_names; i++)
		if (strcmp(name, aov_names[i]) == 0)
			return 1;
	return 0;
}

/* One pixel of an AOV from its three float4 sums: q[0..3] albedo and hits,
 * q[4..7] normal, q[8] depth, q[9] object. */
static void aov_pixel(const char *name, const float *q, float out[3])
{
	float hits = q[3];
	for (int c = 0; c < 3; c++) {
		if (strcmp(name, "albedo") == 0)
			out[c] = hits > 0 ? q[c] / hits : 0;
		else if (strcmp(name, "normal") == 0)
			out[c] = hits > 0 ? q[4 + c] / hits : 0;
		else if (strcmp(name, "depth") == 0)
			out[c] = hits > 0 ? q[8] / hits : INFINITY;
		else
			out[c] = q[9];
	}
	if (strcmp(name, "normal") == 0) {   /* the mean of unit normals, made unit again */
		float l = sqrtf(out[0] * out[0] + out[1] * out[1] + out[2] * out[2]);
		for (int c = 0; c < 3 && l > 0; c++)
			out[c] /= l;
	}
}

int film_aov(const film *f, const char *name, float *rgb)
{
	size_t n = (size_t)f->width * f->height;
	if (strcmp(name, "heat") == 0) {
		for (size_t i = 0; i < n; i++)
			rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = f->heat[i];
		return 0;
	}
	if (!f->aov)
		return -1;
	for (size_t i = 0; i < n; i++)
		aov_pixel(name, f->aov + i * AOV_FLOAT4S * 4, rgb + 3 * i);
	return 0;
}

int film_alpha(const film *f, float *alpha)
{
	if (!f->aov)
		return -1;
	size_t n = (size_t)f->width * f->height;
	float inv = f->samples > 0 ? 1.0f / (float)f->samples : 0.0f;
	for (size_t i = 0; i < n; i++)   /* a[2].z of the pixel's sums (kernels/film.cl) */
		alpha[i] = 1.0f - f->aov[(size_t)AOV_FLOAT4S * 4 * i + 10] * inv;
	return 0;
}
