/* test_function.c: POV-Ray functions through the whole pipeline (the scene
 * text parsed and evaluated into programs, written as OpenCL C by lowering,
 * built into the kernels and run by kernels/raycast.cl's function_values)
 * against the same expressions written here in C, in double precision, and
 * against the host's run of the programs (scene_function_eval).
 *
 * Each case is one function { } of a pigment, evaluated at random points; one
 * ok/FAIL line a case. Then the text lowering writes is checked for what the
 * scene wrote: strings that look like code, folded into constants, must leave
 * no quote, '#' or comment in it.
 *
 *   test_function [POINTS] */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cast.h"
#include "device.h"
#include "diag.h"
#include "eval.h"
#include "lower.h"
#include "parse.h"

static double sel3(double a, double b, double c)
{
	return a < 0 ? b : c;
}

static double f0(double a, double b)   /* F0 below, with K = 3 */
{
	return sin(a * 3) * cos(b * 3);
}

/* Each case: the body of function { } in POV-Ray's language, and the same in C. */
static double c_arith(double x, double y, double z) { return x * y - z / 2 + 1; }
static double c_declared(double x, double y, double z) { (void)z; return f0(x, y); }
static double c_calls(double x, double y, double z) { return f0(x, z) + f0(z, y) * f0(y, x); }
static double c_select(double x, double y, double z)
{
	return sel3(x, y, z) + (y - 1 < 0 ? 1 : y - 1 == 0 ? 2 : 3);
}
static double c_minmax(double x, double y, double z) { return fmin(fmin(x, y), z) + fmax(x, 2 * y); }
static double c_powmod(double x, double y, double z)
{
	return pow(fabs(x), 1.5) + fmod(y * 4, 1) + trunc(z * 4 / 1.5);
}
static double c_logic(double x, double y, double z)
{
	return (x < y) + (y <= z) * 2 + (x > z) * 4 + (y >= x) * 8 + (x != y) * 16 + (x == x) * 32 +
	       ((x > 0) && (y > 0)) * 64 + ((x > 0) || !(y > 0)) * 128;
}
static double c_exp(double x, double y, double z)
{
	return exp(-x * x) + log(fabs(y) + 1) + log10(fabs(z) + 1) + sqrt(fabs(x)) + atan2(y, x) + floor(z) +
	       ceil(x) + trunc(y);
}
static double c_trig(double x, double y, double z)
{
	return tan(x / 4) + asin(x / 3.5) + acos(y / 3.5) + atan(z) + sinh(x / 2) + cosh(y / 2) + tanh(z) + asinh(x) +
	       acosh(fabs(y) + 1) + atanh(z / 3.5) + x * 180 / M_PI + y * M_PI / 180;
}
static double c_folded(double x, double y, double z) { (void)z; return x * M_PI + 2 * y + 16; }   /* the string has 16 characters */
static double c_nested(double x, double y, double z)
{
	double s = 0;
	for (int i = 0; i < 40; i++)
		s = (s + x) * 0.5 + y * z / 8;
	return -(-(-s));
}

static const struct {
	const char *name, *body;
	double (*c)(double, double, double);
} cases[] = {
	{ "arithmetic", "x * y - z / 2 + 1", c_arith },
	{ "a declared function with named parameters", "F0(x, y)", c_declared },
	{ "calls of calls", "F1(x, y, z)", c_calls },
	{ "select of three and of four", "select(x, y, z) + select(y - 1, 1, 2, 3)", c_select },
	{ "min and max of several", "min(x, y, z) + max(x, 2 * y)", c_minmax },
	{ "pow, mod and div", "pow(abs(x), 1.5) + mod(y * 4, 1) + div(z * 4, 1.5)", c_powmod },
	{ "comparisons and logic", "(x < y) + (y <= z) * 2 + (x > z) * 4 + (y >= x) * 8 + (x != y) * 16 + (x = x) * 32"
	  " + (x > 0 & y > 0) * 64 + (x > 0 | !(y > 0)) * 128", c_logic },
	{ "exp, ln, log, sqrt, atan2, floor, ceil, int",
	  "exp(-x * x) + ln(abs(y) + 1) + log(abs(z) + 1) + sqrt(abs(x)) + atan2(y, x) + floor(z) + ceil(x) + int(y)",
	  c_exp },
	{ "trigonometry", "tan(x / 4) + asin(x / 3.5) + acos(y / 3.5) + atan(z) + sinh(x / 2) + cosh(y / 2) + tanh(z)"
	  " + asinh(x) + acosh(abs(y) + 1) + atanh(z / 3.5) + degrees(x) + radians(y)", c_trig },
	{ "constants folded by the host", "x * pi + V.y * y + strlen(\"*/ #define x \\\" \\\\\")", c_folded },
	{ "forty levels deep", NULL, c_nested },
};
#define N_CASES (int)(sizeof cases / sizeof *cases)

static int failures;

static char *scene_text(size_t *len)
{
	char *text = NULL;
	FILE *f = open_memstream(&text, len);
	fputs("#version 3.7;\n#declare K = 3;\n#declare V = <1, 2, 3>;\n"
	      "#declare F0 = function(a, b) { sin(a * K) * cos(b * K) }\n"
	      "#declare F1 = function { F0(x, z) + F0(z, y) * F0(y, x) }\n", f);
	for (int i = 0; i < N_CASES; i++) {
		fputs("plane { y, 0 pigment { function { ", f);
		if (cases[i].body) {
			fputs(cases[i].body, f);
		} else {   /* c_nested: s = (s + x) * 0.5 + y * z / 8, forty times */
			fputs("-(-(-(", f);
			for (int k = 0; k < 40; k++)
				fputs("((", f);
			fputs("0", f);
			for (int k = 0; k < 40; k++)
				fputs(" + x) * 0.5 + y * z / 8)", f);
			fputs(")))", f);
		}
		fputs(" } } }\n", f);
	}
	fclose(f);
	return text;
}

/* Runs function f at n points (float4 each) into out. */
static int run(device_ctx *dev, cl_program prog, int f, const float *pts, int n, float *out)
{
	cl_int err;
	cl_kernel k = clCreateKernel(prog, "function_values", &err);
	if (!k)
		return -1;
	cl_mem bp = clCreateBuffer(dev->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, (size_t)n * 16, (void *)pts,
	                           &err);
	cl_mem bo = clCreateBuffer(dev->context, CL_MEM_WRITE_ONLY, (size_t)n * sizeof *out, NULL, &err);
	clSetKernelArg(k, 0, sizeof f, &f);
	clSetKernelArg(k, 1, sizeof bp, &bp);
	clSetKernelArg(k, 2, sizeof bo, &bo);
	size_t global = (size_t)n;
	err = clEnqueueNDRangeKernel(dev->queue, k, 1, NULL, &global, NULL, 0, NULL, NULL);
	if (err == CL_SUCCESS)
		err = clEnqueueReadBuffer(dev->queue, bo, CL_TRUE, 0, (size_t)n * sizeof *out, out, 0, NULL, NULL);
	clReleaseMemObject(bp);
	clReleaseMemObject(bo);
	clReleaseKernel(k);
	if (err != CL_SUCCESS)
		fprintf(stderr, "function_values: OpenCL error %d\n", err);
	return err == CL_SUCCESS ? 0 : -1;
}

static bool close_to(double a, double b)
{
	if (isnan(a) || isnan(b))
		return isnan(a) && isnan(b);
	return fabs(a - b) <= 1e-5 * fmax(1, fabs(b));
}

/* The OpenCL lowering wrote: nothing of the scene's text may be in it. */
static void check_source(const char *src)
{
	const char *body = strstr(src, "*/");   /* after the heading comment */
	bool clean = body && !strchr(body + 2, '"') && !strchr(body + 2, '#') && !strstr(body + 2, "/*") &&
	             !strstr(body + 2, "define");
	printf("%s: the functions' OpenCL holds no text of the scene\n", clean ? "ok" : "FAIL");
	failures += !clean;
}

int main(int argc, char **argv)
{
	int n = argc > 1 ? atoi(argv[1]) : 4096;
	cast_seed(0x2545f4914f6cdd1dull);
	size_t len;
	char *text = scene_text(&len);
	scene s;
	scene_init(&s);
	ast_node *ast = parse_text("functions", text, len);   /* the source table owns text now */
	lower_result lr;
	if (!ast || eval_scene(ast, &s, NULL) != 0 || diag_error_count() != 0 || lower_scene(&s, NULL, &lr) != 0 ||
	    !lr.functions) {
		printf("FAIL: the scene did not evaluate and lower\n");
		return 1;
	}
	check_source(lr.functions);
	device_ctx dev;
	if (device_open(&dev, -1))
		return 1;
	cl_program prog = device_build(&dev, getenv("ECLAT_KERNEL_DIR"), lower_kernel_options(&lr), lr.functions);
	if (!prog)
		return 1;
	float *pts = malloc((size_t)n * 4 * sizeof *pts), *out = malloc((size_t)n * sizeof *out);
	for (int i = 0; i < n * 4; i++)
		pts[i] = (float)(6 * cast_uniform() - 3);
	for (int c = 0; c < N_CASES; c++) {
		const scene_object *o = &s.objects[c];
		int f = (int)s.pigments[o->material.pattern].params[0][0];
		if (run(&dev, prog, f, pts, n, out)) {
			failures++;
			continue;
		}
		int bad = 0;
		for (int i = 0; i < n; i++) {
			double a[3] = { pts[4 * i], pts[4 * i + 1], pts[4 * i + 2] };
			double want = cases[c].c(a[0], a[1], a[2]), host = scene_function_eval(&s, f, a);
			double dev_v = out[i];   /* a float, before the pattern wraps it */
			bool ok = close_to(host, want) && close_to(dev_v, (float)want);
			if (!ok && bad++ < 3)
				printf("  at <%g, %g, %g>: C %.9g, host %.9g, device %.9g\n", a[0], a[1], a[2], want, host, dev_v);
		}
		printf("%s: %s: %d points, %d disagree\n", bad ? "FAIL" : "ok", cases[c].name, n, bad);
		failures += bad > 0;
	}
	free(pts);
	free(out);
	clReleaseProgram(prog);
	device_close(&dev);
	ast_free(ast);
	lower_free(&lr);
	scene_free(&s);
	printf("%s\n", failures ? "FAIL" : "all function checks passed");
	return failures ? 1 : 0;
}
