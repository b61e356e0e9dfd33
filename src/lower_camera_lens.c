/* lower_camera_lens.c: the Whitted integrator's focal blur as POV-Ray 3.7's
 * TracePixel::FocalBlurData sets it up: the lens's sample points, the
 * thresholds of its confidence test and where the batches end.
 *
 * They go into the camera_rays buffer, which only a mesh_camera uses
 * otherwise, and a mesh_camera has no focal blur:
 *   [0] xyz: POV-Ray's XPerp (unit Up x Direction), w: the focal distance / |Direction|
 *   [1] xyz: its YPerp (unit Direction x XPerp), w: the largest jitter of a lens point
 *   [2] x: blur_samples, y: the fewest samples before the test may stop
 *   [3 + i] xy: lens sample i in the disc of radius 1/2, z: the test's
 *           threshold after i + 1 samples, w: 1 where a batch ends after it
 * (kernels/whitted_pixel.cl, whitted_camera and whitted_focal). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "diag.h"
#include "lower.h"
#include "vec3.h"

#define LENS_HEADER 3
#define LENS_MOST 16384   /* samples a pixel: past this, the thresholds take long to find */

/* POV-Ray's grids: the 4 first points, or the hexagonal ones of 7, 19 and 37,
 * each with the sizes of the batches the test waits for. */
static const double grid4[4][2] = { { -0.25, 0.25 }, { 0.25, 0.25 }, { -0.25, -0.25 }, { 0.25, -0.25 } };
static const double hex7[7][2] = { { -0.288675, 0 }, { 0, 0 }, { 0.288675, 0 }, { -0.144338, 0.25 },
                                   { -0.144338, -0.25 }, { 0.144338, 0.25 }, { 0.144338, -0.25 } };
static const double hex19[19][2] = {
	{ -0.192450, 0.333333 }, { -0.192450, -0.333333 }, { 0.192450, 0.333333 }, { 0.192450, -0.333333 },
	{ 0.384900, 0 }, { -0.384900, 0 }, { 0, 0 }, { 0, 0.333333 }, { 0, -0.333333 },
	{ -0.288675, 0.166667 }, { -0.288675, -0.166667 }, { 0.288675, 0.166667 }, { 0.288675, -0.166667 },
	{ -0.096225, 0.166667 }, { -0.096225, -0.166667 }, { 0.096225, 0.166667 }, { 0.096225, -0.166667 },
	{ -0.192450, 0 }, { 0.192450, 0 } };
static const double hex37[37][2] = {
	{ 0, 0 }, { -0.216506, 0.375 }, { 0.216506, -0.375 }, { -0.216506, -0.375 }, { 0.216506, 0.375 },
	{ -0.433013, 0 }, { 0.433013, 0 }, { -0.144338, 0.25 }, { 0.144338, -0.25 }, { -0.144338, -0.25 },
	{ 0.144338, 0.25 }, { -0.288675, 0 }, { 0.288675, 0 }, { -0.072169, 0.125 }, { 0.072169, -0.125 },
	{ -0.072169, -0.125 }, { 0.072169, 0.125 }, { -0.144338, 0 }, { 0.144338, 0 }, { -0.360844, 0.125 },
	{ -0.360844, -0.125 }, { 0.360844, 0.125 }, { 0.360844, -0.125 }, { -0.288675, 0.25 },
	{ -0.288675, -0.25 }, { 0.288675, 0.25 }, { 0.288675, -0.25 }, { -0.072169, 0.375 },
	{ -0.072169, -0.375 }, { 0.072169, 0.375 }, { 0.072169, -0.375 }, { -0.216506, 0.125 },
	{ -0.216506, -0.125 }, { 0.216506, 0.125 }, { 0.216506, -0.125 }, { 0, 0.25 }, { 0, -0.25 } };
static const int batches7[] = { 7, 0 }, batches19[] = { 7, 6, 6, 0 }, batches37[] = { 7, 6, 6, 4, 4, 4, 4, 2, 0 };

/* The regularized upper incomplete gamma function Q(a, x): a series below
 * a + 1, a continued fraction (modified Lentz) above. */
static double gamma_q(double a, double x)
{
	if (x <= 0)
		return 1;
	double lead = a * log(x) - x - lgamma(a);
	if (x < a + 1) {
		double term = 1 / a, sum = term;
		for (int n = 1; n < 100000 && fabs(term) > fabs(sum) * 1e-15; n++) {
			term *= x / (a + n);
			sum += term;
		}
		return 1 - sum * exp(lead);
	}
	double b = x + 1 - a, c = 1e300, d = 1 / b, h = d;
	for (int i = 1; i < 100000; i++) {
		double an = -i * (i - a);
		b += 2;
		d = an * d + b;
		d = fabs(d) < 1e-300 ? 1e-300 : d;
		c = b + an / c;
		c = fabs(c) < 1e-300 ? 1e-300 : c;
		d = 1 / d;
		double step = d * c;
		h *= step;
		if (fabs(step - 1) < 1e-15)
			break;
	}
	return exp(lead) * h;
}

/* Cephes' chdtri, which POV-Ray uses (lower.h). Found by bisection, since Q
 * falls with x. */
double lower_chdtri(double df, double y)
{
	double lo = 0, hi = df + 10;
	while (gamma_q(df / 2, hi / 2) > y)
		hi *= 2;
	for (int i = 0; i < 200 && hi - lo > 1e-13 * hi; i++) {
		double mid = 0.5 * (lo + hi);
		if (gamma_q(df / 2, mid / 2) > y)
			lo = mid;
		else
			hi = mid;
	}
	return 0.5 * (lo + hi);
}

/* The i-th point (from 0) of POV-Ray's sub-random sequence on a disc of
 * radius 1/2: Halton's in bases 2 (the square of the radius) and 3 (the angle). */
static double halton(unsigned long i, unsigned base)
{
	double h = 0, q = 1.0 / base;
	for (i++; i > 0; i /= base, q /= base)
		h += (double)(i % base) * q;
	return h;
}

static void disc_point(unsigned long i, double v[2])
{
	double r = sqrt(halton(i, 2) * 0.25), theta = halton(i, 3) * 2 * M_PI;
	v[0] = r * cos(theta);
	v[1] = r * sin(theta);
}

/* The points past POV-Ray's standard grid: sub-random points on the disc, each
 * kept only if its cell of a grid about sqrt(n / pi) cells across is still
 * empty, while the sequence's n * 10 points last. */
static int more_points(int n, int standard, float4 *out)
{
	int size = 2 * (int)ceil(sqrt(n / M_PI)) + 1;
	char *cells = calloc((size_t)size * size, 1);
	if (!cells)
		return -1;
	for (int i = 0; i < standard; i++) {
		int xi = (int)((out[i].x + 0.5) * size), yi = (int)((out[i].y + 0.5) * size);
		cells[yi * size + xi]++;
	}
	size_t remain = (size_t)n * 10;
	unsigned long next = 0;
	for (int i = standard; i < n; i++) {
		double v[2];
		int xi, yi;
		do {
			disc_point(next++ % ((size_t)n * 10), v);
			xi = (int)((v[0] + 0.5) * size);
			yi = (int)((v[1] + 0.5) * size);
			xi = xi < size - 1 ? xi : size - 1;
			yi = yi < size - 1 ? yi : size - 1;
			remain--;
		} while ((cells[yi * size + xi] || v[0] * v[0] + v[1] * v[1] > 0.25) && remain > (size_t)(n - i));
		out[i].x = (float)v[0];
		out[i].y = (float)v[1];
		cells[yi * size + xi]++;
	}
	free(cells);
	return 0;
}

/* The lens samples' points, the batches' ends and the largest jitter. */
static int lens_points(int n, float4 *s, float *max_jitter)
{
	const double(*grid)[2] = grid4;
	int standard = 4;
	const int *batches = NULL;
	if (n >= 37)
		grid = hex37, standard = 37, batches = batches37;
	else if (n >= 19)
		grid = hex19, standard = 19, batches = batches19;
	else if (n >= 7)
		grid = hex7, standard = 7, batches = batches7;
	*max_jitter = n == 7 ? 0.144338f : n == 19 ? 0.096225f : n == 37 ? 0.0721688f : (float)(0.5 / sqrt(n));
	for (int i = 0; i < standard && i < n; i++)
		s[i] = (float4){ (float)grid[i][0], (float)grid[i][1], 0, 0 };
	if (n > standard && more_points(n, standard, s))
		return -1;
	/* POV-Ray tests after each batch: its list's sizes, then fours */
	for (int done = 0, level = 0; done < n;) {
		int batch = 4;
		if (batches && batches[level] > 0)
			batch = batches[level++];
		done = done + batch < n ? done + batch : n;
		s[done - 1].w = 1;
	}
	return 0;
}

int lower_camera_lens(const scene *s, lower_result *out)
{
	const scene_camera *c = &s->camera;
	if (!(out->params.lens.x > 0) || c->type == CAMERA_MESH)
		return 0;
	int n = c->blur_samples;
	if (n > LENS_MOST) {
		diag_warning(c->loc, "the whitted integrator takes at most %d blur_samples, not %d", LENS_MOST, n);
		n = LENS_MOST;
	}
	float4 *t = calloc((size_t)n + LENS_HEADER, sizeof *t);
	float max_jitter;
	if (!t || lens_points(n, t + LENS_HEADER, &max_jitter)) {
		free(t);
		diag_error(c->loc, "out of memory for the camera's %d blur_samples", n);
		return -1;
	}
	double x[3], y[3];
	vec3_cross(c->up, c->direction, x);
	vec3_normalize(x);
	vec3_cross(c->direction, x, y);
	vec3_normalize(y);
	double dl = sqrt(c->direction[0] * c->direction[0] + c->direction[1] * c->direction[1] +
	                 c->direction[2] * c->direction[2]);
	double focal = c->focal_distance > 0 ? c->focal_distance : 1;
	t[0] = (float4){ (float)x[0], (float)x[1], (float)x[2], (float)(dl > 0 ? focal / dl : focal) };
	t[1] = (float4){ (float)y[0], (float)y[1], (float)y[2], max_jitter };
	t[2] = (float4){ (float)n, (float)c->blur_samples_min, 0, 0 };
	double t1 = n > 1 ? c->variance / lower_chdtri(n - 1, c->confidence) : 0;
	for (int i = 0; i < n; i++)
		t[LENS_HEADER + i].z = n > 1 ? (float)(t1 * lower_chdtri(i + 1, c->confidence)) : 0;
	out->camera_rays = t;
	out->n_camera_rays = n + LENS_HEADER;
	return 0;
}
