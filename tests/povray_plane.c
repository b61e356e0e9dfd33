/* povray_plane.c: what the device pattern tests share (see povray_plane.h). */
#include "povray_plane.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- the scene and its camera ---- */

FILE *plane_scene_open(const char *dir, const char *name, int perspective)
{
	char path[4096];
	snprintf(path, sizeof path, "%s/%s.pov", dir, name);
	FILE *f = fopen(path, "w");
	if (!f) {
		perror(path);
		return NULL;
	}
	fprintf(f, "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n");
	if (perspective)
		fprintf(f, "camera { perspective location <0, 0, -10> direction z right x * 4/3 up y }\n");
	else
		fprintf(f, "camera { orthographic location <0, 0, -10> look_at 0 right x * 8 up y * 6 }\n");
	return f;
}

void plane_camera_hit(int perspective, int i, int j, double p[3], double d[3])
{
	double sx = (i + 0.5) / PLANE_W - 0.5, sy = 0.5 - (j + 0.5) / PLANE_H;
	if (perspective) {
		d[0] = sx * 4.0 / 3.0, d[1] = sy, d[2] = 1;
		double len = sqrt(d[0] * d[0] + d[1] * d[1] + 1);
		p[0] = 10 * d[0], p[1] = 10 * d[1], p[2] = 0;
		for (int k = 0; k < 3; k++)
			d[k] /= len;
	} else {
		p[0] = sx * 8, p[1] = sy * 6, p[2] = 0;
		d[0] = 0, d[1] = 0, d[2] = 1;
	}
}

static void rotate_axis(double p[3], int axis, double degrees)
{
	double a = degrees * M_PI / 180, cs = cos(a), sn = sin(a);
	int u = (axis + 1) % 3, v = (axis + 2) % 3;
	double pu = p[u] * cs - p[v] * sn, pv = p[u] * sn + p[v] * cs;
	p[u] = pu, p[v] = pv;
}

void plane_to_pattern(const float scale[3], const float rotate[3], const float *translate, double p[3])
{
	if (translate)
		for (int k = 0; k < 3; k++)
			p[k] -= translate[k];
	for (int axis = 2; axis >= 0; axis--)
		if (rotate[axis] != 0)
			rotate_axis(p, axis, -rotate[axis]);
	if (scale[0] != 0)
		for (int k = 0; k < 3; k++)
			p[k] /= scale[k];
}

void plane_fill_pattern(dev_pattern *pt, dev_warp warps[PLANE_MAX_WARPS], int kind, int wave, int gen,
                        const float p0[4], const float p1[4], const struct plane_warp *w, int n)
{
	memset(pt, 0, sizeof *pt);
	pt->kind = kind;
	pt->wave = wave;
	pt->noise_generator = gen ? gen : 2;
	memcpy(&pt->params[0], p0, 4 * sizeof *p0);
	memcpy(&pt->params[1], p1, 4 * sizeof *p1);
	if (kind == PATTERN_GRADIENT) {   /* POV-Ray normalizes the axis */
		float *a = &pt->params[0].x;
		float len = sqrtf(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
		for (int k = 0; k < 3; k++)
			a[k] /= len;
	}
	pt->warp_first = 0;
	pt->warp_count = n;
	memset(warps, 0, PLANE_MAX_WARPS * sizeof *warps);
	for (int i = 0; i < n; i++) {
		warps[i].kind = w[i].kind;
		warps[i].classic = w[i].classic;
		memcpy(&warps[i].a, w[i].a, sizeof warps[i].a);
		memcpy(&warps[i].b, w[i].b, sizeof warps[i].b);
		memcpy(&warps[i].c, w[i].c, sizeof warps[i].c);
	}
}

/* ---- POV-Ray's image: a binary PPM, 16 bits a channel ---- */

static int ppm_token(FILE *f)
{
	int ch;
	for (;;) {
		ch = getc(f);
		if (ch == '#')
			while (ch != '\n' && ch != EOF)
				ch = getc(f);
		else if (ch != ' ' && ch != '\t' && ch != '\n' && ch != '\r')
			break;
	}
	int v = 0;
	while (ch >= '0' && ch <= '9') {
		v = v * 10 + (ch - '0');
		ch = getc(f);
	}
	return v;
}

static int read_ppm(const char *path, float *out, int channels)
{
	FILE *f = fopen(path, "rb");
	if (!f)
		return -1;
	int ok = getc(f) == 'P' && getc(f) == '6';
	int w = ppm_token(f), h = ppm_token(f), max = ppm_token(f);
	ok = ok && w == PLANE_W && h == PLANE_H && max > 0;
	int bytes = max > 255 ? 2 : 1;
	for (int i = 0; ok && i < PLANE_W * PLANE_H; i++)
		for (int ch = 0; ok && ch < 3; ch++) {
			unsigned char px[2];
			if (fread(px, 1, bytes, f) != (size_t)bytes)
				ok = 0;
			else if (ch < channels)
				out[channels * i + ch] = (bytes == 2 ? px[0] << 8 | px[1] : px[0]) / (float)max;
		}
	fclose(f);
	return ok ? 0 : -1;
}

int plane_read_case(const char *dir, const char *name, float *out, int channels)
{
	char path[4096];
	snprintf(path, sizeof path, "%s/%s.ppm", dir, name);
	if (read_ppm(path, out, channels) != 0) {
		printf("FAIL: %s: no image from POV-Ray (%s)\n", name, path);
		return -1;
	}
	return 0;
}

/* ---- the device ---- */

static cl_program build(device_ctx *d, const char *const *kernels, int n_kernels, const char *test_kernel,
                        const char *who)
{
	const char *texts[12];
	int n = 0;
	if (n_kernels + 1 > (int)(sizeof texts / sizeof texts[0])) {
		fprintf(stderr, "%s: too many kernel sources\n", who);
		return NULL;
	}
	for (int k = 0; k < n_kernels; k++) {
		for (int i = 0; device_sources[i].name; i++)
			if (!strcmp(device_sources[i].name, kernels[k]))
				texts[n++] = device_sources[i].text;
		if (n != k + 1) {
			fprintf(stderr, "%s: the embedded kernels lack %s\n", who, kernels[k]);
			return NULL;
		}
	}
	texts[n++] = test_kernel;
	cl_int err;
	cl_program prog = clCreateProgramWithSource(d->context, n, texts, NULL, &err);
	if (!prog) {
		device_fail("clCreateProgramWithSource", err);
		return NULL;
	}
	err = clBuildProgram(prog, 1, &d->device, "-cl-std=CL1.2", NULL, NULL);
	if (err != CL_SUCCESS) {
		char log[16384];
		clGetProgramBuildInfo(prog, d->device, CL_PROGRAM_BUILD_LOG, sizeof log, log, NULL);
		fprintf(stderr, "%s: build failed:\n%s\n", who, log);
		clReleaseProgram(prog);
		return NULL;
	}
	return prog;
}

int plane_open(struct plane_device *pd, const char *const *kernels, int n_kernels, const char *test_kernel,
               const char *kernel_name, const char *who)
{
	if (device_open(&pd->d, -1) != 0)
		return -1;
	pd->prog = build(&pd->d, kernels, n_kernels, test_kernel, who);
	if (!pd->prog)
		return -1;
	cl_int err;
	pd->kernel = clCreateKernel(pd->prog, kernel_name, &err);
	if (!pd->kernel) {
		device_fail("clCreateKernel", err);
		return -1;
	}
	return 0;
}

void plane_close(struct plane_device *pd)
{
	clReleaseKernel(pd->kernel);
	clReleaseProgram(pd->prog);
	device_close(&pd->d);
}

#define MAX_ARGS 8

int plane_run(struct plane_device *pd, const struct plane_arg *args, int n_args, void *out, size_t out_size)
{
	device_ctx *d = &pd->d;
	cl_mem mem[MAX_ARGS + 1] = { 0 };
	cl_int err = CL_SUCCESS;
	int ok = n_args <= MAX_ARGS;
	for (int i = 0; ok && i < n_args; i++)
		if (!args[i].by_value) {
			mem[i] = clCreateBuffer(d->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, args[i].size,
			                        (void *)args[i].data, &err);
			ok = mem[i] != NULL;
		}
	if (ok) {
		mem[n_args] = clCreateBuffer(d->context, CL_MEM_WRITE_ONLY, out_size, NULL, &err);
		ok = mem[n_args] != NULL;
	}
	if (!ok) {
		for (int i = 0; i <= n_args && i <= MAX_ARGS; i++)
			if (mem[i])
				clReleaseMemObject(mem[i]);
		return device_fail("clCreateBuffer", err);
	}
	for (int i = 0; i < n_args; i++)
		if (args[i].by_value)
			clSetKernelArg(pd->kernel, i, args[i].size, args[i].data);
		else
			clSetKernelArg(pd->kernel, i, sizeof mem[i], &mem[i]);
	clSetKernelArg(pd->kernel, n_args, sizeof mem[n_args], &mem[n_args]);
	size_t global = PLANE_W * PLANE_H;
	err = clEnqueueNDRangeKernel(d->queue, pd->kernel, 1, NULL, &global, NULL, 0, NULL, NULL);
	if (err == CL_SUCCESS)
		err = clEnqueueReadBuffer(d->queue, mem[n_args], CL_TRUE, 0, out_size, out, 0, NULL, NULL);
	for (int i = 0; i <= n_args; i++)
		if (mem[i])
			clReleaseMemObject(mem[i]);
	if (err != CL_SUCCESS) {
		char name[256] = "the test kernel";
		clGetKernelInfo(pd->kernel, CL_KERNEL_FUNCTION_NAME, sizeof name, name, NULL);
		return device_fail(name, err);
	}
	return 0;
}

/* ---- main ---- */

int plane_main(int argc, char **argv, const char *who, int n_cases,
               int (*write_case)(const char *dir, int i, const char **name), int (*compare)(const char *dir))
{
	if (argc == 3 && !strcmp(argv[1], "write")) {
		char path[4096];
		snprintf(path, sizeof path, "%s/cases", argv[2]);
		FILE *list = fopen(path, "w");
		if (!list) {
			perror(path);
			return 1;
		}
		for (int i = 0; i < n_cases; i++) {
			const char *name = NULL;
			if (write_case(argv[2], i, &name) != 0)
				return 1;
			if (name)
				fprintf(list, "%s\n", name);
		}
		return fclose(list) != 0;
	}
	if (argc == 3 && !strcmp(argv[1], "compare"))
		return compare(argv[2]);
	fprintf(stderr, "usage: %s write|compare DIR\n", who);
	return 2;
}
