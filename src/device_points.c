/* device_points.c: pattern and pigment functions called while a scene is
 * read, evaluated by the kernels (device_points.h says why). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "device.h"
#include "device_points.h"
#include "diag.h"
#include "lower.h"

/* The kernel's arguments: the scene's buffers (SCENE_BUFFERS, shared.h), of
 * which only the patterns' hold anything, then its own. */
enum {
#define POINTS_ENUM(TYPE, NAME) PB_##NAME,
	SCENE_BUFFERS(POINTS_ENUM)
#undef POINTS_ENUM
	PB_params, PB_root, PB_colour, PB_points, PB_out,
	PB_COUNT
};

struct device_points {
	int device;
	const char *kernel_dir;
	bool opened, failed;     /* failed: the device could not be had (said once) */
	device_ctx dev;
	cl_program prog;
	cl_kernel k;
	char *functions;         /* the scene's functions the program holds (NULL: none) */
	bool args_set;           /* k has every buffer argument */
	cl_mem bufs[PB_params + 1], points, out;
	int capacity;            /* points the points and out buffers hold */
	lower_textures lt;       /* the pigments lowered so far */
	int *roots;              /* by scene pigment: its tree's root in lt, or -1 */
	int n_roots;
	int n_images;            /* the scene's images when lt was begun: lt holds no later ones */
	int sent[4];             /* lt's patterns, warps, maps and texels when last sent */
};

device_points *device_points_new(int device, const char *kernel_dir)
{
	device_points *dp = calloc(1, sizeof *dp);
	if (dp) {
		dp->device = device;
		dp->kernel_dir = kernel_dir;
	}
	return dp;
}

static void release_buffers(device_points *dp)
{
	for (int i = 0; i <= PB_params; i++)
		if (dp->bufs[i])
			clReleaseMemObject(dp->bufs[i]);
	memset(dp->bufs, 0, sizeof dp->bufs);
	memset(dp->sent, 0, sizeof dp->sent);
}

void device_points_forget(device_points *dp)
{
	if (!dp)
		return;
	lower_textures_free(&dp->lt);
	memset(&dp->lt, 0, sizeof dp->lt);
	free(dp->roots);
	dp->roots = NULL;
	dp->n_roots = 0;
	dp->n_images = 0;
	release_buffers(dp);
}

void device_points_free(device_points *dp)
{
	if (!dp)
		return;
	device_points_forget(dp);
	if (dp->points)
		clReleaseMemObject(dp->points);
	if (dp->out)
		clReleaseMemObject(dp->out);
	if (dp->k)
		clReleaseKernel(dp->k);
	if (dp->prog)
		clReleaseProgram(dp->prog);
	free(dp->functions);
	if (dp->opened)
		device_close(&dp->dev);
	free(dp);
}

/* The device, once. */
static int open_device(device_points *dp)
{
	if (dp->opened || dp->failed)
		return dp->failed ? -1 : 0;
	dp->failed = true;
	if (device_open(&dp->dev, dp->device))
		return -1;
	dp->opened = true;
	dp->failed = false;
	return 0;
}

/* A program with no integrator's kernels in it, and with functions (the
 * scene's, as OpenCL C, taken) when a pigment runs function patterns: made
 * again only when they change. Without functions, whatever program there is
 * serves. */
static int use_program(device_points *dp, char *functions, int levels)
{
	if (dp->k && (!functions || (dp->functions && strcmp(functions, dp->functions) == 0))) {
		free(functions);
		return 0;
	}
	if (dp->k)
		clReleaseKernel(dp->k);
	if (dp->prog)
		clReleaseProgram(dp->prog);
	dp->k = NULL;
	free(dp->functions);
	dp->functions = functions;
	dp->args_set = false;
	char options[128];
	snprintf(options, sizeof options, "-cl-std=CL1.2 -DKERNELS_SOME=1%s", functions ? " -DSCENE_FUNCTIONS=1" : "");
	if (functions && levels > 1)
		snprintf(options + strlen(options), sizeof options - strlen(options), " -DFUNCTION_LEVELS=%d", levels);
	dp->prog = device_build(&dp->dev, dp->kernel_dir, options, functions);
	if (!dp->prog)
		return -1;
	cl_int err;
	dp->k = clCreateKernel(dp->prog, "pattern_points", &err);
	if (!dp->k)
		return device_fail("clCreateKernel(pattern_points)", err);
	return 0;
}

/* roots long enough for pigment (and the scene's pigments), the new ones -1. */
static int grow_roots(device_points *dp, const scene *s, int pigment)
{
	if (pigment < dp->n_roots)
		return 0;
	int n = s->n_pigments > pigment ? s->n_pigments : pigment + 1;
	int *r = realloc(dp->roots, (size_t)n * sizeof *r);
	if (!r)
		return -1;
	for (int i = dp->n_roots; i < n; i++)
		r[i] = -1;
	dp->roots = r;
	dp->n_roots = n;
	return 0;
}

/* pigment's tree in lt, lowered at its first use. A scene image read after lt
 * was begun is not in lt's texels (lowering takes them all at once), so lt
 * begins anew then. */
static int root_of(device_points *dp, const scene *s, int pigment)
{
	if (dp->n_roots > 0 && s->n_images != dp->n_images)
		device_points_forget(dp);
	if (dp->n_roots == 0)
		dp->n_images = s->n_images;
	if (grow_roots(dp, s, pigment))
		return -1;
	if (dp->roots[pigment] < 0)
		dp->roots[pigment] = lower_texture_pigment(&dp->lt, s, pigment);
	return dp->roots[pigment];
}

static int make(device_points *dp, int at, const void *host, size_t bytes)
{
	cl_int err;
	if (dp->bufs[at])
		clReleaseMemObject(dp->bufs[at]);
	dp->bufs[at] = clCreateBuffer(dp->dev.context, CL_MEM_READ_ONLY | (bytes ? CL_MEM_COPY_HOST_PTR : 0),
	                              bytes ? bytes : 16, bytes ? (void *)host : NULL, &err);
	return dp->bufs[at] ? 0 : device_fail("clCreateBuffer", err);
}

/* The pattern buffers, sent again when lowering added to them; the others
 * once, empty. */
static int send(device_points *dp)
{
	const lower_textures *lt = &dp->lt;
	int now[4] = { lt->n_patterns, lt->n_warps, lt->n_maps, (int)lt->n_texels };
	if (dp->args_set && dp->bufs[PB_params] && memcmp(now, dp->sent, sizeof now) == 0)
		return 0;
	dev_params params;
	memset(&params, 0, sizeof params);
	params.camera_normal = -1;
	for (int i = 0; i <= PB_params; i++) {
		const void *host = NULL;
		size_t bytes = 0;
		switch (i) {
		case PB_patterns: host = lt->patterns; bytes = lt->n_patterns * sizeof(dev_pattern); break;
		case PB_warps: host = lt->warps; bytes = lt->n_warps * sizeof(dev_warp); break;
		case PB_maps: host = lt->maps; bytes = lt->n_maps * sizeof(dev_map_entry); break;
		case PB_images: host = lt->images; bytes = lt->n_images * sizeof(dev_image); break;
		case PB_texels: host = lt->texels; bytes = lt->n_texels * sizeof(float4); break;
		case PB_params: host = &params; bytes = sizeof params; break;
		default:
			bytes = 0;
		}
		if ((!dp->bufs[i] || host) && make(dp, i, host, bytes))
			return -1;
		cl_int err = clSetKernelArg(dp->k, i, sizeof(cl_mem), &dp->bufs[i]);
		if (err != CL_SUCCESS)
			return device_fail("clSetKernelArg", err);
	}
	memcpy(dp->sent, now, sizeof now);
	dp->args_set = true;
	return 0;
}

/* The program pigment needs: with the scene's functions when its tree runs
 * function patterns, read at level 1 (lower_function_source_reading), their
 * pigments lowered into lt as the render's are. */
static int program_for(device_points *dp, const scene *s, int pigment)
{
	if (scene_pigment_levels(s, pigment) == 0)
		return use_program(dp, NULL, 1);
	for (int f = 0; f < s->n_functions; f++)
		for (int i = 0; i < s->functions[f].n_ops; i++) {
			const scene_fop *o = &s->functions[f].ops[i];
			if ((o->op == FOP_PATTERN || o->op == FOP_PIGMENT) && root_of(dp, s, o->arg) < 0)
				return -1;
		}
	if (grow_roots(dp, s, s->n_pigments - 1))
		return -1;   /* roots covers every pigment lower_function_source may look up */
	char *text = lower_function_source_reading(s, dp->roots, pigment);
	if (!text)
		return -1;
	int levels = lower_function_levels(s), below = 1 + scene_pigment_levels(s, pigment);
	return use_program(dp, text, below > levels ? below : levels);
}

/* Room for n points in the points and out buffers. */
static int room(device_points *dp, int n)
{
	if (n <= dp->capacity)
		return 0;
	cl_int err;
	cl_mem points = clCreateBuffer(dp->dev.context, CL_MEM_READ_ONLY, (size_t)n * sizeof(float4), NULL, &err);
	cl_mem out = points ? clCreateBuffer(dp->dev.context, CL_MEM_WRITE_ONLY, (size_t)n * 2 * sizeof(float4), NULL,
	                                     &err) : NULL;
	if (!out) {
		if (points)
			clReleaseMemObject(points);
		return device_fail("clCreateBuffer", err);
	}
	if (dp->points)
		clReleaseMemObject(dp->points);
	if (dp->out)
		clReleaseMemObject(dp->out);
	dp->points = points;
	dp->out = out;
	dp->capacity = n;
	return 0;
}

int device_points_eval(void *self, const scene *s, int pigment, bool colour, int n, const double *p, double *out,
                       src_loc loc)
{
	device_points *dp = self;
	if (open_device(dp)) {
		diag_error(loc, "a pattern or pigment function called while the scene is read runs on the OpenCL "
		           "device, which could not be had (above)");
		return -1;
	}
	int root = root_of(dp, s, pigment);
	if (root < 0 || program_for(dp, s, pigment)) {
		diag_error(loc, "the pattern function could not be made ready for the device");
		return -1;
	}
	if (n <= 0)
		return 0;
	float4 *host = malloc((size_t)n * 3 * sizeof *host), *got = host + n;
	if (!host || send(dp) || room(dp, n)) {
		free(host);
		diag_error(loc, "the pattern function could not be made ready for the device");
		return -1;
	}
	for (int i = 0; i < n; i++)
		host[i] = (float4){ (float)p[3 * i], (float)p[3 * i + 1], (float)p[3 * i + 2], 0 };
	cl_int c = colour, err;
	size_t global = (size_t)n;
	if ((err = clSetKernelArg(dp->k, PB_root, sizeof root, &root)) != CL_SUCCESS ||
	    (err = clSetKernelArg(dp->k, PB_colour, sizeof c, &c)) != CL_SUCCESS ||
	    (err = clSetKernelArg(dp->k, PB_points, sizeof(cl_mem), &dp->points)) != CL_SUCCESS ||
	    (err = clSetKernelArg(dp->k, PB_out, sizeof(cl_mem), &dp->out)) != CL_SUCCESS ||
	    (err = clEnqueueWriteBuffer(dp->dev.queue, dp->points, CL_FALSE, 0, (size_t)n * sizeof *host, host, 0, NULL,
	                                NULL)) != CL_SUCCESS ||
	    (err = clEnqueueNDRangeKernel(dp->dev.queue, dp->k, 1, NULL, &global, NULL, 0, NULL, NULL)) != CL_SUCCESS ||
	    (err = clEnqueueReadBuffer(dp->dev.queue, dp->out, CL_TRUE, 0, (size_t)n * 2 * sizeof *got, got, 0, NULL,
	                               NULL)) != CL_SUCCESS) {
		free(host);
		device_fail("pattern_points", err);
		diag_error(loc, "the pattern function could not be evaluated on the device");
		return -1;
	}
	for (int i = 0; i < n; i++) {
		const float4 *g = &got[2 * i];
		double *o = &out[5 * i];
		o[0] = g[0].x;
		o[1] = g[0].y;
		o[2] = g[0].z;
		o[3] = g[0].w;
		o[4] = g[1].x;
	}
	free(host);
	return 0;
}
