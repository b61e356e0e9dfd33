/* test_sky.c: the sky's importance sampling (src/lower_sky.c's table,
 * kernels/sky_sample.cl's sampler and pdf) against what it must be.
 *
 * A 48 x 24 image of weights (a dim gradient, a row of zeros, two hot
 * texels) seen through a turned, unevenly scaled sky. The device draws
 * directions with sky_sample and evaluates sky_pdf; the host checks, in
 * double precision:
 *   - the pdf sky_sample returns is sky_pdf at the direction it returns;
 *   - sky_pdf integrates to 1 over the sphere (a fine grid of directions);
 *   - the histogram of the samples over a 16 x 8 grid of the world's
 *     directions matches the pdf's integral over each cell (chi-square);
 *   - sky_pdf at a direction is the weight of the texel texture_image reads
 *     there (POV-Ray's map_type 1, written again here), over the weights'
 *     sum by solid angle, times the Jacobian: the sampler and the lookup
 *     agree on the image's orientation.
 * Exit status 0 when all hold. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/device.h"
#include "../src/lower.h"

#define W 48
#define H 24
#define SAMPLES (1 << 20)
/* The integration grid, in longitude and latitude: the turned sky squeezes
 * the sun's texel to a sliver a coarser grid's midpoint rule misjudges. */
#define GRID_U 2048
#define GRID_V 2048
#define HIST_U 16
#define HIST_V 8

static const char *test_kernel =
	"kernel void sky_test(global const dev_sky *s, global const float *cdf, int mode, int n, int grid_u, int grid_v,\n"
	"                     global float4 *out)\n"
	"{\n"
	"	int i = get_global_id(0);\n"
	"	if (i >= n)\n"
	"		return;\n"
	"	if (mode == 0) {\n"
	"		uint k = rng_key((uint)i, 0u, 1u);\n"
	"		float pdf;\n"
	"		float3 d = sky_sample(s, cdf, rng_uniform(k, 0), rng_uniform(k, 1), rng_uniform(k, 2), rng_uniform(k, 3), &pdf);\n"
	"		out[i] = (float4)(d, pdf);\n"
	"		out[n + i] = (float4)(sky_pdf(s, cdf, d), 0.0f, 0.0f, 0.0f);\n"
	"	} else {\n"
	"		float lon = 2.0f * SKY_PI * ((float)(i % grid_u) + 0.5f) / (float)grid_u;\n"
	"		float lat = SKY_PI * (((float)(i / grid_u) + 0.5f) / (float)grid_v - 0.5f);\n"
	"		float3 d = (float3)(cos(lat) * cos(lon), sin(lat), cos(lat) * sin(lon));\n"
	"		out[i] = (float4)(sky_pdf(s, cdf, d), 0.0f, 0.0f, 0.0f);\n"
	"	}\n"
	"}\n";

static int failures;

static void check(int ok, const char *what, double got, double want)
{
	printf("%s: %s (%.6g, expected %.6g)\n", ok ? "ok" : "FAIL", what, got, want);
	failures += !ok;
}

struct dev {
	device_ctx d;
	cl_program prog;
	cl_kernel k;
	cl_mem sky, cdf;
};

static int dev_open(struct dev *v, const dev_sky *sky, const float *cdf, int n_cdf)
{
	static const char *const names[] = { "kernels/shared.h", "kernels/rng.cl", "kernels/sky_sample.cl" };
	const char *texts[4];
	for (int k = 0; k < 3; k++) {
		texts[k] = NULL;
		for (int i = 0; device_sources[i].name; i++)
			if (!strcmp(device_sources[i].name, names[k]))
				texts[k] = device_sources[i].text;
		if (!texts[k]) {
			fprintf(stderr, "test_sky: the embedded kernels lack %s\n", names[k]);
			return -1;
		}
	}
	texts[3] = test_kernel;
	if (device_open(&v->d, -1) != 0)
		return -1;
	cl_int err;
	v->prog = clCreateProgramWithSource(v->d.context, 4, texts, NULL, &err);
	if (!v->prog)
		return device_fail("clCreateProgramWithSource", err);
	if (clBuildProgram(v->prog, 1, &v->d.device, "-cl-std=CL1.2", NULL, NULL) != CL_SUCCESS) {
		char log[16384];
		clGetProgramBuildInfo(v->prog, v->d.device, CL_PROGRAM_BUILD_LOG, sizeof log, log, NULL);
		fprintf(stderr, "test_sky: build failed:\n%s\n", log);
		return -1;
	}
	v->k = clCreateKernel(v->prog, "sky_test", &err);
	if (!v->k)
		return device_fail("clCreateKernel", err);
	v->sky = clCreateBuffer(v->d.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof *sky, (void *)sky, &err);
	if (v->sky)
		v->cdf = clCreateBuffer(v->d.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, n_cdf * sizeof *cdf,
		                        (void *)cdf, &err);
	return v->sky && v->cdf ? 0 : device_fail("clCreateBuffer", err);
}

/* mode 0: n samples, out 2n float4s; mode 1: the pdf at the grid's n directions. */
static int dev_run(struct dev *v, int mode, int n, float4 *out, size_t out_n)
{
	cl_int err;
	cl_mem o = clCreateBuffer(v->d.context, CL_MEM_WRITE_ONLY, out_n * sizeof *out, NULL, &err);
	if (!o)
		return device_fail("clCreateBuffer", err);
	int gu = GRID_U, gv = GRID_V;
	clSetKernelArg(v->k, 0, sizeof v->sky, &v->sky);
	clSetKernelArg(v->k, 1, sizeof v->cdf, &v->cdf);
	clSetKernelArg(v->k, 2, sizeof mode, &mode);
	clSetKernelArg(v->k, 3, sizeof n, &n);
	clSetKernelArg(v->k, 4, sizeof gu, &gu);
	clSetKernelArg(v->k, 5, sizeof gv, &gv);
	clSetKernelArg(v->k, 6, sizeof o, &o);
	size_t global = (size_t)n;
	err = clEnqueueNDRangeKernel(v->d.queue, v->k, 1, NULL, &global, NULL, 0, NULL, NULL);
	if (err == CL_SUCCESS)
		err = clEnqueueReadBuffer(v->d.queue, o, CL_TRUE, 0, out_n * sizeof *out, out, 0, NULL, NULL);
	clReleaseMemObject(o);
	return err == CL_SUCCESS ? 0 : device_fail("sky_test", err);
}

/* The grid's direction k, as the test kernel makes it (y up). */
static void grid_direction(int k, double d[3])
{
	double lon = 2 * M_PI * (k % GRID_U + 0.5) / GRID_U, lat = M_PI * ((k / GRID_U + 0.5) / GRID_V - 0.5);
	d[0] = cos(lat) * cos(lon);
	d[1] = sin(lat);
	d[2] = cos(lat) * sin(lon);
}

/* The texel texture_image (map_type 1) reads at image-space direction q, as
 * POV-Ray computes it; -1 within eps of a texel's edge. */
static int texel_at(const double q[3], double eps)
{
	double len = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]), xz = sqrt(q[0] * q[0] + q[2] * q[2]);
	double theta = xz == 0 ? 0 : acos(fmax(-1, fmin(1, q[0] / xz)));
	if (q[2] < 0)
		theta = 2 * M_PI - theta;
	double u = theta / (2 * M_PI) * W, v = (0.5 + asin(q[1] / len) / M_PI) * H;
	double y = fmod(-v + H, H);   /* the rows go down */
	if (fabs(u - floor(u + 0.5)) < eps || fabs(y - floor(y + 0.5)) < eps)
		return -1;
	return (int)y * W + (int)u;
}

int main(void)
{
	static float weight[W * H];
	for (int y = 0; y < H; y++)
		for (int x = 0; x < W; x++)
			weight[y * W + x] = y == 15 ? 0.0f : 0.2f + 0.02f * x + 0.05f * y;
	weight[5 * W + 30] = 3000;   /* a sun */
	weight[20 * W + 3] = 800;    /* a lamp below the horizon */
	/* the rows of scale <1, 2.5, 0.6> then rotate <25, 70, 0>: world to the image's space */
	double sc[3] = { 1, 2.5, 0.6 }, ax = 25 * M_PI / 180, ay = 70 * M_PI / 180;
	double rx[3][3] = { { 1, 0, 0 }, { 0, cos(ax), -sin(ax) }, { 0, sin(ax), cos(ax) } };
	double ry[3][3] = { { cos(ay), 0, sin(ay) }, { 0, 1, 0 }, { -sin(ay), 0, cos(ay) } };
	double fwd[3][3], rows_d[3][3];   /* fwd = Ry Rx S, the transformation; rows = its inverse */
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++) {
			double s = 0;
			for (int k = 0; k < 3; k++)
				s += ry[i][k] * rx[k][j];
			fwd[i][j] = s * sc[j];
		}
	/* (R S)^-1 = S^-1 R^T, and R[j][i] = fwd[j][i] / sc[i] */
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			rows_d[i][j] = fwd[j][i] / sc[i] / sc[i];
	float rows[3][4];
	for (int i = 0; i < 3; i++) {
		for (int j = 0; j < 3; j++)
			rows[i][j] = (float)rows_d[i][j];
		rows[i][3] = 0;
	}
	dev_sky sky;
	float *cdf;
	int n_cdf;
	if (lower_sky_table(weight, W, H, (const float(*)[4])rows, &sky, &cdf, &n_cdf) != 1) {
		printf("FAIL: lower_sky_table made no table\n");
		return 1;
	}
	struct dev v = { 0 };
	if (dev_open(&v, &sky, cdf, n_cdf) != 0)
		return 1;

	/* the pdf over a fine grid: its integral, and each histogram cell's share */
	float4 *pdf = malloc((size_t)GRID_U * GRID_V * sizeof *pdf);
	float4 *smp = malloc((size_t)2 * SAMPLES * sizeof *smp);
	if (!pdf || !smp)
		return 1;
	if (dev_run(&v, 1, GRID_U * GRID_V, pdf, (size_t)GRID_U * GRID_V))
		return 1;
	double integral = 0, expect[HIST_V][HIST_U] = { { 0 } };
	for (int j = 0; j < GRID_V; j++) {
		double lat0 = M_PI * ((double)j / GRID_V - 0.5), lat1 = M_PI * ((double)(j + 1) / GRID_V - 0.5);
		double area = (2 * M_PI / GRID_U) * (sin(lat1) - sin(lat0));
		for (int i = 0; i < GRID_U; i++) {
			double p = pdf[j * GRID_U + i].x * area;
			integral += p;
			expect[j * HIST_V / GRID_V][i * HIST_U / GRID_U] += p;
		}
	}
	check(fabs(integral - 1) < 0.01, "the pdf integrates to 1 over the sphere", integral, 1);

	/* samples: their pdf is sky_pdf's, and their histogram the pdf's integrals */
	if (dev_run(&v, 0, SAMPLES, smp, (size_t)2 * SAMPLES))
		return 1;
	long hist[HIST_V][HIST_U] = { { 0 } }, mismatched = 0;
	for (int s = 0; s < SAMPLES; s++) {
		float4 d = smp[s];
		double p = d.w, q = smp[SAMPLES + s].x;
		if (!(p > 0) || fabs(p - q) > 1e-3 * p)
			mismatched++;
		double lon = atan2(d.z, d.x), lat = asin(fmax(-1, fmin(1, d.y)));
		if (lon < 0)
			lon += 2 * M_PI;
		int i = (int)(lon / (2 * M_PI) * HIST_U), j = (int)((lat / M_PI + 0.5) * HIST_V);
		hist[j < 0 ? 0 : j >= HIST_V ? HIST_V - 1 : j][i < 0 ? 0 : i >= HIST_U ? HIST_U - 1 : i]++;
	}
	/* a sample near a texel's edge may round into its neighbour: a few per million */
	check(mismatched <= SAMPLES / 10000, "samples whose pdf is not sky_pdf's", (double)mismatched, 0);
	double chi2 = 0;
	int cells = 0, off = 0;
	for (int j = 0; j < HIST_V; j++)
		for (int i = 0; i < HIST_U; i++) {
			double e = expect[j][i] * SAMPLES, o = (double)hist[j][i];
			if (e < 20)
				continue;
			chi2 += (o - e) * (o - e) / e;
			cells++;
			/* the grid's midpoint rule errs where a texel's edge crosses a cell */
			off += fabs(o - e) > 5 * sqrt(e) + 0.01 * e;
		}
	check(off == 0, "histogram cells off their expected counts", off, 0);
	check(chi2 / cells < 3, "chi-square per cell of the histogram", chi2 / cells, 1);

	/* the orientation: sky_pdf against the weight of the texel texture_image reads */
	double sum = 0;
	for (int y = 0; y < H; y++) {
		double z1 = sin(M_PI * ((double)(H - y) / H - 0.5)), z0 = sin(M_PI * ((double)(H - 1 - y) / H - 0.5));
		for (int x = 0; x < W; x++)
			sum += weight[y * W + x] * (2 * M_PI / W) * (z1 - z0);
	}
	double det = fabs(rows_d[0][0] * (rows_d[1][1] * rows_d[2][2] - rows_d[1][2] * rows_d[2][1]) -
	                  rows_d[0][1] * (rows_d[1][0] * rows_d[2][2] - rows_d[1][2] * rows_d[2][0]) +
	                  rows_d[0][2] * (rows_d[1][0] * rows_d[2][1] - rows_d[1][1] * rows_d[2][0]));
	int checked = 0, wrong = 0, hot = 0;
	for (int k = 0; k < GRID_U * GRID_V; k += 797) {
		double d[3], q[3], len2 = 0;
		grid_direction(k, d);
		for (int i = 0; i < 3; i++) {
			q[i] = rows_d[i][0] * d[0] + rows_d[i][1] * d[1] + rows_d[i][2] * d[2];
			len2 += q[i] * q[i];
		}
		int t = texel_at(q, 1e-3);
		if (t < 0)
			continue;
		double want = weight[t] / sum * det / (len2 * sqrt(len2));
		checked++;
		hot += weight[t] > 100;
		wrong += fabs(pdf[k].x - want) > 1e-3 * want + 1e-7;
	}
	/* and the suns themselves, found by the sampler where the image has them */
	for (int s = 0; s < SAMPLES && hot < 8; s++) {
		double q[3];
		for (int i = 0; i < 3; i++)
			q[i] = rows_d[i][0] * smp[s].x + rows_d[i][1] * smp[s].y + rows_d[i][2] * smp[s].z;
		int t = texel_at(q, 1e-3);
		if (t >= 0 && weight[t] > 100)
			hot++;
	}
	check(wrong == 0 && checked > 1000, "directions where sky_pdf is not the texel's weight", wrong, 0);
	check(hot >= 8, "samples in the hot texels, read as texture_image reads them", hot, 8);
	printf("%d directions checked against texture_image's texel\n", checked);
	free(pdf);
	free(smp);
	free(cdf);
	clReleaseMemObject(v.sky);
	clReleaseMemObject(v.cdf);
	clReleaseKernel(v.k);
	clReleaseProgram(v.prog);
	device_close(&v.d);
	return failures ? 1 : 0;
}
