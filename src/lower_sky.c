/* lower_sky.c: the table by which the path tracer samples a sky_sphere of one
 * spherical image_map (an HDR environment) by importance.
 *
 *   lower_sky(out);   after the materials and textures are lowered
 *   out->params.sky_sampled: 1 when out->sky and out->sky_cdf are there
 *
 * Each texel weighs its brightness, as texture_sky would see it at the
 * texel's centre (over the background, times the sky's emission), spread as
 * the image's interpolation spreads it, times its solid angle; the kernels
 * (kernels/sky_sample.cl) pick a texel by these weights and a direction
 * uniformly within it. Other skies (gradients, layers, warps, a translated
 * image, whose directions no linear map can invert) are found by bounce rays
 * alone, as before. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "lower.h"

/* rows' 3 x 3 part inverted into inv; its |determinant|, 0 when singular. */
static double invert3(const float rows[3][4], double inv[3][3])
{
	double a[3][3];
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			a[i][j] = rows[i][j];
	double c00 = a[1][1] * a[2][2] - a[1][2] * a[2][1], c01 = a[1][2] * a[2][0] - a[1][0] * a[2][2],
	       c02 = a[1][0] * a[2][1] - a[1][1] * a[2][0];
	double det = a[0][0] * c00 + a[0][1] * c01 + a[0][2] * c02;
	if (!(fabs(det) > 1e-30) || !isfinite(det))
		return 0;
	inv[0][0] = c00 / det;
	inv[1][0] = c01 / det;
	inv[2][0] = c02 / det;
	inv[0][1] = (a[0][2] * a[2][1] - a[0][1] * a[2][2]) / det;
	inv[1][1] = (a[0][0] * a[2][2] - a[0][2] * a[2][0]) / det;
	inv[2][1] = (a[0][1] * a[2][0] - a[0][0] * a[2][1]) / det;
	inv[0][2] = (a[0][1] * a[1][2] - a[0][2] * a[1][1]) / det;
	inv[1][2] = (a[0][2] * a[1][0] - a[0][0] * a[1][2]) / det;
	inv[2][2] = (a[0][0] * a[1][1] - a[0][1] * a[1][0]) / det;
	return fabs(det);
}

/* cdf[0..n] from the n sums in s (total: their sum, > 0); the last is 1
 * exactly, so that no u in [0, 1) falls past it. */
static void make_cdf(const double *s, int n, double total, float *cdf)
{
	double run = 0;
	cdf[0] = 0;
	for (int i = 0; i < n; i++) {
		run += s[i];
		cdf[i + 1] = (float)(run / total);
	}
	cdf[n] = 1.0f;
}

int lower_sky_table(const float *weight, int width, int height, const float rows[3][4], dev_sky *sky,
                    float **cdf, int *n)
{
	double inv[3][3], det = invert3(rows, inv);
	if (width <= 0 || height <= 0 || det == 0)
		return 0;
	long count = (long)(height + 1) + (long)height * (width + 1);
	float *c = malloc(count * sizeof *c);
	double *row_sum = malloc(height * sizeof *row_sum), *texel = malloc(width * sizeof *texel);
	if (!c || !row_sum || !texel) {
		free(c);
		free(row_sum);
		free(texel);
		return -1;
	}
	double total = 0;
	for (int y = 0; y < height; y++) {
		/* the row's solid angle over 2 pi / width: the sines of its latitudes,
		 * as kernels/sky_sample.cl's sky_row_z */
		double z_hi = sin(M_PI * ((double)(height - y) / height - 0.5)),
		       z_lo = sin(M_PI * ((double)(height - 1 - y) / height - 0.5));
		double sum = 0;
		for (int x = 0; x < width; x++) {
			double w = weight[(long)y * width + x];
			texel[x] = isfinite(w) && w > 0 ? w * (z_hi - z_lo) : 0;
			sum += texel[x];
		}
		float *row = c + (height + 1) + (long)y * (width + 1);
		if (sum > 0) {
			make_cdf(texel, width, sum, row);
		} else {   /* never chosen (its row has no weight); uniform, so no NaN */
			for (int x = 0; x <= width; x++)
				row[x] = (float)x / width;
		}
		row_sum[y] = sum;
		total += sum;
	}
	free(texel);
	if (!(total > 0) || !isfinite(total)) {
		free(c);
		free(row_sum);
		return 0;
	}
	make_cdf(row_sum, height, total, c);
	free(row_sum);
	*sky = (dev_sky){ .width = width, .height = height, .det = (float)det };
	for (int i = 0; i < 3; i++) {
		sky->rows[i] = (float4){ rows[i][0], rows[i][1], rows[i][2], 0 };
		sky->inv[i] = (float4){ (float)inv[i][0], (float)inv[i][1], (float)inv[i][2], 0 };
	}
	*cdf = c;
	*n = (int)count;
	return 1;
}

/* The sky's radiance seen in texel t of an image_map pattern pt that is the
 * sky's only layer m, as texture_sky adds it up: the colour over the
 * background by filter and transmit, the colour times the sky's emission. */
static double texel_brightness(const float4 *t, int premultiplied, const dev_pattern *pt, const dev_material *m,
                               const float4 *background)
{
	float rgb[3] = { t->x, t->y, t->z }, bg[3] = { background->x, background->y, background->z };
	float em[3] = { m->emission.x, m->emission.y, m->emission.z };
	if (premultiplied && t->w > 1e-10f)
		for (int k = 0; k < 3; k++)
			rgb[k] /= t->w;
	double filter = pt->params[1].x, transmit = 1.0 - t->w + pt->params[1].y, sum = 0;
	for (int k = 0; k < 3; k++)
		sum += rgb[k] * (1.0 - filter - transmit) * em[k] + bg[k] * (filter * rgb[k] + transmit);
	return sum / 3;   /* the mean of the channels: a blue sky is as bright to sample as it looks */
}

/* Texel i's neighbour d (-1, 0, 1) along a side of n texels: wrapped, or at
 * the edge for a once image, as texture_texel reads it. */
static int neighbour(int i, int d, int n, int once)
{
	int j = i + d;
	return once ? (j < 0 ? 0 : j >= n ? n - 1 : j) : (j + n) % n;
}

/* The brightness of every texel of image im, averaged over the texel as the
 * interpolation spreads it: bilinear interpolation between texel centres
 * gives a texel's area 3/4 of its own value and 1/8 of each neighbour's
 * along each axis (taken for interpolate 4 too). */
static float *texel_weights(const lower_result *out, const dev_pattern *pt, const dev_material *m)
{
	const dev_image *im = &out->textures.images[(int)pt->params[0].x];
	const float4 *tx = out->textures.texels + im->first;
	int w = im->width, h = im->height, interp = (int)pt->params[0].z, once = pt->params[0].w != 0;
	long n = (long)w * h;
	float *b = malloc(n * sizeof *b), *spread = interp ? malloc(n * sizeof *spread) : NULL;
	if (!b || (interp && !spread)) {
		free(b);
		free(spread);
		return NULL;
	}
	for (long i = 0; i < n; i++)
		b[i] = (float)texel_brightness(&tx[i], (im->flags & IMAGE_PREMULTIPLIED) != 0, pt, m, &out->params.background);
	if (!interp)
		return b;
	static const double k[3] = { 0.125, 0.75, 0.125 };
	for (int y = 0; y < h; y++)
		for (int x = 0; x < w; x++) {
			double s = 0;
			for (int dy = -1; dy <= 1; dy++)
				for (int dx = -1; dx <= 1; dx++)
					s += k[dy + 1] * k[dx + 1] * b[(long)neighbour(y, dy, h, once) * w + neighbour(x, dx, w, once)];
			spread[(long)y * w + x] = (float)s;
		}
	free(b);
	return spread;
}

/* lower.h; -1 after saying that memory ran out. */
int lower_sky(lower_result *out)
{
	dev_params *p = &out->params;
	p->sky_sampled = 0;
	if (p->sky < 0 || p->sky_layers != 1)
		return 0;
	const dev_material *m = &out->materials[p->sky];
	if (m->pattern < 0 || m->below >= 0 || (m->flags & MATERIAL_TEXTURE_MAP))
		return 0;
	const dev_pattern *pt = &out->textures.patterns[m->pattern];
	if (pt->kind != PATTERN_IMAGE_MAP || (int)pt->params[0].y != 1 || pt->warp_count > 0)
		return 0;
	float rows[3][4];
	double scale = 0, shift = 0;
	for (int i = 0; i < 3; i++) {
		rows[i][0] = pt->rows[i].x;
		rows[i][1] = pt->rows[i].y;
		rows[i][2] = pt->rows[i].z;
		rows[i][3] = 0;
		scale = fmax(scale, fmax(fabs(rows[i][0]), fmax(fabs(rows[i][1]), fabs(rows[i][2]))));
		shift = fmax(shift, fabs(pt->rows[i].w));
	}
	if (shift > 1e-6 * scale)   /* the sky seen from off its centre: not a map of directions */
		return 0;
	const dev_image *im = &out->textures.images[(int)pt->params[0].x];
	float *weight = texel_weights(out, pt, m);
	int rc = weight ? lower_sky_table(weight, im->width, im->height, (const float(*)[4])rows, &out->sky,
	                                  &out->sky_cdf, &out->n_sky_cdf)
	                : -1;
	free(weight);
	if (rc < 0) {
		fprintf(stderr, "eclat: out of memory for the sky's sampling table\n");
		return -1;
	}
	p->sky_sampled = rc;
	return 0;
}
