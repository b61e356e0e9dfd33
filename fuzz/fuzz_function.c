/* fuzz_function.c: libFuzzer target for the translation of POV-Ray functions
 * into OpenCL C (src/lower_function.c). The input is read as programs of
 * postfix ops (scene.h's scene_fop), valid or not, with any constants
 * (NaN, infinities, denormals among them): the translator must refuse a
 * program that breaks scene.h's promises, and write one that keeps them as
 * OpenCL C that builds. Building is slow, so one program in BUILD_EVERY that
 * was written is built on the OpenCL device (PoCL on CI), with a stand-in for
 * the kernels' real and noise; a build that fails is a finding.
 * An input: bytes taken in fours: op, argument, parameters, and the index of
 * a constant in a table of awkward values (or, after byte 0xff, 8 raw bytes).
 *
 *   make fuzz FUZZ_SECONDS=60
 *   fuzz/fuzz_function crash-...   (replays one input with its messages; make fuzz drops
 *   them with -close_fd_mask=2, and keeps libFuzzer's and the sanitizers' reports) */
#include <CL/cl.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "diag.h"
#include "lower.h"
#include "scene.h"

#define BUILD_EVERY 200
#define MAX_FUNCTIONS 4

static const double awkward[] = { 0, -0.0, 1, -1, 0.5, 1e308, -1e308, 4.9e-324, 1e-320, NAN, INFINITY, -INFINITY,
                                  3.141592653589793, 1e17, 123456789.125, -2.5e-7 };

static cl_context context;
static cl_device_id device;

static int open_device(void)
{
	if (context)
		return 0;
	cl_platform_id platform;
	cl_uint n;
	if (clGetPlatformIDs(1, &platform, &n) != CL_SUCCESS || n == 0 ||
	    clGetDeviceIDs(platform, CL_DEVICE_TYPE_ALL, 1, &device, &n) != CL_SUCCESS || n == 0)
		return -1;
	context = clCreateContext(NULL, 1, &device, NULL, NULL, NULL);
	return context ? 0 : -1;
}

static void build(const char *src)
{
	static unsigned written;
	if (++written % BUILD_EVERY != 1 || open_device())
		return;
	const char *parts[2] = { "typedef float real;\ntypedef struct scene_data scene_data;\n"
	                         "float pattern_noise(float3 p, int g) { return p.x + g; }\n"
	                         /* the internal functions' ops (kernels/pattern.cl, function.cl) */
	                         "real function_noise4(real x, real y, real z, real g) { return x + g; }\n"
	                         "#define STAND_IN9(name) real name(real x, real y, real z, real a, real b, real c, "
	                         "real d, real e, real f) { return x + a + b + c + d + e + f; }\n"
	                         "STAND_IN9(function_hetero_mf) STAND_IN9(function_ridge) STAND_IN9(function_ridged_mf) "
	                         "STAND_IN9(function_polytubes)\n", src };
	cl_int err;
	cl_program p = clCreateProgramWithSource(context, 2, parts, NULL, &err);
	if (!p)
		return;
	if (clBuildProgram(p, 1, &device, "", NULL, NULL) != CL_SUCCESS) {
		char log[8192] = "";
		clGetProgramBuildInfo(p, device, CL_PROGRAM_BUILD_LOG, sizeof log - 1, log, NULL);
		fprintf(stderr, "the written functions do not build:\n%s\n%s\n", src, log);
		abort();
	}
	clReleaseProgram(p);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	scene s;
	scene_init(&s);
	size_t i = 0;
	for (int f = 0; f < MAX_FUNCTIONS && i < size; f++) {
		scene_function fn = { .n_params = data[i++] % 5, .loc = SRC_NOWHERE };
		int cap = 0;
		while (i + 3 < size && data[i] != 0xfe) {
			if (fn.n_ops == cap) {
				cap = cap ? 2 * cap : 16;
				fn.ops = realloc(fn.ops, cap * sizeof *fn.ops);
			}
			scene_fop *o = &fn.ops[fn.n_ops++];
			o->op = data[i] % (FOP_COUNT + 2);   /* a few that are no op */
			o->arg = (int8_t)data[i + 1];
			o->value = awkward[data[i + 2] % (sizeof awkward / sizeof *awkward)];
			i += 4;
			if (data[i - 1] == 0xff && i + 8 <= size) {
				memcpy(&o->value, data + i, 8);
				i += 8;
			}
		}
		i++;   /* the 0xfe between functions */
		if (!fn.ops)
			fn.ops = malloc(sizeof *fn.ops);
		scene_add_function(&s, &fn);
	}
	char *src = lower_function_source(&s, NULL);
	int valid = s.n_functions > 0;
	char why[128];
	for (int f = 0; f < s.n_functions; f++)
		valid &= lower_function_valid(&s, f, why, sizeof why);
	if ((src != NULL) != valid)
		abort();   /* written exactly when every program keeps its promises */
	if (src) {
		if (strstr(src, "nan") || strstr(src, "inf"))
			abort();   /* %g's words, which OpenCL C reads as names */
		build(src);
	}
	free(src);
	scene_free(&s);
	return 0;
}
